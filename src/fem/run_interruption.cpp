// The notice and the flag on SIGINT and SIGTERM during a single FEM run
// (include/gradfric/fem/run_interruption.hpp). The handler may only write(2) text prepared
// beforehand and set a flag (async-signal-safe).
#include "gradfric/fem/run_interruption.hpp"

#include "gradfric/core/signal_safe_write.hpp"

#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <cstring>

namespace gradfric::fem {

namespace {

struct Notice {
  bool speaks = false;                  // rank 0
  bool checkpoints = false;             // a checkpoint of the current step will be written
  volatile std::sig_atomic_t signal = 0;
  char kept[4608] = "";                 // what is kept now, to the end of the line
  char path[4096] = "";
  struct sigaction previous[2] {};
};
Notice notice;

void put(const char* text) { writeToStderrFromHandler(text); }

void endBySignal(int signal) {
  struct sigaction fallback {};
  fallback.sa_handler = SIG_DFL;
  sigaction(signal, &fallback, nullptr);
  raise(signal);
}

void onSignal(int signal) {
  if (notice.signal != 0 || !notice.checkpoints) {  // a second signal, or nothing to write: end now
    if (notice.speaks && notice.signal == 0)
      put(signal == SIGINT ? "\ngradfric-fem: interrupted (SIGINT): nothing is kept (no checkpoints: "
                           : "gradfric-fem: interrupted (SIGTERM): nothing is kept (no checkpoints: ");
    if (notice.speaks && notice.signal == 0) put(notice.kept);
    endBySignal(signal);
    return;
  }
  notice.signal = signal;
  if (notice.speaks) {
    put(signal == SIGINT ? "\ngradfric-fem: interrupted (SIGINT): " : "gradfric-fem: interrupted (SIGTERM): ");
    put(notice.kept);
  }
}

void install() {
  struct sigaction action {};
  action.sa_handler = onSignal;
  sigemptyset(&action.sa_mask);
  sigaddset(&action.sa_mask, SIGINT);
  sigaddset(&action.sa_mask, SIGTERM);
  sigaction(SIGINT, &action, &notice.previous[0]);
  sigaction(SIGTERM, &action, &notice.previous[1]);
}

}  // namespace

RunInterruption::RunInterruption(MPI_Comm comm, const CheckpointSettings& settings) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  notice.speaks = rank == 0;
  notice.signal = 0;
  notice.checkpoints = !settings.path.empty();
  std::snprintf(notice.path, sizeof notice.path, "%s", settings.path.c_str());
  if (notice.checkpoints)
    std::snprintf(notice.kept, sizeof notice.kept,
                  "no checkpoint yet; writing one of this step to %s, then stopping; continue with the same "
                  "command and -resume\n",
                  notice.path);
  else
    std::snprintf(notice.kept, sizeof notice.kept, "%s)\n", settings.off.c_str());
  install();
}

void RunInterruption::kept(long step, double time, double tSliding) {
  char when[96];
  if (tSliding >= 0)
    std::snprintf(when, sizeof when, "t - t0 = %.6e s after the start of sliding", tSliding);
  else
    std::snprintf(when, sizeof when, "t = %.6e s, while pressing", time);
  char line[sizeof notice.kept];
  std::snprintf(line, sizeof line,
                "the checkpoint of step %ld (%s) is kept in %s; writing one of this step, then stopping; "
                "continue with the same command and -resume\n",
                step, when, notice.path);
  // The handler reads the line only after a signal: signals are blocked while it changes.
  sigset_t block, before;
  sigemptyset(&block);
  sigaddset(&block, SIGINT);
  sigaddset(&block, SIGTERM);
  sigprocmask(SIG_BLOCK, &block, &before);
  std::memcpy(notice.kept, line, sizeof line);
  sigprocmask(SIG_SETMASK, &before, nullptr);
}

int RunInterruption::pending() { return notice.signal; }

RunInterruption::~RunInterruption() {
  sigaction(SIGINT, &notice.previous[0], nullptr);
  sigaction(SIGTERM, &notice.previous[1], nullptr);
}

}  // namespace gradfric::fem
