#pragma once
// Subcommands of the tomc CLI. Each takes the arguments after its name and returns the exit status;
// bad input throws UsageError (main prints it on one line and exits 2).
#include <iosfwd>
#include <span>
#include <string_view>

namespace tomc::cli {

int telegram_command(std::span<const std::string_view> args, std::ostream& out);
int sim_command(std::span<const std::string_view> args, std::ostream& out);
int gateway_sim_command(std::span<const std::string_view> args, std::ostream& out);
int gateway_command(std::span<const std::string_view> args, std::ostream& out);
int demo_command(std::span<const std::string_view> args, std::ostream& out);

// examples/demo_machine.json, embedded at build time (the machine of `tomc demo` without --config).
std::string_view demo_machine_json() noexcept;

}  // namespace tomc::cli
