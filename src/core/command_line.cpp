#include "gradfric/core/command_line.hpp"

#include <cctype>
#include <cstring>
#include <deque>

namespace gradfric {

namespace {

// The rewritten arguments must outlive PETSc's use of argv: keep them for the whole process.
char* keep(const std::string& text) {
  static std::deque<std::string> storage;
  storage.push_back(text);
  return storage.back().data();
}

bool isLongOption(const char* arg) {
  return arg[0] == '-' && arg[1] == '-' && (std::isalpha(static_cast<unsigned char>(arg[2])) || arg[2] == '_');
}

}  // namespace

void normaliseArguments(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "-h") == 0 || std::strcmp(argv[i], "--help") == 0)
      argv[i] = keep("-help");
    else if (isLongOption(argv[i]))
      argv[i] = keep(argv[i] + 1);  // --sbm_N -> -sbm_N
  }
}

bool versionRequested(int argc, char** argv) {
  for (int i = 1; i < argc; ++i)
    if (std::strcmp(argv[i], "-version") == 0 || std::strcmp(argv[i], "--version") == 0) return true;
  return false;
}

}  // namespace gradfric
