// Arbitrary bytes as a GSDML file (tomc::profinet_gsdml): parsing and, for what parses, every access point
// with nothing chosen and with the first allowed place of each useable module and submodule. A file or
// selection the controller cannot use must be a GsdmlError; anything else (a crash, another exception) is a
// finding.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "tomc/profinet/gsdml.hpp"

namespace gsdml = tomc::profinet::gsdml;

namespace {

void select(const gsdml::Device& device, const gsdml::Selection& selection) {
  try {
    const auto modules = gsdml::expected_modules(device, selection);
    if (modules.empty()) __builtin_trap();  // the DAP is always there
  } catch (const gsdml::GsdmlError&) {
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  gsdml::Device device;
  try {
    device = gsdml::parse(std::string_view(reinterpret_cast<const char*>(data), size));
  } catch (const gsdml::GsdmlError&) {
    return 0;
  }
  for (const gsdml::Module& dap : device.access_points) {
    select(device, {dap.id, {}});
    gsdml::Selection selection{dap.id, {}};
    for (const gsdml::ItemRef& ref : dap.useable) {
      gsdml::ModuleChoice module{ref.allowed.ranges.front().first, ref.target, {}};
      for (const gsdml::Module& m : device.modules) {
        if (m.id != ref.target) continue;
        for (const gsdml::ItemRef& sub : m.useable)
          module.submodules.push_back({sub.allowed.ranges.front().first, sub.target});
      }
      selection.modules.push_back(module);
      select(device, selection);
    }
  }
  return 0;
}
