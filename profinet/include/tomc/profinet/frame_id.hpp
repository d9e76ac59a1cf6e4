#pragma once
// FrameID ranges of PROFINET RT (IEC 61158-6-10, FrameID table; the same ranges p-net checks in
// pf_cmdev.c and Wireshark's packet-pn-rt.c names).

#include <cstdint>

namespace tomc::profinet {

// RT_CLASS_1 unicast cyclic data as PROFINET V2.3 codes it (IOCRProperties.RTClass 2; Wireshark: "RTC1"),
// and the legacy range (IOCRProperties.RTClass 1; Wireshark: "RTC1(legacy)"), which devices still accept.
inline constexpr std::uint16_t kFrameIdRtClass1First = 0x8000;
inline constexpr std::uint16_t kFrameIdRtClass1Last = 0xBBFF;
inline constexpr std::uint16_t kFrameIdRtClass1LegacyFirst = 0xC000;
inline constexpr std::uint16_t kFrameIdRtClass1LegacyLast = 0xF7FF;
// IOCRProperties.RTClass of the two ranges.
inline constexpr std::uint32_t kIocrRtClass1 = 2;
inline constexpr std::uint32_t kIocrRtClass1Legacy = 1;
inline constexpr std::uint16_t kFrameIdAlarmHigh = 0xFC01;
inline constexpr std::uint16_t kFrameIdAlarmLow = 0xFE01;
inline constexpr std::uint16_t kFrameIdDcpHello = 0xFEFC;
inline constexpr std::uint16_t kFrameIdDcpGetSet = 0xFEFD;
inline constexpr std::uint16_t kFrameIdDcpIdentifyRequest = 0xFEFE;
inline constexpr std::uint16_t kFrameIdDcpIdentifyResponse = 0xFEFF;

enum class FrameKind : std::uint8_t { kOther, kCyclicRtClass1, kAlarm, kDcp };

constexpr FrameKind classify_frame_id(std::uint16_t frame_id) noexcept {
  if ((frame_id >= kFrameIdRtClass1First && frame_id <= kFrameIdRtClass1Last) ||
      (frame_id >= kFrameIdRtClass1LegacyFirst && frame_id <= kFrameIdRtClass1LegacyLast)) {
    return FrameKind::kCyclicRtClass1;
  }
  if (frame_id == kFrameIdAlarmHigh || frame_id == kFrameIdAlarmLow) return FrameKind::kAlarm;
  if (frame_id >= kFrameIdDcpHello && frame_id <= kFrameIdDcpIdentifyResponse) return FrameKind::kDcp;
  return FrameKind::kOther;
}

}  // namespace tomc::profinet
