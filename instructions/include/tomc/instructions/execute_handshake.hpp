#pragma once
// The PLCopen handshake of Execute-edge instructions, cycle by cycle as spec 03 §3.2 (E1..E8) and §3.7 state
// it: a job starts on a rising edge of Execute; Busy from acceptance; exactly one of Done / CommandAborted /
// Error at the end; a final flag stays while Execute stays TRUE and is shown for exactly one call otherwise;
// a rejected job shows Error (with ErrorID) from the edge call on.

#include <cstdint>

#include "tomc/techobjects/axis/job.hpp"

namespace tomc::instructions {

struct HandshakeOutputs {
  bool Done = false;
  bool Busy = false;
  bool Active = false;
  bool CommandAborted = false;
  bool Error = false;
  std::uint16_t ErrorID = 0;
};

class ExecuteHandshake {
 public:
  // One call of the instruction. `submit()` is called on a rising edge and returns a techobjects::Submission;
  // `status(JobId)` returns the techobjects::JobStatus of the running job. Both are plain callables.
  template <typename Submit, typename Status>
  void call(bool execute, Submit&& submit, Status&& status) noexcept {
    const bool edge = execute && !last_execute_;
    last_execute_ = execute;
    // E5: a final flag is cleared by the first call that sees Execute = FALSE after the completion call.
    if (phase_ == Phase::kFinal && !execute) reset();
    if (edge) {
      // E6: a new edge starts a new job even while Busy; the outputs now describe the new job.
      const techobjects::Submission s = submit();
      reset();
      if (s.accepted()) {
        job_ = s.id;
        phase_ = Phase::kBusy;
      } else {
        finish_error(s.error_id);  // E2/E7: rejected in the edge call
        return;
      }
    }
    if (phase_ == Phase::kBusy) observe(status(job_));
  }

  const HandshakeOutputs& outputs() const noexcept { return out_; }
  techobjects::JobId job() const noexcept { return job_; }
  bool busy() const noexcept { return phase_ == Phase::kBusy; }
  const techobjects::JobStatus& last_status() const noexcept { return last_status_; }

 private:
  enum class Phase : std::uint8_t { kIdle, kBusy, kFinal };

  void reset() noexcept {
    out_ = HandshakeOutputs{};
    phase_ = Phase::kIdle;
    last_status_ = {};
  }
  void finish_error(std::uint16_t error_id) noexcept {
    out_ = HandshakeOutputs{};
    out_.Error = true;
    out_.ErrorID = error_id;
    phase_ = Phase::kFinal;
  }
  void observe(const techobjects::JobStatus& s) noexcept {
    last_status_ = s;
    switch (s.state) {
      case techobjects::JobState::kPending:
        out_.Busy = true;
        out_.Active = false;
        break;
      case techobjects::JobState::kActive:
        out_.Busy = true;
        out_.Active = true;
        break;
      case techobjects::JobState::kDone:
        out_ = HandshakeOutputs{};
        out_.Done = true;
        phase_ = Phase::kFinal;
        break;
      case techobjects::JobState::kAborted:
        out_ = HandshakeOutputs{};
        out_.CommandAborted = true;
        phase_ = Phase::kFinal;
        break;
      case techobjects::JobState::kError:
        finish_error(s.error_id);
        break;
      case techobjects::JobState::kUnknown:
        // The TO no longer knows the job (restart): report it as aborted rather than hang Busy forever.
        out_ = HandshakeOutputs{};
        out_.CommandAborted = true;
        phase_ = Phase::kFinal;
        break;
    }
  }

  HandshakeOutputs out_{};
  techobjects::JobStatus last_status_{};
  techobjects::JobId job_ = 0;
  Phase phase_ = Phase::kIdle;
  bool last_execute_ = false;
};

// Copies the handshake's outputs into an instruction's output members of the same names (Done, Busy,
// CommandAborted, Error, ErrorID): the outputs stay plain members of each instruction, as in the manual.
template <typename Instruction>
void show_outputs(Instruction& fb, const HandshakeOutputs& o) noexcept {
  fb.Done = o.Done;
  fb.Busy = o.Busy;
  fb.CommandAborted = o.CommandAborted;
  fb.Error = o.Error;
  fb.ErrorID = o.ErrorID;
}

// The outputs of a synchronization instruction without Done (MC_GearInPos, MC_CamIn; spec 07 §2.2, §3.4).
struct SyncInOutputs {
  bool StartSync = false;
  bool InSync = false;
  bool Busy = false;
  bool CommandAborted = false;
  bool Error = false;
  std::uint16_t ErrorID = 0;
};

// Sets them from the handshake and the job's synchronous outputs `s`.
template <typename Instruction, typename SyncOutputs>
void show_sync_in_outputs(Instruction& fb, const HandshakeOutputs& o, const SyncOutputs& s) noexcept {
  fb.Busy = o.Busy;
  fb.CommandAborted = o.CommandAborted;
  fb.Error = o.Error;
  fb.ErrorID = o.ErrorID;
  fb.StartSync = fb.Busy && s.StartSync && !s.InSync;
  fb.InSync = fb.Busy && s.InSync;
}

}  // namespace tomc::instructions
