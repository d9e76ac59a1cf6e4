#pragma once
// SIGINT/SIGTERM for the long-running subcommands (gateway-sim, gateway): taken by sigwait(), never by a
// handler. Block them before any DDS or cyclic thread exists, so that every thread inherits the mask and the
// process can delete its participant and release its connections cleanly.
#include <pthread.h>
#include <signal.h>

namespace tomc::cli {

inline sigset_t block_stop_signals() {
  sigset_t signals;
  sigemptyset(&signals);
  sigaddset(&signals, SIGINT);
  sigaddset(&signals, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &signals, nullptr);
  return signals;
}

// Waits for SIGINT or SIGTERM; returns its number.
inline int wait_for_stop_signal(const sigset_t& signals) {
  int signal_number = 0;
  sigwait(&signals, &signal_number);
  return signal_number;
}

}  // namespace tomc::cli
