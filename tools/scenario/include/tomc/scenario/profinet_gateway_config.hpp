#pragma once
// The configuration file of the PROFINET gateway, `tomc gateway --config FILE` (docs/profinet-gateway.md):
// the DDS side as in the gateway simulator's file (docs/gateway.md §9, §11), the PROFINET IO controller's
// interface and send clock, and per device its name on DDS, its PROFINET name of station and IP, its
// telegram, and the modules and submodules the controller expects (default: the emulated drive's).
//
//   { "gateway": "gw1", "domain": 42, "watchdog": 0.05,
//     "profinet": { "interface": "eth1", "ip": "192.168.0.1", "send_clock_factor": 32 },
//     "devices": [ { "name": "axis1", "name_of_station": "drive-1", "ip": "192.168.0.10", "telegram": 3 } ] }

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "tomc/drives/dds/network.hpp"
#include "tomc/drives/telegram_place.hpp"
#include "tomc/scenario/config.hpp"

namespace tomc::scenario {

struct ProfinetSubmoduleConfig {
  std::uint16_t subslot = 1;
  std::uint32_t ident = 0;
  std::uint16_t input_length = 0;   // bytes the device sends (0 with output_length 0: no IO data)
  std::uint16_t output_length = 0;  // bytes the controller sends
};

struct ProfinetModuleConfig {
  std::uint32_t api = 0;  // 0, or e.g. 0x3A00 (PROFIdrive) for a GSDML submodule with that API
  std::uint16_t slot = 0;
  std::uint32_t ident = 0;
  std::vector<ProfinetSubmoduleConfig> submodules;
};

// A start-up parameter record: written to the device after the Connect, before PrmEnd (IEC 61158-6-10
// IODWriteReq), e.g. a PROFIdrive parameter request to index 0xB02E. First the GSDML file's
// ParameterRecordDataItems of the plugged submodules (their DefaultValues), then the file's "records" in its
// order; a file record of the same slot, subslot and index replaces the GSDML one (decision I34).
struct ProfinetRecordConfig {
  std::uint16_t slot = 0;
  std::uint16_t subslot = 1;
  std::uint16_t index = 0;
  std::vector<std::uint8_t> data;  // "data": hex digits, two per byte, spaces allowed ("01 00 01 01 10 01")
  std::uint32_t api = 0;           // the API of the submodule plugged at slot/subslot (from the GSDML); else 0
  bool from_gsdml = false;         // a ParameterRecordDataItem's default rather than the file's "records"
};

// A drive parameter written at start-up through PROFIdrive parameter access ("parameters", decision I33):
// after the telegram check, in the file's order, each read back; its format is the one the drive answers a
// read of it with (FloatingPoint, Unsigned16, ...), so the file gives only the number.
struct ProfinetParameterConfig {
  std::uint16_t slot = 0;  // the object's slot; 0: the one p0922 is checked on (telegram_slot / encoder_slot)
  std::uint16_t number = 0;
  std::uint16_t subindex = 0;
  double value = 0.0;
};

// Where a slot's telegram submodule is (slot, subslot); the default layout is drives::telegram_place().
using ProfinetTelegramPlace = drives::TelegramPlace;

// Where the gateway reads bit 15 (encoder error, its code in Gx_XIST2: spec 06 §3.7) of an encoder status
// word in a device's actual frames (decision I26), and what its status calls the word.
struct ProfinetEncoderErrorBit {
  drives::Slot slot = drives::Slot::kDrive;
  std::size_t byte = 0;  // in the slot's actual frame: the byte that holds bit 15 in the device's byte order
  std::uint8_t mask = 0x80;  // bit 15 within that byte
  const char* name = "";     // "G1_ZSW of the drive telegram", ...
};

struct ProfinetDeviceConfig {
  std::string name;  // the device's name on DDS (the contract's `device`)
  telegrams::ByteOrder byte_order = telegrams::ByteOrder::kBig;
  std::string name_of_station;
  std::array<std::uint8_t, 4> ip{};
  std::array<std::uint8_t, 4> netmask{255, 255, 255, 0};
  // The telegrams of the contract's slots (docs/gateway.md §2): the drive telegram (0 in an encoder-only
  // device), the supplementary telegram 750, the encoder telegram 81/83 of a separately connected encoder.
  std::uint16_t telegram = 0;
  std::uint16_t supplementary_telegram = 0;
  std::uint16_t encoder_telegram = 0;
  std::uint16_t encoder2_telegram = 0;  // a second encoder (slot kEncoder2), only beside encoder_telegram
  // Where each slot's telegram submodule is; subslot 0: the emulated drive's layout (drive 1/2, supplementary
  // 1/3, encoder 2/2, or 1/2 in an encoder-only device). Its input/output lengths must be the telegram's.
  std::array<ProfinetTelegramPlace, drives::kSlotCount> places{};
  // The place of slot s: {} when the slot has no telegram, else `places` or the default.
  ProfinetTelegramPlace place(drives::Slot s) const noexcept;
  // DAP first; by hand ("modules" with idents) or from the drive's GSDML ("gsdml", "dap", "modules" by ID);
  // default: the emulated drive's layout.
  std::vector<ProfinetModuleConfig> modules;
  // At start-up, read p0922 (and p2000) through PROFIdrive parameter access and refuse the AR unless p0922 is
  // `telegram` (in an encoder-only device: the encoder object's p0922 is `encoder_telegram`); false for a
  // device without base-mode parameter access.
  bool check_telegram = true;
  std::vector<ProfinetRecordConfig> records;  // the GSDML file's, then at most kMaxRecords of "records"
  static constexpr std::size_t kMaxRecords = 64;
  std::vector<ProfinetParameterConfig> parameters;  // at most kMaxParameters
  static constexpr std::size_t kMaxParameters = 64;
  drives::DeviceConfig device_config() const;
  // G1_ZSW and G2_ZSW of the drive telegram, G1_ZSW of each encoder telegram, where the telegrams carry them
  // (at most kMaxEncoderErrorBits).
  static constexpr std::size_t kMaxEncoderErrorBits = 4;
  std::vector<ProfinetEncoderErrorBit> encoder_error_bits() const;
};

struct ProfinetGatewayConfig {
  std::string gateway = "gateway";
  int domain = 0;
  std::string partition;
  drives::dds::NetworkSettings network;  // DDS side: "interface", "peers", "multicast_discovery"
  double watchdog = 0.05;                // s without setpoints before the outputs go invalid (G6)
  // PROFINET side ("profinet" object).
  std::string interface;
  std::array<std::uint8_t, 4> ip{};      // the controller's IPv4 address on that interface (RPC, UDP 34964)
  std::uint16_t send_clock_factor = 32;  // × 31.25 µs: 32 = 1 ms (RT_CLASS_1: 32..128)
  std::uint16_t reduction_ratio = 1;
  std::uint16_t watchdog_factor = 3;  // the data-hold watchdog, in send clock × reduction ratio
  // The AlarmCRBlock's RTA timer (decision I35): our alarm DATA resent after rta_timeout_factor × 100 ms,
  // at most rta_retries times, then the AR ends (IEC 61158-6-10 AlarmCRBlockReq: 1..100, 3..15).
  std::uint16_t rta_timeout_factor = 1;
  std::uint16_t rta_retries = 3;
  int fifo_priority = 0;  // the cyclic thread: 1..99 SCHED_FIFO, 0 normal
  // The cyclic thread wakes this early and spins to its send time (RealTimeRunnerConfig::wake_margin):
  // 0 = no spin; at most half the cycle.
  int wake_margin_us = 0;
  bool lock_memory = false;
  std::vector<ProfinetDeviceConfig> devices;

  double cycle_time() const noexcept { return send_clock_factor * reduction_ratio * 31.25e-6; }
};

// Every problem with its JSON path ("devices[1].ip: '10.0.0' is not an IPv4 address"). A device's "gsdml"
// file is found relative to base_directory (the configuration file's folder).
void load_profinet_gateway_config(const Json& document, ProfinetGatewayConfig& config, Problems& problems,
                                  const std::filesystem::path& base_directory = {});
void load_profinet_gateway_config_file(const std::filesystem::path& file, ProfinetGatewayConfig& config,
                                       Problems& problems);

// Why `name` is no name of station ("" when it is one): lower-case labels of letters, digits and '-'
// separated by '.', 1..240 characters (IEC 61158-6-10). The file's check and `tomc gateway --set-name`.
std::string station_name_problem(const std::string& name);

}  // namespace tomc::scenario
