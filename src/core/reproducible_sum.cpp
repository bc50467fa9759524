#include "gradfric/core/reproducible_sum.hpp"

#include "gradfric/core/petsc_call.hpp"

#include <algorithm>
#include <vector>

namespace gradfric {

void allreduceExact(MPI_Comm comm, ExactSum* sums, int count) {
  std::vector<std::int64_t> words(static_cast<std::size_t>(count) * ExactSum::kWords);
  for (int i = 0; i < count; ++i) {
    sums[i].normalise();
    std::copy_n(sums[i].words(), ExactSum::kWords, words.begin() + static_cast<std::ptrdiff_t>(i) * ExactSum::kWords);
  }
  GF_CALL_MPI(MPI_Allreduce(MPI_IN_PLACE, words.data(), static_cast<int>(words.size()), MPI_INT64_T, MPI_SUM, comm));
  for (int i = 0; i < count; ++i)
    std::copy_n(words.begin() + static_cast<std::ptrdiff_t>(i) * ExactSum::kWords, ExactSum::kWords, sums[i].words());
}

double sumOverRanks(MPI_Comm comm, const ExactSum& local) {
  ExactSum total = local;
  allreduceExact(comm, &total, 1);
  return total.value();
}

}  // namespace gradfric
