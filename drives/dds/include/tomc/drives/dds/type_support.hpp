#pragma once
// The contract's DDS type support, made safe against malformed samples from the network. fastddsgen 2.3's
// generated deserialize() catches only Fast CDR's NotEnoughMemoryException; a malformed encapsulation or enum
// throws BadParamException through Fast DDS into the listener thread, which ends the process (found by
// tests/fuzz/dds_answer_fuzzer.cpp). Every tomc reader uses these wrappers: a sample that does not
// deserialize is cleared to its default value — contract version 0 — which every receiver rejects.
#include "tomc_gatewayPubSubTypes.h"

namespace tomc::drives::dds {

template <typename Generated>
class CheckedType final : public Generated {
 public:
  using Data = typename Generated::type;
  bool deserialize(eprosima::fastrtps::rtps::SerializedPayload_t* payload, void* data) override {
    bool ok = false;
    try {
      ok = Generated::deserialize(payload, data);
    } catch (...) {
      ok = false;
    }
    if (!ok) *static_cast<Data*>(data) = Data{};
    return ok;
  }
};

using SetpointCycleType = CheckedType<gateway::SetpointCyclePubSubType>;
using ActualCycleType = CheckedType<gateway::ActualCyclePubSubType>;
using GatewayStatusType = CheckedType<gateway::GatewayStatusPubSubType>;
using GatewayCommandType = CheckedType<gateway::GatewayCommandPubSubType>;

}  // namespace tomc::drives::dds
