#pragma once
// The cam plot of the diagnostics page (issue 19 "Page"): a TO_Cam's position, velocity and acceleration
// over the leading value — f(x), f'(x), f''(x) of its interpolated form (spec 07 §3.1–§3.2), unit-neutral
// like the cam — sampled on request by the web server's thread, never in the cycle, at a bounded number of
// evenly spaced leading values.
//
// The cam's profile belongs to the cycle (MC_InterpolateCam rebuilds it in the user program's call). The
// server reads it while the cycle runs, so plot_cam() checks the cam's interpolation count (published with
// each snapshot) before and in a snapshot taken after the sampling: a cam re-interpolated meanwhile is
// sampled again (decisions W20).

#include <chrono>
#include <cstddef>
#include <string>
#include <variant>
#include <vector>

#include "tomc/diagnostics/diagnostics.hpp"
#include "tomc/techobjects/cam/cam_profile.hpp"

namespace tomc::diagnostics {

inline constexpr std::size_t kMinCamSamples = 2;
inline constexpr std::size_t kMaxCamSamples = 2001;
inline constexpr std::size_t kDefaultCamSamples = 501;

struct CamPlot {
  double start = 0.0;                // StatusCam.StartLeadingValue
  double end = 0.0;                  // StatusCam.EndLeadingValue
  std::uint64_t revision = 0;        // the interpolation count the samples belong to
  std::vector<double> leading;       // x_i = start + i·(end − start)/(n − 1)
  std::vector<double> position;      // f(x_i)
  std::vector<double> velocity;      // f'(x_i): following per leading unit
  std::vector<double> acceleration;  // f''(x_i)
};

// `samples` evenly spaced leading values over the profile's definition range, clamped to kMinCamSamples ..
// kMaxCamSamples; an empty profile gives an empty plot.
CamPlot sample_cam(const techobjects::CamProfile& profile, std::size_t samples);

// The plot of the TO_Cam `object` (a CamView), validated against a re-interpolation while it was sampled.
// A message instead when the object is no cam, is not interpolated, or no consistent sampling succeeded
// within `timeout` (no snapshot arrived: the runtime does not run).
std::variant<CamPlot, std::string> plot_cam(
    Diagnostics& diagnostics, std::size_t object, std::size_t samples,
    std::chrono::milliseconds timeout = std::chrono::milliseconds(1000));

}  // namespace tomc::diagnostics
