/* <tomc/tomc.h> is C11: this file is compiled with -std=c11 -Wall -Wextra -Wpedantic -Werror (TOMC_WERROR)
 * and checks, from C, the struct versioning and a call with a zeroed (not initialised) instance. */
#include <stdio.h>
#include <string.h>

#include "tomc/tomc.h"

int main(void) {
  tomc_MC_MoveAbsolute move;
  memset(&move, 0, sizeof move);
  /* Not initialised: refused with TOMC_ERROR_VERSION, the struct left alone. */
  const tomc_status s = tomc_MC_MoveAbsolute_call(NULL, &move);
  if (s != TOMC_ERROR_NULL_ARGUMENT) {
    fprintf(stderr, "null axis: %s\n", tomc_status_name(s));
    return 1;
  }
  tomc_MC_MoveAbsolute_init(&move);
  if (move.header.size != sizeof move || move.header.version != TOMC_ABI_VERSION || move.Velocity != -1.0 ||
      move.Direction != 1) {
    fprintf(stderr, "init: header %u/%u, Velocity %g, Direction %d\n", (unsigned)move.header.size,
            (unsigned)move.header.version, move.Velocity, (int)move.Direction);
    return 1;
  }
  /* MC_PositionProfile's two profile inputs (decision U15): the point structure, or a TO_Cam's handle. */
  tomc_MC_PositionProfile profile;
  tomc_MC_PositionProfile_init(&profile);
  if (profile.TimePosition != NULL || profile.TimePositionCam != NULL ||
      tomc_MC_PositionProfile_call(NULL, &profile) != TOMC_ERROR_NULL_ARGUMENT) {
    fprintf(stderr, "MC_PositionProfile: inputs not NULL after init, or a NULL axis accepted\n");
    return 1;
  }
  tomc_runner_config config = {TOMC_STRUCT_HEADER(tomc_runner_config), 0, 0, -1, false};
  if (tomc_runtime_run_realtime(NULL, &config) != TOMC_ERROR_NULL_ARGUMENT ||
      strlen(tomc_last_error()) == 0) {
    fprintf(stderr, "run_realtime(NULL): no error message\n");
    return 1;
  }
  printf("C11 header ok: %s\n", tomc_last_error());
  return 0;
}
