#include "gradfric/campaign/unconfirmed_peaks.hpp"

#include "gradfric/core/petsc_call.hpp"

#include <petscsys.h>

namespace gradfric::campaign {

int reportUnconfirmedPeaks(MPI_Comm comm, const std::string& program, const std::vector<PointStatistics>& stats,
                           const RunLengthChoice& length) {
  long unconfirmed = 0, points = 0;
  for (const PointStatistics& st : stats) {
    unconfirmed += st.peaksUnconfirmed;
    points += st.peaksUnconfirmed > 0 ? 1 : 0;
  }
  if (unconfirmed == 0) return 0;
  const std::string why = length.fixed ? "the run length was fixed by " + length.fixedBy
                                       : "a longer " + length.longer + " may confirm them";
  GF_CALL(PetscPrintf(comm,
                      "%s: %s: %ld run(s) at %ld point(s) ended before their peak of mu(t) was confirmed: their mu_s "
                      "is the largest mu reached, not the static coefficient (%s)%s\n",
                      program.c_str(), length.fixed ? "warning" : "error", unconfirmed, points, why.c_str(),
                      length.fixed ? "" : "; exit 5"));
  return length.fixed ? 0 : 5;
}

}  // namespace gradfric::campaign
