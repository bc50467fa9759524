// The designer's spring-block variants (include/gradfric/design/variants.hpp).
#include "gradfric/design/variants.hpp"

#include "gradfric/core/broadcast.hpp"
#include "gradfric/core/input_error.hpp"
#include "gradfric/core/petsc_call.hpp"
#include "gradfric/design/evaluator.hpp"
#include "gradfric/design/problem.hpp"
#include "gradfric/sbm/parameter_options.hpp"

#include <petscsys.h>

#include <cctype>
#include <fstream>
#include <sstream>

namespace gradfric::design {

namespace {

const char* const kOption = "-design_variants";
const char* const kAllowed = "options files of spring-block options only (-sbm_*, -friction_*, -surface_*; -ensemble_* are ignored)";

// The options a database holds, as (name without the dash, value) in its order.
std::vector<std::pair<std::string, std::string>> optionsOf(PetscOptions options) {
  char* all = nullptr;
  GF_CALL(PetscOptionsGetAll(options, &all));
  std::vector<std::pair<std::string, std::string>> list;
  std::stringstream in(all ? all : "");
  GF_CALL(PetscFree(all));
  for (std::string token; in >> token;) {
    const bool name = token.size() > 1 && token[0] == '-' && std::isalpha(static_cast<unsigned char>(token[1]));
    if (name)
      list.emplace_back(token.substr(1), "");
    else if (!list.empty())
      list.back().second += (list.back().second.empty() ? "" : " ") + token;
  }
  return list;
}

// The options of a file in PETSc's format (-name value, # comments), read
// on rank 0 and parsed by every rank from the same text: a missing or malformed file is refused
// on every rank alike (PETSc's own reader stops rank 0 alone, and the others would wait).
std::vector<std::pair<std::string, std::string>> readOptionsFile(MPI_Comm comm, const std::string& file) {
  int rank = 0;
  GF_CALL_MPI(MPI_Comm_rank(comm, &rank));
  std::string text;
  int exists = 0;
  if (rank == 0) {
    std::ifstream in(file);
    if (in) {
      std::stringstream all;
      all << in.rdbuf();
      text = all.str();
      exists = 1;
    }
  }
  GF_CALL_MPI(MPI_Bcast(&exists, 1, MPI_INT, 0, comm));
  if (file.empty() || !exists)
    throw InputError(kOption, file.empty() ? "(an empty item)" : file, std::string(kAllowed) + " that exist");
  broadcast(comm, text);
  // As the options files PETSc reads at start-up: -name [value] pairs, several on a line allowed.
  std::vector<std::pair<std::string, std::string>> options;
  std::stringstream lines(text);
  int number = 0;
  for (std::string line; std::getline(lines, line);) {
    ++number;
    std::stringstream tokens(line.substr(0, line.find('#')));
    for (std::string token; tokens >> token;) {
      const bool isName = token.size() > 1 && token[0] == '-' && std::isalpha(static_cast<unsigned char>(token[1]));
      if (isName)
        options.emplace_back(token.substr(1), "");
      else if (!options.empty() && options.back().second.empty())
        options.back().second = token;
      else
        throw InputError(kOption, file, std::string(kAllowed) + " in PETSc's format, -name value (line " +
                                            std::to_string(number) + ": " + token + " follows no option)");
    }
  }
  return options;
}

// A database with the scene's options (the global database without -options_file, whose values
// it already holds, later ones winning) under the variant's.
PetscOptions sceneWith(const std::vector<std::pair<std::string, std::string>>& variant) {
  PetscOptions options = nullptr;
  GF_CALL(PetscOptionsCreate(&options));
  for (const auto& [name, value] : optionsOf(nullptr))
    if (name != "options_file" && name != "design_variants")
      GF_CALL(PetscOptionsSetValue(options, ("-" + name).c_str(), value.empty() ? nullptr : value.c_str()));
  for (const auto& [name, value] : variant)
    GF_CALL(PetscOptionsSetValue(options, ("-" + name).c_str(), value.empty() ? nullptr : value.c_str()));
  return options;
}

// The default database for the options read while it lives.
struct PushedOptions {
  PetscOptions options;
  explicit PushedOptions(PetscOptions o) : options(o) { GF_CALL(PetscOptionsPush(options)); }
  ~PushedOptions() {
    PetscOptionsPop();
    PetscOptionsDestroy(&options);
  }
  PushedOptions(const PushedOptions&) = delete;
  PushedOptions& operator=(const PushedOptions&) = delete;
};

}  // namespace

std::vector<SpringBlockVariant> readVariants(MPI_Comm comm, const std::vector<std::string>& files, const Plate& plate,
                                             const Grading& stiffest) {
  std::vector<SpringBlockVariant> variants;
  for (const std::string& file : files) {
    const auto all = readOptionsFile(comm, file);
    SpringBlockVariant v;
    v.file = file;
    std::vector<std::pair<std::string, std::string>> set;
    std::string ignored;
    for (const auto& [name, value] : all) {
      // A calibration's scene file (gradfric-calibrate) also sets its ensemble: the design's own decide.
      if (name.rfind("ensemble_", 0) == 0) {
        ignored += (ignored.empty() ? "-" : ", -") + name;
        continue;
      }
      const bool springBlocks = name.rfind("sbm_", 0) == 0 || name.rfind("friction_", 0) == 0 || name.rfind("surface_", 0) == 0;
      if (!springBlocks) throw InputError(kOption, file, std::string(kAllowed) + "; it sets -" + name);
      v.options += (v.options.empty() ? "-" : " -") + name + (value.empty() ? "" : " " + value);
      set.emplace_back(name, value);
    }
    if (set.empty()) throw InputError(kOption, file, std::string(kAllowed) + ", each setting at least one");
    if (!ignored.empty())
      GF_CALL(PetscPrintf(comm, "%s %s: %s not used (the design's -design_tolerance and -design_seed decide its ensembles)\n",
                          kOption, file.c_str(), ignored.c_str()));
    const PushedOptions scene(sceneWith(set));  // the file read once, its -ensemble_* left out
    std::string unread;
    try {
      RunParameters record;
      v.parameters = sbm::readParameters(comm, &record, plate, stiffest);
      v.request = sbm::readRequest(comm, &record, v.parameters);
    } catch (const InputError& e) {
      throw InputError(std::string(e.what()) + " (in the " + kOption + " file " + file + ")");
    }
    PetscInt count = 0;
    char **names = nullptr, **values = nullptr;
    GF_CALL(PetscOptionsLeftGet(scene.options, &count, &names, &values));
    for (PetscInt i = 0; i < count && unread.empty(); ++i)
      for (const auto& kv : set)
        if (kv.first == names[i]) unread = names[i];
    GF_CALL(PetscOptionsLeftRestore(scene.options, &count, &names, &values));
    if (!unread.empty())
      throw InputError(kOption, file, std::string(kAllowed) + " that the spring blocks read; nothing reads -" + unread);
    measureMuStaticOnly(&v.request);
    variants.push_back(std::move(v));
  }
  return variants;
}

std::vector<Evaluation> evaluateVariants(MPI_Comm comm, const Problem& problem, const std::vector<double>& x,
                                         std::uint32_t stream, long* realisations) {
  std::vector<Evaluation> evaluations;
  for (std::size_t k = 0; k < problem.variants.size(); ++k) {
    Problem variant = problem;  // the scene with the variant's spring blocks
    variant.parameters = problem.variants[k].parameters;
    variant.request = problem.variants[k].request;
    variant.variants.clear();
    Evaluator ensembles(comm, variant);
    evaluations.push_back(ensembles.evaluate(x, problem.tolerance, "variant", stream));
    evaluations.back().index = static_cast<int>(k);
    *realisations += ensembles.realisationsRun();
  }
  return evaluations;
}

}  // namespace gradfric::design
