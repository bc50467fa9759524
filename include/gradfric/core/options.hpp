#pragma once
// Reading PETSc options with one record per option: its value, unit, help line and origin.
// The same record serves -help, validation messages, the parameter printout at start and the
// attributes of the results file. Built-in defaults never override what the user set.
#include "gradfric/core/format.hpp"

#include <mpi.h>
#include <petscsys.h>

#include <optional>
#include <string>
#include <vector>

namespace gradfric {

enum class OptionOrigin { Default, User, Derived };
// How the printout and the results files name an origin: default, set, derived.
const char* originName(OptionOrigin origin);

struct ResolvedOption {
  std::string name;  // with its leading dash, e.g. "-sbm_E"
  std::string value;
  std::string unit;
  std::string help;
  OptionOrigin origin;
  std::string fallback = "";  // the built-in default of a real option, for blaming the option a bad run comes from
  bool path = false;          // a file to read (OptionReader::path): a scene written elsewhere makes it absolute
  std::string defaultValue = "";  // the built-in default as text, of every kind ("": derived from other options)
};

// Every option a run resolved, in the order read.
class RunParameters {
public:
  void add(ResolvedOption option);
  const std::vector<ResolvedOption>& all() const { return options_; }
  const ResolvedOption* find(const std::string& name) const;
  // Rank 0 prints a table "name = value [unit]  (default|set|derived)".
  void print(MPI_Comm comm, const char* title) const;

private:
  std::vector<ResolvedOption> options_;
};

// Reads the options of one component (one prefix). Library code passes its communicator.
class OptionReader {
public:
  OptionReader(MPI_Comm comm, std::string prefix, std::string title, RunParameters* record);

  // Reals must be finite and representable (no inf, nan, 1e999 or 1e-999): refused naming the option.
  double real(const std::string& name, double fallback, const std::string& unit, const std::string& help);
  // For defaults derived from other parameters: returns the user's value if set, else nullopt;
  // the component then computes the default and calls recordDerived().
  std::optional<double> realIfSet(const std::string& name, const std::string& unit, const std::string& help,
                                  const std::string& defaultText);
  void recordDerived(const std::string& name, double value, const std::string& unit, const std::string& help);
  // Integers are read as text and refused outside [lo, hi] (no wrap-around: 4294967304 is not 8);
  // -help shows the range.
  PetscInt integer(const std::string& name, PetscInt fallback, PetscInt lo, PetscInt hi, const std::string& unit,
                   const std::string& help);
  bool flag(const std::string& name, bool fallback, const std::string& help);
  // One of `allowed`; anything else is refused with the list.
  std::string choice(const std::string& name, const std::string& fallback, const std::vector<std::string>& allowed,
                     const std::string& help);
  std::string text(const std::string& name, const std::string& fallback, const std::string& help);
  // A file to read: set in an options file, a relative path is taken from that file's folder
  // (resolveOptionPath); commaList: each comma-separated item so.
  std::string path(const std::string& name, const std::string& fallback, const std::string& help,
                   bool commaList = false);
  // Comma-separated lists: an empty item (0.1,,0.2 or a trailing comma) is refused, not dropped.
  std::vector<double> realList(const std::string& name, const std::vector<double>& fallback, const std::string& unit,
                               const std::string& help);
  std::vector<std::string> choiceList(const std::string& name, const std::vector<std::string>& fallback,
                                      const std::vector<std::string>& allowed, const std::string& help);

  bool wasSet(const std::string& name) const;
  std::string fullName(const std::string& name) const { return "-" + prefix_ + name; }
  MPI_Comm comm() const { return comm_; }

  // Validation: each throws InputError naming the option, its value and the allowed range.
  void requirePositive(const std::string& name, double value, const std::string& unit) const;
  void requireNonNegative(const std::string& name, double value, const std::string& unit) const;
  void requireRange(const std::string& name, double value, double lo, double hi, const std::string& allowedText) const;
  void requireAtLeast(const std::string& name, PetscInt value, PetscInt minimum) const;

private:
  void printHelp(const std::string& name, const std::string& current, const std::string& unit,
                 const std::string& help);
  void store(const std::string& name, const std::string& value, const std::string& unit, const std::string& help,
             bool userSet, const std::string& fallback = "", bool isPath = false, const std::string& defaultText = "");

  MPI_Comm comm_;
  std::string prefix_;
  std::string title_;
  RunParameters* record_;
  bool help_ = false;
};

// True when -help was given: drivers print the option lists, then stop before any work.
// -help <prefix> (gradfric-fem -help fem) lists only the options whose names start with it; an
// option read by several components (the -friction_ options of both models) is listed once.
bool helpRequested();
// -help's option lines are kept by section and printed together, each section once, at the end.
int helpLinesPrinted();
void printHelpSections(MPI_Comm comm);

// Every option name any OptionReader of this process has read (with its dash), for near misses.
std::vector<std::string> knownOptionNames();

// Options the user set that nothing has read so far. Refused as misspellings: those under one of
// `strictPrefixes` (the components this run uses) and near misses of a known option (within an
// edit or two: -ouput, --sbm_N) that are not PETSc's own; the rest are reported as unused.
void checkUnusedOptions(MPI_Comm comm, const std::vector<std::string>& strictPrefixes);

// An option a scene may still carry from before it was renamed: if `old` is set, throws
// InputError "invalid option <old> = <value>: <why>; use <now> = <value>" instead of running with
// a silently ignored value.
void refuseRenamedOption(const std::string& old, const std::string& now, const std::string& why);
// An option that no longer exists: if `old` is set, throws InputError "invalid option <old> =
// <value>: <why>".
void refuseRetiredOption(const std::string& old, const std::string& why);
// Options of a PETSc object's family (`family` "ts_", "tao_") set without the prefix its
// component reads them with: each refused as renamed to -<prefix><name> (`why` says whose prefix).
void refuseUnprefixedOptions(const std::string& family, const std::string& prefix, const std::string& why);

// The options every driver names one way for its results file: -output, -output_overwrite,
// -resume. The spellings of before (-fem_output, -ensemble_resume, ...) are refused with the new one.
void refuseRenamedRunControl();

}  // namespace gradfric
