#include "tomc/profinet/cyclic.hpp"

#include <algorithm>
#include <cstring>

#include "tomc/profinet/frame_id.hpp"

namespace tomc::profinet {

namespace {

struct Range {
  std::size_t begin;
  std::size_t end;
};

}  // namespace

ProfinetError CyclicCodec::create(const CyclicLayout& layout, CyclicCodec& codec) noexcept {
  if (classify_frame_id(layout.frame_id) != FrameKind::kCyclicRtClass1) return ProfinetError::kWrongFrameId;
  if (layout.c_sdu_length < kMinCSduLength || layout.c_sdu_length > kMaxCSduLength) {
    return ProfinetError::kBadValue;
  }
  if (layout.data_object_count > kMaxDataObjectsPerIocr || layout.iocs_count > kMaxDataObjectsPerIocr) {
    return ProfinetError::kTooMany;
  }
  std::array<Range, 2 * kMaxDataObjectsPerIocr> ranges{};
  std::size_t count = 0;
  for (std::size_t i = 0; i < layout.data_object_count; ++i) {
    const IoDataObject& object = layout.data_objects[i];
    ranges[count++] = {object.frame_offset, std::size_t{object.frame_offset} + object.data_length + 1};
  }
  for (std::size_t i = 0; i < layout.iocs_count; ++i) {
    ranges[count++] = {layout.iocs[i].frame_offset, std::size_t{layout.iocs[i].frame_offset} + 1};
  }
  std::sort(ranges.begin(), ranges.begin() + static_cast<std::ptrdiff_t>(count),
            [](const Range& a, const Range& b) { return a.begin < b.begin; });
  for (std::size_t i = 0; i < count; ++i) {
    if (ranges[i].end > layout.c_sdu_length) return ProfinetError::kBadBlockLength;
    if (i > 0 && ranges[i].begin < ranges[i - 1].end) return ProfinetError::kBadBlockLength;
  }
  codec.layout_ = layout;
  return ProfinetError::kNone;
}

std::span<std::uint8_t> CyclicCodec::data(std::span<std::uint8_t> c_sdu, std::size_t index) const noexcept {
  const IoDataObject& object = layout_.data_objects[index];
  return c_sdu.subspan(object.frame_offset, object.data_length);
}

std::span<const std::uint8_t> CyclicCodec::read_data(std::span<const std::uint8_t> c_sdu,
                                                     std::size_t index) const noexcept {
  const IoDataObject& object = layout_.data_objects[index];
  return c_sdu.subspan(object.frame_offset, object.data_length);
}

std::uint8_t& CyclicCodec::iops(std::span<std::uint8_t> c_sdu, std::size_t index) const noexcept {
  const IoDataObject& object = layout_.data_objects[index];
  return c_sdu[std::size_t{object.frame_offset} + object.data_length];
}

std::uint8_t CyclicCodec::read_iops(std::span<const std::uint8_t> c_sdu, std::size_t index) const noexcept {
  const IoDataObject& object = layout_.data_objects[index];
  return c_sdu[std::size_t{object.frame_offset} + object.data_length];
}

std::uint8_t& CyclicCodec::iocs(std::span<std::uint8_t> c_sdu, std::size_t index) const noexcept {
  return c_sdu[layout_.iocs[index].frame_offset];
}

std::uint8_t CyclicCodec::read_iocs(std::span<const std::uint8_t> c_sdu, std::size_t index) const noexcept {
  return c_sdu[layout_.iocs[index].frame_offset];
}

ProfinetError CyclicCodec::encode(const EthernetHeader& header, std::span<const std::uint8_t> c_sdu,
                                  ApduStatus status, std::span<std::uint8_t> out,
                                  std::size_t& written) const noexcept {
  written = 0;
  if (c_sdu.size() != layout_.c_sdu_length) return ProfinetError::kBadBlockLength;
  WireWriter writer(out);
  profinet::encode(header, writer);
  writer.u16(layout_.frame_id);
  writer.bytes(c_sdu);
  writer.u16(status.cycle_counter);
  writer.u8(status.data_status);
  writer.u8(status.transfer_status);
  if (!writer.ok()) return writer.error();
  written = writer.position();
  return ProfinetError::kNone;
}

ProfinetError CyclicCodec::decode(std::span<const std::uint8_t> frame, std::span<std::uint8_t> c_sdu,
                                  ApduStatus& status) const noexcept {
  if (c_sdu.size() != layout_.c_sdu_length) return ProfinetError::kBadBlockLength;
  WireReader reader(frame);
  (void)decode_ethernet(reader);
  const std::uint16_t frame_id = reader.u16();
  if (!reader.ok()) return reader.error();
  if (frame_id != layout_.frame_id) return ProfinetError::kWrongFrameId;
  const auto payload = reader.view(layout_.c_sdu_length);
  ApduStatus received;
  received.cycle_counter = reader.u16();
  received.data_status = reader.u8();
  received.transfer_status = reader.u8();
  if (!reader.ok()) return reader.error();
  std::memcpy(c_sdu.data(), payload.data(), payload.size());
  status = received;
  return ProfinetError::kNone;
}

std::uint16_t peek_frame_id(std::span<const std::uint8_t> frame) noexcept {
  WireReader reader(frame);
  (void)decode_ethernet(reader);
  const std::uint16_t frame_id = reader.u16();
  return reader.ok() ? frame_id : 0;
}

}  // namespace tomc::profinet
