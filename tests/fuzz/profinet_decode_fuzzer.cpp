// Arbitrary bytes through every PROFINET decoder (tomc::profinet): Ethernet/DCP, RT_CLASS_1 cyclic, RTA
// alarms, DCE/RPC with the Connect/Control/record blocks, and the IO device and controller behind them. Must
// never crash or read outside the input; what decodes without error must encode again and decode to the same
// value.
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <span>
#include <vector>

#include "tomc/profinet/alarm.hpp"
#include "tomc/profinet/blocks.hpp"
#include "tomc/profinet/cyclic.hpp"
#include "tomc/profinet/dcp.hpp"
#include "tomc/profinet/io_controller.hpp"
#include "tomc/profinet/io_device.hpp"
#include "tomc/profinet/parameter_access.hpp"

namespace pn = tomc::profinet;

namespace {

template <typename Value, typename Decode>
void round_trip(const Value& value, Decode decode) {
  std::vector<std::uint8_t> bytes(65536);
  pn::WireWriter out(bytes);
  pn::encode(value, out);
  if (!out.ok()) return;  // e.g. more than a frame can hold
  pn::WireReader again(out.written());
  if (!(decode(again) == value) || !again.ok()) std::abort();
}

void fuzz_cyclic(std::span<const std::uint8_t> frame) {
  pn::CyclicLayout layout;
  layout.frame_id = pn::peek_frame_id(frame);
  layout.c_sdu_length = 40;
  layout.data_objects[0] = {1, 1, 0, 4};
  layout.data_object_count = 1;
  layout.iocs[0] = {1, 2, 5, 0};
  layout.iocs_count = 1;
  pn::CyclicCodec codec;
  if (pn::CyclicCodec::create(layout, codec) != pn::ProfinetError::kNone) return;
  std::array<std::uint8_t, 40> c_sdu{};
  pn::ApduStatus status;
  (void)codec.decode(frame, c_sdu, status);
  (void)codec.read_iops(c_sdu, 0);
  (void)codec.read_iocs(c_sdu, 0);
}

// A device with an AR already set up (the Connect of a drive with a DAP and a 4-byte IO telegram
// submodule), so that the fuzzed bytes reach record access, control and the cyclic path, not only Connect.
pn::IoDevice connected_device() {
  pn::DeviceIdentity identity;
  identity.mac = {2, 0, 0, 0, 0, 2};
  identity.modules = {{0, 1, {{1, 1, pn::SubmoduleDirection::kNoIo, 0, 0}}},
                      {1, 0x100, {{2, 0x101, pn::SubmoduleDirection::kInputOutput, 4, 4}}}};
  pn::IoDevice device(identity);
  pn::ConnectRequest connect;
  connect.ar.ar_uuid = {0x11223344, 0x5566, 0x7788, {1, 2, 3, 4, 5, 6, 7, 8}};  // as in the corpus
  pn::IocrBlockRequest input;
  input.frame_id = 0x8001;
  input.apis = {{0, {{0, 1, 0}, {1, 2, 1}}, {{1, 2, 6}}}};
  pn::IocrBlockRequest output = input;
  output.type = pn::IocrType::kOutput;
  output.frame_id = 0x8002;
  output.apis = {{0, {{1, 2, 0}}, {{0, 1, 5}, {1, 2, 6}}}};
  connect.iocrs = {input, output};
  connect.expected = {{0, 0, 1, {{1, 1, pn::SubmoduleDirection::kNoIo, 0, 0}}},
                      {0, 1, 0x100, {{2, 0x101, pn::SubmoduleDirection::kInputOutput, 4, 4}}}};
  std::vector<std::uint8_t> blocks(1024);
  pn::WireWriter block_out(blocks);
  pn::encode(connect, block_out);
  pn::RpcHeader header;
  header.object = pn::pnio_object_uuid(1, identity.device_id, identity.vendor_id);
  header.interface = pn::kPnioDeviceInterface;
  std::vector<std::uint8_t> request(2048);
  pn::WireWriter out(request);
  pn::encode_rpc(header, 1024, {}, block_out.written(), out);
  if (device.on_rpc(out.written()).empty() || device.state() != pn::ArState::kParameterizing) std::abort();
  return device;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const std::span<const std::uint8_t> bytes(data + 1, size - 1);
  switch (data[0] % 8) {
    case 0: {  // an Ethernet frame: DCP
      pn::WireReader in(bytes);
      (void)pn::decode_ethernet(in);
      const pn::DcpMessage message = pn::decode_dcp(in);
      if (in.ok()) {
        std::vector<std::uint8_t> again(1514);
        pn::WireWriter out(again);
        pn::encode(pn::EthernetHeader{}, message, out);
        pn::WireReader reread(out.written());
        (void)pn::decode_ethernet(reread);
        if (out.ok() && (!(pn::decode_dcp(reread) == message) || !reread.ok())) std::abort();
      }
      break;
    }
    case 1:
      fuzz_cyclic(bytes);
      break;
    case 2: {
      pn::RtaFrame frame;
      (void)pn::decode_rta(bytes, frame);
      break;
    }
    case 3: {  // a UDP payload: RPC, then the blocks as each operation
      pn::WireReader in(bytes);
      const pn::RpcPacket packet = pn::decode_rpc(in);
      if (!in.ok()) break;
      pn::WireReader control(packet.blocks);
      (void)pn::decode_control(control);
      pn::WireReader record(packet.blocks);
      (void)pn::decode_record(record);
      break;
    }
    case 4: {  // PNIO blocks of a Connect
      pn::WireReader request_in(bytes);
      const pn::ConnectRequest request = pn::decode_connect_request(request_in);
      if (request_in.ok())
        round_trip(request, [](pn::WireReader& r) { return pn::decode_connect_request(r); });
      pn::WireReader response_in(bytes);
      const pn::ConnectResponse response = pn::decode_connect_response(response_in);
      if (response_in.ok())
        round_trip(response, [](pn::WireReader& r) { return pn::decode_connect_response(r); });
      break;
    }
    case 6: {  // the IO device: the bytes as DCP frame, RPC packet and cyclic frame, with an AR set up
      static const pn::IoDevice prototype = connected_device();
      pn::IoDevice device = prototype;
      (void)device.on_dcp(bytes);
      (void)device.on_rpc(bytes);
      if (bytes.size() >= 24) {  // the same packet to the device's own object: a wrong one is rejected first
        std::vector<std::uint8_t> own(bytes.begin(), bytes.end());
        pn::WireWriter object_out(std::span(own).subspan(8, 16));
        pn::encode(pn::pnio_object_uuid(1, 0, 0), object_out, (own[4] & 0xF0) == 0x10);
        (void)device.on_rpc(own);
      }
      (void)device.on_cyclic(bytes, 1000);
      std::array<std::uint8_t, 1514> frame{};
      (void)device.next_input_frame(frame);
      (void)device.take_application_ready();
      (void)device.watchdog_expired(1000000);
      break;
    }
    case 7: {  // the IO controller's receive paths, waiting for a Connect answer and then running
      pn::ControllerDeviceConfig config;
      config.name_of_station = "drive-1";
      config.modules = {{0, 0, 1, {{1, 1, pn::SubmoduleDirection::kNoIo, 0, 0}}},
                        {0, 1, 0x100, {{2, 0x101, pn::SubmoduleDirection::kInputOutput, 4, 4}}}};
      pn::IoController controller({2, 0, 0, 0, 0, 1}, "gw", config, {1, 2, 3, {4}});
      (void)controller.on_dcp(bytes, 1);
      (void)controller.connect_request();
      (void)controller.on_connect_response(bytes);
      (void)controller.next_request();
      (void)controller.on_response(bytes);
      (void)controller.on_application_ready(bytes);
      (void)controller.on_input_frame(bytes, 1000);
      std::array<std::uint8_t, 256> ack{};
      std::array<std::uint8_t, 256> alarm_ack{};
      std::size_t ack_bytes = 0;
      std::size_t alarm_ack_bytes = 0;
      (void)controller.on_alarm(bytes, ack, alarm_ack, ack_bytes, alarm_ack_bytes, 1000);
      (void)controller.alarm_timer(false, 200'000, alarm_ack, alarm_ack_bytes);
      std::array<std::uint8_t, 1514> frame{};
      (void)controller.next_output_frame(frame);
      (void)controller.input_valid(2000);
      break;
    }
    default: {  // Control and record blocks without the RPC around them
      pn::WireReader control_in(bytes);
      const pn::ControlBlock control = pn::decode_control(control_in);
      if (control_in.ok()) round_trip(control, [](pn::WireReader& r) { return pn::decode_control(r); });
      pn::WireReader record_in(bytes);
      const pn::RecordAccess record = pn::decode_record(record_in);
      if (record_in.ok()) round_trip(record, [](pn::WireReader& r) { return pn::decode_record(r); });
      // The same bytes as PROFIdrive parameter access data (record index 0xB02E): what decodes re-encodes to
      // a value that decodes the same.
      if (const auto request = pn::decode_parameter_request(bytes)) {
        if (pn::decode_parameter_request(pn::encode(*request)) != request) std::abort();
      }
      if (const auto response = pn::decode_parameter_response(bytes)) {
        if (pn::decode_parameter_response(pn::encode(*response)) != response) std::abort();
        (void)pn::integer_value(*response, 0);
        (void)pn::float_value(*response, 0);
        (void)pn::error_value(*response, 0);
        for (const pn::ParameterValue& v : response->parameters) {
          // A value that reads as a number writes back to the same bits (integers exactly, finite floats).
          if (v.values.empty()) continue;
          const auto number = pn::numeric_value(v.format, v.values.front());
          if (!number || !std::isfinite(*number)) continue;
          if (pn::raw_value(v.format, *number) != v.values.front()) std::abort();
        }
      }
      break;
    }
  }
  return 0;
}
