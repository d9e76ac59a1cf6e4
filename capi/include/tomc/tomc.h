/* tomc C ABI (C11): embed the technology objects and MC_* instructions of tomc in a PLC runtime written in C
 * or in any language that calls C (docs/embedding.md).
 *
 * Rules of the interface:
 *  - Opaque handles (tomc_runtime, tomc_object); every function checks its pointers.
 *  - Every function that can fail returns a tomc_status; on failure tomc_last_error() gives a message for
 *    this thread ("technology_objects[0].config.Mechanics.LeadScrew: ..."). No C++ exception crosses it.
 *  - Structs passed in carry a tomc_struct_header (size and ABI version), set by their init function or
 *    TOMC_STRUCT_HEADER(type): a program built against another layout gets TOMC_ERROR_VERSION, not garbage.
 *  - Threads: a runtime is used by one thread at a time. Stepped with tomc_runtime_step(), that is the
 *    caller's thread; on the real-time runner (tomc_runtime_run_realtime()), instructions and variables are
 *    used from the user-program callback, which runs in the runner's thread after MC_Interpolator. Calls
 *    from other threads while the runner runs are refused with TOMC_ERROR_STATE.
 */
#ifndef TOMC_TOMC_H
#define TOMC_TOMC_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#if defined(__GNUC__)
#define TOMC_API __attribute__((visibility("default")))
#else
#define TOMC_API
#endif

#ifdef __cplusplus
extern "C" {
#endif

/* Incremented whenever a struct of this header changes its layout. */
#define TOMC_ABI_VERSION 1u

typedef enum tomc_status {
  TOMC_OK = 0,
  TOMC_ERROR_NULL_ARGUMENT = 1,     /* a handle or pointer argument is NULL */
  TOMC_ERROR_VERSION = 2,           /* a struct's header does not match this library (call its init) */
  TOMC_ERROR_CONFIG = 3,            /* the machine configuration has problems (one per line, with paths) */
  TOMC_ERROR_UNKNOWN_OBJECT = 4,    /* no technology object of that name / index */
  TOMC_ERROR_UNKNOWN_PATH = 5,      /* no data-block variable of that path on this TO */
  TOMC_ERROR_WRONG_TYPE = 6,        /* the variable's data type does not fit the typed call */
  TOMC_ERROR_OUT_OF_RANGE = 7,      /* the value is outside the variable's range or not permitted */
  TOMC_ERROR_ACCESS = 8,            /* the manual's access rules forbid it (status / read-only / restart) */
  TOMC_ERROR_WRONG_OBJECT_TYPE = 9, /* the instruction does not apply to this TO type */
  TOMC_ERROR_STATE = 10,            /* not now: e.g. stepping while the real-time runner runs */
  TOMC_ERROR_SYSTEM = 11,           /* the operating system refused (file, thread) */
  TOMC_ERROR_INTERNAL = 12          /* an unexpected failure inside the library (a bug: please report) */
} tomc_status;

/* The message of the last failed call on this thread ("" if none); valid until the next failing call on
 * this thread. */
TOMC_API const char* tomc_last_error(void);
/* "TOMC_ERROR_CONFIG", ... */
TOMC_API const char* tomc_status_name(tomc_status status);
/* The library's version, "0.1.0". */
TOMC_API const char* tomc_version(void);

typedef struct tomc_struct_header {
  uint32_t size;    /* sizeof the struct */
  uint32_t version; /* TOMC_ABI_VERSION */
} tomc_struct_header;
#define TOMC_STRUCT_HEADER(type) \
  { (uint32_t)sizeof(type), TOMC_ABI_VERSION }

/* Instance data of an instruction (the PLCopen handshake's state), owned by the library. */
typedef struct tomc_instance_data {
  uint64_t words[32];
} tomc_instance_data;

typedef struct tomc_runtime tomc_runtime;
typedef struct tomc_object tomc_object;

typedef enum tomc_object_type {
  TOMC_TO_SPEED_AXIS = 1,
  TOMC_TO_POSITIONING_AXIS = 2,
  TOMC_TO_SYNCHRONOUS_AXIS = 3,
  TOMC_TO_EXTERNAL_ENCODER = 4,
  TOMC_TO_CAM = 5
} tomc_object_type;

/* ---- the runtime ---- */

/* A runtime from a machine configuration: a JSON object with "cycle_time" (s, default 0.001) and
 * "technology_objects" as in `tomc sim` / `tomc demo --config` (docs/scenarios.md). The scenario and demo
 * sections ("cycles", "timeline", "trace", "expect", "program", "diagnostics") are ignored, so the same files
 * load. Every problem is reported, each with its JSON path, in tomc_last_error(), one per line. */
TOMC_API tomc_status tomc_runtime_create(const char* machine_json, tomc_runtime** runtime);
TOMC_API tomc_status tomc_runtime_create_from_file(const char* path, tomc_runtime** runtime);
/* Stops the real-time runner if it runs. NULL is allowed. */
TOMC_API void tomc_runtime_destroy(tomc_runtime* runtime);

/* The user program: called in every user-program cycle after MC_Interpolator, in the thread that steps the
 * runtime. Set before tomc_runtime_start(). */
typedef void (*tomc_user_program)(tomc_runtime* runtime, void* context);
TOMC_API tomc_status tomc_runtime_set_user_program(tomc_runtime* runtime, tomc_user_program program,
                                                   void* context);
/* Ends the set-up (from here on the cycle allocates nothing). tomc_runtime_step() starts implicitly. */
TOMC_API tomc_status tomc_runtime_start(tomc_runtime* runtime);
/* Runs `cycles` application cycles (MC_Servo, MC_Interpolator, user program) in the calling thread. */
TOMC_API tomc_status tomc_runtime_step(tomc_runtime* runtime, uint64_t cycles);
TOMC_API tomc_status tomc_runtime_cycle_time(const tomc_runtime* runtime, double* seconds);
TOMC_API tomc_status tomc_runtime_cycle_count(const tomc_runtime* runtime, uint64_t* cycles);

typedef struct tomc_runner_config {
  tomc_struct_header header; /* TOMC_STRUCT_HEADER(tomc_runner_config) */
  uint64_t
      period_ns; /* 0: the machine's cycle_time (another period runs it faster or slower than real time) */
  int32_t fifo_priority; /* 1..99: SCHED_FIFO at that priority; 0: normal scheduling */
  int32_t cpu;           /* >= 0: pin the runner thread to this CPU; -1: any */
  bool lock_memory;      /* mlockall and a pre-faulted stack */
} tomc_runner_config;

typedef struct tomc_runner_statistics {
  tomc_struct_header header; /* TOMC_STRUCT_HEADER(tomc_runner_statistics) */
  uint64_t cycles;
  uint64_t overruns;
  double jitter_median_us;
  double jitter_p99_us;
  double jitter_max_us;
  char warnings[256]; /* set-up that did not take effect, e.g. "SCHED_FIFO: Operation not permitted" */
} tomc_runner_statistics;

/* Runs the runtime in its own thread at the period, with absolute-time wake-ups (RealTimeRunner). Settings
 * the system refuses (priority without CAP_SYS_NICE, a CPU not allowed) are reported in the statistics'
 * warnings; the runner still runs. */
TOMC_API tomc_status tomc_runtime_run_realtime(tomc_runtime* runtime, const tomc_runner_config* config);
TOMC_API tomc_status tomc_runtime_stop_realtime(tomc_runtime* runtime);
TOMC_API tomc_status tomc_runtime_runner_statistics(const tomc_runtime* runtime,
                                                    tomc_runner_statistics* statistics);

/* ---- the user task on its own thread ----
 * A PLC task (e.g. OB1 or a cyclic interrupt at 10 ms) beside MC_Servo: `program` runs at `period_ns` in its
 * own thread, started and stopped with the real-time runner. Its instruction calls reach the TOs through
 * lock-free mailboxes (the servo thread calls the instance with the newest inputs after every
 * MC_Interpolator and posts the outputs back, which the task's next call shows); its tomc_read_* calls read
 * the data blocks of the last interpolator cycle, taken at the start of each task cycle (one consistent data
 * block per TO). The servo thread never waits for the task. Writes and alarms are not available from the
 * task yet (TOMC_ERROR_STATE). At most one task per runtime, with up to 64 instruction instances; add it
 * before the runtime starts. */
typedef struct tomc_task_config {
  tomc_struct_header header; /* TOMC_STRUCT_HEADER(tomc_task_config) */
  uint64_t period_ns;        /* 1 ms .. 1 s */
  int32_t fifo_priority;     /* 1..99: SCHED_FIFO (below the runner's); 0: normal scheduling */
  int32_t cpu;               /* >= 0: pin the task to this CPU; -1: any */
} tomc_task_config;
typedef void (*tomc_task_program)(void* context);
TOMC_API tomc_status tomc_runtime_add_task(tomc_runtime* runtime, const tomc_task_config* config,
                                           tomc_task_program program, void* context);
/* The task's period statistics (running, or of its last run). */
TOMC_API tomc_status tomc_runtime_task_statistics(const tomc_runtime* runtime,
                                                  tomc_runner_statistics* statistics);

/* ---- the diagnostics page (docs/diagnostics.md) ----
 * Serves the web page and its JSON API for every TO of the runtime (status, telegrams, alarms, axis control
 * panel with the token, traces). Call before the runtime starts; the cycle publishes the snapshots, the
 * server runs in its own threads and never blocks the cycle. */
typedef struct tomc_diagnostics_config {
  tomc_struct_header header; /* TOMC_STRUCT_HEADER(tomc_diagnostics_config) */
  const char* bind_address;  /* NULL or "": 127.0.0.1 (this machine only) */
  int32_t port;              /* 0: any free port (tomc_runtime_diagnostics_port) */
  const char* token;         /* NULL or "": a read-only page; else control actions need this token */
} tomc_diagnostics_config;
TOMC_API tomc_status tomc_runtime_serve_diagnostics(tomc_runtime* runtime,
                                                    const tomc_diagnostics_config* config);
TOMC_API tomc_status tomc_runtime_diagnostics_port(const tomc_runtime* runtime, int32_t* port);
TOMC_API tomc_status tomc_runtime_stop_diagnostics(tomc_runtime* runtime);

/* ---- technology objects ---- */

TOMC_API tomc_status tomc_runtime_object_count(const tomc_runtime* runtime, size_t* count);
TOMC_API tomc_status tomc_runtime_object_at(tomc_runtime* runtime, size_t index, tomc_object** object);
TOMC_API tomc_status tomc_runtime_find_object(tomc_runtime* runtime, const char* name, tomc_object** object);
/* The name stays valid as long as the runtime. */
TOMC_API tomc_status tomc_object_name(const tomc_object* object, const char** name);
TOMC_API tomc_status tomc_object_type_of(const tomc_object* object, tomc_object_type* type);

/* ---- data-block variables, by the manual's path ("Position", "StatusWord.X5", "DynamicDefaults.Velocity")
 * ---- Reads: any variable. tomc_read_lreal takes LREAL variables, tomc_read_bool BOOL variables and bits of
 * status words ("StatusWord.X5"), tomc_read_int the integer and bit-string types. Writes follow the manual's
 * access rules for the user program (spec 04 §0.2): DIR and CAL variables only; status, read-only (RON) and
 * restart-relevant (RES) variables give TOMC_ERROR_ACCESS. A synchronous axis' StatusSynchronizedMotion.*
 * ("StatusSynchronizedMotion.PhaseShift", ".FunctionState", ".StatusWord.X3") is read the same way, from the
 * runtime's thread; a user task (tomc_task_*) gets TOMC_ERROR_STATE for it (not in its snapshot). */
TOMC_API tomc_status tomc_read_lreal(const tomc_object* object, const char* path, double* value);
TOMC_API tomc_status tomc_read_bool(const tomc_object* object, const char* path, bool* value);
TOMC_API tomc_status tomc_read_int(const tomc_object* object, const char* path, int64_t* value);
TOMC_API tomc_status tomc_write_lreal(tomc_object* object, const char* path, double value);
TOMC_API tomc_status tomc_write_bool(tomc_object* object, const char* path, bool value);
TOMC_API tomc_status tomc_write_int(tomc_object* object, const char* path, int64_t value);

/* ---- technology alarms ---- */

typedef struct tomc_alarm {
  tomc_struct_header header; /* TOMC_STRUCT_HEADER(tomc_alarm) */
  uint32_t number;           /* the manual's alarm number, e.g. 533 */
  uint32_t additional_value;
  uint32_t alarm_class; /* 0 warning (W), 1 acknowledge (F), 2 restart (R): spec 01 §7 */
  uint32_t reaction;    /* 0 none, 1 stop with current dynamics, 2 max dynamics, 3 emergency, 4 remove enable,
                           5 follow setpoint */
  uint64_t raised_cycle;
} tomc_alarm;

/* The pending technology alarms of a TO. */
TOMC_API tomc_status tomc_object_alarm_count(const tomc_object* object, size_t* count);
TOMC_API tomc_status tomc_object_alarm(const tomc_object* object, size_t index, tomc_alarm* alarm);

#ifdef __cplusplus
}
#endif

#include "tomc/tomc_instructions.h"

#endif /* TOMC_TOMC_H */
