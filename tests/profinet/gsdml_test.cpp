// GSDML (tomc::profinet_gsdml): the emulated drive's own file against the emulator and the telegram codec,
// a selection of modules turned into the Connect's expected modules, every broken file or selection reported
// with the element (and line) or the choice at fault, and `tomc gateway`'s configuration by GSDML.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "build_paths.hpp"
#include "tomc/drives/profinet_drive.hpp"
#include "tomc/profinet/gsdml.hpp"
#include "tomc/profinet/io_controller.hpp"
#include "tomc/profinet/parameter_access.hpp"
#include "tomc/scenario/profinet_gateway_config.hpp"
#include "tomc/telegrams/codec.hpp"
#include "tomc/telegrams/layout.hpp"

#ifndef TOMC_GSDML_DIR
#error "TOMC_GSDML_DIR must name drives/profinet/gsdml"
#endif

namespace pn = tomc::profinet;
namespace gsdml = tomc::profinet::gsdml;
namespace sc = tomc::scenario;
namespace tg = tomc::telegrams;

namespace {

const std::filesystem::path kEmulatorFile =
    std::filesystem::path(TOMC_GSDML_DIR) / "GSDML-V2.35-tomc-EmulatedDrive-20261127.xml";

std::string emulator_text() {
  std::ifstream in(kEmulatorFile);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// The emulator's file with every `from` replaced by `to` (the test fails if `from` is not in it).
std::string edited(const std::string& from, const std::string& to) {
  std::string text = emulator_text();
  EXPECT_NE(text.find(from), std::string::npos) << from;
  for (auto at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  return text;
}

std::string error_of(const std::string& xml) {
  try {
    gsdml::parse(xml);
  } catch (const gsdml::GsdmlError& e) {
    return e.what();
  }
  return "(no error)";
}

gsdml::Selection drive_on(const std::string& telegram_submodule) {
  return {"DAP", {{1, "DO_DRIVE", {{2, telegram_submodule}}}}};
}

std::string selection_error(const gsdml::Device& device, const gsdml::Selection& selection) {
  try {
    gsdml::expected_modules(device, selection);
  } catch (const gsdml::GsdmlError& e) {
    return e.what();
  }
  return "(no error)";
}

std::uint16_t pzd_bytes(std::uint16_t telegram, tg::Direction direction) {
  const auto layout = tg::find_layout(telegram, direction);
  return layout ? layout->length : 0;
}

// The file's submodule TEL<telegram>: ident 0x10000 + telegram, the PZD bytes of the codec's layout, its
// name.
void expect_telegram_submodule(const gsdml::Device& device, std::uint16_t telegram) {
  const std::string id = "TEL" + std::to_string(telegram);
  const auto found = std::find_if(device.submodules.begin(), device.submodules.end(),
                                  [&](const gsdml::Submodule& s) { return s.id == id; });
  ASSERT_NE(found, device.submodules.end());
  EXPECT_EQ(found->ident, tomc::drives::telegram_submodule_ident(telegram));
  EXPECT_EQ(found->input_length, pzd_bytes(telegram, tg::Direction::kActual));
  EXPECT_EQ(found->output_length, pzd_bytes(telegram, tg::Direction::kSetpoint));
  EXPECT_EQ(found->name, "Telegram " + std::to_string(telegram));
}

}  // namespace

TEST(Gsdml, TheEmulatorsFileDescribesTheEmulator) {
  const gsdml::Device device = gsdml::parse_file(kEmulatorFile);
  EXPECT_EQ(device.vendor_id, 0x002A);
  EXPECT_EQ(device.device_id, 0x0C01);
  EXPECT_EQ(device.vendor_name, "tomc emulated drive");
  ASSERT_EQ(device.access_points.size(), 1u);
  const gsdml::Module& dap = device.access_points[0];
  EXPECT_EQ(dap.id, "DAP");
  EXPECT_EQ(dap.ident, tomc::drives::kDapIdent);
  EXPECT_EQ(dap.slot, 0);
  EXPECT_EQ(dap.name, "tomc emulated drive");  // ModuleInfo/Name through the ExternalTextList
  ASSERT_EQ(dap.submodules.size(), 1u);
  EXPECT_EQ(dap.submodules[0].ident, tomc::drives::kDapIdent);
  EXPECT_EQ(dap.submodules[0].fixed_in_subslots.text(), "1");
  ASSERT_EQ(device.modules.size(), 2u);
  EXPECT_EQ(device.modules[0].ident, tomc::drives::kDriveObjectIdent);
  EXPECT_EQ(device.modules[1].ident, tomc::drives::kEncoderObjectIdent);
  // Every drive telegram of spec 06 §2 has its submodule: ident 0x10000 + telegram, IO data = the PZD bytes
  // of the codec's layout (e.g. telegram 3: 18 bytes in, 10 out, §2.3), and the selection gives exactly what
  // the emulator has (profidrive_modules), so the file and the emulator cannot drift apart.
  std::size_t telegrams = 0;
  for (const std::uint16_t telegram : tg::supported_telegrams()) {
    if (!tg::is_drive_telegram(telegram)) continue;
    ++telegrams;
    SCOPED_TRACE("telegram " + std::to_string(telegram));
    expect_telegram_submodule(device, telegram);
    EXPECT_EQ(gsdml::expected_modules(device, drive_on("TEL" + std::to_string(telegram))),
              tomc::drives::profidrive_modules(telegram));
  }
  EXPECT_EQ(telegrams, 10u);                           // 1-6, 102, 103, 105, 106
  EXPECT_EQ(device.submodules.size(), telegrams + 3);  // and TEL750, TEL81, TEL83 (next test)
}

// The supplementary telegram 750 (spec 06 §2.14: 6 bytes out, 2 in) in the drive object's subslot 3, and
// the encoder object with telegram 81 (§2.12: 4 out, 12 in) or 83 (§2.13: 4 out, 16 in) in its subslot 2:
// the selections give exactly what the emulator has for those slots (profidrive_modules).
TEST(Gsdml, TheSupplementaryAndEncoderTelegramSubmodulesDescribeTheEmulator) {
  const gsdml::Device device = gsdml::parse_file(kEmulatorFile);
  for (const std::uint16_t telegram : {750, 81, 83}) {
    SCOPED_TRACE("telegram " + std::to_string(telegram));
    expect_telegram_submodule(device, telegram);
  }
  EXPECT_EQ(pzd_bytes(750, tg::Direction::kSetpoint), 6);
  EXPECT_EQ(pzd_bytes(81, tg::Direction::kActual), 12);
  tomc::drives::DeviceConfig torque;  // telegram 105 + 750, as an MC_TorqueAdditive axis
  torque.drive_telegram = 105;
  torque.supplementary_telegram = 750;
  EXPECT_EQ(gsdml::expected_modules(device, {"DAP", {{1, "DO_DRIVE", {{2, "TEL105"}, {3, "TEL750"}}}}}),
            tomc::drives::profidrive_modules(torque));
  tomc::drives::DeviceConfig both;  // a drive with a separately connected encoder: its object in slot 2
  both.drive_telegram = 3;
  both.encoder_telegrams[0] = 83;
  EXPECT_EQ(gsdml::expected_modules(
                device, {"DAP", {{1, "DO_DRIVE", {{2, "TEL3"}}}, {2, "DO_ENCODER", {{2, "TEL83"}}}}}),
            tomc::drives::profidrive_modules(both));
  tomc::drives::DeviceConfig encoder;  // an encoder-only device (TO_ExternalEncoder): its object in slot 1
  encoder.encoder_telegrams[0] = 81;
  EXPECT_EQ(gsdml::expected_modules(device, {"DAP", {{1, "DO_ENCODER", {{2, "TEL81"}}}}}),
            tomc::drives::profidrive_modules(encoder));
  EXPECT_EQ(tomc::drives::telegram_place(encoder, tomc::drives::Slot::kEncoder1),
            (tomc::drives::TelegramPlace{1, 2}));
  EXPECT_EQ(tomc::drives::telegram_place(both, tomc::drives::Slot::kEncoder1),
            (tomc::drives::TelegramPlace{2, 2}));
  EXPECT_EQ(tomc::drives::telegram_place(torque, tomc::drives::Slot::kSupplementary),
            (tomc::drives::TelegramPlace{1, 3}));
}

// Decision I17 (GSDML through tinyxml2), ARCHITECTURE-GUIDE §6 (every problem named where it is).
TEST(Gsdml, ABrokenFileIsNamedByItsElementAndLine) {
  struct Case {
    std::string from, to, message;
  };
  const Case cases[] = {
      {"</ModuleList>", "</ModuleLis>", "not well-formed XML (XML_ERROR_MISMATCHED_ELEMENT)"},
      {"ProfileBody>", "Body>", "<ISO15745Profile>: no <ProfileBody> element"},
      {"<DeviceIdentity VendorID=\"0x002A\" DeviceID=\"0x0C01\">", "<DeviceIdentity VendorID=\"0x002A\">",
       "<DeviceIdentity>: no DeviceID"},
      {"VendorID=\"0x002A\"", "VendorID=\"0x1002A\"",
       "<DeviceIdentity>: VendorID \"0x1002A\" is not a number"},
      {"<DeviceAccessPointItem ID=\"DAP\" PhysicalSlots=\"0..3\" ModuleIdentNumber=\"0x00000001\"",
       "<DeviceAccessPointItem ID=\"DAP\" PhysicalSlots=\"0..3\"",
       "<DeviceAccessPointItem ID=\"DAP\">: no ModuleIdentNumber"},
      {"<SubmoduleItem ID=\"TEL3\" SubmoduleIdentNumber=\"0x00010003\"", "<SubmoduleItem ID=\"TEL3\"",
       "<SubmoduleItem ID=\"TEL3\">: no SubmoduleIdentNumber"},
      {"<DataItem DataType=\"V2\" TextId=\"T_ZSW1\"/>", "<DataItem DataType=\"Word\" TextId=\"T_ZSW1\"/>",
       "<DataItem>: DataType \"Word\" is not a GSDML data type of IO data"},
      {"<SubmoduleItemRef SubmoduleItemTarget=\"TEL3\" AllowedInSubslots=\"2\"/>",
       "<SubmoduleItemRef SubmoduleItemTarget=\"TEL3\" AllowedInSubslots=\"5..2\"/>",
       "<SubmoduleItemRef>: AllowedInSubslots \"5..2\": the range 5..2 is empty"},
      {"<ModuleItemRef ModuleItemTarget=\"DO_DRIVE\" AllowedInSlots=\"1\"/>",
       "<ModuleItemRef AllowedInSlots=\"1\"/>", "<ModuleItemRef>: no ModuleItemTarget"},
      {"<ModuleItemRef ModuleItemTarget=\"DO_DRIVE\" AllowedInSlots=\"1\"/>",
       "<ModuleItemRef ModuleItemTarget=\"DO_DRIVE\"/>",
       "<ModuleItemRef>: neither AllowedInSlots nor FixedInSlots"},
  };
  for (const Case& c : cases) {
    const std::string message = error_of(edited(c.from, c.to));
    EXPECT_NE(message.find(c.message), std::string::npos) << message;
    EXPECT_EQ(message.rfind("GSDML line ", 0), 0u) << message;  // every message names its line
  }
  EXPECT_EQ(error_of("<root/>"), "GSDML: the root element is not <ISO15745Profile> (is this a GSDML file?)");
  EXPECT_EQ(error_of(""), "GSDML line 0: not well-formed XML (XML_ERROR_EMPTY_DOCUMENT)");
  // The line is the element's: the broken SubmoduleItem of telegram 3 is on line 132 of the file.
  EXPECT_EQ(error_of(edited("<SubmoduleItem ID=\"TEL3\" SubmoduleIdentNumber=\"0x00010003\"",
                            "<SubmoduleItem ID=\"TEL3\"")),
            "GSDML line 132: <SubmoduleItem ID=\"TEL3\">: no SubmoduleIdentNumber");
  // 185 Unsigned64 items and NIST_A: 1482 bytes in telegram 1's input, more than one frame's C_SDU (1440).
  std::string items;
  for (int i = 0; i < 185; ++i)
    items += "<DataItem DataType=\"Unsigned64\"/>";
  const std::string message = error_of(edited("<DataItem DataType=\"V2\" TextId=\"T_ZSW1\"/>", items));
  EXPECT_NE(message.find("<Input>: 1482 bytes of IO data; one IOCR carries at most 1440"), std::string::npos)
      << message;
  try {
    gsdml::parse_file("/nonexistent/GSDML.xml");
    ADD_FAILURE() << "no error";
  } catch (const gsdml::GsdmlError& e) {
    EXPECT_STREQ(e.what(), "/nonexistent/GSDML.xml: cannot be read");
  }
}

// Decision I18 (a DAP and modules chosen by GSDML ID, checked against UseableModules,
// AllowedInSlots/Subslots).
TEST(Gsdml, ASelectionOutsideTheFileIsNamed) {
  const gsdml::Device device = gsdml::parse(emulator_text());
  EXPECT_EQ(selection_error(device, {"DAP2", {}}),
            "no <DeviceAccessPointItem ID=\"DAP2\"> (the file has DAP)");
  EXPECT_EQ(selection_error(device, {"DAP", {{1, "DO_AXIS", {}}}}),
            "slot 1: module 'DO_AXIS' is not in the UseableModules of 'DAP' (DO_DRIVE, DO_ENCODER)");
  EXPECT_EQ(selection_error(device, {"DAP", {{2, "DO_DRIVE", {}}}}),
            "slot 2: module 'DO_DRIVE' is not allowed there (AllowedInSlots \"1\")");
  EXPECT_EQ(
      selection_error(device, {"", {{1, "DO_DRIVE", {{3, "TEL3"}}}}}),
      "module 'DO_DRIVE' in slot 1: submodule 'TEL3' is not allowed in subslot 3 (AllowedInSubslots \"2\")");
  EXPECT_EQ(
      selection_error(device, {"", {{1, "DO_DRIVE", {{2, "TEL81"}}}}}),
      "module 'DO_DRIVE' in slot 1: submodule 'TEL81' is not in its UseableSubmodules (TEL1, TEL2, TEL3, "
      "TEL4, TEL5, TEL6, TEL102, TEL103, TEL105, TEL106, TEL750)");
  EXPECT_EQ(selection_error(device, {"", {{1, "DO_DRIVE", {{2, "TEL750"}}}}}),
            "module 'DO_DRIVE' in slot 1: submodule 'TEL750' is not allowed in subslot 2 (AllowedInSubslots "
            "\"3\")");
  EXPECT_EQ(selection_error(device, {"", {{4, "DO_ENCODER", {{2, "TEL81"}}}}}),
            "slot 4: module 'DO_ENCODER' is not allowed there (AllowedInSlots \"1..3\")");
  EXPECT_EQ(selection_error(device, {"", {{1, "DO_DRIVE", {{2, "TEL3"}, {2, "TEL1"}}}}}),
            "module 'DO_DRIVE' in slot 1: subslot 2 of slot 1 is taken by 'TEL3'");
  EXPECT_EQ(selection_error(device, {"", {{1, "DO_DRIVE", {}}, {1, "DO_DRIVE", {}}}}),
            "slot 1 is taken by 'DO_DRIVE'");
  // Only the DAP: a device with nothing plugged is a valid (if useless) selection.
  const auto dap_only = gsdml::expected_modules(device, {});
  ASSERT_EQ(dap_only.size(), 1u);
  EXPECT_EQ(dap_only[0].slot, 0);
}

// A file shaped like a vendor's drive: a DAP with its interface and port submodules, a drive object fixed in
// slot 1 with a parameter access point, a PROFIdrive telegram in API 0x3A00 (14848), a fixed submodule, and
// OctetString data. Everything it plugs without being chosen, and the API grouping of the Connect.
// Decision I18 (the DAP's own and system-defined submodules and fixed modules are plugged without being
// chosen; grouped by API).
TEST(Gsdml, FixedModulesSystemSubmodulesAndApisBecomeExpectedModules) {
  const gsdml::Device device = gsdml::parse(R"(<?xml version="1.0"?>
<ISO15745Profile xmlns="http://www.profibus.com/GSDML/2003/11/DeviceProfile">
 <ProfileBody>
  <DeviceIdentity VendorID="0x1234" DeviceID="17"/>
  <ApplicationProcess>
   <DeviceAccessPointList>
    <DeviceAccessPointItem ID="DAP_V2" ModuleIdentNumber="0x00000002" FixedInSlots="0">
     <VirtualSubmoduleList><VirtualSubmoduleItem ID="S0" SubmoduleIdentNumber="0x2"/></VirtualSubmoduleList>
     <SystemDefinedSubmoduleList>
      <InterfaceSubmoduleItem ID="IF" SubmoduleIdentNumber="0x8000" SubslotNumber="32768"/>
      <PortSubmoduleItem ID="P1" SubmoduleIdentNumber="0x8001" SubslotNumber="32769"/>
      <PortSubmoduleItem ID="P2" SubmoduleIdentNumber="0x8001" SubslotNumber="32770"/>
     </SystemDefinedSubmoduleList>
     <UseableModules>
      <ModuleItemRef ModuleItemTarget="DO_SERVO" AllowedInSlots="1..4" FixedInSlots="1"/>
      <ModuleItemRef ModuleItemTarget="IO" AllowedInSlots="5"/>
     </UseableModules>
    </DeviceAccessPointItem>
    <DeviceAccessPointItem ID="DAP_V1" ModuleIdentNumber="0x1"/>
   </DeviceAccessPointList>
   <ModuleList>
    <ModuleItem ID="DO_SERVO" ModuleIdentNumber="0x00000200">
     <VirtualSubmoduleList><VirtualSubmoduleItem ID="MAP" SubmoduleIdentNumber="0x1"/></VirtualSubmoduleList>
     <UseableSubmodules>
      <SubmoduleItemRef SubmoduleItemTarget="T105" AllowedInSubslots="2"/>
      <SubmoduleItemRef SubmoduleItemTarget="T750" AllowedInSubslots="3" FixedInSubslots="3"/>
     </UseableSubmodules>
    </ModuleItem>
    <ModuleItem ID="IO" ModuleIdentNumber="0x300">
     <VirtualSubmoduleList>
      <VirtualSubmoduleItem ID="DI" SubmoduleIdentNumber="0x301" FixedInSubslots="1">
       <IOData><Input><DataItem DataType="OctetString" Length="3"/><DataItem DataType="Float32+Status8"/></Input></IOData>
      </VirtualSubmoduleItem>
     </VirtualSubmoduleList>
    </ModuleItem>
   </ModuleList>
   <SubmoduleList>
    <SubmoduleItem ID="T105" API="14848" SubmoduleIdentNumber="0x10069">
     <IOData><Input><DataItem DataType="Unsigned16"/><DataItem DataType="Integer32"/></Input>
             <Output><DataItem DataType="Unsigned16"/></Output></IOData>
    </SubmoduleItem>
    <SubmoduleItem ID="T750" API="0x3A00" SubmoduleIdentNumber="0x102EE">
     <IOData><Input><DataItem DataType="Integer16"/></Input><Output><DataItem DataType="Integer16"/>
       <DataItem DataType="Integer16"/><DataItem DataType="Integer16"/></Output></IOData>
    </SubmoduleItem>
   </SubmoduleList>
  </ApplicationProcess>
 </ProfileBody>
</ISO15745Profile>)");
  EXPECT_EQ(device.vendor_id, 0x1234);
  EXPECT_EQ(device.device_id, 17);
  EXPECT_EQ(selection_error(device, {}), "the file has 2 access points (DAP_V2, DAP_V1): choose one");
  using D = pn::SubmoduleDirection;
  // Nothing chosen but the DAP: the drive object is fixed in slot 1 with its MAP and the fixed telegram 750.
  const auto fixed = gsdml::expected_modules(device, {"DAP_V2", {}});
  const std::vector<pn::ExpectedModule> expected_fixed = {
      {0,
       0,
       2,
       {{1, 2, D::kNoIo, 0, 0},
        {0x8000, 0x8000, D::kNoIo, 0, 0},
        {0x8001, 0x8001, D::kNoIo, 0, 0},
        {0x8002, 0x8001, D::kNoIo, 0, 0}}},
      {0, 1, 0x200, {{1, 1, D::kNoIo, 0, 0}}},
      {0x3A00, 1, 0x200, {{3, 0x102EE, D::kInputOutput, 2, 6}}}};
  EXPECT_EQ(fixed, expected_fixed);
  // Chosen: the drive object in slot 2 with telegram 105 (slot 1 keeps its fixed one) and the IO module.
  const auto chosen =
      gsdml::expected_modules(device, {"DAP_V2", {{2, "DO_SERVO", {{2, "T105"}}}, {5, "IO", {}}}});
  ASSERT_EQ(chosen.size(), 6u);
  EXPECT_EQ(chosen[3], (pn::ExpectedModule{0, 2, 0x200, {{1, 1, D::kNoIo, 0, 0}}}));
  EXPECT_EQ(
      chosen[4],
      (pn::ExpectedModule{
          0x3A00, 2, 0x200, {{2, 0x10069, D::kInputOutput, 6, 2}, {3, 0x102EE, D::kInputOutput, 2, 6}}}));
  EXPECT_EQ(chosen[5], (pn::ExpectedModule{0, 5, 0x300, {{1, 0x301, D::kInput, 8, 0}}}));  // 3 + 5 bytes
}

// ---- `tomc gateway --config`: devices configured from a GSDML file ----

namespace {

std::vector<std::string> gateway_problems(const std::string& device_keys, sc::ProfinetGatewayConfig& config) {
  config = {};
  sc::Problems problems;
  sc::load_profinet_gateway_config(
      sc::Json::parse(R"({ "domain": 1, "profinet": { "interface": "eth1", "ip": "10.0.0.1" }, "devices": [
        { "name": "axis1", "name_of_station": "drive-1", "ip": "10.0.0.2", "telegram": 3, )" +
                      device_keys + " } ] }"),
      config, problems, TOMC_GSDML_DIR);
  return problems.lines();
}

// The emulated drive's file with the drive object in slot 1 and `submodule` in subslot 2.
std::string emulated_drive_with(const std::string& submodule) {
  return R"("gsdml": "GSDML-V2.35-tomc-EmulatedDrive-20261127.xml",
      "modules": [ { "slot": 1, "module": "DO_DRIVE", "submodules": [ { "subslot": 2, "submodule": ")" +
         submodule + R"(" } ] } ])";
}

std::string only(const std::vector<std::string>& lines) {
  return lines.size() == 1 ? lines[0] : "(" + std::to_string(lines.size()) + " problems)";
}

}  // namespace

TEST(GatewayConfig, ADeviceIsConfiguredFromItsGsdmlFile) {
  sc::ProfinetGatewayConfig config;
  const auto lines = gateway_problems(R"("dap": "DAP", )" + emulated_drive_with("TEL3"), config);
  ASSERT_TRUE(lines.empty()) << lines[0];
  // The idents and lengths of the file: what the emulator of a telegram-3 drive has (spec 06 §2.3: 18/10).
  const auto& modules = config.devices.at(0).modules;
  ASSERT_EQ(modules.size(), 2u);
  EXPECT_EQ(modules[0].slot, 0);
  EXPECT_EQ(modules[0].ident, tomc::drives::kDapIdent);
  ASSERT_EQ(modules[1].submodules.size(), 1u);
  EXPECT_EQ(modules[1].ident, tomc::drives::kDriveObjectIdent);
  EXPECT_EQ(modules[1].submodules[0].subslot, 2);
  EXPECT_EQ(modules[1].submodules[0].ident, 0x10003u);
  EXPECT_EQ(modules[1].submodules[0].input_length, 18);
  EXPECT_EQ(modules[1].submodules[0].output_length, 10);
}

TEST(GatewayConfig, AGsdmlProblemNamesTheKeyAndTheElement) {
  sc::ProfinetGatewayConfig config;
  // Telegram 1's submodule cannot carry telegram 3 (spec 06 §2.15: 4/4 bytes, telegram 3 needs 18/10).
  EXPECT_EQ(
      only(gateway_problems(emulated_drive_with("TEL1"), config)),
      "devices[0].modules: slot 1 subslot 2: the telegram submodule has input_length 4 and output_length 4; "
      "telegram 3 needs 18 and 10");
  EXPECT_EQ(
      only(gateway_problems(emulated_drive_with("TEL7"), config)),
      "devices[0].modules: module 'DO_DRIVE' in slot 1: submodule 'TEL7' is not in its UseableSubmodules "
      "(TEL1, TEL2, TEL3, TEL4, TEL5, TEL6, TEL102, TEL103, TEL105, TEL106, TEL750)");
  // Hand-written idents do not mix with a GSDML selection: the unknown key is named.
  const auto mixed = gateway_problems(R"("gsdml": "GSDML-V2.35-tomc-EmulatedDrive-20261127.xml",
      "modules": [ { "slot": 1, "ident": 256, "module": "DO_DRIVE",
                     "submodules": [ { "subslot": 2, "submodule": "TEL3" } ] } ])",
                                      config);
  ASSERT_FALSE(mixed.empty());
  EXPECT_EQ(mixed[0].rfind("devices[0].modules[0].ident:", 0), 0u) << mixed[0];
  EXPECT_EQ(only(gateway_problems(R"("gsdml": "missing.xml")", config)),
            "devices[0].gsdml: " + (std::filesystem::path(TOMC_GSDML_DIR) / "missing.xml").string() +
                ": cannot be read");
  // A malformed file: the path, the line and the element.
  const auto broken = std::filesystem::temp_directory_path() / ("tomc17-gsdml-" + std::to_string(::getpid()));
  std::filesystem::create_directories(broken);
  std::ofstream(broken / "drive.xml")
      << edited("<SubmoduleItem ID=\"TEL3\" SubmoduleIdentNumber=\"0x00010003\"",
                "<SubmoduleItem ID=\"TEL3\" SubmoduleIdentNumber=\"0x1000G\"");
  EXPECT_EQ(only(gateway_problems("\"gsdml\": \"" + (broken / "drive.xml").string() + "\"", config)),
            "devices[0].gsdml: " + (broken / "drive.xml").string() +
                ": GSDML line 132: <SubmoduleItem ID=\"TEL3\">: SubmoduleIdentNumber \"0x1000G\" is not a "
                "number in "
                "0..4294967295");
  std::filesystem::remove_all(broken);
}

// GSDML RecordDataList/ParameterRecordDataItem (decision I34): Index, Length, the Const bytes at their
// ByteOffset and each Ref's DefaultValue in its DataType (big-endian; Bit/BitArea at BitOffset of the byte),
// the items of a submodule in TransferSequence order, placed where the submodule is plugged.
TEST(Gsdml, ParameterRecordDataItemsBecomeTheRecordsOfTheirPlace) {
  const gsdml::Device emulator = gsdml::parse(emulator_text());
  ASSERT_EQ(emulator.access_points.at(0).submodules.at(0).records.size(), 1u);
  const gsdml::ParameterRecord& monitoring = emulator.access_points[0].submodules[0].records[0];
  EXPECT_EQ(monitoring.index, tomc::drives::kMonitoringRecordIndex);              // Index="256"
  EXPECT_EQ(monitoring.data, (std::vector<std::uint8_t>{0x00, 0x01, 0x00, 20}));  // Const 00 01, Ref 20
  EXPECT_EQ(gsdml::parameter_records(emulator, drive_on("TEL3")),
            (std::vector<gsdml::PlacedRecord>{{0, 0, 1, 0x0100, {0x00, 0x01, 0x00, 20}}}));

  // Two items in one submodule, the second written first (TransferSequence 1 before 2), every Ref type.
  const std::string items = R"(<RecordDataList>
      <ParameterRecordDataItem Index="0x20" Length="12" TransferSequence="2">
        <Const Data="0xAA, 0xBB" ByteOffset="10"/>
        <Ref DataType="Integer16" ByteOffset="0" DefaultValue="-2"/>
        <Ref DataType="Unsigned32" ByteOffset="2" DefaultValue="0x01020304"/>
        <Ref DataType="Float32" ByteOffset="6" DefaultValue="1.5"/>
        <Ref DataType="Bit" ByteOffset="10" BitOffset="0" DefaultValue="1"/>
        <Ref DataType="BitArea" ByteOffset="11" BitOffset="4" BitLength="3" DefaultValue="5"/>
      </ParameterRecordDataItem>
      <ParameterRecordDataItem Index="33" Length="1" TransferSequence="1">
        <Ref DataType="Integer8" ByteOffset="0" DefaultValue="-128"/>
      </ParameterRecordDataItem>
    </RecordDataList>
    <ModuleInfo>
                <Name TextId="T_DAP"/>
                <InfoText TextId="T_DAP_Info"/>)";
  const auto replace_records = [&](const std::string& with) {
    std::string text = emulator_text();
    const auto from = text.find("<RecordDataList>");
    const auto to = text.find("<InfoText TextId=\"T_DAP_Info\"/>", from);
    EXPECT_NE(from, std::string::npos);
    return text.replace(from, to + std::string("<InfoText TextId=\"T_DAP_Info\"/>").size() - from, with);
  };
  const gsdml::Device device = gsdml::parse(replace_records(items));
  const auto records = gsdml::parameter_records(device, drive_on("TEL3"));
  ASSERT_EQ(records.size(), 2u);
  EXPECT_EQ(records[0].index, 33);
  EXPECT_EQ(records[0].data, (std::vector<std::uint8_t>{0x80}));
  EXPECT_EQ(records[1].index, 0x20);
  // FFFE, 01020304, 1.5f = 3FC00000, 0xAA with bit 0 set = 0xAB, 0xBB with bits 4..6 = 101 = 0xDB.
  EXPECT_EQ(records[1].data, (std::vector<std::uint8_t>{0xFF, 0xFE, 0x01, 0x02, 0x03, 0x04, 0x3F, 0xC0, 0x00,
                                                        0x00, 0xAB, 0xDB}));
  EXPECT_EQ(records[1].slot, 0);
  EXPECT_EQ(records[1].subslot, 1);

  // What a controller cannot build is named with its element and line.
  struct Case {
    std::string item, message;
  };
  const Case cases[] = {
      {R"(<ParameterRecordDataItem Length="4"/>)", "<ParameterRecordDataItem>: no Index"},
      {R"(<ParameterRecordDataItem Index="0x8000" Length="4"/>)",
       "Index \"0x8000\" is not a number in 0..32767"},
      {R"(<ParameterRecordDataItem Index="1" Length="0"/>)", "<ParameterRecordDataItem>: Length 0"},
      {R"(<ParameterRecordDataItem Index="1" Length="2"><Ref DataType="Unsigned16" ByteOffset="1" DefaultValue="1"/></ParameterRecordDataItem>)",
       "<Ref>: ByteOffset 1 + 2 bytes is beyond the record's Length 2"},
      {R"(<ParameterRecordDataItem Index="1" Length="2"><Ref DataType="Unsigned8" ByteOffset="0" DefaultValue="256"/></ParameterRecordDataItem>)",
       "<Ref>: DefaultValue \"256\" is not a number in 0..255"},
      {R"(<ParameterRecordDataItem Index="1" Length="2"><Ref DataType="Integer16" ByteOffset="0" DefaultValue="-32769"/></ParameterRecordDataItem>)",
       "<Ref>: DefaultValue \"-32769\" is not a number in -32768..32767"},
      {R"(<ParameterRecordDataItem Index="1" Length="8"><Ref DataType="Float64" ByteOffset="0" DefaultValue="1"/></ParameterRecordDataItem>)",
       "<Ref>: DataType \"Float64\" of a parameter Ref is not supported"},
      {R"(<ParameterRecordDataItem Index="1" Length="2"><Ref DataType="BitArea" ByteOffset="0" BitOffset="6" BitLength="3" DefaultValue="1"/></ParameterRecordDataItem>)",
       "<Ref>: BitOffset 6 and BitLength 3 leave the byte at ByteOffset"},
      {R"(<ParameterRecordDataItem Index="1" Length="2"><Const Data="0x01,0x02,0x03"/></ParameterRecordDataItem>)",
       "<Const>: ByteOffset 2 + 1 bytes is beyond the record's Length 2"},
      {R"(<ParameterRecordDataItem Index="1" Length="2"><Const Data="0x01,,0x03"/></ParameterRecordDataItem>)",
       "<Const>: Data \"0x01,,0x03\" has an empty byte"},
      {R"(<ParameterRecordDataItem Index="1" Length="2"/><ParameterRecordDataItem Index="1" Length="2"/>)",
       "<ParameterRecordDataItem>: Index 1 twice in one submodule"},
      // A Float32 default is one finite number, all of the attribute (review of stop 33).
      {R"(<ParameterRecordDataItem Index="1" Length="4"><Ref DataType="Float32" ByteOffset="0" DefaultValue="1.5abc"/></ParameterRecordDataItem>)",
       "<Ref>: DefaultValue \"1.5abc\" is not a finite Float32"},
      {R"(<ParameterRecordDataItem Index="1" Length="4"><Ref DataType="Float32" ByteOffset="0" DefaultValue="nan"/></ParameterRecordDataItem>)",
       "<Ref>: DefaultValue \"nan\" is not a finite Float32"},
      {R"(<ParameterRecordDataItem Index="1" Length="4"><Ref DataType="Float32" ByteOffset="0" DefaultValue="1e39"/></ParameterRecordDataItem>)",
       "<Ref>: DefaultValue \"1e39\" is not a finite Float32"},
  };
  for (const Case& c : cases) {
    const std::string message = error_of(replace_records(
        "<RecordDataList>" + c.item + "</RecordDataList><ModuleInfo><InfoText TextId=\"T_DAP_Info\"/>"));
    EXPECT_NE(message.find(c.message), std::string::npos) << c.item << ": " << message;
    EXPECT_EQ(message.rfind("GSDML line ", 0), 0u) << message;
  }
}

// Decision I34 in the gateway's file: the GSDML file's records come first (IODWriteReq before PrmEnd), then
// the file's "records"; a file record of the same slot, subslot and index replaces the GSDML default. The
// emulated drive takes its monitoring record (setpoint timeout 20 by default, 50 from the file) and refuses
// another version with PNIOStatus DF 80 B8, which ends the start-up.
TEST(GatewayConfig, GsdmlParameterRecordsAreWrittenFirstAndTheFileMayReplaceThem) {
  const auto start = [](const sc::ProfinetDeviceConfig& c, std::vector<std::uint16_t>& indexes) {
    pn::ControllerDeviceConfig config;
    config.name_of_station = c.name_of_station;
    config.ip = {c.ip, c.netmask, {}};
    for (const sc::ProfinetModuleConfig& m : c.modules) {
      pn::ExpectedModule module{m.api, m.slot, m.ident, {}};
      for (const sc::ProfinetSubmoduleConfig& s : m.submodules) {
        module.submodules.push_back(
            {s.subslot, s.ident,
             s.input_length != 0 ? pn::SubmoduleDirection::kInputOutput : pn::SubmoduleDirection::kNoIo,
             s.input_length, s.output_length});
      }
      config.modules.push_back(module);
    }
    for (const sc::ProfinetRecordConfig& r : c.records) {  // as the gateway does
      config.startup_records.push_back({r.slot, r.subslot, r.index, r.data, r.api});
      indexes.push_back(r.index);
    }
    auto controller = std::make_unique<pn::IoController>(pn::MacAddress{2, 0, 0, 0, 0, 1}, "gw", config,
                                                         pn::Uuid{0x5E, 1, 2, {3}});
    pn::DeviceIdentity identity;
    identity.name_of_station = c.name_of_station;
    identity.ip = config.ip;
    identity.mac = {2, 0, 0, 0, 0, 2};
    auto drive = std::make_unique<tomc::drives::ProfinetDrive>(identity, c.device_config(),
                                                               tomc::drives::SimulatedDriveParameters{});
    const bool running = [&] {
      (void)controller->on_dcp(drive->device().on_dcp(controller->identify_request(1)), 2);
      if (!controller->on_connect_response(drive->device().on_rpc(controller->connect_request())))
        return false;
      while (controller->state() == pn::ControllerArState::kParameterizing ||
             controller->state() == pn::ControllerArState::kPrmEnd) {
        if (!controller->on_response(drive->device().on_rpc(controller->next_request()))) return false;
      }
      const auto ready = drive->device().take_application_ready();
      return ready && !controller->on_application_ready(*ready).empty();
    }();
    return std::tuple{running, std::move(controller), std::move(drive)};
  };

  sc::ProfinetGatewayConfig config;
  ASSERT_TRUE(gateway_problems(emulated_drive_with("TEL3") + R"(, "records": [
      { "slot": 1, "index": "0xB02E", "data": "01 01 01 01 10 01 03 9A 00 00" } ])",
                               config)
                  .empty());
  const auto& records = config.devices.at(0).records;
  ASSERT_EQ(records.size(), 2u);
  EXPECT_TRUE(records[0].from_gsdml);
  EXPECT_EQ(records[0].index, tomc::drives::kMonitoringRecordIndex);
  EXPECT_EQ(records[0].data, (std::vector<std::uint8_t>{0x00, 0x01, 0x00, 20}));
  EXPECT_FALSE(records[1].from_gsdml);
  EXPECT_EQ(records[1].index, pn::kParameterAccessIndex);
  std::vector<std::uint16_t> indexes;
  {
    auto [running, controller, drive] = start(config.devices[0], indexes);
    EXPECT_TRUE(running);
    EXPECT_EQ(indexes, (std::vector<std::uint16_t>{0x0100, 0xB02E}));
    EXPECT_EQ(drive->monitoring_records(), 1);
    EXPECT_EQ(drive->drive().parameters().setpoint_timeout_cycles, 20u);
  }

  sc::ProfinetGatewayConfig replaced;
  ASSERT_TRUE(gateway_problems(emulated_drive_with("TEL3") + R"(, "records": [
      { "slot": 0, "subslot": 1, "index": 256, "data": "00 01 00 32" } ])",
                               replaced)
                  .empty());
  ASSERT_EQ(replaced.devices.at(0).records.size(), 1u);
  EXPECT_FALSE(replaced.devices[0].records[0].from_gsdml);
  indexes.clear();
  {
    auto [running, controller, drive] = start(replaced.devices[0], indexes);
    EXPECT_TRUE(running);
    EXPECT_EQ(drive->monitoring_records(), 1);  // written once, with the file's data
    EXPECT_EQ(drive->drive().parameters().setpoint_timeout_cycles, 50u);
  }

  sc::ProfinetGatewayConfig refused;
  ASSERT_TRUE(gateway_problems(emulated_drive_with("TEL3") + R"(, "records": [
      { "slot": 0, "subslot": 1, "index": 256, "data": "00 02 00 32" } ])",
                               refused)
                  .empty());
  indexes.clear();
  auto [running, controller, drive] = start(refused.devices[0], indexes);
  EXPECT_FALSE(running);
  EXPECT_EQ(controller->state(), pn::ControllerArState::kOffline);
  EXPECT_EQ(controller->last_error(), (pn::PnioStatus{0xDF, 0x80, 0xB8, 0x00}));
  EXPECT_EQ(drive->monitoring_records(), 0);
}

// An IODWriteReq addresses its record by API, slot, subslot and index (IEC 61158-6-10), and a PROFIdrive
// submodule is in API 0x3A00: a record of the file goes to the API of the submodule plugged at its place, as
// the GSDML's own records do (decision I34; found in the review of stop 33, when the file's records kept API
// 0).
TEST(GatewayConfig, AFileRecordGoesToTheApiOfTheSubmoduleAtItsPlace) {
  const auto dir =
      std::filesystem::temp_directory_path() / ("tomc17-gsdml-api-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "drive.xml") << edited(
      "<SubmoduleItem ID=\"TEL3\" SubmoduleIdentNumber=\"0x00010003\"",
      "<SubmoduleItem ID=\"TEL3\" API=\"0x3A00\" SubmoduleIdentNumber=\"0x00010003\"");
  sc::ProfinetGatewayConfig config;
  const auto problems = gateway_problems("\"gsdml\": \"" + (dir / "drive.xml").string() + R"(",
      "modules": [ { "slot": 1, "module": "DO_DRIVE", "submodules": [ { "subslot": 2, "submodule": "TEL3" } ] } ],
      "records": [ { "slot": 1, "subslot": 2, "index": 1, "data": "01" },
                   { "slot": 0, "subslot": 1, "index": 2, "data": "02" } ])",
                                         config);
  std::filesystem::remove_all(dir);
  ASSERT_TRUE(problems.empty()) << only(problems);
  const auto& records = config.devices.at(0).records;
  ASSERT_EQ(records.size(), 3u);  // the DAP's GSDML record, then the file's two in their order
  EXPECT_TRUE(records[0].from_gsdml);
  EXPECT_EQ(records[0].api, 0u);
  EXPECT_EQ(records[1].index, 1);
  EXPECT_EQ(records[1].api, 0x3A00u);  // the telegram submodule's
  EXPECT_EQ(records[2].index, 2);
  EXPECT_EQ(records[2].api, 0u);  // the DAP's
}
