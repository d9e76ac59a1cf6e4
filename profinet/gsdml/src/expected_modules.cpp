// From a GSDML description and a module selection to the modules an IO controller expects (gsdml.hpp).
#include <algorithm>
#include <map>

#include "tomc/profinet/gsdml.hpp"

namespace tomc::profinet::gsdml {

namespace {

constexpr std::size_t kMaxModules = 64;  // as the Connect codec (blocks.hpp)
constexpr std::size_t kMaxSubmodules = 64;

template <typename Item>
const Item* find_id(const std::vector<Item>& items, std::string_view id) {
  const auto found = std::find_if(items.begin(), items.end(), [&](const Item& i) { return i.id == id; });
  return found == items.end() ? nullptr : &*found;
}

const ItemRef* find_ref(const std::vector<ItemRef>& refs, std::string_view target) {
  const auto found =
      std::find_if(refs.begin(), refs.end(), [&](const ItemRef& r) { return r.target == target; });
  return found == refs.end() ? nullptr : &*found;
}

template <typename Items>
std::string ids_of(const Items& items) {
  std::string out;
  for (const auto& item : items) {
    if constexpr (requires { item.target; }) {
      out += (out.empty() ? "" : ", ") + item.target;
    } else {
      out += (out.empty() ? "" : ", ") + item.id;
    }
  }
  return out.empty() ? "none" : out;
}

std::string in_quotes(std::string_view id) {
  return "'" + std::string(id) + "'";
}

ExpectedSubmodule expected(const Submodule& s, std::uint16_t subslot) {
  const auto direction = s.input_length != 0 && s.output_length != 0 ? SubmoduleDirection::kInputOutput
                         : s.input_length != 0                       ? SubmoduleDirection::kInput
                         : s.output_length != 0                      ? SubmoduleDirection::kOutput
                                                                     : SubmoduleDirection::kNoIo;
  return {subslot, s.ident, direction, s.input_length, s.output_length};
}

// Every number of a ValueList, stopping once more than `limit` were produced (a hostile "0..32767").
template <typename Visit>
void for_each_value(const ValueList& list, std::size_t limit, Visit visit) {
  std::size_t n = 0;
  for (const auto& [low, high] : list.ranges) {
    for (std::uint32_t v = low; v <= high; ++v) {
      if (++n > limit) throw GsdmlError("more than " + std::to_string(limit) + " fixed slots or subslots");
      visit(static_cast<std::uint16_t>(v));
    }
  }
}

// One plugged module: its submodules by subslot, each with its API.
struct Plugged {
  std::uint16_t slot = 0;
  const Module* module = nullptr;
  std::map<std::uint16_t, const Submodule*> submodules;
};

void plug_submodule(Plugged& plugged, std::uint16_t subslot, const Submodule& s, const std::string& what) {
  if (!plugged.submodules.emplace(subslot, &s).second) {
    throw GsdmlError(what + ": subslot " + std::to_string(subslot) + " of slot " +
                     std::to_string(plugged.slot) + " is taken by " +
                     in_quotes(plugged.submodules[subslot]->id));
  }
  if (plugged.submodules.size() > kMaxSubmodules)
    throw GsdmlError("slot " + std::to_string(plugged.slot) + ": more than 64 submodules");
}

// A module's own submodules and its fixed useable ones, then the chosen ones.
Plugged plug_module(const Device& device, const Module& module, std::uint16_t slot,
                    const std::vector<SubmoduleChoice>& chosen) {
  Plugged plugged{slot, &module, {}};
  const std::string where = "module " + in_quotes(module.id) + " in slot " + std::to_string(slot);
  for (const Submodule& own : module.submodules)
    plug_submodule(plugged, own.fixed_in_subslots.ranges.front().first, own, where);
  for (const SubmoduleChoice& choice : chosen) {
    const ItemRef* ref = find_ref(module.useable, choice.id);
    if (ref == nullptr) {
      throw GsdmlError(where + ": submodule " + in_quotes(choice.id) + " is not in its UseableSubmodules (" +
                       ids_of(module.useable) + ")");
    }
    if (!ref->allowed.contains(choice.subslot)) {
      throw GsdmlError(where + ": submodule " + in_quotes(choice.id) + " is not allowed in subslot " +
                       std::to_string(choice.subslot) + " (AllowedInSubslots \"" + ref->allowed.text() +
                       "\")");
    }
    const Submodule* s = find_id(device.submodules, choice.id);
    if (s == nullptr) throw GsdmlError("no <SubmoduleItem ID=\"" + choice.id + "\"> in the SubmoduleList");
    plug_submodule(plugged, choice.subslot, *s, where);
  }
  for (const ItemRef& ref : module.useable) {
    const Submodule* s = find_id(device.submodules, ref.target);
    for_each_value(ref.fixed, kMaxSubmodules, [&](std::uint16_t subslot) {
      if (plugged.submodules.contains(subslot)) return;
      if (s == nullptr) throw GsdmlError("no <SubmoduleItem ID=\"" + ref.target + "\"> in the SubmoduleList");
      plug_submodule(plugged, subslot, *s, where);
    });
  }
  return plugged;
}

const Module& choose_access_point(const Device& device, const std::string& id) {
  if (id.empty()) {
    if (device.access_points.size() == 1) return device.access_points.front();
    throw GsdmlError("the file has " + std::to_string(device.access_points.size()) + " access points (" +
                     ids_of(device.access_points) + "): choose one");
  }
  const Module* dap = find_id(device.access_points, id);
  if (dap == nullptr) {
    throw GsdmlError("no <DeviceAccessPointItem ID=\"" + id + "\"> (the file has " +
                     ids_of(device.access_points) + ")");
  }
  return *dap;
}

// Every plugged module by slot: the DAP, the chosen modules and the ones fixed in a slot nobody chose.
std::map<std::uint16_t, Plugged> plug(const Device& device, const Selection& selection) {
  const Module& dap = choose_access_point(device, selection.access_point);
  std::map<std::uint16_t, Plugged> slots;
  slots.emplace(dap.slot, plug_module(device, dap, dap.slot, {}));
  for (const ModuleChoice& choice : selection.modules) {
    const std::string where = "slot " + std::to_string(choice.slot);
    if (slots.contains(choice.slot)) {
      throw GsdmlError(where + " is taken by " + in_quotes(slots[choice.slot].module->id));
    }
    const ItemRef* ref = find_ref(dap.useable, choice.id);
    if (ref == nullptr) {
      throw GsdmlError(where + ": module " + in_quotes(choice.id) + " is not in the UseableModules of " +
                       in_quotes(dap.id) + " (" + ids_of(dap.useable) + ")");
    }
    if (!ref->allowed.contains(choice.slot)) {
      throw GsdmlError(where + ": module " + in_quotes(choice.id) +
                       " is not allowed there (AllowedInSlots \"" + ref->allowed.text() + "\")");
    }
    const Module* module = find_id(device.modules, choice.id);
    if (module == nullptr) throw GsdmlError("no <ModuleItem ID=\"" + choice.id + "\"> in the ModuleList");
    slots.emplace(choice.slot, plug_module(device, *module, choice.slot, choice.submodules));
  }
  for (const ItemRef& ref : dap.useable) {
    const Module* module = find_id(device.modules, ref.target);
    for_each_value(ref.fixed, kMaxModules, [&](std::uint16_t slot) {
      if (slots.contains(slot)) return;
      if (module == nullptr) throw GsdmlError("no <ModuleItem ID=\"" + ref.target + "\"> in the ModuleList");
      slots.emplace(slot, plug_module(device, *module, slot, {}));
    });
  }
  if (slots.size() > kMaxModules) throw GsdmlError("more than 64 modules");
  return slots;
}

}  // namespace

std::vector<ExpectedModule> expected_modules(const Device& device, const Selection& selection) {
  const std::map<std::uint16_t, Plugged> slots = plug(device, selection);
  // One entry per slot and API (ExpectedSubmoduleBlockReq groups the submodules of a slot by API).
  std::vector<ExpectedModule> modules;
  for (const auto& [slot, plugged] : slots) {
    const std::size_t first = modules.size();
    for (const auto& [subslot, submodule] : plugged.submodules) {
      const Submodule* s = submodule;  // clang 14 cannot capture a structured binding
      auto entry = std::find_if(modules.begin() + static_cast<std::ptrdiff_t>(first), modules.end(),
                                [&](const ExpectedModule& m) { return m.api == s->api; });
      if (entry == modules.end()) {
        modules.push_back({s->api, slot, plugged.module->ident, {}});
        entry = modules.end() - 1;
      }
      entry->submodules.push_back(expected(*s, subslot));
    }
    if (modules.size() == first) modules.push_back({0, slot, plugged.module->ident, {}});
  }
  return modules;
}

std::vector<PlacedRecord> parameter_records(const Device& device, const Selection& selection) {
  std::vector<PlacedRecord> records;
  for (const auto& [slot, plugged] : plug(device, selection)) {
    for (const auto& [subslot, submodule] : plugged.submodules) {
      for (const ParameterRecord& r : submodule->records)
        records.push_back({submodule->api, slot, subslot, r.index, r.data});
    }
  }
  return records;
}

}  // namespace tomc::profinet::gsdml
