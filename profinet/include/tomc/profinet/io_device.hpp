#pragma once
// The protocol side of a PROFINET IO device, without sockets: it answers DCP, accepts a Connect against its
// real modules (ModuleDiffBlock for every difference), takes record writes and reads, PrmEnd, Release, and
// exchanges the cyclic frames of the two IOCRs the Connect set up. The device emulator of the tests (and any
// transport) feeds it received frames and sends what it returns. One AR at a time (IOCARSingle).

#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "tomc/profinet/blocks.hpp"
#include "tomc/profinet/cyclic.hpp"
#include "tomc/profinet/dcp.hpp"

namespace tomc::profinet {

struct DeviceSubmodule {
  std::uint16_t subslot = 1;
  std::uint32_t ident = 0;
  SubmoduleDirection direction = SubmoduleDirection::kNoIo;
  std::uint16_t input_length = 0;
  std::uint16_t output_length = 0;
};

struct DeviceModule {
  std::uint16_t slot = 0;
  std::uint32_t ident = 0;
  std::vector<DeviceSubmodule> submodules;
};

struct DeviceIdentity {
  std::string name_of_station;
  IpSuite ip;
  MacAddress mac{};
  std::uint16_t vendor_id = 0;
  std::uint16_t device_id = 0;
  std::string vendor;                 // DeviceVendorValue
  std::vector<DeviceModule> modules;  // the real configuration
};

enum class ArState : std::uint8_t {
  kNone,              // no AR
  kParameterizing,    // Connect accepted; record writes until PrmEnd
  kApplicationReady,  // PrmEnd answered; the device's ApplicationReady is due (take_application_ready)
  kRunning,           // ApplicationReady sent; cyclic data are valid
};

class IoDevice {
 public:
  // Record access: a write returns its PNIOStatus; a read returns the record's data or an error status.
  using WriteHandler = std::function<PnioStatus(const RecordHeader&, std::span<const std::uint8_t>)>;
  using ReadHandler = std::function<PnioStatus(const RecordHeader&, std::vector<std::uint8_t>&)>;

  explicit IoDevice(DeviceIdentity identity);

  const DeviceIdentity& identity() const noexcept { return identity_; }
  ArState state() const noexcept { return state_; }
  const ConnectRequest& connection() const noexcept { return connection_; }
  const std::vector<ModuleDiff>& module_diff() const noexcept { return module_diff_; }
  void set_write_handler(WriteHandler handler) { write_handler_ = std::move(handler); }
  void set_read_handler(ReadHandler handler) { read_handler_ = std::move(handler); }

  // A received DCP frame (from its first byte); the answer frame, or empty when the frame is not for this
  // device (an Identify of another name) or malformed.
  std::vector<std::uint8_t> on_dcp(std::span<const std::uint8_t> frame);
  // The Hello the device sends at start-up.
  std::vector<std::uint8_t> hello() const;

  // A received RPC packet (UDP payload to port 34964); the answer packet, or empty.
  std::vector<std::uint8_t> on_rpc(std::span<const std::uint8_t> payload);
  // After PrmEnd: the ApplicationReady request (an RPC packet to the controller's port 34964), once; the
  // AR is then kRunning.
  std::optional<std::vector<std::uint8_t>> take_application_ready();

  // A received cyclic frame of the output CR: updates the output image (false: not this AR's frame or a
  // stale/malformed one). now_us is the receive time for the watchdog.
  bool on_cyclic(std::span<const std::uint8_t> frame, std::uint64_t now_us);
  // The input CR's next frame into out; 0 without an AR. The device's cycle counter advances by
  // send clock factor x reduction ratio per frame.
  std::size_t next_input_frame(std::span<std::uint8_t> out);
  // Data of a submodule in the input image (to fill) / the output image (received), empty if the submodule
  // has no such data in this AR.
  std::span<std::uint8_t> input_data(std::uint16_t slot, std::uint16_t subslot);
  std::span<const std::uint8_t> output_data(std::uint16_t slot, std::uint16_t subslot) const;
  // The controller's provider state of that output data (kIoxsBad if the submodule has none in this AR).
  std::uint8_t output_iops(std::uint16_t slot, std::uint16_t subslot) const noexcept;
  ApduStatus last_output_status() const noexcept { return output_status_; }
  // The watchdog (IEC 61158-6-10: DataHoldFactor x cycle without a new output frame): ends the AR.
  bool watchdog_expired(std::uint64_t now_us);
  // Ends the AR (cable cut, watchdog, Release).
  void abort_ar() noexcept;

 private:
  std::vector<std::uint8_t> answer_connect(const RpcPacket& request);
  std::vector<std::uint8_t> answer_control(const RpcPacket& request);
  std::vector<std::uint8_t> answer_record(const RpcPacket& request, bool write);
  std::vector<std::uint8_t> response(const RpcHeader& request, PnioStatus status,
                                     std::span<const std::uint8_t> blocks) const;
  const DeviceSubmodule* real_submodule(std::uint16_t slot, std::uint16_t subslot) const;
  bool build_cyclic(const ConnectRequest& request);

  DeviceIdentity identity_;
  ArState state_ = ArState::kNone;
  ConnectRequest connection_;
  std::vector<ModuleDiff> module_diff_;
  CyclicCodec input_codec_;
  CyclicCodec output_codec_;
  std::vector<std::uint8_t> input_image_;
  std::vector<std::uint8_t> output_image_;
  ApduStatus output_status_;
  std::uint16_t input_cycle_counter_ = 0;
  std::uint16_t cycle_counter_step_ = 32;
  std::uint64_t data_hold_us_ = 3000;
  std::uint64_t last_output_us_ = 0;
  bool output_seen_ = false;
  std::uint32_t application_ready_sequence_ = 0;
  bool application_ready_due_ = false;
  WriteHandler write_handler_;
  ReadHandler read_handler_;
};

}  // namespace tomc::profinet
