#pragma once
// MC_GetCamFollowingValue and MC_GetCamLeadingValue (spec 07 §3.6): read the scaled and shifted cam at a
// leading value, or find the leading value of a following value near an approach value. Both complete within
// the call of the rising edge; Value (and the derivatives) hold the result while Done is shown.
// MC_GetCamFollowingValueCyclic reads the cam at every call while Enable holds, the result in that call.
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

// The scaling inputs of every read instruction (MasterScaling ≠ 0; spec 07 §3.3): the cam TO is not changed.
struct CamScalingInputs {
  double MasterOffset = 0.0;
  double SlaveOffset = 0.0;
  double MasterScaling = 1.0;
  double SlaveScaling = 1.0;

 protected:
  techobjects::CamScaling scaling() const noexcept {
    return {MasterOffset, SlaveOffset, MasterScaling, SlaveScaling};
  }
};

// What both Execute read instructions have: the scaling inputs and the handshake outputs, as plain members.
struct CamReadInstruction : CamScalingInputs {
  bool Execute = false;
  bool Done = false;
  bool Busy = false;
  bool CommandAborted = false;  // never set
  bool Error = false;
  std::uint16_t ErrorID = 0;

 protected:
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

// MC_GetCamFollowingValueCyclic (spec 07 §3.6; MCI8 V8): an Enable instruction that reads the cam in every
// call while Enable is TRUE, so Value is the following value of the LeadingValue given in the same
// application cycle. Busy while enabled; Valid when this call's lookup succeeded; a lookup that fails (the
// errors of MC_GetCamFollowingValue: 16#8064, 16#8023, tomc's 16#8150) shows Error/ErrorID for as long as it
// fails, Valid FALSE and the values 0, and a later valid LeadingValue clears it without a new Enable edge
// (decision C25). Nothing is kept between calls: several instances may read one cam, none changes it.
struct MC_GetCamFollowingValueCyclic : CamScalingInputs {
  bool Enable = false;
  double LeadingValue = 0.0;
  bool Valid = false;
  bool Busy = false;
  bool Error = false;
  std::uint16_t ErrorID = 0;
  double Value = 0.0;
  double FirstDerivative = 0.0;
  double SecondDerivative = 0.0;

  void operator()(const techobjects::Cam& cam) noexcept {
    const techobjects::CamLookup r =
        Enable ? cam.get_following_value(LeadingValue, scaling()) : techobjects::CamLookup{};
    Busy = Enable;
    ErrorID = r.error_id;
    Error = ErrorID != 0;
    Valid = Enable && !Error;
    Value = Valid ? r.value.y : 0.0;
    FirstDerivative = Valid ? r.value.dy : 0.0;
    SecondDerivative = Valid ? r.value.ddy : 0.0;
  }
};

}  // namespace tomc::instructions
