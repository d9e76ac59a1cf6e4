#pragma once
// `tomc gateway` in the caller's process (tomc::profinet_gateway), made on a thread that has entered a
// network namespace, so that its sockets and DDS participant live there. Shared by
// gateway_allocation_test.cpp and bench/profinet_gateway_jitter.cpp.
#include <memory>
#include <stdexcept>
#include <string>
#include <thread>

#include "netns_hosts.hpp"
#include "tomc/gateway/profinet_gateway.hpp"

namespace tomc::profinet::testing {

// The running gateway, or nullptr with `error` saying why (setns failed, or the gateway's own message).
inline std::unique_ptr<profinet_gateway::ProfinetGateway> gateway_in(
    const std::string& ns, const scenario::ProfinetGatewayConfig& config, std::string& error) {
  std::unique_ptr<profinet_gateway::ProfinetGateway> gateway;
  std::thread([&] {
    if (!enter(ns)) return void(error = "setns failed");
    try {
      gateway = std::make_unique<profinet_gateway::ProfinetGateway>(config);
    } catch (const std::exception& e) {
      error = e.what();
    }
  }).join();
  return gateway;
}

}  // namespace tomc::profinet::testing
