#pragma once
// A PROFINET device's description (GSDML, the XML file every IO device ships with): the device access points
// (DAP), the modules and submodules with their ident numbers and IO data lengths, and which module may sit in
// which slot. `parse` reads the parts an IO controller needs to build its Connect; `expected_modules` turns a
// selection of modules (as a user would plug them in an engineering tool) into the ExpectedSubmoduleBlock's
// content. Configuration time only: both allocate and throw GsdmlError (docs/profinet-gateway.md).

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "tomc/profinet/blocks.hpp"

namespace tomc::profinet::gsdml {

// A file that cannot be used: the message names the element, its line and what is wrong with it.
class GsdmlError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A GSDML ValueList ("1 3..5"): slot or subslot numbers, kept as ranges.
struct ValueList {
  std::vector<std::pair<std::uint16_t, std::uint16_t>> ranges;  // inclusive
  bool empty() const noexcept { return ranges.empty(); }
  bool contains(std::uint32_t value) const noexcept;
  std::string text() const;  // as written in GSDML: "1 3..5"
};

// A RecordDataList/ParameterRecordDataItem: a record the controller writes to the submodule at start-up
// (IODWriteReq before PrmEnd, decision I34), its bytes built from the item's Const and Ref elements (the
// Ref's DefaultValue in its DataType at its ByteOffset/BitOffset, big-endian; unset bytes 0).
struct ParameterRecord {
  std::uint16_t index = 0;              // Index (0..0x7FFF: the submodule's own records)
  std::uint32_t transfer_sequence = 0;  // TransferSequence: written in ascending order (0: the file's)
  std::vector<std::uint8_t> data;       // Length bytes
  int line = 0;
};

struct Submodule {
  std::string id;    // the ID attribute
  std::string name;  // ModuleInfo/Name in the primary language ("" without)
  std::uint32_t api = 0;
  std::uint32_t ident = 0;               // SubmoduleIdentNumber
  std::uint16_t input_length = 0;        // IOData/Input: bytes the device sends
  std::uint16_t output_length = 0;       // IOData/Output: bytes the controller sends
  ValueList fixed_in_subslots;           // a module's own (virtual / system-defined) submodule: where it sits
  std::vector<ParameterRecord> records;  // RecordDataList, in TransferSequence order
  int line = 0;                          // in the file, for messages
};

// A ModuleItemRef (in a DAP's UseableModules) or SubmoduleItemRef (in a module's UseableSubmodules).
struct ItemRef {
  std::string target;  // the ID of a ModuleItem / SubmoduleItem
  ValueList allowed;   // AllowedInSlots / AllowedInSubslots (default: the fixed ones)
  ValueList fixed;     // FixedInSlots / FixedInSubslots: plugged without being chosen
  int line = 0;
};

struct Module {
  std::string id;
  std::string name;
  std::uint32_t ident = 0;            // ModuleIdentNumber
  std::vector<Submodule> submodules;  // VirtualSubmoduleList (and a DAP's SystemDefinedSubmoduleList)
  std::vector<ItemRef> useable;       // UseableSubmodules; for a DAP: UseableModules
  std::uint16_t slot = 0;             // a DAP's slot (FixedInSlots, normally 0)
  int line = 0;
};

struct Device {
  std::uint16_t vendor_id = 0;
  std::uint16_t device_id = 0;
  std::string vendor_name;
  std::vector<Module> access_points;  // DeviceAccessPointList
  std::vector<Module> modules;        // ModuleList
  std::vector<Submodule> submodules;  // SubmoduleList
};

// Reads a GSDML document. Unknown elements and attributes are ignored; a missing or malformed one the
// controller needs is a GsdmlError ("GSDML line 41: <SubmoduleItem ID=\"TEL3\">: no SubmoduleIdentNumber").
Device parse(std::string_view xml);
Device parse_file(const std::filesystem::path& file);  // "<file>: " before the message

// Modules chosen for the slots, each with the submodules chosen for its subslots, by GSDML ID.
struct SubmoduleChoice {
  std::uint16_t subslot = 0;
  std::string id;
};
struct ModuleChoice {
  std::uint16_t slot = 0;
  std::string id;
  std::vector<SubmoduleChoice> submodules;
};
struct Selection {
  std::string access_point;  // the DAP's ID; "" when the file has exactly one
  std::vector<ModuleChoice> modules;
};

// What the controller expects (ExpectedSubmoduleBlockReq), slot by slot: the DAP with its own submodules,
// every chosen module (allowed in its slot by the DAP's UseableModules) with its own submodules, its fixed
// useable ones and the chosen ones (allowed in their subslots); modules fixed in a slot nobody chose are
// plugged too. Submodules of another API than their module's first become an entry of their own (same slot,
// that API).
std::vector<ExpectedModule> expected_modules(const Device& device, const Selection& selection);

// The ParameterRecordDataItems of every submodule expected_modules() plugs, where it plugs it: slot by slot,
// subslot by subslot, each submodule's in its TransferSequence order (the IODWriteReqs at start-up).
struct PlacedRecord {
  std::uint32_t api = 0;
  std::uint16_t slot = 0;
  std::uint16_t subslot = 0;
  std::uint16_t index = 0;
  std::vector<std::uint8_t> data;
  bool operator==(const PlacedRecord&) const = default;
};
std::vector<PlacedRecord> parameter_records(const Device& device, const Selection& selection);

}  // namespace tomc::profinet::gsdml
