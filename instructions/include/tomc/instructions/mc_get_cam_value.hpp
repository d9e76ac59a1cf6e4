#pragma once
// MC_GetCamFollowingValue and MC_GetCamLeadingValue (spec 07 §3.6): read the scaled and shifted cam at a
// leading value, or find the leading value of a following value near an approach value. Both complete within
// the call of the rising edge; Value (and the derivatives) hold the result while Done is shown.
#include <cstdint>

#include "tomc/instructions/execute_handshake.hpp"
#include "tomc/techobjects/cam/cam.hpp"

namespace tomc::instructions {

// A read instruction: one lookup on the rising edge, its result shown with Done.
class CamReadHandshake {
 public:
  template <typename Lookup>
  const techobjects::CamLookup& call(bool execute, Lookup&& lookup) noexcept {
    handshake_.call(
        execute,
        [&] {
          result_ = lookup();
          return result_.error_id == 0 ? techobjects::Submission::accept(1)
                                       : techobjects::Submission::reject(result_.error_id);
        },
        [](techobjects::JobId) {
          return techobjects::JobStatus{techobjects::JobState::kDone, 0, false};
        });
    if (!handshake_.outputs().Done) result_ = {};
    return result_;
  }
  const HandshakeOutputs& outputs() const noexcept { return handshake_.outputs(); }

 private:
  ExecuteHandshake handshake_;
  techobjects::CamLookup result_{};
};

// What both read instructions have: the scaling inputs (MasterScaling ≠ 0; spec 07 §3.3) and the handshake
// outputs, as plain members.
struct CamReadInstruction {
  bool Execute = false;
  double MasterOffset = 0.0;
  double SlaveOffset = 0.0;
  double MasterScaling = 1.0;
  double SlaveScaling = 1.0;
  bool Done = false;
  bool Busy = false;
  bool CommandAborted = false;  // never set
  bool Error = false;
  std::uint16_t ErrorID = 0;

 protected:
  techobjects::CamScaling scaling() const noexcept {
    return {MasterOffset, SlaveOffset, MasterScaling, SlaveScaling};
  }
  CamReadHandshake read_;
};

struct MC_GetCamFollowingValue : CamReadInstruction {
  double LeadingValue = 0.0;
  double Value = 0.0;
  double FirstDerivative = 0.0;
  double SecondDerivative = 0.0;

  void operator()(const techobjects::Cam& cam) noexcept {
    const auto& r = read_.call(Execute, [&] { return cam.get_following_value(LeadingValue, scaling()); });
    show_outputs(*this, read_.outputs());
    Value = r.value.y;
    FirstDerivative = r.value.dy;
    SecondDerivative = r.value.ddy;
  }
};

struct MC_GetCamLeadingValue : CamReadInstruction {
  double FollowingValue = 0.0;
  double ApproachLeadingValue = 0.0;
  std::int32_t ApproachDirection = 3;  // 1 positive, 2 negative, 3 nearest
  double Value = 0.0;

  void operator()(const techobjects::Cam& cam) noexcept {
    const auto& r = read_.call(Execute, [&] {
      return cam.get_leading_value(FollowingValue, ApproachLeadingValue, ApproachDirection, scaling());
    });
    show_outputs(*this, read_.outputs());
    Value = r.leading_value;
  }
};

}  // namespace tomc::instructions
