// The trace PNG (trace_image.hpp). OpenCV stays in this file: the rest of tomc never sees it.
#include "tomc/diagnostics/trace_image.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

namespace tomc::diagnostics {

namespace {

// Distinguishable colours (BGR), repeated after 10 channels.
const cv::Scalar kColours[] = {{180, 119, 31},  {14, 127, 255}, {44, 160, 44},   {40, 39, 214},
                               {189, 103, 148}, {75, 86, 140},  {194, 119, 227}, {127, 127, 127},
                               {34, 189, 188},  {207, 190, 23}};
const cv::Scalar kBlack{0, 0, 0};
const cv::Scalar kGrid{225, 225, 225};
const cv::Scalar kTrigger{0, 0, 220};
constexpr int kFont = cv::FONT_HERSHEY_SIMPLEX;

std::string format(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", v);
  return text;
}

}  // namespace

std::vector<std::uint8_t> render_trace_png(const TraceCapture& c, int width, int height) {
  width = std::clamp(width, kMinImageWidth, kMaxImageWidth);
  height = std::clamp(height, kMinImageHeight, kMaxImageHeight);
  cv::Mat image(height, width, CV_8UC3, cv::Scalar(255, 255, 255));
  const std::size_t rows = c.rows();
  const std::size_t width_ch = c.channels.size();
  const int legend_lines = static_cast<int>((width_ch + 1) / 2);
  const int left = 60;
  const int right = width - 20;
  const int top = 40;
  const int bottom = height - 40 - 18 * legend_lines;

  std::string title = "tomc trace: " + std::to_string(rows) + " samples, trigger " + c.trigger_description;
  if (c.lost > 0) title += ", " + std::to_string(c.lost) + " lost";
  cv::putText(image, title, {left, 25}, kFont, 0.5, kBlack, 1, cv::LINE_AA);
  if (rows == 0 || width_ch == 0 || bottom - top < 40) {
    cv::putText(image, "no samples", {left, top + 40}, kFont, 0.7, kBlack, 1, cv::LINE_AA);
  } else {
    const double cycle_s = c.decimation == 0 ? c.sample_period_s : c.sample_period_s / c.decimation;
    const double t0 = c.trigger_row < rows ? static_cast<double>(c.cycles[c.trigger_row])
                                           : static_cast<double>(c.cycles[0]);
    const double t_first = (static_cast<double>(c.cycles.front()) - t0) * cycle_s;
    double t_last = (static_cast<double>(c.cycles.back()) - t0) * cycle_s;
    if (t_last <= t_first) t_last = t_first + cycle_s;
    auto x_of = [&](double t) { return left + (t - t_first) / (t_last - t_first) * (right - left); };

    // Grid and time axis.
    cv::rectangle(image, {left, top}, {right, bottom}, kBlack, 1);
    for (int k = 1; k < 10; ++k) {
      const int x = left + k * (right - left) / 10;
      const int y = top + k * (bottom - top) / 10;
      cv::line(image, {x, top + 1}, {x, bottom - 1}, kGrid, 1);
      cv::line(image, {left + 1, y}, {right - 1, y}, kGrid, 1);
    }
    for (int k = 0; k <= 5; ++k) {
      const double t = t_first + k * (t_last - t_first) / 5.0;
      const int x = static_cast<int>(x_of(t));
      cv::putText(image, format(t), {x - 15, bottom + 15}, kFont, 0.4, kBlack, 1, cv::LINE_AA);
    }
    cv::putText(image, "t [s]", {right - 35, bottom + 30}, kFont, 0.4, kBlack, 1, cv::LINE_AA);
    if (c.trigger_row < rows) {
      const int x = static_cast<int>(x_of(0.0));
      for (int y = top; y < bottom; y += 8)
        cv::line(image, {x, y}, {x, std::min(y + 4, bottom)}, kTrigger, 1);
    }

    // Each channel scaled to its own range, with a margin.
    std::vector<cv::Point> points;
    points.reserve(rows);
    for (std::size_t ch = 0; ch < width_ch; ++ch) {
      double lo = std::numeric_limits<double>::infinity();
      double hi = -lo;
      for (std::size_t r = 0; r < rows; ++r) {
        const double v = c.values[r * width_ch + ch];
        if (!std::isfinite(v)) continue;
        lo = std::min(lo, v);
        hi = std::max(hi, v);
      }
      const cv::Scalar colour = kColours[ch % std::size(kColours)];
      if (std::isfinite(lo)) {
        const double span = hi > lo ? hi - lo : 1.0;
        const double base = hi > lo ? lo : lo - 0.5;
        auto y_of = [&](double v) { return bottom - 8 - (v - base) / span * (bottom - top - 16); };
        points.clear();
        for (std::size_t r = 0; r < rows; ++r) {
          const double v = c.values[r * width_ch + ch];
          if (!std::isfinite(v)) continue;
          const double t = (static_cast<double>(c.cycles[r]) - t0) * cycle_s;
          points.emplace_back(static_cast<int>(std::lround(x_of(t))), static_cast<int>(std::lround(y_of(v))));
        }
        if (points.size() == 1) points.push_back(points.front());
        cv::polylines(image, points, false, colour, 1, cv::LINE_AA);
      }
      const int column = static_cast<int>(ch % 2);
      const int line = static_cast<int>(ch / 2);
      const int lx = left + column * (right - left) / 2;
      const int ly = bottom + 45 + 18 * line - 18 * 0;
      cv::line(image, {lx, ly - 4}, {lx + 20, ly - 4}, colour, 2);
      std::string label = c.channels[ch];
      label += std::isfinite(lo) ? "  [" + format(lo) + " .. " + format(hi) + "]" : "  [no value]";
      cv::putText(image, label, {lx + 26, ly}, kFont, 0.42, kBlack, 1, cv::LINE_AA);
    }
  }
  std::vector<std::uint8_t> png;
  cv::imencode(".png", image, png);
  return png;
}

}  // namespace tomc::diagnostics
