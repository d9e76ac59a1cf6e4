/* A minimal PLC runtime in C on the C ABI <tomc/tomc.h> (docs/embedding.md):
 *   c_runtime [machine.json] [seconds] [port]
 * loads a machine configuration, runs MC_Servo/MC_Interpolator at the machine's cycle (1 ms) on the real-time
 * runner, and runs the user logic every 10th cycle (a 10 ms task) in the runner's user-program slot:
 * MC_Power, MC_Home (set position 0), then MC_MoveAbsolute between 0 and 100 mm on the first positioning
 * axis. Prints the moves and the runner's statistics; exits 0 if at least one move was Done and no
 * instruction failed.
 *
 * The user logic runs in the runner's thread after MC_Interpolator (the one thread that may use the TOs while
 * the runner runs); a user task on its own thread is not part of the ABI yet (docs/embedding.md). */
#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>
#include <tomc/tomc.h>

typedef struct UserProgram {
  tomc_object* axis;
  tomc_MC_Power power;
  tomc_MC_Home home;
  tomc_MC_MoveAbsolute move;
  double targets[2];
  int next_target;
  int moves_done; /* read by main() after the task stopped */
  int failures;
  tomc_status failure;
} UserProgram;

/* The user task: every 10 ms in its own thread. */
static void user_task(void* context) {
  UserProgram* p = context;
  tomc_status s = tomc_MC_Power_call(p->axis, &p->power);
  p->home.Execute = p->power.Status;
  if (s == TOMC_OK) s = tomc_MC_Home_call(p->axis, &p->home);
  /* The outputs a call shows are those of the servo thread's call with the inputs of the previous task
   * cycle: wait for Done to fall before the next move's rising edge, as with any asynchronous instruction. */
  if (p->move.Execute) {
    if (p->move.Done) {
      ++p->moves_done;
      p->next_target = 1 - p->next_target;
      p->move.Execute = false;
    }
  } else if (p->home.Done && !p->move.Done && !p->move.Busy) {
    p->move.Position = p->targets[p->next_target];
    p->move.Execute = true;
  }
  if (s == TOMC_OK) s = tomc_MC_MoveAbsolute_call(p->axis, &p->move);
  if (s != TOMC_OK) {
    ++p->failures;
    p->failure = s;
  }
}

static volatile sig_atomic_t g_stop = 0;
static void on_signal(int signal_number) {
  (void)signal_number;
  g_stop = 1;
}

int main(int argc, char** argv) {
  const char* machine = argc > 1 ? argv[1] : "examples/c_runtime/machine.json";
  const double seconds = argc > 2 ? atof(argv[2]) : 5.0;
  const int port = argc > 3 ? atoi(argv[3]) : 0;

  tomc_runtime* runtime = NULL;
  if (tomc_runtime_create_from_file(machine, &runtime) != TOMC_OK) {
    fprintf(stderr, "%s\n", tomc_last_error());
    return 2;
  }
  /* The first positioning axis of the machine. */
  UserProgram program = {0};
  size_t count = 0;
  tomc_runtime_object_count(runtime, &count);
  for (size_t i = 0; i < count && program.axis == NULL; ++i) {
    tomc_object* object = NULL;
    tomc_object_type type;
    if (tomc_runtime_object_at(runtime, i, &object) == TOMC_OK &&
        tomc_object_type_of(object, &type) == TOMC_OK && type == TOMC_TO_POSITIONING_AXIS)
      program.axis = object;
  }
  if (program.axis == NULL) {
    fprintf(stderr, "%s: no TO_PositioningAxis\n", machine);
    tomc_runtime_destroy(runtime);
    return 2;
  }
  tomc_MC_Power_init(&program.power);
  tomc_MC_Home_init(&program.home);
  tomc_MC_MoveAbsolute_init(&program.move);
  program.power.Enable = true;
  program.targets[0] = 100.0;
  program.targets[1] = 0.0;
  const tomc_task_config task = {TOMC_STRUCT_HEADER(tomc_task_config), 10 * 1000 * 1000, 0, -1};
  if (tomc_runtime_add_task(runtime, &task, user_task, &program) != TOMC_OK) {
    fprintf(stderr, "%s\n", tomc_last_error());
    tomc_runtime_destroy(runtime);
    return 1;
  }

  const tomc_diagnostics_config page = {TOMC_STRUCT_HEADER(tomc_diagnostics_config), "127.0.0.1", port, NULL};
  int32_t served_port = 0;
  if (tomc_runtime_serve_diagnostics(runtime, &page) != TOMC_OK ||
      tomc_runtime_diagnostics_port(runtime, &served_port) != TOMC_OK) {
    fprintf(stderr, "%s\n", tomc_last_error());
    tomc_runtime_destroy(runtime);
    return 1;
  }
  printf("diagnostics page (read-only) at http://127.0.0.1:%d/\n", (int)served_port);
  fflush(stdout);

  /* SCHED_FIFO 80 on CPU 1 if allowed (CAP_SYS_NICE, PREEMPT_RT: docs/embedding.md); refused settings are
   * reported as warnings and the runner runs with normal scheduling. */
  tomc_runner_config config = {TOMC_STRUCT_HEADER(tomc_runner_config), 0, 80, 1, false};
  if (tomc_runtime_run_realtime(runtime, &config) != TOMC_OK) {
    fprintf(stderr, "%s\n", tomc_last_error());
    tomc_runtime_destroy(runtime);
    return 1;
  }
  signal(SIGINT, on_signal);
  signal(SIGTERM, on_signal);
  const struct timespec tick = {0, 100 * 1000 * 1000};
  for (double t = 0.0; t < seconds && !g_stop; t += 0.1)
    nanosleep(&tick, NULL);
  tomc_runtime_stop_realtime(runtime);

  tomc_runner_statistics statistics = {TOMC_STRUCT_HEADER(tomc_runner_statistics), 0, 0, 0.0, 0.0, 0.0, ""};
  tomc_runner_statistics task_statistics = statistics;
  tomc_runtime_runner_statistics(runtime, &statistics);
  tomc_runtime_task_statistics(runtime, &task_statistics);
  double position = NAN;
  tomc_read_lreal(program.axis, "Position", &position);
  const char* name = "";
  tomc_object_name(program.axis, &name);
  const tomc_runner_statistics* both[2] = {&statistics, &task_statistics};
  for (int i = 0; i < 2; ++i) {
    const tomc_runner_statistics* s = both[i];
    printf("%s: cycles %llu, overruns %llu, wake-up jitter median %.0f us, p99 %.0f us, max %.0f us%s%s\n",
           i == 0 ? "MC_Servo  (1 ms) " : "user task (10 ms)", (unsigned long long)s->cycles,
           (unsigned long long)s->overruns, s->jitter_median_us, s->jitter_p99_us, s->jitter_max_us,
           s->warnings[0] != '\0' ? "; " : "", s->warnings);
  }
  printf("%s: %d moves done, Position %.3f mm, instruction failures %d%s%s\n", name, program.moves_done,
         position, program.failures, program.failures > 0 ? ": " : "",
         program.failures > 0 ? tomc_status_name(program.failure) : "");
  tomc_runtime_destroy(runtime);
  return program.moves_done > 0 && program.failures == 0 ? 0 : 1;
}
