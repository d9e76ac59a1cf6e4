#include "tomc/profinet/error.hpp"

namespace tomc::profinet {

std::string_view describe(ProfinetError error) noexcept {
  switch (error) {
    case ProfinetError::kNone:
      return "no error";
    case ProfinetError::kTruncated:
      return "frame ends before a required field";
    case ProfinetError::kBufferTooSmall:
      return "output buffer too small for the frame";
    case ProfinetError::kWrongEtherType:
      return "EtherType is not PROFINET (0x8892)";
    case ProfinetError::kWrongFrameId:
      return "FrameID outside the expected range";
    case ProfinetError::kWrongBlockType:
      return "unexpected PNIO block type";
    case ProfinetError::kBadBlockLength:
      return "PNIO block length inconsistent with its content";
    case ProfinetError::kBadBlockVersion:
      return "PNIO block version not supported";
    case ProfinetError::kBadValue:
      return "field value out of its defined range";
    case ProfinetError::kTooMany:
      return "more entries than supported";
  }
  return "unknown error";
}

}  // namespace tomc::profinet
