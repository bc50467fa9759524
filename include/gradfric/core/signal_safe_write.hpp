#pragma once
// Text written from a signal handler: write(2) alone (async-signal-safe, no allocation, no stdio
// buffer a handler could find half-full), retried until all of it is written or it fails.
#include <unistd.h>

#include <cstring>

namespace gradfric {

inline void writeToStderrFromHandler(const char* text) {
  for (size_t left = std::strlen(text); left > 0;) {
    const ssize_t n = write(STDERR_FILENO, text, left);
    if (n <= 0) return;
    text += n;
    left -= static_cast<size_t>(n);
  }
}

}  // namespace gradfric
