// Sign-of-life counter and monitor, spec 06 §5.
#include "tomc/telegrams/sign_of_life.hpp"

namespace tomc::telegrams {

void SignOfLifeGenerator::reset(std::uint8_t start) noexcept {
  start_ = (start == 0 || start > 15) ? 1 : start;
  current_ = 0;
}

SignOfLifeMonitor::SignOfLifeMonitor(SignOfLifeMonitorConfig config) noexcept : config_(config) {
  if (config_.step % 15 == 0) config_.step = 1;  // a step of 0 or 15 would expect the same value forever
}

SignOfLifeStatus SignOfLifeMonitor::check(std::uint8_t received) noexcept {
  if (status_ == SignOfLifeStatus::kFailed) return status_;
  if (config_.tolerance == 0xFFFF) {  // monitoring switched off
    status_ = received == 0 ? SignOfLifeStatus::kNotSynchronised : SignOfLifeStatus::kOk;
    return status_;
  }
  if (status_ == SignOfLifeStatus::kNotSynchronised) {
    // spec 06 §5.1: a partner sending 0 does not (yet) support/synchronise its sign-of-life: no fault.
    if (received != 0) {
      status_ = SignOfLifeStatus::kOk;
      expected_ = advance_sign_of_life(received, config_.step);
    }
    return status_;
  }
  // spec 06 §5.2 [OUR CHOICE]: +10 per unexpected value (0 included), -1 per expected value, trip above
  // 10 * tolerance. The expectation runs on regardless of what was received (TV18).
  if ((received & 0x0Fu) == expected_ && received != 0) {
    if (error_counter_ > 0) --error_counter_;
  } else {
    error_counter_ += 10;
  }
  expected_ = advance_sign_of_life(expected_, config_.step);
  if (error_counter_ > 10u * config_.tolerance) status_ = SignOfLifeStatus::kFailed;
  return status_;
}

void SignOfLifeMonitor::reset() noexcept {
  status_ = SignOfLifeStatus::kNotSynchronised;
  expected_ = 0;
  error_counter_ = 0;
}

}  // namespace tomc::telegrams
