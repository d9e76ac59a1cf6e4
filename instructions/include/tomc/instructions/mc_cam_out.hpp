#pragma once
// MC_CamOut (spec 07 §3.5): desynchronize a camming, with MC_GearOut's parameters and behaviour (the one
// desynchronization instruction of mc_gear_out.hpp).
#include "tomc/instructions/mc_gear_out.hpp"
