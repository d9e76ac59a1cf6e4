// The terminals of an analog or stepper actor as the page shows them (issue 20, decision W21): which actor,
// and its signals copied as the actor reports them.
#include <gtest/gtest.h>

#include "tomc/diagnostics/actor_view.hpp"
#include "tomc/drives/simulated_actor_drive.hpp"

namespace {

using namespace tomc;

TEST(ActorView, AnalogAndStepperTerminals) {
  diagnostics::ActorSnapshot none;
  diagnostics::ActorSource().read(none);
  EXPECT_EQ(none.kind, diagnostics::ActorKind::kNone);
  EXPECT_EQ(diagnostics::to_string(none.kind), "none");

  const drives::SimulatedAnalogDrive analog({}, {});
  diagnostics::ActorSnapshot a;
  diagnostics::ActorSource(analog.actor()).read(a);
  EXPECT_EQ(diagnostics::to_string(a.kind), "analog");
  EXPECT_EQ(a.output_volts, analog.actor().output_volts());
  EXPECT_EQ(a.output_code, analog.actor().output_code());
  EXPECT_DOUBLE_EQ(a.output_percent,
                   analog.actor().output_volts() / analog.actor().parameters().volts_at_reference * 100.0);
  EXPECT_EQ(a.enable_output, analog.actor().enable_output());
  EXPECT_EQ(a.ready_input, analog.actor().ready_input());
  EXPECT_EQ(a.counter, analog.actor().counter_value());
  EXPECT_EQ(a.drive_state, static_cast<std::uint8_t>(analog.actor().state()));
  EXPECT_FALSE(a.enable_output);  // not switched on: no enable (spec 01 §3.12)

  const drives::SimulatedStepperDrive stepper({}, {});
  diagnostics::ActorSnapshot s;
  diagnostics::ActorSource(stepper.actor()).read(s);
  EXPECT_EQ(diagnostics::to_string(s.kind), "stepper");
  EXPECT_EQ(s.pulse_frequency_hz, stepper.actor().pulse_frequency_hz());
  EXPECT_EQ(s.counter, stepper.actor().counter_value());
  EXPECT_EQ(s.output_volts, 0.0);  // no analog output on a stepper
}

}  // namespace
