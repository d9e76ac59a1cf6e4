#pragma once
// The JSON side of the web API (docs/diagnostics.md): reading request bodies into commands, and writing what
// Diagnostics collected as JSON. Pure functions of their inputs, without any HTTP: the server wires them to
// routes, the tests and the request fuzzer call them directly.
//
// Request bodies are untrusted: every function here takes arbitrary bytes and answers with a value or one
// line naming what is wrong; nothing throws for bad input.

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>

#include <nlohmann/json.hpp>

#include "tomc/diagnostics/cam_plot.hpp"
#include "tomc/diagnostics/diagnostics.hpp"
#include "tomc/diagnostics/panel.hpp"
#include "tomc/diagnostics/trace.hpp"
#include "tomc/techobjects/datablocks/variables.hpp"

namespace tomc::diagnostics::api {

using Json = nlohmann::json;

inline constexpr std::size_t kMaxBodyBytes = 64 * 1024;
inline constexpr int kMaxJsonDepth = 8;

// A JSON object body, or a message. Rejects bodies that are not one object, are nested deeper than
// kMaxJsonDepth, or are larger than kMaxBodyBytes.
std::variant<Json, std::string> parse_object(std::string_view body);

// POST /api/panel/<object>: {"command": "take"|"give_back"|"lifebeat"|"enable"|"disable"|"jog"|"velocity"|
// "stop"|"acknowledge"|"dynamics"|"adapt"|"home"|"move_absolute"|"move_relative", "session": "<16 hex>",
// ...parameters}. The object index is the caller's (from the URL).
std::variant<PanelCommand, std::string> parse_panel_command(std::string_view body);

// The values of a parsed panel command against the axis' data block (issue 21: no 1e308 velocity, no
// ±1e308 set position on a modulo axis): `variables` is the object's reflection table, `values` its newest
// snapshot (one per row; empty when none arrived yet: then only the data-block ranges are checked).
// Dynamics within DynamicLimits (MaxJerk only when > 0), positions and distances within ±1.0E12 (spec 04
// §0.2), on a modulo axis within [Modulo.StartValue, StartValue + Length), an absolute target within active
// software limits, the lifebeat within 0.1 .. 60 s. nullopt: in range; else a message for a 400 answer.
std::optional<std::string> check_panel_ranges(const PanelCommand& command,
                                              std::span<const techobjects::VariableInfo> variables,
                                              std::span<const double> values);

// POST /api/trace: {"channels": [...], "trigger": {"kind", "signal", "threshold"}, "pre_samples",
// "post_samples", "decimation"}.
std::variant<TraceRequest, std::string> parse_trace_request(std::string_view body);

// POST /api/switches/<name>: {"on": true|false}.
std::variant<bool, std::string> parse_switch(std::string_view body);

// Serialises a response; strings with invalid UTF-8 (echoed user input) are repaired, never thrown about.
std::string to_text(const Json& json);

// "16#8013"
std::string hex_error_id(std::uint16_t error_id);
std::string session_text(std::uint64_t session);  // 16 hex digits
std::optional<std::uint64_t> parse_session(std::string_view text) noexcept;

// ---- responses ----

// GET /api/objects: what does not change while the machine runs (types, layouts, telegram words, panels).
Json describe_objects(const Diagnostics& diagnostics);
// GET /api/status, and each server-sent event: the newest snapshot of every object, evaluated layouts,
// telegram words, alarms, the last history events, panels, switches, the trace's progress.
Json status(const Diagnostics& diagnostics, const Diagnostics::State& state, std::size_t history_events = 20);
// GET /api/objects/<name>/variables: every data-block variable with its newest value.
Json variables(const Diagnostics& diagnostics, const Diagnostics::State& state, std::size_t object);
// GET /api/objects/<name>/alarms: the pending alarms and the whole history the reader kept.
Json alarms(const Diagnostics& diagnostics, const Diagnostics::State& state, std::size_t object);
// GET /api/objects/<cam>/plot: the sampled cam (cam_plot.hpp).
Json cam_plot(const CamPlot& plot);
// GET /api/trace: the capture; at most max_points rows (evenly picked; the trigger row always kept).
Json trace(const TraceCapture& capture, std::size_t max_points);
// GET /api/trace.csv: "cycle,time,<channels>" with time relative to the trigger (s).
std::string trace_csv(const TraceCapture& capture);

}  // namespace tomc::diagnostics::api
