// PROFIdrive base-mode parameter access (parameter_access.hpp). Big-endian throughout, as PROFIdrive data on
// PROFINET.
#include "tomc/profinet/parameter_access.hpp"

#include <bit>
#include <cmath>
#include <cstdio>
#include <limits>

#include "tomc/profinet/wire.hpp"

namespace tomc::profinet {

namespace {

// Bytes per value of a format; 0 for a format this codec does not know.
std::size_t value_bytes(std::uint8_t format) noexcept {
  switch (format) {
    case parameter_format::kInteger16:
    case parameter_format::kUnsigned16:
    case parameter_format::kWord:
    case parameter_format::kError:
      return 2;
    case parameter_format::kInteger32:
    case parameter_format::kUnsigned32:
    case parameter_format::kFloatingPoint:
    case parameter_format::kDoubleWord:
      return 4;
    default:
      return 0;
  }
}

void write_value(WireWriter& out, const ParameterValue& v) {
  out.u8(v.format);
  out.u8(static_cast<std::uint8_t>(v.values.size()));
  for (const std::uint32_t value : v.values) {
    if (value_bytes(v.format) == 2) {
      out.u16(static_cast<std::uint16_t>(value));
    } else {
      out.u32(value);
    }
  }
}

// One value: its format, the number of values and the values. A format of unknown width ends the decoding
// (the rest is unreadable); kZero carries no values. `in_request`: only the formats that hold data.
std::optional<ParameterValue> read_value(WireReader& in, bool in_request) {
  ParameterValue v;
  v.format = in.u8();
  const std::uint8_t values = in.u8();
  if (!in.ok()) return std::nullopt;
  if (v.format == parameter_format::kZero) {
    if (in_request || values != 0) return std::nullopt;
    return v;
  }
  const std::size_t width = value_bytes(v.format);
  if (width == 0 || (in_request && v.format == parameter_format::kError)) return std::nullopt;
  for (std::uint8_t k = 0; k < values; ++k)
    v.values.push_back(width == 2 ? in.u16() : in.u32());
  if (!in.ok()) return std::nullopt;
  return v;
}

}  // namespace

std::string describe_parameter_error(std::uint16_t error) {
  const char* text = nullptr;
  switch (error) {
    case parameter_error::kImpermissibleNumber:
      text = "impermissible parameter number";
      break;
    case parameter_error::kNotChangeable:
      text = "parameter value cannot be changed";
      break;
    case parameter_error::kLimitExceeded:
      text = "low or high limit exceeded";
      break;
    case parameter_error::kFaultySubindex:
      text = "faulty subindex";
      break;
    case parameter_error::kNoArray:
      text = "no array";
      break;
    case parameter_error::kIncorrectDataType:
      text = "incorrect data type";
      break;
    case parameter_error::kOperatingState:
      text = "request cannot be executed because of the operating state";
      break;
    case parameter_error::kValueImpermissible:
      text = "value impermissible";
      break;
    case parameter_error::kAddressImpermissible:
      text = "parameter address impermissible";
      break;
    case parameter_error::kIllegalFormat:
      text = "illegal format";
      break;
    case parameter_error::kValuesInconsistent:
      text = "number of values inconsistent";
      break;
    default:
      break;
  }
  char number[8];
  std::snprintf(number, sizeof number, "0x%02X", static_cast<unsigned>(error));
  return text == nullptr ? std::string(number) : std::string(number) + " (" + text + ")";
}

std::vector<std::uint8_t> encode(const ParameterRequest& request) {
  std::size_t size = 4 + 6 * request.parameters.size();
  if (request.id == parameter_request_id::kChange) {
    for (const ParameterValue& v : request.values)
      size += 2 + v.values.size() * value_bytes(v.format);
  }
  std::vector<std::uint8_t> bytes(size);
  WireWriter out(bytes);
  out.u8(request.reference);
  out.u8(request.id);
  out.u8(request.axis);
  out.u8(static_cast<std::uint8_t>(request.parameters.size()));
  for (const ParameterAddress& p : request.parameters) {
    out.u8(p.attribute);
    out.u8(p.elements);
    out.u16(p.number);
    out.u16(p.subindex);
  }
  if (request.id == parameter_request_id::kChange) {
    for (const ParameterValue& v : request.values)
      write_value(out, v);
  }
  return {out.written().begin(), out.written().end()};
}

std::optional<ParameterRequest> decode_parameter_request(std::span<const std::uint8_t> bytes) {
  WireReader in(bytes);
  ParameterRequest request;
  request.reference = in.u8();
  request.id = in.u8();
  request.axis = in.u8();
  const std::uint8_t count = in.u8();
  if (!in.ok() ||
      (request.id != parameter_request_id::kRead && request.id != parameter_request_id::kChange) ||
      count == 0 || count > kMaxParametersPerRequest) {
    return std::nullopt;
  }
  for (std::uint8_t i = 0; i < count; ++i) {
    ParameterAddress p;
    p.attribute = in.u8();
    p.elements = in.u8();
    p.number = in.u16();
    p.subindex = in.u16();
    request.parameters.push_back(p);
  }
  if (request.id == parameter_request_id::kChange) {
    for (std::uint8_t i = 0; i < count; ++i) {
      auto v = read_value(in, true);
      if (!v) return std::nullopt;
      request.values.push_back(std::move(*v));
    }
  }
  if (!in.ok()) return std::nullopt;
  return request;
}

std::vector<std::uint8_t> encode(const ParameterResponse& response) {
  const bool header_only = response.id == parameter_response_id::kChangeOk;
  std::size_t size = 4;
  for (const ParameterValue& v : response.parameters)
    size += header_only ? 0 : 2 + v.values.size() * value_bytes(v.format);
  std::vector<std::uint8_t> bytes(size);
  WireWriter out(bytes);
  out.u8(response.reference);
  out.u8(response.id);
  out.u8(response.axis);
  out.u8(static_cast<std::uint8_t>(response.parameters.size()));
  if (!header_only) {
    for (const ParameterValue& v : response.parameters)
      write_value(out, v);
  }
  return {out.written().begin(), out.written().end()};
}

std::optional<ParameterResponse> decode_parameter_response(std::span<const std::uint8_t> bytes) {
  WireReader in(bytes);
  ParameterResponse response;
  response.reference = in.u8();
  response.id = in.u8();
  response.axis = in.u8();
  const std::uint8_t count = in.u8();
  if (!in.ok() || count > kMaxParametersPerRequest) return std::nullopt;
  if (response.id == parameter_response_id::kChangeOk) {  // the header alone: every parameter changed
    response.parameters.assign(count, ParameterValue{parameter_format::kZero, {}});
    return response;
  }
  for (std::uint8_t i = 0; i < count; ++i) {
    auto v = read_value(in, false);
    if (!v) return std::nullopt;
    response.parameters.push_back(std::move(*v));
  }
  if (!in.ok()) return std::nullopt;
  return response;
}

std::optional<std::int64_t> integer_value(const ParameterResponse& response, std::size_t k) {
  if (k >= response.parameters.size() || response.parameters[k].values.empty()) return std::nullopt;
  const ParameterValue& v = response.parameters[k];
  const std::uint32_t raw = v.values.front();
  switch (v.format) {
    case parameter_format::kInteger16:
      return static_cast<std::int16_t>(raw);
    case parameter_format::kInteger32:
      return static_cast<std::int32_t>(raw);
    case parameter_format::kUnsigned16:
    case parameter_format::kUnsigned32:
    case parameter_format::kWord:
    case parameter_format::kDoubleWord:
      return raw;
    default:
      return std::nullopt;
  }
}

std::optional<float> float_value(const ParameterResponse& response, std::size_t k) {
  if (k >= response.parameters.size() || response.parameters[k].values.empty() ||
      response.parameters[k].format != parameter_format::kFloatingPoint) {
    return std::nullopt;
  }
  return std::bit_cast<float>(response.parameters[k].values.front());
}

std::optional<std::uint16_t> error_value(const ParameterResponse& response, std::size_t k) {
  if (k >= response.parameters.size() || response.parameters[k].format != parameter_format::kError ||
      response.parameters[k].values.empty()) {
    return std::nullopt;
  }
  return static_cast<std::uint16_t>(response.parameters[k].values.front());
}

std::optional<std::uint32_t> raw_value(std::uint8_t format, double value) {
  if (!std::isfinite(value)) return std::nullopt;
  const auto integral = [value](double low, double high) -> std::optional<std::int64_t> {
    if (value != std::trunc(value) || value < low || value > high) return std::nullopt;
    return static_cast<std::int64_t>(value);
  };
  std::optional<std::int64_t> i;
  switch (format) {
    case parameter_format::kInteger16:
      i = integral(-32768.0, 32767.0);
      break;
    case parameter_format::kUnsigned16:
    case parameter_format::kWord:
      i = integral(0.0, 65535.0);
      break;
    case parameter_format::kInteger32:
      i = integral(-2147483648.0, 2147483647.0);
      break;
    case parameter_format::kUnsigned32:
    case parameter_format::kDoubleWord:
      i = integral(0.0, 4294967295.0);
      break;
    case parameter_format::kFloatingPoint:
      if (std::abs(value) > static_cast<double>(std::numeric_limits<float>::max())) return std::nullopt;
      return std::bit_cast<std::uint32_t>(static_cast<float>(value));
    default:
      return std::nullopt;
  }
  if (!i) return std::nullopt;
  // Two's complement bits of the value in the format's width (a 16-bit value in the low half).
  const auto bits = static_cast<std::uint32_t>(static_cast<std::uint64_t>(*i) & 0xFFFFFFFFu);
  return value_bytes(format) == 2 ? bits & 0xFFFFu : bits;
}

std::optional<double> numeric_value(std::uint8_t format, std::uint32_t raw) {
  switch (format) {
    case parameter_format::kInteger16:
      return static_cast<std::int16_t>(raw);
    case parameter_format::kInteger32:
      return static_cast<std::int32_t>(raw);
    case parameter_format::kUnsigned16:
    case parameter_format::kWord:
      return raw & 0xFFFFu;
    case parameter_format::kUnsigned32:
    case parameter_format::kDoubleWord:
      return raw;
    case parameter_format::kFloatingPoint:
      return std::bit_cast<float>(raw);
    default:
      return std::nullopt;
  }
}

}  // namespace tomc::profinet
