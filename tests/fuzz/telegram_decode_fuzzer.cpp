// Decodes arbitrary bytes as every telegram type, direction and byte order. Must never crash; a frame of
// the right length must survive decode -> encode unchanged (every byte of every layout belongs to a signal).
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <span>

#include "tomc/telegrams/codec.hpp"
#include "tomc/telegrams/drive_state.hpp"
#include "tomc/telegrams/encoder.hpp"
#include "tomc/telegrams/normalisation.hpp"
#include "tomc/telegrams/sign_of_life.hpp"

namespace tg = tomc::telegrams;

namespace {

template <typename Values>
void check(const tg::TelegramCodec& codec, std::span<const std::byte> frame) {
  Values values;
  const tg::TelegramError error = codec.decode(frame, values);
  if (frame.size() != codec.frame_size()) {
    if (error != tg::TelegramError::kFrameLengthMismatch) std::abort();
    return;
  }
  if (error != tg::TelegramError::kNone) std::abort();
  std::array<std::byte, tg::kMaxFrameBytes> again{};
  if (codec.encode(values, std::span(again.data(), frame.size())) != tg::TelegramError::kNone) std::abort();
  if (std::memcmp(again.data(), frame.data(), frame.size()) != 0) std::abort();
  // The interpretation helpers must accept any value, too.
  if constexpr (std::is_same_v<Values, tg::ActualSignals>) {
    (void)tg::decode_zsw1(values.ZSW1.value());
    (void)tg::xist2_content(tg::EncoderControlWord{static_cast<std::uint16_t>(values.G1_XIST1)},
                            values.G1_ZSW);
    (void)tg::describe_encoder_error(tg::encoder_error_code(values.G1_XIST2));
    (void)tg::n4_to_speed(values.NIST_B, 3000.0);
    tg::SignOfLifeMonitor monitor;
    (void)monitor.check(static_cast<std::uint8_t>(values.ZSW2.field(tg::kSignOfLifeField)));
  } else {
    (void)tg::next_drive_state(static_cast<tg::DriveState>(values.STW2.value() % 8), values.STW1.value(),
                               (values.NSOLL_B & 1) != 0);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 2) return 0;
  // Byte 0 picks telegram and direction, byte 1 the byte order and the telegram 83 option; the rest is the
  // frame.
  const auto telegrams = tg::supported_telegrams();
  const int telegram = data[0] == 0xFF ? 104 : telegrams[data[0] % telegrams.size()];
  const auto direction = (data[0] & 0x80) != 0 ? tg::Direction::kActual : tg::Direction::kSetpoint;
  tg::CodecOptions options;
  options.byte_order = static_cast<tg::ByteOrder>(data[1] % 4);
  options.telegram83_nist_b_offset = static_cast<std::uint8_t>((data[1] >> 2) % 16);
  const auto codec = tg::TelegramCodec::create(telegram, direction, options);
  const std::span frame(reinterpret_cast<const std::byte*>(data + 2), size - 2);
  if (!codec) {
    const bool expected = telegram == 104 || (telegram == 83 && direction == tg::Direction::kActual);
    if (!expected) std::abort();
    return 0;
  }
  if (direction == tg::Direction::kSetpoint) {
    check<tg::SetpointSignals>(codec.value(), frame);
  } else {
    check<tg::ActualSignals>(codec.value(), frame);
  }
  return 0;
}
