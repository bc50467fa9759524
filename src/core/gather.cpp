#include "gradfric/core/gather.hpp"

#include "gradfric/core/petsc_call.hpp"

namespace gradfric {

std::vector<double> gatherOnRoot(MPI_Comm comm, const std::vector<double>& local) {
  int rank = 0, size = 1;
  GF_CALL_MPI(MPI_Comm_rank(comm, &rank));
  GF_CALL_MPI(MPI_Comm_size(comm, &size));
  int count = static_cast<int>(local.size());
  std::vector<int> counts(size), offsets(size, 0);
  GF_CALL_MPI(MPI_Gather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, comm));
  std::vector<double> all;
  if (rank == 0) {
    for (int r = 1; r < size; ++r) offsets[r] = offsets[r - 1] + counts[r - 1];
    all.resize(std::size_t(offsets[size - 1]) + counts[size - 1]);
  }
  GF_CALL_MPI(MPI_Gatherv(local.data(), count, MPI_DOUBLE, all.data(), counts.data(), offsets.data(), MPI_DOUBLE, 0,
                          comm));
  return all;
}

namespace {

template <class T>
std::vector<T> allGathered(MPI_Comm comm, const std::vector<T>& local, MPI_Datatype type) {
  int size = 1;
  GF_CALL_MPI(MPI_Comm_size(comm, &size));
  const int count = static_cast<int>(local.size());
  std::vector<int> counts(size), offsets(size, 0);
  GF_CALL_MPI(MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, comm));
  for (int r = 1; r < size; ++r) offsets[r] = offsets[r - 1] + counts[r - 1];
  std::vector<T> all(std::size_t(offsets[size - 1]) + counts[size - 1]);
  GF_CALL_MPI(MPI_Allgatherv(local.data(), count, type, all.data(), counts.data(), offsets.data(), type, comm));
  return all;
}

}  // namespace

std::vector<double> gatherOnAll(MPI_Comm comm, const std::vector<double>& local) {
  return allGathered(comm, local, MPI_DOUBLE);
}

std::vector<long> gatherOnAll(MPI_Comm comm, const std::vector<long>& local) { return allGathered(comm, local, MPI_LONG); }

}  // namespace gradfric
