#pragma once
// Physical value <-> wire value conversions (spec 06 §1.2, §7, §8, §9).
// Rule [OUR CHOICE] spec 06 §1.2: raw = round_half_away_from_zero(value / reference * 2^n), then saturate to
// the representable range. A non-finite value gives 0 (never a random setpoint); a reference <= 0 or
// non-finite also gives 0: references are validated when a connection is configured, this is only the last
// guard.

#include <cstdint>

namespace tomc::telegrams {

inline constexpr double kN2Hundred = 16384.0;       // 0x4000 = 100 %
inline constexpr double kN4Hundred = 1073741824.0;  // 0x40000000 = 100 %

// NSOLL_A / NIST_A (N2) and NSOLL_B / NIST_B (N4): speed in any unit, reference in the same unit.
std::int16_t speed_to_n2(double speed, double reference_speed) noexcept;
std::int32_t speed_to_n4(double speed, double reference_speed) noexcept;
double n2_to_speed(std::int16_t raw, double reference_speed) noexcept;
double n4_to_speed(std::int32_t raw, double reference_speed) noexcept;

// Telegram 750 torques (M_ADD1, M_LIMIT_POS, M_LIMIT_NEG, M_ACT): N2 of ReferenceTorque (or ReferenceForce).
std::int16_t torque_to_n2(double torque, double reference_torque) noexcept;
double n2_to_torque(std::int16_t raw, double reference_torque) noexcept;

// MOMRED, spec 06 §9 [OUR CHOICE]: 0x4000 = 100 % reduction; T_limit = T_ref * (1 - MOMRED / 16384).
std::uint16_t momred_from_reduction_percent(double reduction_percent) noexcept;  // clamped to 0..100 %
std::uint16_t momred_from_torque_limit(double torque_limit, double reference_torque) noexcept;
double torque_limit_from_momred(std::uint16_t momred, double reference_torque) noexcept;

// KPC, spec 06 §7 [OUR CHOICE]: unit 0.001 1/s, KPC = round(Kv * 1000), saturated to int32.
std::int32_t kpc_from_kv(double kv_per_second) noexcept;
double kv_from_kpc(std::int32_t kpc) noexcept;

// XERR, spec 06 §7: following error in encoder-1 counts (XIST1 format incl. fine bits), rounded, saturated.
std::int32_t xerr_from_counts(double counts) noexcept;

}  // namespace tomc::telegrams
