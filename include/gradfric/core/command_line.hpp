#pragma once
// What the drivers do with the command line before PETSc reads it (PETSc would abort with a
// banner and a traceback, or crash, on a bad options file, and silently ignore --name).
#include <string>

namespace gradfric {

// In place: --name becomes -name (GNU style is accepted, not ignored), -h and --help become -help.
void normaliseArguments(int argc, char** argv);

// -version (or --version before normalising) anywhere on the command line.
bool versionRequested(int argc, char** argv);

// Checks every -options_file / -options_file_yaml of the command line and, recursively, every
// -options_file named inside those files: a readable regular file, text (no NUL byte, UTF-8),
// parseable (an options file's lines start with an option; YAML parses to a mapping), no file
// including itself directly or through others. Returns the first problem as one line
// ("invalid option -options_file = X: ..."), or an empty string when every file is fine.
// Deterministic: every rank checking the same files reaches the same answer.
std::string checkOptionFiles(int argc, char** argv);

}  // namespace gradfric
