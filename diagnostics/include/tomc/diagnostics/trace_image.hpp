#pragma once
// A trace as a PNG image, drawn on the server with OpenCV (GET /api/trace.png): every channel in its own
// colour, each scaled to its own range (the legend gives it), time relative to the trigger, the trigger as a
// line.

#include <cstdint>
#include <vector>

#include "tomc/diagnostics/trace.hpp"

namespace tomc::diagnostics {

inline constexpr int kMinImageWidth = 320;
inline constexpr int kMaxImageWidth = 4000;
inline constexpr int kMinImageHeight = 200;
inline constexpr int kMaxImageHeight = 3000;

// PNG bytes; an empty trace gives an image saying so. width/height are clamped to the limits above.
std::vector<std::uint8_t> render_trace_png(const TraceCapture& capture, int width, int height);

}  // namespace tomc::diagnostics
