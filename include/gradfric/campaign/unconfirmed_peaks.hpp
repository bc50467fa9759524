#pragma once
// A campaign whose runs ended before the rule confirmed their static peak (both models): their
// mu_s is only the largest mu reached. Said in one line after the results, and an exit status of
// 5, unless the user fixed the run length (then the line is a warning and the status 0).
#include "gradfric/campaign/statistics.hpp"

#include <mpi.h>

#include <string>
#include <vector>

namespace gradfric::campaign {

struct RunLengthChoice {
  bool fixed = false;   // the user fixed the run length
  std::string fixedBy;  // the options that fix it, in words ("-sbm_t_end")
  std::string longer;   // the option a longer run takes ("-sbm_t_max")
};

// Collective: prints the line (program: "gradfric", "gradfric-fem") if any run's peak was not
// confirmed; returns the exit status, 5 or 0.
int reportUnconfirmedPeaks(MPI_Comm comm, const std::string& program, const std::vector<PointStatistics>& stats,
                           const RunLengthChoice& length);

}  // namespace gradfric::campaign
