#include "gradfric/study/scene_key.hpp"

#include "gradfric/core/format.hpp"
#include "gradfric/core/petsc_call.hpp"

#include <petscsys.h>

#include <algorithm>
#include <cctype>
#include <map>
#include <sstream>

namespace gradfric::study {

namespace {

// Options that steer a run without changing its results (prefixes end in '_').
const char* const kSteering[] = {"-output", "-output_overwrite", "-resume", "-plot", "-plot_dir",
                                 "-friction_observables",  // a mu_s-only run stops at the confirmed peak: the same mu_s
                                 "-ensemble_",             // sweep lists (their values come with the point), size, seed
                                 "-fem_sweep_", "-fem_verbose", "-fem_dry_run", "-fem_partitioner", "-fem_monitor_every",
                                 "-fem_monitor_factor", "-fem_snapshot_times", "-fem_compare_sbm",
                                 "-sbm_snapshot_times", "-checkpoint_"};

bool steers(const std::string& name) {
  return std::any_of(std::begin(kSteering), std::end(kSteering), [&](const std::string& s) {
    return s.back() == '_' ? name.rfind(s, 0) == 0 : name == s;
  });
}

// The options PETSc's objects read under a component's prefix (the FEM's TS: -fem_ts_type, ...),
// which no OptionReader records but which change the results all the same.
void addObjectOptions(std::map<std::string, std::string>* set) {
  char* all = nullptr;
  GF_CALL(PetscOptionsGetAll(nullptr, &all));
  std::istringstream tokens(all);
  GF_CALL(PetscFree(all));
  std::string token, name;
  const auto isName = [](const std::string& t) { return t.size() > 1 && t[0] == '-' && std::isalpha(static_cast<unsigned char>(t[1])); };
  while (tokens >> token) {
    if (isName(token)) {
      name = token.rfind("-fem_ts_", 0) == 0 ? token : "";
      if (!name.empty()) (*set)[name] = "";
    } else if (!name.empty()) {
      (*set)[name] += ((*set)[name].empty() ? "" : " ") + token;
    }
  }
}

}  // namespace

SceneKey sceneKey(const RunParameters& record, const std::vector<std::string>& coordinates,
                  const campaign::SweepPoint* point) {
  std::map<std::string, std::string> set;  // name with its dash -> value
  const auto atDefault = [&](const std::string& name, const std::string& value) {
    const ResolvedOption* o = record.find(name);
    return o && !o->defaultValue.empty() && sameSettingValue(value, o->defaultValue);
  };
  const auto put = [&](const std::string& name, const std::string& value) {
    if (atDefault(name, value))
      set.erase(name);
    else
      set[name] = value;
  };
  for (const ResolvedOption& o : record.all())
    if (o.origin == OptionOrigin::User && !steers(o.name) &&
        std::find(coordinates.begin(), coordinates.end(), o.name) == coordinates.end())
      put(o.name, o.value);
  addObjectOptions(&set);
  if (point) {
    put("-grading_delta", formatReal(point->delta));
    put("-grading_property", point->property);
    put("-grading_profile", point->profile);
    put("-plate_theta", formatReal(point->theta));
    if (record.find("-surface_sigma_s")) put("-surface_sigma_s", formatReal(point->sigma));
    if (record.find("-surface_sigma_k")) put("-surface_sigma_k", formatReal(point->sigmaKinetic));
    const ResolvedOption* field = record.find("-ensemble_field");  // the swept parameter, e.g. mu_delta
    if (point->fieldSwept && field) put("-field_" + field->value, formatReal(point->fieldValue));
  }
  const auto profile = set.find("-grading_profile"), delta = set.find("-grading_delta");
  if (profile == set.end() || delta == set.end() || atDefault("-grading_delta", delta->second))
    for (auto it = set.begin(); it != set.end();) it = it->first.rfind("-grading_", 0) == 0 ? set.erase(it) : std::next(it);
  SceneKey key;
  for (const auto& [name, value] : set) key.emplace_back(name.substr(1), value);
  return key;
}

}  // namespace gradfric::study
