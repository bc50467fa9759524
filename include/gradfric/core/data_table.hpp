#pragma once
// The rows of a whitespace-separated data table, such as the convergence studies docs/fem_study.tsv
// and docs/sbm_study.tsv that the error bars are computed from. Blank lines and lines starting
// with '#' are skipped. A row that does not read, or has fields left over, is an error naming the
// table, the line and its text: a skipped row would silently drop a rung from a study, and with
// it a bar or a reason. PETSc-free.
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace gradfric {

// Whether a run's setting is the value a study ran (relative 1e-9: the tables' decimal text).
inline bool sameStudiedValue(double value, double studied) {
  return std::fabs(value - studied) <= 1e-9 * std::fabs(studied);
}

// read(fields) takes one row's fields from the stream and returns whether it read them all.
template <class Read>
void forEachDataRow(const std::string& text, const std::string& table, Read read) {
  std::istringstream lines(text);
  std::string line;
  for (int number = 1; std::getline(lines, line); ++number) {
    if (line.find_first_not_of(" \t\r") == std::string::npos || line[0] == '#') continue;
    std::istringstream fields(line);
    std::string extra;
    if (!read(fields) || fields >> extra)
      throw std::invalid_argument(table + ", line " + std::to_string(number) + ": a row that does not read: \"" +
                                  line + "\"");
  }
}

}  // namespace gradfric
