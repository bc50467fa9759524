#pragma once
// The curve a calibration fits: mu(t) from the start of sliding, read from a gradfric-fem results
// file (the stored history of its one run, its own mu_s and peak time, its /scene; also the older
// gradfric-fem-history files), any HDF5 file
// with two 1D datasets (time [s], mu), or a CSV file with columns t, mu. Rank 0 reads; every rank
// gets the same curve or the same InputError (exit 2) naming the option and what is wrong.
#include "gradfric/calibration/loading_curve.hpp"

#include <mpi.h>

#include <map>
#include <string>
#include <vector>

namespace gradfric::calibration {

struct ReferenceSource {
  std::string option = "-calibrate_reference";  // for messages
  std::string path;
  std::string timeDataset = "history/time";  // HDF5 only
  std::string muDataset = "history/mu";
};

struct ReferenceCurve {
  std::string kind;  // "gradfric-fem run", "gradfric-fem history", "HDF5 datasets", "CSV"
  std::vector<double> time, mu;
  double peak = LoadingFeatures::kNaN;      // the FEM's own mu_s (/realisations/mu_s), else NaN
  double peakTime = LoadingFeatures::kNaN;  // its peak time
  std::map<std::string, std::string> scene;  // a gradfric-fem file's /scene attributes (else empty)
};

// Collective. Refuses a missing or unreadable file, missing datasets, fewer than 5 samples,
// non-finite values, a time that does not increase.
ReferenceCurve readReferenceCurve(MPI_Comm comm, const ReferenceSource& source);

}  // namespace gradfric::calibration
