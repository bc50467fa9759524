// Broadcasts of values one rank knows (include/gradfric/core/broadcast.hpp).
#include "gradfric/core/broadcast.hpp"

#include "gradfric/core/petsc_call.hpp"

namespace gradfric {

namespace {

template <class Container>
void broadcastContainer(MPI_Comm comm, Container& c, MPI_Datatype type, int root) {
  unsigned long n = c.size();
  GF_CALL_MPI(MPI_Bcast(&n, 1, MPI_UNSIGNED_LONG, root, comm));
  c.resize(n);
  if (n > 0) GF_CALL_MPI(MPI_Bcast(c.data(), static_cast<int>(n), type, root, comm));
}

}  // namespace

void broadcast(MPI_Comm comm, std::string& text, int root) { broadcastContainer(comm, text, MPI_CHAR, root); }

void broadcast(MPI_Comm comm, std::vector<double>& values, int root) {
  broadcastContainer(comm, values, MPI_DOUBLE, root);
}

}  // namespace gradfric
