#pragma once
// MC_PhasingAbsolute / MC_PhasingRelative (spec 07 §4.1) shift the leading value of a synchronous operation
// in status Synchronous (StatusSynchronizedMotion.PhaseShift); MC_OffsetAbsolute / MC_OffsetRelative (§4.2)
// its following value (.Offset). StartPhasing / StartOffset while the shift runs (not while profile 2 waits
// for StartPosition), Done when the shift is reached; AbsolutePhaseShift / AbsoluteOffset show the shift
// reached, CoveredPhaseShift / CoveredOffset the part this job covered.
#include <cstdint>

#include "tomc/instructions/execute_handshake.hpp"
#include "tomc/techobjects/synchronous/synchronous_axis.hpp"

namespace tomc::instructions {

namespace detail {

// The handshake and outputs both kinds share; `submit` posts the job.
struct ShiftOutputs {
  bool Done = false;
  bool Busy = false;
  bool CommandAborted = false;
  bool Error = false;
  std::uint16_t ErrorID = 0;

 protected:
  template <typename Slave, typename Submit>
  techobjects::ShiftJobOutputs call(Slave& slave, bool execute, Submit&& submit) noexcept {
    handshake_.call(execute, submit, [&](techobjects::JobId id) { return slave.job_status(id); });
    show_outputs(*this, handshake_.outputs());
    techobjects::ShiftJobOutputs o = slave.shift_outputs(handshake_.job());
    o.Start = o.Start && Busy;
    return o;
  }

 private:
  ExecuteHandshake handshake_;
};

template <typename Slave, bool kAbsolute>
struct Phasing : ShiftOutputs {
  const techobjects::LeadingValueSource* Master = nullptr;
  bool Execute = false;
  double PhaseShift = 0.0;
  double Velocity = -1.0;
  double Acceleration = -1.0;
  double Deceleration = -1.0;
  double Jerk = -1.0;
  std::int32_t ProfileReference = 0;
  double PhasingDistance = 0.0;
  double StartPosition = 0.0;
  std::int32_t Direction = 3;
  bool StartPhasing = false;

 protected:
  techobjects::ShiftJobOutputs run(Slave& slave) noexcept {
    const auto o = call(slave, Execute, [&] {
      return slave.phasing(
          techobjects::PhasingInputs{Master, PhaseShift, Velocity, Acceleration, Deceleration, Jerk,
                                     ProfileReference, PhasingDistance, StartPosition, Direction},
          kAbsolute);
    });
    StartPhasing = o.Start;
    return o;
  }
};

template <typename Slave, bool kAbsolute>
struct OffsetShift : ShiftOutputs {
  bool Execute = false;
  double Offset = 0.0;
  std::int32_t ProfileReference = 1;
  double OffsetDistance = 0.0;
  double StartPosition = 0.0;
  std::int32_t Direction = 3;
  bool StartOffset = false;

 protected:
  techobjects::ShiftJobOutputs run(Slave& slave) noexcept {
    const auto o = call(slave, Execute, [&] {
      return slave.offset(
          techobjects::OffsetInputs{this->Offset, ProfileReference, OffsetDistance, StartPosition, Direction},
          kAbsolute);
    });
    StartOffset = o.Start;
    return o;
  }
};

}  // namespace detail

template <typename Slave>
struct MC_PhasingAbsolute : detail::Phasing<Slave, true> {
  double AbsolutePhaseShift = 0.0;
  void operator()(Slave& slave) noexcept { AbsolutePhaseShift = this->run(slave).Absolute; }
};
template <typename Slave>
struct MC_PhasingRelative : detail::Phasing<Slave, false> {
  double CoveredPhaseShift = 0.0;
  void operator()(Slave& slave) noexcept { CoveredPhaseShift = this->run(slave).Covered; }
};
template <typename Slave>
struct MC_OffsetAbsolute : detail::OffsetShift<Slave, true> {
  double AbsoluteOffset = 0.0;
  void operator()(Slave& slave) noexcept { AbsoluteOffset = this->run(slave).Absolute; }
};
template <typename Slave>
struct MC_OffsetRelative : detail::OffsetShift<Slave, false> {
  double CoveredOffset = 0.0;
  void operator()(Slave& slave) noexcept { CoveredOffset = this->run(slave).Covered; }
};

}  // namespace tomc::instructions
