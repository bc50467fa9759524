// Options refused because they were renamed, retired or lost their prefix: each names what the
// user set and what to use instead (include/gradfric/core/options.hpp).
#include "gradfric/core/input_error.hpp"
#include "gradfric/core/options.hpp"
#include "gradfric/core/petsc_call.hpp"

#include <petscsys.h>

#include <string>
#include <utility>
#include <vector>

namespace gradfric {

void refuseRenamedOption(const std::string& old, const std::string& now, const std::string& why) {
  char value[256] = "";
  PetscBool set = PETSC_FALSE;
  GF_CALL(PetscOptionsGetString(nullptr, nullptr, old.c_str(), value, sizeof value, &set));
  if (!set) return;
  const std::string shown = value[0] ? std::string(" = ") + value : "";  // a flag has no value
  throw InputError("invalid option " + old + shown + ": " + why + "; use " + now + shown);
}

void refuseRetiredOption(const std::string& old, const std::string& why) {
  char value[256] = "";
  PetscBool set = PETSC_FALSE;
  GF_CALL(PetscOptionsGetString(nullptr, nullptr, old.c_str(), value, sizeof value, &set));
  if (!set) return;
  throw InputError("invalid option " + old + (value[0] ? std::string(" = ") + value : "") + ": " + why);
}

void refuseRenamedRunControl() {
  const std::pair<const char*, const char*> renamed[] = {
      {"-fem_output", "-output"},          {"-fem_output_overwrite", "-output_overwrite"},
      {"-fem_sweep_resume", "-resume"},    {"-ensemble_resume", "-resume"},
      {"-calibrate_output", "-output"},    {"-calibrate_output_overwrite", "-output_overwrite"}};
  for (const auto& [old, now] : renamed)
    refuseRenamedOption(old, now, "renamed: every driver says -output, -output_overwrite and -resume");
}

void refuseUnprefixedOptions(const std::string& family, const std::string& prefix, const std::string& why) {
  PetscInt count = 0;
  char** names = nullptr;
  char** values = nullptr;
  GF_CALL(PetscOptionsLeftGet(nullptr, &count, &names, &values));
  std::vector<std::string> unprefixed;
  for (PetscInt i = 0; i < count; ++i)
    if (std::string(names[i]).rfind(family, 0) == 0) unprefixed.push_back(names[i]);
  GF_CALL(PetscOptionsLeftRestore(nullptr, &count, &names, &values));
  for (const std::string& name : unprefixed) refuseRenamedOption("-" + name, "-" + prefix + name, why);
}

}  // namespace gradfric
