#include "gradfric/core/options.hpp"

#include "gradfric/core/command_line.hpp"
#include "gradfric/core/input_error.hpp"
#include "gradfric/core/near_miss.hpp"
#include "gradfric/core/petsc_call.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cfloat>
#include <map>
#include <set>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <utility>

namespace gradfric {

namespace {

std::string joined(const std::vector<std::string>& items, const char* separator) {
  std::string out;
  for (size_t i = 0; i < items.size(); ++i) out += (i ? separator : "") + items[i];
  return out;
}

std::string joinedReals(const std::vector<double>& values) {
  std::vector<std::string> items;
  for (double v : values) items.push_back(formatReal(v));
  return joined(items, ",");
}

// The items of a comma-separated list; an empty one (0.1,,0.2, a trailing comma) is refused
// instead of dropped, since it usually stands for a value that went missing.
std::vector<std::string> splitList(const std::string& option, const std::string& text, const std::string& allowed) {
  std::vector<std::string> items;
  if (text.find_first_not_of(" \t") == std::string::npos) return items;  // no value: the empty list
  size_t start = 0;
  while (true) {
    const size_t comma = text.find(',', start);
    std::string item = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    item.erase(0, item.find_first_not_of(" \t"));
    item.erase(item.find_last_not_of(" \t") + 1);
    if (item.empty())
      throw InputError(option, text, allowed + " (item " + std::to_string(items.size() + 1) + " is empty)");
    items.push_back(item);
    if (comma == std::string::npos) return items;
    start = comma + 1;
  }
}

// -help's lines by section, in the order the sections were first met: printed at the end, each
// section once even when its readers were interleaved with others' (the SBM's parameters and
// its request, the results file's options and the FEM sweep's).
struct HelpText {
  std::vector<std::string> sections;
  std::map<std::string, std::vector<std::string>> lines;
  std::set<std::string> listed;  // an option read twice (both models' -friction_ ones) is listed once
};

HelpText& helpText() {
  static HelpText text;
  return text;
}

// GRADFRIC_HELP_FORMAT=tsv: -help prints one line per option, section<TAB>name<TAB>default<TAB>
// unit<TAB>help, and no section headings (scripts/options_reference.sh makes docs/options.md of it).
bool helpAsTsv() {
  const char* format = std::getenv("GRADFRIC_HELP_FORMAT");
  return format && std::string(format) == "tsv";
}

std::string tsvField(std::string text) {
  std::replace_if(text.begin(), text.end(), [](char c) { return c == '\t' || c == '\n' || c == '\r'; }, ' ');
  return text;
}

std::set<std::string>& knownNames() {
  static std::set<std::string> names;
  return names;
}

// strtod with every way of going wrong refused: junk, inf, nan, overflow, and a non-zero value
// below the smallest normal double (1e-320 would silently lose its digits).
bool parseFiniteReal(const std::string& text, double* value) {
  char* end = nullptr;
  errno = 0;
  *value = std::strtod(text.c_str(), &end);
  if (end == text.c_str() || *end != '\0' || errno == ERANGE) return false;
  return std::isfinite(*value);
}

const char* kRealAllowed = "a finite real number (|x| <= 1.8e308; 0 or |x| >= 2.3e-308)";

}  // namespace

const char* originName(OptionOrigin origin) {
  switch (origin) {
    case OptionOrigin::User: return "set";
    case OptionOrigin::Derived: return "derived";
    default: return "default";
  }
}

std::vector<std::string> knownOptionNames() { return {knownNames().begin(), knownNames().end()}; }

void RunParameters::add(ResolvedOption option) {
  for (auto& existing : options_)
    if (existing.name == option.name) {
      existing = std::move(option);
      return;
    }
  options_.push_back(std::move(option));
}

const ResolvedOption* RunParameters::find(const std::string& name) const {
  for (const auto& option : options_)
    if (option.name == name) return &option;
  return nullptr;
}

void RunParameters::print(MPI_Comm comm, const char* title) const {
  size_t width = 0;
  for (const auto& o : options_) width = std::max(width, o.name.size());
  GF_CALL(PetscPrintf(comm, "%s\n", title));
  for (const auto& o : options_) {
    std::string unit = o.unit.empty() ? "" : " [" + o.unit + "]";
    GF_CALL(PetscPrintf(comm, "  %-*s = %s%s  (%s)\n", static_cast<int>(width), o.name.c_str(), o.value.c_str(),
                        unit.c_str(), originName(o.origin)));
  }
}

OptionReader::OptionReader(MPI_Comm comm, std::string prefix, std::string title, RunParameters* record)
    : comm_(comm), prefix_(std::move(prefix)), title_(std::move(title)), record_(record), help_(helpRequested()) {}

bool helpRequested() {
  PetscBool help = PETSC_FALSE;
  PetscOptionsHasHelp(nullptr, &help);
  return help;
}

int helpLinesPrinted() { return static_cast<int>(helpText().listed.size()); }

void printHelpSections(MPI_Comm comm) {
  HelpText& text = helpText();
  for (const auto& section : text.sections) {
    if (!helpAsTsv()) GF_CALL(PetscPrintf(comm, "%s:\n", section.c_str()));
    for (const auto& line : text.lines[section]) GF_CALL(PetscPrintf(comm, "%s\n", line.c_str()));
  }
  text.sections.clear();
  text.lines.clear();
}

void OptionReader::printHelp(const std::string& name, const std::string& current, const std::string& unit,
                             const std::string& help) {
  if (!help_) return;
  HelpText& text = helpText();
  const std::string option = fullName(name);
  if (option.compare(1, helpFilter().size(), helpFilter()) != 0 || !text.listed.insert(option).second) return;
  const std::string section = prefix_.empty() ? title_ : title_ + " (-" + prefix_ + ")";
  if (!text.lines.count(section)) text.sections.push_back(section);
  if (helpAsTsv()) {
    text.lines[section].push_back(tsvField(section) + "\t" + option + "\t" + tsvField(current) + "\t" + tsvField(unit) +
                                  "\t" + tsvField(help));
    return;
  }
  std::string unitText = unit.empty() ? "" : " [" + unit + "]";
  text.lines[section].push_back("  " + option + " <" + current + ">" + unitText + ": " + help);
}

void OptionReader::store(const std::string& name, const std::string& value, const std::string& unit,
                         const std::string& help, bool userSet, const std::string& fallback, bool isPath,
                         const std::string& defaultText) {
  knownNames().insert(fullName(name));
  if (record_)
    record_->add({fullName(name), value, unit, help, userSet ? OptionOrigin::User : OptionOrigin::Default, fallback,
                  isPath, defaultText.empty() ? fallback : defaultText});
}

bool OptionReader::wasSet(const std::string& name) const {
  PetscBool set = PETSC_FALSE;
  GF_CALL(PetscOptionsHasName(nullptr, prefix_.c_str(), ("-" + name).c_str(), &set));
  return set;
}

double OptionReader::real(const std::string& name, double fallback, const std::string& unit, const std::string& help) {
  PetscReal value = fallback;
  PetscBool set = PETSC_FALSE;
  const std::string option = "-" + name;
  // Read as text first so that a malformed number is reported by us, with the option's name.
  char raw[256] = "";
  GF_CALL(PetscOptionsGetString(nullptr, prefix_.c_str(), option.c_str(), raw, sizeof raw, &set));
  if (set && !parseFiniteReal(raw, &value))
    throw InputError(fullName(name), raw, std::string(kRealAllowed) + (unit.empty() ? "" : " [" + unit + "]"));
  printHelp(name, formatReal(value), unit, help);
  store(name, formatReal(value), unit, help, set, formatReal(fallback));
  return value;
}

std::optional<double> OptionReader::realIfSet(const std::string& name, const std::string& unit,
                                              const std::string& help, const std::string& defaultText) {
  if (!wasSet(name)) {
    knownNames().insert(fullName(name));
    printHelp(name, defaultText, unit, help);
    return std::nullopt;
  }
  return real(name, 0.0, unit, help);
}

void OptionReader::recordDerived(const std::string& name, double value, const std::string& unit,
                                 const std::string& help) {
  if (record_) record_->add({fullName(name), formatReal(value), unit, help, OptionOrigin::Derived});
}

PetscInt OptionReader::integer(const std::string& name, PetscInt fallback, PetscInt lo, PetscInt hi,
                               const std::string& unit, const std::string& help) {
  PetscInt value = fallback;
  PetscBool set = PETSC_FALSE;
  char raw[256] = "";
  GF_CALL(PetscOptionsGetString(nullptr, prefix_.c_str(), ("-" + name).c_str(), raw, sizeof raw, &set));
  const std::string range = std::to_string(lo) + " <= " + name + " <= " + std::to_string(hi);
  if (set) {
    char* end = nullptr;
    errno = 0;
    const long long parsed = std::strtoll(raw, &end, 10);
    if (end == raw || *end != '\0') throw InputError(fullName(name), raw, "an integer, " + range);
    if (errno == ERANGE || parsed < lo || parsed > hi) throw InputError(fullName(name), raw, range);
    value = static_cast<PetscInt>(parsed);
  }
  printHelp(name, std::to_string(value), unit, help + " (" + range + ")");
  store(name, std::to_string(value), unit, help, set, "", false, std::to_string(fallback));
  return value;
}

bool OptionReader::flag(const std::string& name, bool fallback, const std::string& help) {
  PetscBool value = fallback ? PETSC_TRUE : PETSC_FALSE;
  PetscBool set = PETSC_FALSE;
  char raw[64] = "";
  GF_CALL(PetscOptionsGetString(nullptr, prefix_.c_str(), ("-" + name).c_str(), raw, sizeof raw, &set));
  if (set) {
    std::string text = raw;
    if (text.empty() || text == "1" || text == "true" || text == "yes" || text == "on") value = PETSC_TRUE;
    else if (text == "0" || text == "false" || text == "no" || text == "off") value = PETSC_FALSE;
    else throw InputError(fullName(name), text, "true or false");
  }
  printHelp(name, value ? "true" : "false", "", help);
  store(name, value ? "true" : "false", "", help, set, "", false, fallback ? "true" : "false");
  return value;
}

std::string OptionReader::choice(const std::string& name, const std::string& fallback,
                                 const std::vector<std::string>& allowed, const std::string& help) {
  std::string value = text(name, fallback, help + " (" + joined(allowed, ", ") + ")");
  if (std::find(allowed.begin(), allowed.end(), value) == allowed.end())
    throw InputError(fullName(name), value, "one of: " + joined(allowed, ", "));
  return value;
}

std::string OptionReader::text(const std::string& name, const std::string& fallback, const std::string& help) {
  char raw[PETSC_MAX_PATH_LEN] = "";
  PetscBool set = PETSC_FALSE;
  GF_CALL(PetscOptionsGetString(nullptr, prefix_.c_str(), ("-" + name).c_str(), raw, sizeof raw, &set));
  std::string value = set ? std::string(raw) : fallback;
  printHelp(name, value, "", help);
  store(name, value, "", help, set, "", false, fallback);
  return value;
}

std::string OptionReader::path(const std::string& name, const std::string& fallback, const std::string& help,
                               bool commaList) {
  char raw[PETSC_MAX_PATH_LEN] = "";
  PetscBool set = PETSC_FALSE;
  GF_CALL(PetscOptionsGetString(nullptr, prefix_.c_str(), ("-" + name).c_str(), raw, sizeof raw, &set));
  std::string value = set ? std::string(raw) : fallback;
  if (set) {  // each item of a list (an empty one is left for the reader to refuse by its rule)
    std::string resolved;
    size_t start = 0;
    for (size_t comma = 0; comma != std::string::npos; start = comma + 1) {
      comma = commaList ? value.find(',', start) : std::string::npos;
      const std::string item = value.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
      resolved += (start ? "," : "") + (item.empty() ? item : resolveOptionPath(fullName(name), item));
    }
    value = resolved;
  }
  printHelp(name, value, "", help);
  store(name, value, "", help, set, "", true);
  return value;
}

std::vector<double> OptionReader::realList(const std::string& name, const std::vector<double>& fallback,
                                           const std::string& unit, const std::string& help) {
  char raw[4096] = "";
  PetscBool set = PETSC_FALSE;
  GF_CALL(PetscOptionsGetString(nullptr, prefix_.c_str(), ("-" + name).c_str(), raw, sizeof raw, &set));
  std::vector<double> values = fallback;
  if (set) {
    values.clear();
    const std::string allowed = "a comma-separated list of finite real numbers [" + unit + "]";
    for (const auto& item : splitList(fullName(name), raw, allowed)) {
      double v = 0;
      if (!parseFiniteReal(item, &v))
        throw InputError(fullName(name), raw,
                         "a comma-separated list of finite real numbers [" + unit + "] (" + item + " is not one)");
      values.push_back(v);
    }
  }
  printHelp(name, joinedReals(values), unit, help + " (comma-separated)");
  store(name, joinedReals(values), unit, help, set, "", false, joinedReals(fallback));
  return values;
}

std::vector<std::string> OptionReader::choiceList(const std::string& name, const std::vector<std::string>& fallback,
                                                  const std::vector<std::string>& allowed, const std::string& help) {
  char raw[4096] = "";
  PetscBool set = PETSC_FALSE;
  GF_CALL(PetscOptionsGetString(nullptr, prefix_.c_str(), ("-" + name).c_str(), raw, sizeof raw, &set));
  std::vector<std::string> values =
      set ? splitList(fullName(name), raw, "a comma-separated list of: " + joined(allowed, ", ")) : fallback;
  for (const auto& v : values)
    if (std::find(allowed.begin(), allowed.end(), v) == allowed.end())
      throw InputError(fullName(name), v, "a comma-separated list of: " + joined(allowed, ", "));
  printHelp(name, joined(values, ","), "", help + " (comma-separated from " + joined(allowed, ", ") + ")");
  store(name, joined(values, ","), "", help, set, "", false, joined(fallback, ","));
  return values;
}

void OptionReader::requirePositive(const std::string& name, double value, const std::string& unit) const {
  if (!(value > 0)) throw InputError(fullName(name), formatReal(value), "> 0" + (unit.empty() ? "" : " [" + unit + "]"));
}

void OptionReader::requireNonNegative(const std::string& name, double value, const std::string& unit) const {
  if (!(value >= 0))
    throw InputError(fullName(name), formatReal(value), ">= 0" + (unit.empty() ? "" : " [" + unit + "]"));
}

void OptionReader::requireRange(const std::string& name, double value, double lo, double hi,
                                const std::string& allowedText) const {
  if (!(value >= lo && value <= hi)) throw InputError(fullName(name), formatReal(value), allowedText);
}

void OptionReader::requireAtLeast(const std::string& name, PetscInt value, PetscInt minimum) const {
  if (value < minimum) throw InputError(fullName(name), std::to_string(value), ">= " + std::to_string(minimum));
}

namespace {

// The components' prefixes and the programs that read them: an option of another program is refused
// naming it, where PETSc would only warn at the end of the run.
const std::pair<const char*, const char*> kReaders[] = {
    {"fem_", "gradfric-fem (and gradfric-study -study_model fem, gradfric-design -design_verify_fem)"},
    {"sbm_", "gradfric, gradfric-design, gradfric-calibrate, gradfric-study (and gradfric-fem -fem_compare_sbm)"},
    {"surface_", "gradfric, gradfric-fem, gradfric-design, gradfric-calibrate, gradfric-study"},
    {"ensemble_", "gradfric and gradfric-fem (sweeps)"},
    {"design_", "gradfric-design"},
    {"calibrate_", "gradfric-calibrate"},
    {"study_", "gradfric-study"},
    {"pressure_", "gradfric"},
    {"field_", "gradfric, gradfric-fem and gradfric-design"}};

}  // namespace

void checkUnusedOptions(MPI_Comm comm, const std::vector<std::string>& strictPrefixes) {
  PetscInt count = 0;
  char** names = nullptr;
  char** values = nullptr;
  GF_CALL(PetscOptionsLeftGet(nullptr, &count, &names, &values));
  const std::vector<std::string> known = knownOptionNames();
  std::string refused;
  for (PetscInt i = 0; i < count; ++i) {
    const std::string name = names[i];
    bool strict = false;
    for (const auto& prefix : strictPrefixes) strict = strict || name.rfind(prefix, 0) == 0;
    // The results file's options are every driver's: a misspelt -output_overwrite, or -resume
    // where nothing resumes, must not pass as unused.
    strict = strict || name.rfind("output", 0) == 0 || name == "resume";
    // "--sbm_N" reaches PETSc as the option "-sbm_N" (a name with a dash): one edit from sbm_N.
    const std::string suggestion = isPetscOptionName(name) ? "" : nearMiss("-" + name, known);
    const auto reader = std::find_if(std::begin(kReaders), std::end(kReaders),
                                     [&](const auto& r) { return name.rfind(r.first, 0) == 0; });
    if (!strict && suggestion.empty() && reader != std::end(kReaders)) {
      const std::string value = values[i] ? values[i] : "";
      GF_CALL(PetscOptionsLeftRestore(nullptr, &count, &names, &values));
      throw InputError("-" + name, value, std::string("only where it is read: ") + reader->second + ", not in this run");
    }
    if (strict || !suggestion.empty()) {
      refused += (refused.empty() ? "-" : ", -") + name + (suggestion.empty() ? "" : " (did you mean " + suggestion + "?)");
    } else if (name != "help" && name != "options_left") {
      PetscPrintf(comm, "WARNING: option -%s was given but nothing in this run uses it\n", names[i]);
    }
  }
  GF_CALL(PetscOptionsLeftRestore(nullptr, &count, &names, &values));
  if (!refused.empty()) throw InputError("unknown option " + refused + " (misspelt? -help lists every option)");
}

}  // namespace gradfric
