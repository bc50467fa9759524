// Reading the reference mu(t) of a calibration (include/gradfric/calibration/reference_curve.hpp).
#include "gradfric/calibration/reference_curve.hpp"

#include "gradfric/core/broadcast.hpp"
#include "gradfric/core/input_error.hpp"
#include "gradfric/core/petsc_call.hpp"
#include "gradfric/io/hdf5_attributes.hpp"
#include "gradfric/io/hdf5_datasets.hpp"
#include "gradfric/io/hdf5_handle.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace gradfric::calibration {

namespace {

bool endsWith(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

// Thrown while reading on rank 0; becomes the InputError of every rank.
struct Unreadable : std::runtime_error {
  using std::runtime_error::runtime_error;
};

std::vector<double> readVector(hid_t file, const std::string& name) {
  htri_t exists = 0;
  H5E_BEGIN_TRY { exists = H5Lexists(file, name.c_str(), H5P_DEFAULT); }
  H5E_END_TRY;
  if (exists <= 0) throw Unreadable("a file with the dataset " + name + " (it has none)");
  io::H5Dataset d(GF_H5(H5Dopen2(file, name.c_str(), H5P_DEFAULT)));
  io::H5Space space(GF_H5(H5Dget_space(d)));
  if (H5Sget_simple_extent_ndims(space) != 1) throw Unreadable("a 1D dataset " + name);
  hsize_t n = 0;
  H5Sget_simple_extent_dims(space, &n, nullptr);
  std::vector<double> v(n);
  if (n > 0) GF_H5(H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()));
  return v;
}

double realAttribute(hid_t object, const char* name) {
  if (H5Aexists(object, name) <= 0) return LoadingFeatures::kNaN;
  io::H5Attribute a(GF_H5(H5Aopen(object, name, H5P_DEFAULT)));
  double v = LoadingFeatures::kNaN;
  GF_H5(H5Aread(a, H5T_NATIVE_DOUBLE, &v));
  return v;
}

std::string formatOf(hid_t file) {
  if (H5Aexists(file, "format") <= 0) return "";
  io::H5Attribute a(GF_H5(H5Aopen(file, "format", H5P_DEFAULT)));
  return io::readStringAttribute(a);
}

// The first `count` values of a task's row [0, 0, :] of a results-file dataset.
std::vector<double> readTaskRow(hid_t file, const std::string& name, hsize_t count) {
  io::H5Dataset d(GF_H5(H5Dopen2(file, name.c_str(), H5P_DEFAULT)));
  std::vector<double> all = io::readAll<double>(d, H5T_NATIVE_DOUBLE);
  all.resize(std::min<std::size_t>(all.size(), count));
  return all;
}

// A single FEM run's results file (gradfric-fem-run, the campaign layout): the stored mu(t) of its
// one task, its mu_s and peak time, its /scene.
void readFemRun(hid_t file, ReferenceCurve* c) {
  io::H5Dataset length(GF_H5(H5Dopen2(file, "history/length", H5P_DEFAULT)));
  const std::vector<int> n = io::readAll<int>(length, H5T_NATIVE_INT);
  const hsize_t samples = n.empty() ? 0 : static_cast<hsize_t>(std::max(0, n[0]));
  c->time = readTaskRow(file, "history/time", samples);
  c->mu = readTaskRow(file, "history/mu", samples);
  c->peak = readTaskRow(file, "realisations/mu_s", 1).at(0);
  c->peakTime = readTaskRow(file, "realisations/peak_time", 1).at(0);
  c->kind = "gradfric-fem run";
}

ReferenceCurve readHdf5(const ReferenceSource& s) {
  ReferenceCurve c;
  htri_t isHdf5 = 0;
  H5E_BEGIN_TRY { isHdf5 = H5Fis_hdf5(s.path.c_str()); }
  H5E_END_TRY;
  if (isHdf5 <= 0) throw Unreadable("a readable HDF5 file (missing or not HDF5)");
  io::H5File file(GF_H5(H5Fopen(s.path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT)));
  const std::string format = formatOf(file);
  const ReferenceSource defaults;
  if (format == "gradfric-fem-run" && s.timeDataset == defaults.timeDataset && s.muDataset == defaults.muDataset) {
    readFemRun(file, &c);
  } else {
    c.time = readVector(file, s.timeDataset);
    c.mu = readVector(file, s.muDataset);
    c.kind = "HDF5 datasets " + s.timeDataset + ", " + s.muDataset;
  }
  if (format == "gradfric-fem-history") {  // a single run's file before the campaign layout
    c.kind = "gradfric-fem history";
    if (H5Lexists(file, "results", H5P_DEFAULT) > 0) {
      io::H5Group results(GF_H5(H5Gopen2(file, "results", H5P_DEFAULT)));
      c.peak = realAttribute(results, "mu_s");
      c.peakTime = realAttribute(results, "peak_time");
    }
  }
  if ((format == "gradfric-fem-run" || format == "gradfric-fem-history") && H5Lexists(file, "scene", H5P_DEFAULT) > 0) {
    io::H5Group scene(GF_H5(H5Gopen2(file, "scene", H5P_DEFAULT)));
    for (const auto& [k, v] : io::readStringAttributes(scene)) c.scene[k] = v;
  }
  return c;
}

ReferenceCurve readCsv(const ReferenceSource& s) {
  std::ifstream in(s.path);
  if (!in) throw Unreadable("a readable CSV file (cannot open it)");
  ReferenceCurve c;
  c.kind = "CSV";
  std::string line;
  int lineNumber = 0;
  while (std::getline(in, line)) {
    ++lineNumber;
    if (line.empty() || line[0] == '#') continue;
    for (char& ch : line)
      if (ch == ',' || ch == ';' || ch == '\t') ch = ' ';
    std::istringstream fields(line);
    std::string a, b;
    fields >> a >> b;
    if (a.empty()) continue;
    char* end1 = nullptr;
    char* end2 = nullptr;
    const double t = std::strtod(a.c_str(), &end1);
    const double m = b.empty() ? 0.0 : std::strtod(b.c_str(), &end2);
    if (*end1 != '\0' || b.empty() || *end2 != '\0') {
      if (c.time.empty() && a == "t" && b == "mu") continue;  // the header
      throw Unreadable("a CSV file with columns t, mu (line " + std::to_string(lineNumber) + ": \"" + line + "\")");
    }
    c.time.push_back(t);
    c.mu.push_back(m);
  }
  return c;
}

void check(const ReferenceCurve& c) {
  if (c.time.size() != c.mu.size()) throw Unreadable("time and mu of the same length");
  if (c.time.size() < 5) throw Unreadable("a curve of at least 5 samples (it has " + std::to_string(c.time.size()) + ")");
  for (std::size_t i = 0; i < c.time.size(); ++i) {
    if (!std::isfinite(c.time[i]) || !std::isfinite(c.mu[i]))
      throw Unreadable("finite t and mu (sample " + std::to_string(i) + " is not)");
    if (i > 0 && !(c.time[i] > c.time[i - 1]))
      throw Unreadable("a time that increases (sample " + std::to_string(i) + ")");
  }
}

}  // namespace

ReferenceCurve readReferenceCurve(MPI_Comm comm, const ReferenceSource& source) {
  int rank = 0;
  GF_CALL_MPI(MPI_Comm_rank(comm, &rank));
  ReferenceCurve c;
  std::string problem;
  if (rank == 0) {
    try {
      c = endsWith(source.path, ".csv") ? readCsv(source) : readHdf5(source);
      check(c);
    } catch (const Unreadable& e) {
      problem = e.what();
    } catch (const std::exception& e) {  // an HDF5 failure inside a readable file
      problem = std::string("a readable reference (") + e.what() + ")";
    }
  }
  broadcast(comm, problem);
  if (!problem.empty()) throw InputError(source.option, source.path, problem);
  broadcast(comm, c.kind);
  broadcast(comm, c.time);
  broadcast(comm, c.mu);
  std::vector<double> peak{c.peak, c.peakTime};
  broadcast(comm, peak);
  c.peak = peak[0];
  c.peakTime = peak[1];
  unsigned long entries = c.scene.size();
  GF_CALL_MPI(MPI_Bcast(&entries, 1, MPI_UNSIGNED_LONG, 0, comm));
  auto it = c.scene.begin();
  std::map<std::string, std::string> scene;
  for (unsigned long i = 0; i < entries; ++i) {
    std::string k, v;
    if (rank == 0) {
      k = it->first;
      v = it->second;
      ++it;
    }
    broadcast(comm, k);
    broadcast(comm, v);
    scene[k] = v;
  }
  c.scene = std::move(scene);
  return c;
}

}  // namespace gradfric::calibration
