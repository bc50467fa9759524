#pragma once
// What the drivers do with the command line before PETSc reads it (PETSc would abort with a
// banner and a traceback, or crash, on a bad options file, silently ignore --name and stray
// words, and read the paths inside an options file from the working directory).
#include <map>
#include <string>
#include <vector>

namespace gradfric {

// In place: --name becomes -name (GNU style is accepted, not ignored), -h and --help become -help.
void normaliseArguments(int argc, char** argv);

// -version (or --version before normalising) anywhere on the command line.
bool versionRequested(int argc, char** argv);

// The command line PETSc reads, settled on every rank alike before PetscInitialize:
//  - every -options_file (on the command line and, recursively, inside options files) is checked
//    (a readable regular file, text: no NUL byte, UTF-8; its lines start with an option; no file
//    including itself) and expanded in place, a relative path inside a file taken from that
//    file's folder; -options_file_yaml files are checked (YAML mapping) and left to PETSc;
//  - a word that is neither an option nor the one value after it (-ensemble_delta 0 0.2) is
//    refused: PETSc would ignore it;
//  - -help <prefix> keeps the prefix for OptionReader and gives PETSc a plain -help;
//  - the words PETSc reads from the environment's PETSC_OPTIONS and from the petscrc files
//    (~/.petscrc, .petscrc, petscrc, unless -skip_petscrc) get the same checks, their source named.
struct SettledCommandLine {
  std::vector<std::string> arguments;  // argv[0], then the options and values PETSc reads
  std::string problem;                 // the first problem as one line, "" when none
  std::string helpFilter;              // -help <prefix>: the prefix without its dash
  // lower-case option name (PETSc's names ignore case) -> folder of the options file that set it
  // last ("" when the command line did)
  std::map<std::string, std::string> folders;
};
SettledCommandLine settleCommandLine(int argc, char** argv);

// Keeps what settleCommandLine learnt for the rest of the run (the functions below).
void adoptCommandLine(const SettledCommandLine& settled, int argc, char** argv);

// The options-file part of settleCommandLine alone: its first problem, or "" (kept for the
// checks of options files that need no expansion).
std::string checkOptionFiles(int argc, char** argv);

// After adoptCommandLine:
// the arguments as the user gave them (after normaliseArguments), for the results' provenance;
const std::vector<std::string>& originalArguments();
// -help <prefix>: the prefix without its dash ("" without one);
const std::string& helpFilter();
// a path option's value resolved as the user meant it: relative to the folder of the options
// file that set it last; a value from the command line (or absolute, or empty) unchanged.
std::string resolveOptionPath(const std::string& fullName, const std::string& value);

}  // namespace gradfric
