#include "gradfric/core/options.hpp"

#include "gradfric/core/input_error.hpp"
#include "gradfric/core/near_miss.hpp"
#include "gradfric/core/petsc_call.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cfloat>
#include <set>
#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace gradfric {

namespace {

const char* originText(OptionOrigin origin) {
  switch (origin) {
    case OptionOrigin::User: return "set";
    case OptionOrigin::Derived: return "derived";
    default: return "default";
  }
}

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

std::vector<std::string> splitList(const std::string& text) {
  std::vector<std::string> items;
  std::stringstream stream(text);
  std::string item;
  while (std::getline(stream, item, ',')) {
    item.erase(0, item.find_first_not_of(" \t"));
    item.erase(item.find_last_not_of(" \t") + 1);
    if (!item.empty()) items.push_back(item);
  }
  return items;
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
                        unit.c_str(), originText(o.origin)));
  }
}

OptionReader::OptionReader(MPI_Comm comm, std::string prefix, std::string title, RunParameters* record)
    : comm_(comm), prefix_(std::move(prefix)), title_(std::move(title)), record_(record), help_(helpRequested()) {}

bool helpRequested() {
  PetscBool help = PETSC_FALSE;
  PetscOptionsHasHelp(nullptr, &help);
  return help;
}

void OptionReader::printHelp(const std::string& name, const std::string& current, const std::string& unit,
                             const std::string& help) {
  if (!help_) return;
  // Several readers may share a section (the SBM's parameters and its request): its title is
  // printed once, unless another section came in between.
  static std::string lastSection;
  const std::string section = prefix_.empty() ? title_ : title_ + " (-" + prefix_ + ")";
  if (!titlePrinted_ && section != lastSection) GF_CALL(PetscPrintf(comm_, "%s:\n", section.c_str()));
  titlePrinted_ = true;
  lastSection = section;
  std::string unitText = unit.empty() ? "" : " [" + unit + "]";
  GF_CALL(PetscPrintf(comm_, "  %s <%s>%s: %s\n", fullName(name).c_str(), current.c_str(), unitText.c_str(),
                      help.c_str()));
}

void OptionReader::store(const std::string& name, const std::string& value, const std::string& unit,
                         const std::string& help, bool userSet, const std::string& fallback) {
  knownNames().insert(fullName(name));
  if (record_)
    record_->add({fullName(name), value, unit, help, userSet ? OptionOrigin::User : OptionOrigin::Default, fallback});
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
  store(name, std::to_string(value), unit, help, set);
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
  store(name, value ? "true" : "false", "", help, set);
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
  store(name, value, "", help, set);
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
    for (const auto& item : splitList(raw)) {
      double v = 0;
      if (!parseFiniteReal(item, &v))
        throw InputError(fullName(name), raw,
                         "a comma-separated list of finite real numbers [" + unit + "] (" + item + " is not one)");
      values.push_back(v);
    }
  }
  printHelp(name, joinedReals(values), unit, help + " (comma-separated)");
  store(name, joinedReals(values), unit, help, set);
  return values;
}

std::vector<std::string> OptionReader::choiceList(const std::string& name, const std::vector<std::string>& fallback,
                                                  const std::vector<std::string>& allowed, const std::string& help) {
  char raw[4096] = "";
  PetscBool set = PETSC_FALSE;
  GF_CALL(PetscOptionsGetString(nullptr, prefix_.c_str(), ("-" + name).c_str(), raw, sizeof raw, &set));
  std::vector<std::string> values = set ? splitList(raw) : fallback;
  for (const auto& v : values)
    if (std::find(allowed.begin(), allowed.end(), v) == allowed.end())
      throw InputError(fullName(name), v, "a comma-separated list of: " + joined(allowed, ", "));
  printHelp(name, joined(values, ","), "", help + " (comma-separated from " + joined(allowed, ", ") + ")");
  store(name, joined(values, ","), "", help, set);
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

void refuseRenamedOption(const std::string& old, const std::string& now, const std::string& why) {
  char value[256] = "";
  PetscBool set = PETSC_FALSE;
  GF_CALL(PetscOptionsGetString(nullptr, nullptr, old.c_str(), value, sizeof value, &set));
  if (set) throw InputError("invalid option " + old + " = " + value + ": " + why + "; use " + now + " = " + value);
}

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
    // "--sbm_N" reaches PETSc as the option "-sbm_N" (a name with a dash): one edit from sbm_N.
    const std::string suggestion = isPetscOptionName(name) ? "" : nearMiss("-" + name, known);
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
