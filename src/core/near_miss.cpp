#include "gradfric/core/near_miss.hpp"

#include <algorithm>

namespace gradfric {

size_t editDistance(const std::string& a, const std::string& b) {
  const size_t n = a.size(), m = b.size();
  std::vector<std::vector<size_t>> d(n + 1, std::vector<size_t>(m + 1));
  for (size_t i = 0; i <= n; ++i) d[i][0] = i;
  for (size_t j = 0; j <= m; ++j) d[0][j] = j;
  for (size_t i = 1; i <= n; ++i)
    for (size_t j = 1; j <= m; ++j) {
      const size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[n][m];
}

std::string nearMiss(const std::string& name, const std::vector<std::string>& known) {
  const size_t allowed = name.size() <= 6 ? 1 : 2;  // "-ouput" has 6 characters with its dash
  std::string best;
  size_t bestDistance = allowed + 1;
  for (const auto& candidate : known) {
    const size_t distance = editDistance(name, candidate);
    if (distance > 0 && distance < bestDistance) {
      best = candidate;
      bestDistance = distance;
    }
  }
  return best;
}

bool isPetscOptionName(const std::string& name) {
  // Prefixes of PETSc 3.18's components and of the options PetscInitialize/PetscFinalize read.
  static const char* const prefixes[] = {
      "help", "version", "options_", "log", "malloc", "memory_", "info", "ts_", "snes_", "ksp_", "pc_", "mat_",
      "vec_", "dm_", "da_", "plex_", "petscpartitioner_", "petscsection_", "sf_", "is_", "tao_", "viewer_",
      "draw_", "on_error_", "fp_trap", "debugger", "start_in_debugger", "stop_for_debugger", "no_signal_handler",
      "check_pointer_intensity", "mpi_", "saws", "objects_dump", "history", "skip_petscrc", "use_gpu_aware_mpi",
      "device_", "cuda_", "hip_", "kokkos_", "error_output_", "nox", "display", "x_virtual", "python", "checkstack",
      "petscspace_", "petscfe_", "petscds_", "petscdualspace_", "random_", "options_left", "citations",
      "matload_", "bag_", "prefix_push", "prefix_pop", "timeout", "omp_", "compare", "petsc_", "ao_",
      "characteristic_", "pf_", "ls_"};
  for (const char* prefix : prefixes)
    if (name.rfind(prefix, 0) == 0) return true;
  return false;
}

}  // namespace gradfric
