#include "tomc/profinet/alarm.hpp"

#include <algorithm>

#include "tomc/profinet/blocks.hpp"

namespace tomc::profinet {

namespace {
constexpr std::uint8_t kRtaVersion = 1;
}

ProfinetError encode(const EthernetHeader& header, const RtaFrame& frame, std::span<std::uint8_t> out,
                     std::size_t& written) noexcept {
  written = 0;
  WireWriter w(out);
  encode(header, w);
  w.u16(frame.frame_id);
  w.u16(frame.destination_endpoint);
  w.u16(frame.source_endpoint);
  w.u8(static_cast<std::uint8_t>(static_cast<unsigned>(frame.pdu_type) | kRtaVersion << 4));
  w.u8(static_cast<std::uint8_t>(1 | (frame.tack ? 0x10 : 0)));  // WindowSize 1
  w.u16(frame.send_sequence);
  w.u16(frame.ack_sequence);
  const std::size_t var_part_at = w.position();
  w.u16(0);
  if (frame.has_block) {
    const AlarmBlock& b = frame.block;
    const std::size_t block_at = w.position();
    w.u16(b.is_ack
              ? (b.high_priority ? block_type::kAlarmAckHigh : block_type::kAlarmAckLow)
              : (b.high_priority ? block_type::kAlarmNotificationHigh : block_type::kAlarmNotificationLow));
    w.u16(0);
    w.u8(1);
    w.u8(0);
    w.u16(b.alarm_type);
    w.u32(b.api);
    w.u16(b.slot);
    w.u16(b.subslot);
    if (!b.is_ack) {
      w.u32(b.module_ident);
      w.u32(b.submodule_ident);
    }
    w.u16(b.specifier);
    if (b.is_ack) {
      w.u32(b.status.value());
    } else if (b.payload_length > 0) {
      if (b.payload_length > kMaxAlarmPayload) return ProfinetError::kTooMany;
      w.u16(b.user_structure_identifier);
      w.bytes(std::span(b.payload).first(b.payload_length));
    }
    w.patch_u16(block_at + 2, static_cast<std::uint16_t>(w.position() - block_at - 4));
  } else if (frame.pdu_type == RtaPduType::kError) {
    w.u32(frame.error.value());
  }
  w.patch_u16(var_part_at, static_cast<std::uint16_t>(w.position() - var_part_at - 2));
  pad_to_minimum(w);
  if (!w.ok()) return w.error();
  written = w.position();
  return ProfinetError::kNone;
}

ProfinetError decode_rta(std::span<const std::uint8_t> bytes, RtaFrame& frame) noexcept {
  WireReader in(bytes);
  (void)decode_ethernet(in);
  RtaFrame result;
  result.frame_id = in.u16();
  if (!in.ok()) return in.error();
  if (classify_frame_id(result.frame_id) != FrameKind::kAlarm) return ProfinetError::kWrongFrameId;
  result.destination_endpoint = in.u16();
  result.source_endpoint = in.u16();
  const std::uint8_t pdu = in.u8();
  const std::uint8_t flags = in.u8();
  result.send_sequence = in.u16();
  result.ack_sequence = in.u16();
  const std::uint16_t var_part_length = in.u16();
  if (!in.ok()) return in.error();
  if ((pdu >> 4) != kRtaVersion || (pdu & 0xF) < 1 || (pdu & 0xF) > 4) return ProfinetError::kBadValue;
  result.pdu_type = static_cast<RtaPduType>(pdu & 0xF);
  result.tack = (flags & 0x10) != 0;
  if (var_part_length > in.remaining()) return ProfinetError::kTruncated;
  if (result.pdu_type == RtaPduType::kData) {
    WireReader var(in.view(var_part_length));
    const BlockHeader header = decode_block_header(var);
    if (!var.ok()) return var.error();
    AlarmBlock& b = result.block;
    switch (header.type) {
      case block_type::kAlarmNotificationHigh:
        b.high_priority = true;
        break;
      case block_type::kAlarmNotificationLow:
        break;
      case block_type::kAlarmAckHigh:
        b.high_priority = b.is_ack = true;
        break;
      case block_type::kAlarmAckLow:
        b.is_ack = true;
        break;
      default:
        return ProfinetError::kWrongBlockType;
    }
    WireReader content(var.view(header.length - 2u));
    b.alarm_type = content.u16();
    b.api = content.u32();
    b.slot = content.u16();
    b.subslot = content.u16();
    if (!b.is_ack) {
      b.module_ident = content.u32();
      b.submodule_ident = content.u32();
    }
    b.specifier = content.u16();
    if (b.is_ack) {
      b.status = PnioStatus::from(content.u32());
    } else if (content.ok() && content.remaining() > 0) {
      b.user_structure_identifier = content.u16();
      const std::size_t n = content.remaining();
      if (n > kMaxAlarmPayload) return ProfinetError::kTooMany;
      content.bytes(b.payload.data(), n);
      b.payload_length = static_cast<std::uint16_t>(n);
    }
    if (!content.ok()) return ProfinetError::kBadBlockLength;
    if (b.is_ack && content.remaining() != 0) return ProfinetError::kBadBlockLength;
    result.has_block = true;
  } else if (result.pdu_type == RtaPduType::kError) {
    if (var_part_length < 4) return ProfinetError::kTruncated;  // an ERR without its PNIOStatus
    result.error = PnioStatus::from(in.u32());
  }
  frame = result;
  return ProfinetError::kNone;
}

AlarmBlock alarm_ack_for(const AlarmBlock& notification) noexcept {
  AlarmBlock ack;
  ack.high_priority = notification.high_priority;
  ack.is_ack = true;
  ack.alarm_type = notification.alarm_type;
  ack.api = notification.api;
  ack.slot = notification.slot;
  ack.subslot = notification.subslot;
  ack.specifier = notification.specifier;
  return ack;
}

}  // namespace tomc::profinet
