#pragma once
// The start-up of an IoController against an IoDevice in memory (frames and RPC packets handed over
// directly): DCP identify (+ Set IP), Connect, start-up records, PrmEnd, ApplicationReady.
#include "tomc/profinet/io_controller.hpp"
#include "tomc/profinet/io_device.hpp"

namespace tomc::profinet::testing {

// Returns false if the controller did not get to kRunning.
inline bool start_up(IoController& c, IoDevice& d, std::uint32_t xid = 1) {
  const auto identified = d.on_dcp(c.identify_request(xid));
  if (identified.empty()) return false;
  const auto set = c.on_dcp(identified, xid + 1);
  if (!set.empty() && d.on_dcp(set).empty()) return false;
  if (!c.on_connect_response(d.on_rpc(c.connect_request()))) return false;
  for (int guard = 0; guard < 16 && c.state() != ControllerArState::kWaitApplicationReady; ++guard) {
    const auto request = c.next_request();
    if (request.empty() || !c.on_response(d.on_rpc(request))) return false;
  }
  const auto ready = d.take_application_ready();
  return ready && !c.on_application_ready(*ready).empty() && c.state() == ControllerArState::kRunning;
}

}  // namespace tomc::profinet::testing
