// Names of the library's small enums, for messages and tools.
#include "tomc/telegrams/byte_order.hpp"
#include "tomc/telegrams/error.hpp"
#include "tomc/telegrams/signals.hpp"

namespace tomc::telegrams {

std::string_view to_string(ByteOrder order) noexcept {
  switch (order) {
    case ByteOrder::kBig:
      return "big";
    case ByteOrder::kLittleBytes:
      return "little-bytes";
    case ByteOrder::kSwappedWords:
      return "swapped-words";
    case ByteOrder::kLittle:
      return "little";
  }
  return "?";
}

std::optional<ByteOrder> parse_byte_order(std::string_view text) noexcept {
  for (auto order :
       {ByteOrder::kBig, ByteOrder::kLittleBytes, ByteOrder::kSwappedWords, ByteOrder::kLittle}) {
    if (text == to_string(order)) return order;
  }
  return std::nullopt;
}

std::string_view to_string(Direction direction) noexcept {
  return direction == Direction::kSetpoint ? "setpoint" : "actual";
}

std::optional<Direction> parse_direction(std::string_view text) noexcept {
  if (text == "setpoint") return Direction::kSetpoint;
  if (text == "actual") return Direction::kActual;
  return std::nullopt;
}

std::string_view describe(TelegramError error) noexcept {
  switch (error) {
    case TelegramError::kNone:
      return "no error";
    case TelegramError::kUnknownTelegram:
      return "unknown telegram (supported: 1, 2, 3, 4, 5, 6, 81, 83, 102, 103, 105, 106, 750)";
    case TelegramError::kTelegram104NotDefined:
      return "not defined for SINAMICS drives or S7-1500 technology objects";
    case TelegramError::kFrameLengthMismatch:
      return "frame length does not match the telegram";
    case TelegramError::kWrongDirection:
      return "signals of the other direction for this telegram";
    case TelegramError::kInvalidOption:
      return "invalid codec option";
  }
  return "?";
}

}  // namespace tomc::telegrams
