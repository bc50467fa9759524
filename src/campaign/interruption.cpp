// The notice on SIGINT and SIGTERM while tasks run (include/gradfric/campaign/interruption.hpp).
#include "gradfric/campaign/interruption.hpp"

#include "gradfric/core/signal_safe_write.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <ctime>

namespace gradfric::campaign {

namespace {

// Everything the handler needs, prepared beforehand: it may only read these.
struct Notice {
  bool speaks = false;  // rank 0
  volatile std::sig_atomic_t watching = 0;  // the results file exists: its done flags are counted
  char before[4608] = "";  // while the file is created or opened: the whole line
  char path[4096] = "";
  off_t offset = 0;           // of the done flags in the file
  std::uint64_t count = 0;    // P x R flags
  char middle[64] = "";       // " of 15 tasks are finished and kept in "
  char tail[4352] = "";       // "out.h5.partial; continue with ...\n"
  struct sigaction previous[2] {};
};
Notice notice;

void put(const char* text) { writeToStderrFromHandler(text); }

void putNumber(std::uint64_t value) {
  char digits[24];
  int n = 0;
  do digits[n++] = static_cast<char>('0' + value % 10);
  while ((value /= 10) > 0 && n < 23);
  char text[24];
  for (int i = 0; i < n; ++i) text[i] = digits[n - 1 - i];
  text[n] = '\0';
  put(text);
}

// The done flags that are set, read from the file; -1 if it cannot be read.
long long countDone() {
  if (notice.count == 0) return -1;
  const int fd = open(notice.path, O_RDONLY);
  if (fd < 0) return -1;
  long long done = 0;
  unsigned char buffer[4096];
  for (std::uint64_t at = 0; at < notice.count;) {
    const size_t want = notice.count - at < sizeof buffer ? static_cast<size_t>(notice.count - at) : sizeof buffer;
    const ssize_t n = pread(fd, buffer, want, notice.offset + static_cast<off_t>(at));
    if (n <= 0) {
      done = -1;
      break;
    }
    for (ssize_t i = 0; i < n; ++i) done += buffer[i] != 0;
    at += static_cast<std::uint64_t>(n);
  }
  close(fd);
  return done;
}

void onSignal(int signal) {
  if (notice.speaks) {
    put(signal == SIGINT ? "\ngradfric: interrupted (SIGINT): " : "gradfric: interrupted (SIGTERM): ");
    const long long done = notice.watching ? countDone() : -2;
    if (done == -2) {
      put(notice.before);
    } else if (done >= 0) {
      putNumber(static_cast<std::uint64_t>(done));
      put(notice.middle);
    } else {
      put("the finished tasks are kept in ");
    }
    if (done != -2) put(notice.tail);
  } else {
    // The others end a moment later: mpiexec kills the whole job at once (SIGKILL) when a rank
    // ends, which could come before rank 0 has had its own signal and said its line.
    const struct timespec moment = {0, 300000000};
    nanosleep(&moment, nullptr);
  }
  // Ended by the same signal, as without the notice (the shell and mpiexec see why).
  struct sigaction fallback {};
  fallback.sa_handler = SIG_DFL;
  sigaction(signal, &fallback, nullptr);
  raise(signal);
}

}  // namespace

namespace {

void install() {
  struct sigaction action {};
  action.sa_handler = onSignal;
  sigemptyset(&action.sa_mask);
  sigaddset(&action.sa_mask, SIGINT);  // one notice, even if both signals come
  sigaddset(&action.sa_mask, SIGTERM);
  sigaction(SIGINT, &action, &notice.previous[0]);
  sigaction(SIGTERM, &action, &notice.previous[1]);
}

}  // namespace

InterruptionNotice::InterruptionNotice(MPI_Comm comm, const std::string& path, bool resuming) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  notice.speaks = rank == 0;
  notice.watching = 0;
  if (resuming)
    std::snprintf(notice.before, sizeof notice.before,
                  "while %s was opened: its finished tasks are kept; continue with the same command and -resume\n",
                  path.c_str());
  else
    std::snprintf(notice.before, sizeof notice.before,
                  "while %s was created, before any task ran: start again with the same command and -output_overwrite\n",
                  path.c_str());
  install();
}

InterruptionNotice::InterruptionNotice(MPI_Comm comm, const io::ResultsFile& file, const std::string& path,
                                       const char* what, const std::string& resumeOption) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  notice.speaks = rank == 0;
  watch(file, path, what, resumeOption);
  install();
}

void InterruptionNotice::watch(const io::ResultsFile& file, const std::string& path, const char* what,
                               const std::string& resumeOption) {
  const auto [offset, count] = file.doneFlags();
  std::snprintf(notice.path, sizeof notice.path, "%s", path.c_str());
  notice.offset = static_cast<off_t>(offset);
  notice.count = count;
  std::snprintf(notice.middle, sizeof notice.middle, " of %llu %s are finished and kept in ",
                static_cast<unsigned long long>(count), what);
  std::snprintf(notice.tail, sizeof notice.tail, "%s; continue with the same command and %s\n", path.c_str(),
                resumeOption.c_str());
  notice.watching = 1;  // last: the handler reads the fields above only once this is set
}

InterruptionNotice::~InterruptionNotice() {
  sigaction(SIGINT, &notice.previous[0], nullptr);
  sigaction(SIGTERM, &notice.previous[1], nullptr);
}

}  // namespace gradfric::campaign
