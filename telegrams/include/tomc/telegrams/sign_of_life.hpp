#pragma once
// Sign-of-life (lifebeat) in both directions, spec 06 §5: a 4-bit counter 1..15 that never shows 0 in
// normal operation, and a leaky-bucket monitor (+10 per unexpected value, -1 per expected value).

#include <cstdint>

namespace tomc::telegrams {

// The next counter value after `current` in steps of `step` (1..15, skipping 0). current 0 = not started.
// Inline: two calls per fresh frame (master counter and slave expectation).
inline std::uint8_t advance_sign_of_life(std::uint8_t current, std::uint8_t step = 1) noexcept {
  // Values 1..15 form a ring of 15; 0 is outside it ("not started" -> the first step lands on `step`).
  // Subtraction instead of % keeps this a handful of instructions; step and current are at most 15.
  unsigned next = (current & 0x0Fu) + (step < 15u ? step : step % 15u);  // no division in the usual case
  if (next > 15u) next -= 15u;
  return static_cast<std::uint8_t>(next == 0 ? 15u : next);
}

// Produces the own counter once per application cycle (controller: master LS in STW2; drive: slave LS).
class SignOfLifeGenerator {
 public:
  // Advances and returns the counter; the first call after construction/reset returns start (1..15).
  std::uint8_t next() noexcept {
    current_ = current_ == 0 ? start_ : advance_sign_of_life(current_);
    return current_;
  }
  std::uint8_t current() const noexcept { return current_; }
  void reset(std::uint8_t start = 1) noexcept;

 private:
  std::uint8_t start_ = 1;
  std::uint8_t current_ = 0;
};

struct SignOfLifeMonitorConfig {
  // Tolerated errors: trip when the error counter exceeds 10 * tolerance. 0xFFFF switches monitoring off
  // (as SINAMICS p0925 = 65535). Default 1 = one isolated error tolerated ([OUR CHOICE] spec 06 §5.2).
  std::uint16_t tolerance = 1;
  // Expected advance per check (T_MAPC / T_DP, [OUR CHOICE] spec 06 §5.1), 1..14.
  std::uint8_t step = 1;
};

enum class SignOfLifeStatus : std::uint8_t {
  kNotSynchronised,  // only zeros seen so far: partner does not (yet) send a sign-of-life; no fault
  kOk,
  kFailed,  // latched until reset()
};

// Checks the partner's counter once per cycle. Keeps its own expectation running after a mismatch (as the
// PROFIdrive DevKit does), so a partner that slipped by one cycle keeps mismatching and trips (spec 06 TV18).
class SignOfLifeMonitor {
 public:
  SignOfLifeMonitor() noexcept = default;
  explicit SignOfLifeMonitor(SignOfLifeMonitorConfig config) noexcept;

  SignOfLifeStatus check(std::uint8_t received) noexcept;
  SignOfLifeStatus status() const noexcept { return status_; }
  std::uint32_t error_counter() const noexcept { return error_counter_; }
  std::uint8_t expected() const noexcept { return expected_; }
  const SignOfLifeMonitorConfig& config() const noexcept { return config_; }
  void reset() noexcept;

 private:
  SignOfLifeMonitorConfig config_{};
  SignOfLifeStatus status_ = SignOfLifeStatus::kNotSynchronised;
  std::uint8_t expected_ = 0;
  std::uint32_t error_counter_ = 0;
};

}  // namespace tomc::telegrams
