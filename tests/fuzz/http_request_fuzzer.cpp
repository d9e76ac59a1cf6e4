// Arbitrary bytes as the body of every POST of the diagnostics web API (panel commands, traces, program
// switches) and as a session key. Must never crash or throw; whatever is accepted holds only values the parser
// promises, and every refusal has a message that serialises into a response.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>
#include <variant>

#include "tomc/diagnostics/api.hpp"

namespace api = tomc::diagnostics::api;
using tomc::diagnostics::PanelCommand;
using tomc::diagnostics::PanelCommandKind;
using tomc::diagnostics::TraceRequest;

namespace {

void refused(const std::string& message) {
  if (message.empty()) std::abort();
  (void)api::to_text(api::Json{{"error", message}});  // must not throw on any bytes echoed in a message
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view body(reinterpret_cast<const char*>(data), size);

  const auto command = api::parse_panel_command(body);
  if (const auto* c = std::get_if<PanelCommand>(&command)) {
    if (c->session == 0 || c->direction < -1 || c->direction > 1) std::abort();
    if (!std::isfinite(c->value)) std::abort();
    if (c->kind == PanelCommandKind::kMoveVelocity && c->direction == 0) std::abort();
    if (c->kind == PanelCommandKind::kHome && c->mode != 0 && c->mode != 3) std::abort();
    if (c->kind == PanelCommandKind::kStop && c->mode != 0 && c->mode != 1) std::abort();
    if (c->kind == PanelCommandKind::kSetDynamics &&
        !(std::isfinite(c->dynamics.velocity) && std::isfinite(c->dynamics.acceleration) &&
          std::isfinite(c->dynamics.deceleration) && std::isfinite(c->dynamics.jerk))) {
      std::abort();
    }
  } else {
    refused(std::get<std::string>(command));
  }

  const auto trace = api::parse_trace_request(body);
  if (const auto* t = std::get_if<TraceRequest>(&trace)) {
    if (t->channels.empty() || t->channels.size() > tomc::diagnostics::kMaxTraceChannels) std::abort();
    if (t->post_samples < 1 || t->pre_samples + t->post_samples > tomc::diagnostics::kMaxTraceSamples) std::abort();
    if (t->decimation < 1 || t->decimation > tomc::diagnostics::kMaxTraceDecimation) std::abort();
    if (!std::isfinite(t->threshold)) std::abort();
    (void)api::to_text(api::Json{{"channels", t->channels}});
  } else {
    refused(std::get<std::string>(trace));
  }

  const auto on = api::parse_switch(body);
  if (const auto* message = std::get_if<std::string>(&on)) refused(*message);

  if (const auto session = api::parse_session(body)) {
    if (*session == 0 || body.empty() || body.size() > 16) std::abort();
  }
  return 0;
}
