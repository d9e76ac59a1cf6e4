#pragma once
// Error values of the telegram library. Nothing here throws: a bad telegram number or a frame of the
// wrong length is reported as a value the caller must look at.

#include <cstdint>
#include <string_view>
#include <utility>

namespace tomc::telegrams {

enum class TelegramError : std::uint8_t {
  kNone,
  kUnknownTelegram,        // not one of 1, 2, 3, 4, 5, 6, 81, 83, 102, 103, 105, 106, 750
  kTelegram104NotDefined,  // spec 06 §2.9: 104 exists for no target of this project
  kFrameLengthMismatch,    // the byte span does not have the telegram's length
  kWrongDirection,         // e.g. setpoint signals given to an actual-value codec
  kInvalidOption,          // a codec option out of its range (e.g. telegram 83 NIST_B offset)
};

std::string_view describe(TelegramError error) noexcept;

// A value or the reason there is none; T must be default-constructible (all uses here are small PODs).
template <typename T>
class [[nodiscard]] Result {
 public:
  Result(T value) noexcept : value_(std::move(value)) {}   // NOLINT(google-explicit-constructor)
  Result(TelegramError error) noexcept : error_(error) {}  // NOLINT(google-explicit-constructor)

  bool ok() const noexcept { return error_ == TelegramError::kNone; }
  explicit operator bool() const noexcept { return ok(); }
  TelegramError error() const noexcept { return error_; }
  const T& value() const& noexcept { return value_; }
  T& value() & noexcept { return value_; }
  const T& operator*() const& noexcept { return value_; }
  const T* operator->() const noexcept { return &value_; }

 private:
  T value_{};
  TelegramError error_ = TelegramError::kNone;
};

}  // namespace tomc::telegrams
