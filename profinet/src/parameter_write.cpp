// One parameter changed and read back through base-mode parameter access (parameter_write.hpp).
#include "tomc/profinet/parameter_write.hpp"

#include <cstdio>

namespace tomc::profinet {

namespace {

std::string number_text(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.10g", value);
  return text;
}

std::uint8_t next_reference(std::uint8_t& reference) {
  reference =
      static_cast<std::uint8_t>(reference == 255 ? 1 : reference + 1);  // 1..255: 0 is not a reference
  return reference;
}

// The response to `request`, or why it is none: a transport problem, another reference, another ID kind, not
// one value per parameter.
std::variant<ParameterResponse, std::string> ask(const ParameterExchange& exchange,
                                                 const ParameterRequest& request, const std::string& name) {
  auto answer = exchange(request);
  if (auto* problem = std::get_if<std::string>(&answer)) return name + ": " + *problem;
  const ParameterResponse& response = std::get<ParameterResponse>(answer);
  const bool read = request.id == parameter_request_id::kRead;
  const bool ok_id = read ? (response.id == parameter_response_id::kReadOk ||
                             response.id == parameter_response_id::kReadError)
                          : (response.id == parameter_response_id::kChangeOk ||
                             response.id == parameter_response_id::kChangeError);
  if (response.reference != request.reference || !ok_id || response.parameters.size() != 1) {
    return name + ": the drive's parameter response does not answer the " + (read ? "read" : "change") +
           " request";
  }
  return answer;
}

}  // namespace

std::string parameter_name(std::uint16_t number, std::uint16_t subindex) {
  char text[24];
  if (subindex == 0) {
    std::snprintf(text, sizeof text, "p%04u", static_cast<unsigned>(number));
  } else {
    std::snprintf(text, sizeof text, "p%04u[%u]", static_cast<unsigned>(number),
                  static_cast<unsigned>(subindex));
  }
  return text;
}

std::string parameter_format_name(std::uint8_t format) {
  switch (format) {
    case parameter_format::kInteger16:
      return "Integer16";
    case parameter_format::kInteger32:
      return "Integer32";
    case parameter_format::kUnsigned16:
      return "Unsigned16";
    case parameter_format::kUnsigned32:
      return "Unsigned32";
    case parameter_format::kFloatingPoint:
      return "FloatingPoint";
    case parameter_format::kWord:
      return "Word";
    case parameter_format::kDoubleWord:
      return "DoubleWord";
    default:
      break;
  }
  char text[16];
  std::snprintf(text, sizeof text, "format 0x%02X", static_cast<unsigned>(format));
  return text;
}

std::string write_parameter(const ParameterWrite& write, std::uint8_t axis, std::uint8_t& reference,
                            const ParameterExchange& exchange) {
  const std::string name = parameter_name(write.number, write.subindex);
  const std::string assignment = name + " = " + number_text(write.value);
  const ParameterAddress address{0x10, 1, write.number, write.subindex};
  const auto read = [&]() {
    return ask(exchange,
               ParameterRequest{next_reference(reference), parameter_request_id::kRead, axis, {address}, {}},
               name);
  };
  // 1. The parameter's format: what the drive answers a read with (the file gives only a number).
  auto before = read();
  if (auto* problem = std::get_if<std::string>(&before)) return *problem;
  const ParameterValue current = std::get<ParameterResponse>(before).parameters.front();
  if (const auto error = error_value(std::get<ParameterResponse>(before), 0)) {
    return name + ": the drive refused the read, PROFIdrive error " + describe_parameter_error(*error);
  }
  const auto raw = raw_value(current.format, write.value);
  if (current.values.size() != 1 || !raw) {
    return assignment + " does not fit its format " + parameter_format_name(current.format) +
           (current.values.size() != 1 ? " (" + std::to_string(current.values.size()) + " values)" : "");
  }
  // 2. The change request (request ID 0x02) with the value in that format.
  auto changed = ask(exchange,
                     ParameterRequest{next_reference(reference),
                                      parameter_request_id::kChange,
                                      axis,
                                      {address},
                                      {ParameterValue{current.format, {*raw}}}},
                     name);
  if (auto* problem = std::get_if<std::string>(&changed)) return *problem;
  const ParameterResponse& change = std::get<ParameterResponse>(changed);
  if (change.id != parameter_response_id::kChangeOk) {
    const auto error = error_value(change, 0);
    return assignment + ": the drive refused the change, PROFIdrive error " +
           (error ? describe_parameter_error(*error) : std::string("(none given)"));
  }
  // 3. Read back: a drive may accept a value and keep another (rounded, limited by another parameter).
  auto after = read();
  if (auto* problem = std::get_if<std::string>(&after)) return *problem;
  const ParameterValue& now = std::get<ParameterResponse>(after).parameters.front();
  if (now.format != current.format || now.values.size() != 1 || now.values.front() != *raw) {
    const auto value = now.values.empty() ? std::nullopt : numeric_value(now.format, now.values.front());
    return assignment + " reads back as " +
           (value ? number_text(*value) : parameter_format_name(now.format) + " without a value");
  }
  return {};
}

}  // namespace tomc::profinet
