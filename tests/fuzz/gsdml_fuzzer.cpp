// Arbitrary bytes as a GSDML file (tomc::profinet_gsdml): parsing and, for what parses, every access point
// with nothing chosen and with the first allowed place of each useable module and submodule, and the
// parameter records of what it plugs. A file or selection the controller cannot use must be a GsdmlError;
// anything else (a crash, another exception) is a finding.
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
    // The ParameterRecordDataItems of the same plugged submodules (decision I34): each in a plugged place.
    for (const gsdml::PlacedRecord& record : gsdml::parameter_records(device, selection)) {
      bool placed = false;
      for (const auto& m : modules) {
        for (const auto& s : m.submodules)
          placed = placed || (m.slot == record.slot && s.subslot == record.subslot && m.api == record.api);
      }
      if (!placed || record.data.empty()) __builtin_trap();
    }
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
