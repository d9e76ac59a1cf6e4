#pragma once
// Bad command-line input: one line on stderr and exit status 2 (README "tomc").
#include <stdexcept>
#include <string>

namespace tomc::cli {

inline constexpr int kExitBadInput = 2;

class UsageError : public std::runtime_error {
 public:
  explicit UsageError(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace tomc::cli
