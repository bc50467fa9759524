#pragma once
// Numbers in messages and option records: 10 significant digits, no PETSc.
#include <cmath>
#include <cstdio>
#include <string>

namespace gradfric {

inline std::string formatReal(double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.10g", value);
  return buffer;
}

// One number with a printf format ("%.6f", "%+.3g"): the pieces of a message.
inline std::string formatNumber(const char* format, double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, format, value);
  return buffer;
}

// h:mm:ss, "?" for a negative or infinite time (progress lines).
inline std::string hms(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0) return "?";
  const long s = static_cast<long>(seconds + 0.5);
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%ld:%02ld:%02ld", s / 3600, (s / 60) % 60, s % 60);
  return buffer;
}

}  // namespace gradfric
