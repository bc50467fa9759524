// FEM runs read back from earlier design files (include/gradfric/design/known_runs.hpp).
#include "gradfric/design/known_runs.hpp"

#include "gradfric/core/broadcast.hpp"
#include "gradfric/core/input_error.hpp"
#include "gradfric/core/study_table.hpp"
#include "gradfric/design/problem.hpp"
#include "gradfric/design/uncertainty.hpp"
#include "gradfric/io/hdf5_attributes.hpp"
#include "gradfric/io/hdf5_datasets.hpp"
#include "gradfric/io/hdf5_handle.hpp"

#include <hdf5.h>

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

namespace gradfric::design {

bool femRunIndependentOf(const std::string& option) {
  for (const char* prefix : {"design_", "sbm_", "output"})
    if (option.rfind(prefix, 0) == 0) return true;
  return option == "fem_nx" || option == "fem_ny" || option == "fem_nz" || option == "options_file";
}

namespace {

constexpr int kFields = 8;  // per run, flattened: nx, ny, nz, reference, mu_s, nodes, area, then x

std::vector<double> column(hid_t group, const std::string& name, const std::string& path) {
  if (H5Lexists(group, name.c_str(), H5P_DEFAULT) <= 0)
    throw std::runtime_error(path + " has no column " + name + " (written before -design_reuse existed?)");
  io::H5Dataset d(GF_H5(H5Dopen2(group, name.c_str(), H5P_DEFAULT)));
  return io::readAll<double>(d, H5T_NATIVE_DOUBLE);
}

void addRun(std::vector<double>* runs, const std::array<double, 3>& mesh, bool reference, double mu, double nodes,
            double area, const std::vector<double>& x) {
  runs->insert(runs->end(), {mesh[0], mesh[1], mesh[2], reference ? 1.0 : 0.0, mu, nodes, area, double(x.size())});
  runs->insert(runs->end(), x.begin(), x.end());
}

// Rank 0: the rows of a FEM study table that stand for runs of this design: mu_s rows whose
// scene is the scene of the design's plate at the row's grading amplitude, or of its non-graded
// plate (the same key the design's study bar is looked up by).
std::vector<double> readTable(const std::string& path, const std::string& text, const Problem& problem,
                              const RunParameters& record) {
  if (problem.free.size() != 1 || problem.free[0].name != "grading_delta")
    throw std::runtime_error(path + " is a study table, whose rows serve a design of grading_delta alone, not of " +
                             problem.free[0].name + (problem.free.size() > 1 ? ",..." : ""));
  const std::vector<study::StudyRow> rows = study::parseStudyTable(text, path);
  const study::SceneKey uniform = designRunScene(problem, record, problem.referenceGrading(), true);
  std::vector<double> runs;
  for (const study::StudyRow& row : rows) {
    if (row.observable != "mu_s" || row.mesh.size() != 3 || row.stdError != 0) continue;
    const std::array<double, 3> mesh{double(row.mesh[0]), double(row.mesh[1]), double(row.mesh[2])};
    double delta = 0.0;
    for (const auto& [name, value] : row.scene)
      if (name == "grading_delta") delta = std::stod(value);
    if (study::sameScene(row.scene, designRunScene(problem, record, problem.gradingAt({delta}), true)))
      addRun(&runs, mesh, false, row.value, -1, 0, {delta});
    if (study::sameScene(row.scene, uniform)) addRun(&runs, mesh, true, row.value, -1, 0, {});
  }
  return runs;
}

// Rank 0: the runs of one file (a design file or a study table; "study": the FEM study table the
// bars come from), flattened, or a reason it cannot serve.
std::vector<double> readFile(const std::string& name, const Problem& problem, const RunParameters& record) {
  const std::string path = name == "study" ? study::studyTablePath("fem_study.tsv") : name;
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + " cannot be read");
  if (H5Fis_hdf5(path.c_str()) <= 0) {
    std::ostringstream text;
    text << in.rdbuf();
    try {
      return readTable(path, text.str(), problem, record);
    } catch (const std::invalid_argument& e) {
      throw std::runtime_error(path + " is neither a design file (HDF5) nor a study table (" + e.what() + ")");
    }
  }
  io::H5File file(GF_H5(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT)));
  std::map<std::string, std::string> stored;
  for (const auto& [name, value] : io::readStringAttributes(file)) stored[name] = value;
  if (stored["format"] != "gradfric-design" || stored["model"] != "fem")
    throw std::runtime_error(path + " is not a design file of -design_model fem");
  std::string names;
  for (const auto& f : problem.free) names += (names.empty() ? "" : ",") + f.name;
  if (stored["free_parameters"] != names)
    throw std::runtime_error(path + " has the free parameters " + stored["free_parameters"] + ", not " + names);
  // Every option a FEM run depends on, both ways: the same scene, law, surface, numerics.
  // The options the user set or left at their defaults first, the derived ones after: the first
  // difference named is the cause, not one of its consequences.
  for (const bool derived : {false, true})
    for (const io::Attribute& o : io::optionAttributes(record)) {
      if ((o.origin == "derived") != derived || femRunIndependentOf(o.name)) continue;
      const auto old = stored.find(o.name);
      if (old == stored.end() || old->second != o.value)
        throw std::runtime_error(path + " was run with -" + o.name + " = " +
                                 (old == stored.end() ? std::string("(not recorded)") : old->second) +
                                 ", this design with " + o.value);
    }
  std::vector<double> runs;
  const auto add = [&](const std::array<double, 3>& mesh, bool reference, double mu, double nodes, double area,
                       const std::vector<double>& x) { addRun(&runs, mesh, reference, mu, nodes, area, x); };
  {
    io::H5Group group(GF_H5(H5Gopen2(file, "evaluations", H5P_DEFAULT)));
    const std::string where = path + ":/evaluations";
    const auto nx = column(group, "fem_nx", where), ny = column(group, "fem_ny", where), nz = column(group, "fem_nz", where);
    const auto mu = column(group, "mu_s", where), nodes = column(group, "nodes_slid_above_one", where),
               area = column(group, "area_slid_above_one", where);
    const auto reference = column(group, "fem_reference_mu_s", where);
    std::vector<std::vector<double>> x;
    for (const auto& f : problem.free) x.push_back(column(group, "x_" + f.name, where));
    std::map<std::array<double, 3>, double> references;  // the non-graded plate per mesh
    for (std::size_t i = 0; i < mu.size(); ++i) {
      std::vector<double> at;
      for (const auto& c : x) at.push_back(c[i]);
      add({nx[i], ny[i], nz[i]}, false, mu[i], nodes[i], area[i], at);
      if (std::isfinite(reference[i])) references[{nx[i], ny[i], nz[i]}] = reference[i];
    }
    for (const auto& [mesh, mu_s] : references) add(mesh, true, mu_s, -1, 0, {});
  }
  return runs;
}

}  // namespace

std::vector<KnownFemRun> readKnownFemRuns(MPI_Comm comm, const std::vector<std::string>& paths, const Problem& problem,
                                          const RunParameters& record) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  std::vector<double> flat;
  std::string failure;
  if (rank == 0) {
    try {
      for (const std::string& path : paths) {
        const std::vector<double> runs = readFile(path, problem, record);
        flat.insert(flat.end(), runs.begin(), runs.end());
      }
    } catch (const std::exception& e) {
      failure = e.what();
    }
  }
  broadcast(comm, failure);
  std::string list;
  for (const std::string& p : paths) list += (list.empty() ? "" : ",") + p;
  if (!failure.empty())  // every rank alike: a bad input, before any work
    throw InputError("-design_reuse", list,
                     "design files of -design_model fem with the same scene and FEM options, or FEM study tables (" +
                         failure + ")");
  broadcast(comm, flat);
  std::vector<KnownFemRun> runs;
  for (std::size_t i = 0; i + kFields <= flat.size();) {
    KnownFemRun r;
    r.mesh = {static_cast<int>(flat[i]), static_cast<int>(flat[i + 1]), static_cast<int>(flat[i + 2])};
    r.reference = flat[i + 3] != 0;
    r.muStatic = flat[i + 4];
    r.flutter = {static_cast<long>(flat[i + 5]), flat[i + 6]};
    const std::size_t d = static_cast<std::size_t>(flat[i + 7]);
    r.x.assign(flat.begin() + static_cast<long>(i + kFields), flat.begin() + static_cast<long>(i + kFields + d));
    runs.push_back(std::move(r));
    i += kFields + d;
  }
  return runs;
}

}  // namespace gradfric::design
