#include "gradfric/core/options.hpp"

#include "gradfric/core/input_error.hpp"
#include "gradfric/core/petsc_call.hpp"

#include <algorithm>
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

}  // namespace

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
  if (!titlePrinted_) {
    GF_CALL(PetscPrintf(comm_, "%s (-%s):\n", title_.c_str(), prefix_.c_str()));
    titlePrinted_ = true;
  }
  std::string unitText = unit.empty() ? "" : " [" + unit + "]";
  GF_CALL(PetscPrintf(comm_, "  %s <%s>%s: %s\n", fullName(name).c_str(), current.c_str(), unitText.c_str(),
                      help.c_str()));
}

void OptionReader::store(const std::string& name, const std::string& value, const std::string& unit,
                         const std::string& help, bool userSet) {
  if (record_) record_->add({fullName(name), value, unit, help, userSet ? OptionOrigin::User : OptionOrigin::Default});
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
  if (set) {
    char* end = nullptr;
    value = std::strtod(raw, &end);
    if (end == raw || *end != '\0') throw InputError(fullName(name), raw, "a real number [" + unit + "]");
  }
  printHelp(name, formatReal(value), unit, help);
  store(name, formatReal(value), unit, help, set);
  return value;
}

std::optional<double> OptionReader::realIfSet(const std::string& name, const std::string& unit,
                                              const std::string& help, const std::string& defaultText) {
  if (!wasSet(name)) {
    printHelp(name, defaultText, unit, help);
    return std::nullopt;
  }
  return real(name, 0.0, unit, help);
}

void OptionReader::recordDerived(const std::string& name, double value, const std::string& unit,
                                 const std::string& help) {
  if (record_) record_->add({fullName(name), formatReal(value), unit, help, OptionOrigin::Derived});
}

PetscInt OptionReader::integer(const std::string& name, PetscInt fallback, const std::string& unit,
                               const std::string& help) {
  PetscInt value = fallback;
  PetscBool set = PETSC_FALSE;
  char raw[256] = "";
  GF_CALL(PetscOptionsGetString(nullptr, prefix_.c_str(), ("-" + name).c_str(), raw, sizeof raw, &set));
  if (set) {
    char* end = nullptr;
    long parsed = std::strtol(raw, &end, 10);
    if (end == raw || *end != '\0') throw InputError(fullName(name), raw, "an integer");
    value = static_cast<PetscInt>(parsed);
  }
  printHelp(name, std::to_string(value), unit, help);
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
      char* end = nullptr;
      double v = std::strtod(item.c_str(), &end);
      if (end == item.c_str() || *end != '\0')
        throw InputError(fullName(name), raw, "a comma-separated list of real numbers [" + unit + "]");
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

void checkUnusedOptions(MPI_Comm comm, const std::vector<std::string>& strictPrefixes) {
  PetscInt count = 0;
  char** names = nullptr;
  char** values = nullptr;
  GF_CALL(PetscOptionsLeftGet(nullptr, &count, &names, &values));
  std::string refused;
  for (PetscInt i = 0; i < count; ++i) {
    std::string name = names[i];
    bool strict = false;
    for (const auto& prefix : strictPrefixes) strict = strict || name.rfind(prefix, 0) == 0;
    if (strict) {
      refused += (refused.empty() ? "-" : ", -") + name;
    } else if (name != "help" && name != "options_left") {
      PetscPrintf(comm, "WARNING: option -%s was given but nothing in this run uses it\n", names[i]);
    }
  }
  GF_CALL(PetscOptionsLeftRestore(nullptr, &count, &names, &values));
  if (!refused.empty()) throw InputError("unknown option " + refused + " (misspelt? -help lists every option)");
}

}  // namespace gradfric
