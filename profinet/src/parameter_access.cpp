// PROFIdrive base-mode parameter access (parameter_access.hpp). Big-endian throughout, as PROFIdrive data on
// PROFINET.
#include "tomc/profinet/parameter_access.hpp"

#include <bit>

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

}  // namespace

std::vector<std::uint8_t> encode(const ParameterRequest& request) {
  std::vector<std::uint8_t> bytes(4 + 6 * request.parameters.size());
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
  return {out.written().begin(), out.written().end()};
}

std::optional<ParameterRequest> decode_parameter_request(std::span<const std::uint8_t> bytes) {
  WireReader in(bytes);
  ParameterRequest request;
  request.reference = in.u8();
  request.id = in.u8();
  request.axis = in.u8();
  const std::uint8_t count = in.u8();
  if (!in.ok() || request.id != parameter_request_id::kRead || count == 0 || count > kMaxParametersPerRequest)
    return std::nullopt;
  for (std::uint8_t i = 0; i < count; ++i) {
    ParameterAddress p;
    p.attribute = in.u8();
    p.elements = in.u8();
    p.number = in.u16();
    p.subindex = in.u16();
    request.parameters.push_back(p);
  }
  if (!in.ok()) return std::nullopt;
  return request;
}

std::vector<std::uint8_t> encode(const ParameterResponse& response) {
  std::size_t size = 4;
  for (const ParameterValue& v : response.parameters)
    size += 2 + v.values.size() * value_bytes(v.format);
  std::vector<std::uint8_t> bytes(size);
  WireWriter out(bytes);
  out.u8(response.reference);
  out.u8(response.id);
  out.u8(response.axis);
  out.u8(static_cast<std::uint8_t>(response.parameters.size()));
  for (const ParameterValue& v : response.parameters) {
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
  for (std::uint8_t i = 0; i < count; ++i) {
    ParameterValue v;
    v.format = in.u8();
    const std::uint8_t values = in.u8();
    const std::size_t width = value_bytes(v.format);
    if (!in.ok() || width == 0)
      return std::nullopt;  // a format whose length is unknown: the rest is unreadable
    for (std::uint8_t k = 0; k < values; ++k)
      v.values.push_back(width == 2 ? in.u16() : in.u32());
    response.parameters.push_back(std::move(v));
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

}  // namespace tomc::profinet
