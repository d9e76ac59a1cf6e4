// Arbitrary bytes as what a client sends to the diagnostics server (http_server.hpp, issue 21): the request
// parser must never crash, never accept more than its limits, refuse only with its documented statuses, and
// give the same answer whether the bytes come at once or trickle in pieces (the server parses again after
// each read).
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "tomc/diagnostics/http_server.hpp"

using tomc::diagnostics::http::Limits;
using tomc::diagnostics::http::RequestParser;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const std::size_t step = 1 + data[0] % 16;  // how the bytes trickle in
  const std::string_view input(reinterpret_cast<const char*>(data + 1), size - 1);
  const Limits limits{512, 1024};

  RequestParser whole(limits);
  const RequestParser::State a = whole.parse(input);

  RequestParser pieces(limits);
  RequestParser::State b = RequestParser::State::kIncomplete;
  for (std::size_t n = std::min(step, input.size()); b == RequestParser::State::kIncomplete; n += step) {
    b = pieces.parse(input.substr(0, std::min(n, input.size())));
    if (n >= input.size()) break;
  }
  if (a == RequestParser::State::kComplete) {
    if (b != a) std::abort();
    if (whole.consumed() > input.size() || whole.consumed() != pieces.consumed()) std::abort();
    if (whole.request().body != pieces.request().body || whole.request().method != pieces.request().method ||
        whole.request().target != pieces.request().target)
      std::abort();
    if (whole.request().body.size() > limits.max_body_bytes) std::abort();
    if (whole.request().target.empty() || whole.request().target[0] != '/') std::abort();
    (void)whole.request().param("width");
  }
  if (a == RequestParser::State::kError) {
    const int s = whole.error_status();
    if (s != 400 && s != 413 && s != 431 && s != 501 && s != 505) std::abort();
    if (whole.error_message().empty()) std::abort();
  }
  // Trickled bytes may be refused earlier (a limit seen in a prefix) but never accepted differently.
  if (b == RequestParser::State::kComplete && a != RequestParser::State::kComplete) std::abort();
  return 0;
}
