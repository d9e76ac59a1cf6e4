// The cam plot: sampling a cam's interpolated form outside the cycle (cam_plot.hpp).
#include "tomc/diagnostics/cam_plot.hpp"

#include <algorithm>
#include <optional>
#include <thread>

#include "tomc/techobjects/cam/cam.hpp"

namespace tomc::diagnostics {

namespace to = tomc::techobjects;

CamPlot sample_cam(const to::CamProfile& profile, std::size_t samples) {
  CamPlot plot;
  if (profile.empty()) return plot;
  const std::size_t n = std::clamp(samples, kMinCamSamples, kMaxCamSamples);
  plot.start = profile.start();
  plot.end = profile.end();
  for (auto* v : {&plot.leading, &plot.position, &plot.velocity, &plot.acceleration})
    v->reserve(n);
  std::size_t piece = 0;
  for (std::size_t i = 0; i < n; ++i) {
    // The last sample is the end exactly (no rounding past the definition range).
    const double x = i + 1 == n ? plot.end
                                : plot.start + (plot.end - plot.start) * static_cast<double>(i) /
                                                   static_cast<double>(n - 1);
    piece = profile.find(x, piece);
    const to::CamValue v = to::CamProfile::evaluate(profile.pieces()[piece], x);
    plot.leading.push_back(x);
    plot.position.push_back(v.y);
    plot.velocity.push_back(v.dy);
    plot.acceleration.push_back(v.ddy);
  }
  return plot;
}

namespace {

struct Published {
  bool valid = false;
  std::uint64_t cycle = 0;
  std::uint64_t revision = 0;
  bool interpolated = false;
};

Published newest(Diagnostics& diagnostics, std::size_t object, std::size_t status_word_row) {
  diagnostics.poll();
  return diagnostics.read([&](const Diagnostics::State& state) {
    const Diagnostics::ObjectState& o = state.objects[object];
    const double word = o.valid ? o.snapshot.values[status_word_row] : 0.0;
    const auto bit = static_cast<std::uint32_t>(to::CamStatusWordBit::kInterpolated);
    return Published{o.valid, o.snapshot.cycle, o.snapshot.revision,
                     ((static_cast<std::uint32_t>(word) >> bit) & 1u) != 0};
  });
}

}  // namespace

std::variant<CamPlot, std::string> plot_cam(Diagnostics& diagnostics, std::size_t object, std::size_t samples,
                                            std::chrono::milliseconds timeout) {
  const to::Cam* cam = object < diagnostics.object_count() ? diagnostics.view(object).cam() : nullptr;
  if (cam == nullptr) return std::string("not a cam");
  const auto table = diagnostics.view(object).variables();
  const to::VariableInfo* status_word = to::find_variable(table, "StatusWord");
  if (status_word == nullptr) return std::string("the cam has no StatusWord");
  const auto row = static_cast<std::size_t>(status_word - table.data());
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  auto wait_for = [&](auto&& done) -> std::optional<Published> {
    for (;;) {
      const Published p = newest(diagnostics, object, row);
      if (done(p)) return p;
      if (std::chrono::steady_clock::now() >= deadline) return std::nullopt;
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
  };
  for (;;) {
    // A snapshot taken after the request came: an older one may predate the last MC_InterpolateCam.
    const Published entry = newest(diagnostics, object, row);
    const auto before =
        wait_for([&](const Published& p) { return p.valid && (!entry.valid || p.cycle > entry.cycle); });
    if (!before) return std::string("no snapshot of the cam arrived (is the runtime running?)");
    if (!before->interpolated) return std::string("the cam is not interpolated (MC_InterpolateCam)");
    CamPlot plot = sample_cam(cam->profile(), samples);
    plot.revision = before->revision;
    // A snapshot taken after the sampling: the newest one now may have been taken during it.
    const std::uint64_t during = newest(diagnostics, object, row).cycle;
    const auto after = wait_for([&](const Published& p) { return p.cycle > during; });
    if (!after) return std::string("the cycle published no snapshot of the cam within the timeout");
    if (after->revision == before->revision && after->interpolated) return plot;
    // Re-interpolated while sampled: sample the new form.
  }
}

}  // namespace tomc::diagnostics
