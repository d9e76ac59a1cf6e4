#pragma once
// Error values of the PROFINET codecs. Decoders take bytes from the network, so every malformed input is a
// value the caller looks at, never an exception or a read outside the span.

#include <cstdint>
#include <string_view>

namespace tomc::profinet {

enum class ProfinetError : std::uint8_t {
  kNone,
  kTruncated,        // the bytes end before the field the layout requires
  kBufferTooSmall,   // the encoder's output span cannot hold the frame
  kWrongEtherType,   // not 0x8892 (PROFINET) after the optional VLAN tag
  kWrongFrameId,     // a frame ID outside the range of the decoder that was called
  kWrongBlockType,   // a PNIO block of another type than the one expected
  kBadBlockLength,   // BlockLength disagrees with the block's layout or leaves its container
  kBadBlockVersion,  // BlockVersionHigh is not 1
  kBadValue,         // a field holds a value its definition excludes (e.g. an RPC version other than 4)
  kTooMany,          // more entries than the fixed capacity of the decoded structure
};

std::string_view describe(ProfinetError error) noexcept;

}  // namespace tomc::profinet
