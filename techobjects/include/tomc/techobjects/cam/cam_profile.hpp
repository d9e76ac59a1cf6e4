#pragma once
// The interpolated transfer function y = f(x) of a cam (spec 07 §3.1–§3.2): an ordered, gap-free list of
// pieces, each a polynomial of degree ≤ 6 plus a sine term, produced by MC_InterpolateCam
// (cam_interpolation.hpp). Evaluation is what a follower does every cycle: a binary search and two Horner
// sums, noexcept, no allocation, bounded (log2 of the piece count).

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace tomc::techobjects {

// One piece on [x0, x1]: y = Σ c[k]·(x − origin)^k + sine_amplitude·sin(sine_period·x + sine_phase).
// A segment of the data block keeps origin 0 (its coefficients are for absolute x, spec 07 O-7); pieces
// tomc generates (point interpolation, transitions) use origin = x0, which keeps them well conditioned.
struct CamPiece {
  double x0 = 0.0;
  double x1 = 0.0;
  double origin = 0.0;
  std::array<double, 7> c{};
  double sine_amplitude = 0.0;
  double sine_period = 0.0;
  double sine_phase = 0.0;
};

// The value of the cam and its first two derivatives with respect to the leading value.
struct CamValue {
  double y = 0.0;
  double dy = 0.0;
  double ddy = 0.0;
};

// Steps of position, velocity and acceleration (in leading-value units) at the joins of the pieces, and the
// differences between the end and the start of the cam that cyclic use sees (spec 07 §3.3).
struct CamContinuity {
  std::array<double, 3> max_step{};         // largest |jump| of y, y', y'' at an inner join
  std::array<double, 3> max_step_at{};      // the leading value of that join
  std::array<double, 3> end_minus_start{};  // f(End) − f(Start), f'(End) − f'(Start), f''(End) − f''(Start)
};

// Job-related scaling and shifting (spec 07 §3.3): y = SlaveScaling·f((x − MasterOffset)/MasterScaling) +
// SlaveOffset.
struct CamScaling {
  double MasterOffset = 0.0;
  double SlaveOffset = 0.0;
  double MasterScaling = 1.0;
  double SlaveScaling = 1.0;
};

// MC_GetCamLeadingValue.ApproachDirection (spec 07 §3.6).
enum class ApproachDirection : std::int32_t { kPositive = 1, kNegative = 2, kNearest = 3 };

class CamProfile {
 public:
  CamProfile() = default;
  // Reserves room for `max_pieces`; push() never grows beyond it.
  explicit CamProfile(std::size_t max_pieces) { pieces_.reserve(max_pieces); }

  // ---- building (MC_InterpolateCam) ----
  void clear() noexcept { pieces_.clear(); }
  std::size_t capacity() const noexcept { return pieces_.capacity(); }
  // Appends a piece; false if the capacity is exhausted (nothing appended).
  bool push(const CamPiece& piece) noexcept;
  void set_continuity(const CamContinuity& c) noexcept { continuity_ = c; }

  // ---- reading ----
  bool empty() const noexcept { return pieces_.empty(); }
  double start() const noexcept { return pieces_.empty() ? 0.0 : pieces_.front().x0; }
  double end() const noexcept { return pieces_.empty() ? 0.0 : pieces_.back().x1; }
  std::span<const CamPiece> pieces() const noexcept { return pieces_; }
  const CamContinuity& continuity() const noexcept { return continuity_; }
  bool contains(double x) const noexcept { return !pieces_.empty() && x >= start() && x <= end(); }

  // The piece that holds x (the first of two at a join is the left one); x is clamped to [start, end].
  std::size_t find(double x) const noexcept;
  // The same, trying the piece `hint` and its neighbours first: a follower's leading value moves little per
  // cycle, so its last piece almost always answers without the binary search.
  std::size_t find(double x, std::size_t hint) const noexcept;
  // f(x) with x clamped to [start, end]; zero for an empty profile.
  CamValue evaluate(double x) const noexcept;
  static CamValue evaluate(const CamPiece& piece, double x) noexcept;

 private:
  std::vector<CamPiece> pieces_;
  CamContinuity continuity_{};
};

// ---- the cam with scaling and shifting (spec 07 §3.3, §3.6) ----

struct CamLookup {
  std::uint16_t error_id = 0;  // 0: `value` is valid
  CamValue value{};            // MC_GetCamFollowingValue: Value, FirstDerivative, SecondDerivative
  double leading_value = 0.0;  // MC_GetCamLeadingValue: Value
};

// MC_GetCamFollowingValue: the scaled following value at leading value x, and its derivatives with respect to
// x. Errors: MasterScaling 0 (16#8023), x not finite or outside the scaled cam (16#8064).
CamLookup following_value(const CamProfile& cam, double x, const CamScaling& s) noexcept;

// MC_GetCamLeadingValue: the leading value at which the scaled cam takes `y`, chosen relative to
// `approach` (spec 07 §3.6: positive = the first solution above it, negative = the last one below it; a
// solution equal to it only with nearest). Errors: MasterScaling 0 (16#8023), SlaveScaling 0 (16#8024),
// approach not finite (16#8062), no solution at all (16#8063), direction not 1…3 (16#8065), no solution in
// the given direction before the cam ends (16#8066).
CamLookup leading_value(const CamProfile& cam, double y, double approach, std::int32_t direction,
                        const CamScaling& s) noexcept;

}  // namespace tomc::techobjects
