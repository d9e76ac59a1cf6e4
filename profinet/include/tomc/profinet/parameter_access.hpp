#pragma once
// PROFIdrive base-mode parameter access (PROFIdrive profile "Base Mode Parameter Access", carried over
// PROFINET as record data: the controller writes a parameter request to record index 0xB02E of the drive
// object's parameter access point and reads the response from the same index). Used at start-up to read p0922
// (the telegram the drive is configured for) and p2000 (its reference speed) and to change the parameters of
// the gateway file's "parameters" (decision I33). Standard library only.

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace tomc::profinet {

inline constexpr std::uint16_t kParameterAccessIndex = 0xB02E;  // base-mode parameter access, local
inline constexpr std::size_t kMaxParametersPerRequest = 39;

namespace parameter_request_id {
inline constexpr std::uint8_t kRead = 0x01;    // request parameter
inline constexpr std::uint8_t kChange = 0x02;  // change parameter
}  // namespace parameter_request_id
namespace parameter_response_id {
inline constexpr std::uint8_t kReadOk = 0x01;
inline constexpr std::uint8_t kChangeOk = 0x02;
inline constexpr std::uint8_t kReadError = 0x81;
inline constexpr std::uint8_t kChangeError = 0x82;
}  // namespace parameter_response_id
// Format of a value in a response (PROFIdrive data types and the 0x40.. formats).
namespace parameter_format {
inline constexpr std::uint8_t kInteger16 = 0x03;
inline constexpr std::uint8_t kInteger32 = 0x04;
inline constexpr std::uint8_t kUnsigned16 = 0x06;
inline constexpr std::uint8_t kUnsigned32 = 0x07;
inline constexpr std::uint8_t kFloatingPoint = 0x08;  // IEEE 754 single
inline constexpr std::uint8_t kWord = 0x42;
inline constexpr std::uint8_t kDoubleWord = 0x43;
inline constexpr std::uint8_t kZero = 0x40;   // no value: a parameter of a change request that was executed
inline constexpr std::uint8_t kError = 0x44;  // one 16-bit error number (e.g. 0 = impermissible parameter)
}  // namespace parameter_format
// PROFIdrive error numbers of a kError value (PROFIdrive profile, base mode parameter access; the numbers
// SINAMICS lists as "error values in parameter responses").
namespace parameter_error {
inline constexpr std::uint16_t kImpermissibleNumber = 0x00;   // impermissible parameter number
inline constexpr std::uint16_t kNotChangeable = 0x01;         // parameter value cannot be changed
inline constexpr std::uint16_t kLimitExceeded = 0x02;         // low or high limit exceeded
inline constexpr std::uint16_t kFaultySubindex = 0x03;        // faulty subindex
inline constexpr std::uint16_t kNoArray = 0x04;               // no array
inline constexpr std::uint16_t kIncorrectDataType = 0x05;     // incorrect data type
inline constexpr std::uint16_t kOperatingState = 0x11;        // request cannot be executed (operating state)
inline constexpr std::uint16_t kValueImpermissible = 0x14;    // value impermissible
inline constexpr std::uint16_t kAddressImpermissible = 0x16;  // parameter address impermissible
inline constexpr std::uint16_t kIllegalFormat = 0x17;         // illegal format
inline constexpr std::uint16_t kValuesInconsistent = 0x18;    // number of values inconsistent
}  // namespace parameter_error
// "0x02 (low or high limit exceeded)"; "0x65" for a number without a profile text (vendor-specific).
std::string describe_parameter_error(std::uint16_t error);

struct ParameterAddress {
  std::uint8_t attribute = 0x10;  // 0x10 value, 0x20 description, 0x30 text
  std::uint8_t elements = 1;      // 0 for a parameter without index
  std::uint16_t number = 0;       // e.g. 922
  std::uint16_t subindex = 0;
  bool operator==(const ParameterAddress&) const = default;
};

struct ParameterValue {
  std::uint8_t format = parameter_format::kUnsigned16;
  std::vector<std::uint32_t> values;  // raw bits (a float's IEEE bits), one per element
  bool operator==(const ParameterValue&) const = default;
};

// A request parameter (kRead: the addresses) or change parameter (kChange: the addresses, then one value per
// address, in the same order: PROFIdrive's "parameter address" and "parameter value" parts).
struct ParameterRequest {
  std::uint8_t reference = 1;  // 1..255, mirrored in the response
  std::uint8_t id = parameter_request_id::kRead;
  std::uint8_t axis = 1;  // drive object
  std::vector<ParameterAddress> parameters;
  std::vector<ParameterValue> values;  // kChange only: as many as parameters
  bool operator==(const ParameterRequest&) const = default;
};

// The answer: for a read, one value (or kError value) per parameter; for a change, kChangeOk carries only the
// number of parameters (decoded as that many kZero values, no bytes each), kChangeError one kZero (executed)
// or kError value per parameter.
struct ParameterResponse {
  std::uint8_t reference = 1;
  std::uint8_t id = parameter_response_id::kReadOk;
  std::uint8_t axis = 1;
  std::vector<ParameterValue> parameters;
  bool operator==(const ParameterResponse&) const = default;
};

// Read and change requests (other request IDs, a count of 0 or more than kMaxParametersPerRequest, a value
// of an unknown format do not decode).
std::vector<std::uint8_t> encode(const ParameterRequest& request);
std::optional<ParameterRequest> decode_parameter_request(std::span<const std::uint8_t> bytes);
std::vector<std::uint8_t> encode(const ParameterResponse& response);
std::optional<ParameterResponse> decode_parameter_response(std::span<const std::uint8_t> bytes);

// The first value of parameter k as an integer (formats 0x03..0x07, 0x42, 0x43), or as a float (0x08);
// nullopt for an error value, another format or a missing parameter.
std::optional<std::int64_t> integer_value(const ParameterResponse& response, std::size_t k);
std::optional<float> float_value(const ParameterResponse& response, std::size_t k);
// The PROFIdrive error number of parameter k (a kError value), nullopt when it has none.
std::optional<std::uint16_t> error_value(const ParameterResponse& response, std::size_t k);

// A value of the file (a JSON number) in a parameter's format: the raw bits for ParameterValue::values, or
// nullopt when it does not fit (an integer format and a fraction or out of its range, a float out of
// single range, a format that holds no numbers).
std::optional<std::uint32_t> raw_value(std::uint8_t format, double value);
// The number raw bits of `format` stand for (nullopt for kZero/kError or an unknown format).
std::optional<double> numeric_value(std::uint8_t format, std::uint32_t raw);

}  // namespace tomc::profinet
