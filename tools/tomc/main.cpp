// tomc — the project's command-line program. Subcommands: telegram, sim, demo, gateway-sim (more arrive with
// later layers).
#include <exception>
#include <iostream>
#include <string_view>
#include <vector>

#include "cli_error.hpp"
#include "commands.hpp"

namespace {

constexpr std::string_view kUsage =
    "usage: tomc <command> [arguments]\n"
    "\n"
    "commands:\n"
    "  telegram   encode and decode PROFIdrive telegrams (tomc telegram --help)\n"
    "  sim        run a scenario on simulated drives and write its trace (tomc sim --help)\n"
    "  demo       run a simulated machine with its diagnostics web page (tomc demo --help)\n"
    "  gateway-sim  simulated drives behind the Fast DDS gateway contract (tomc gateway-sim --help)\n"
    "  gateway    PROFINET IO controller for real drives behind that contract (tomc gateway --help)\n"
    "\n"
    "Bad input prints one line on stderr and exits with status 2.\n";

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string_view> args(argv + 1, argv + argc);
  try {
    if (args.empty()) throw tomc::cli::UsageError("missing command (try: tomc --help)");
    const std::string_view command = args.front();
    const std::span<const std::string_view> rest(args.data() + 1, args.size() - 1);
    if (command == "--help" || command == "-h" || command == "help") {
      std::cout << kUsage;
      return 0;
    }
    if (command == "--version") {
      std::cout << "tomc 0.1.0\n";
      return 0;
    }
    if (command == "telegram") return tomc::cli::telegram_command(rest, std::cout);
    if (command == "sim") return tomc::cli::sim_command(rest, std::cout);
    if (command == "demo") return tomc::cli::demo_command(rest, std::cout);
    if (command == "gateway-sim") return tomc::cli::gateway_sim_command(rest, std::cout);
    if (command == "gateway") return tomc::cli::gateway_command(rest, std::cout);
    throw tomc::cli::UsageError("unknown command '" + std::string(command) + "' (try: tomc --help)");
  } catch (const tomc::cli::UsageError& e) {
    std::cerr << "tomc: " << e.what() << '\n';
    return tomc::cli::kExitBadInput;
  } catch (const std::exception& e) {
    std::cerr << "tomc: internal error: " << e.what() << '\n';
    return 1;
  }
}
