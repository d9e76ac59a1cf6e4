/* An out-of-tree C program against the installed C ABI only (built by install_test.sh with
 * `cc -std=c11 -Wall -Wextra -Werror $(pkg-config --cflags --libs tomc)`): a positioning axis on the
 * simulated drive from a machine configuration, MC_Power, MC_Home (set position 0), MC_MoveAbsolute to 200
 * mm; exits 0 only if the move is Done at 200 mm. */
#include <math.h>
#include <stdio.h>
#include <tomc/tomc.h>

#define CHECK(call)                                                                    \
  do {                                                                                 \
    const tomc_status s_ = (call);                                                     \
    if (s_ != TOMC_OK) {                                                               \
      fprintf(stderr, "%s: %s: %s\n", #call, tomc_status_name(s_), tomc_last_error()); \
      return 1;                                                                        \
    }                                                                                  \
  } while (0)

static const char* const kMachine =
    "{\"cycle_time\": 0.001, \"technology_objects\": [{\"name\": \"Slide\", \"type\": \"TO_PositioningAxis\","
    " \"config\": {\"Mechanics.LeadScrew\": 5.0, \"LoadGear.Numerator\": 2, \"LoadGear.Denominator\": 1,"
    " \"DynamicLimits.MaxJerk\": 0.0, \"DynamicLimits.MaxVelocity\": 120.0, \"DynamicLimits.Velocity\": "
    "120.0,"
    " \"DynamicDefaults.Velocity\": 100.0, \"DynamicDefaults.Acceleration\": 1000.0,"
    " \"DynamicDefaults.Deceleration\": 1000.0},"
    " \"drive\": {\"adapter\": \"simulated\", \"telegram\": 3, \"load_inertia_kgm2\": 1.0e-4}}]}";

int main(void) {
  tomc_runtime* runtime = NULL;
  CHECK(tomc_runtime_create(kMachine, &runtime));
  tomc_object* slide = NULL;
  CHECK(tomc_runtime_find_object(runtime, "Slide", &slide));

  tomc_MC_Power power;
  tomc_MC_Home home;
  tomc_MC_MoveAbsolute move;
  tomc_MC_Power_init(&power);
  tomc_MC_Home_init(&home);
  tomc_MC_MoveAbsolute_init(&move);
  power.Enable = true;
  home.Mode = 0;
  home.Position = 0.0;
  move.Position = 200.0;

  int cycle = 0;
  for (; cycle < 6000 && !move.Done && !move.Error; ++cycle) {
    CHECK(tomc_runtime_step(runtime, 1));
    CHECK(tomc_MC_Power_call(slide, &power));
    home.Execute = power.Status;
    CHECK(tomc_MC_Home_call(slide, &home));
    move.Execute = home.Done;
    CHECK(tomc_MC_MoveAbsolute_call(slide, &move));
  }
  double position = 0.0;
  double actual = 0.0;
  CHECK(tomc_read_lreal(slide, "Position", &position));
  CHECK(tomc_read_lreal(slide, "ActualPosition", &actual));
  printf("tomc %s: cycle %d, Done %d, Error %d (16#%04X), Position %.4f mm, ActualPosition %.4f mm\n",
         tomc_version(), cycle, (int)move.Done, (int)move.Error, (unsigned)move.ErrorID, position, actual);
  tomc_runtime_destroy(runtime);
  return move.Done && fabs(position - 200.0) < 1e-6 && fabs(actual - 200.0) < 0.01 ? 0 : 1;
}
