# Finds what gradfric links to and exposes each as one target:
#   gradfric::petsc  gradfric::hdf5  gradfric::metis  gradfric::random123   (and MPI::MPI_C)
# Works with Debian's packages (pkg-config, /usr paths) and with the PETSc of a cluster (Spack,
# modules, a build of one's own) described by PETSC_DIR / PETSC_ARCH. docs/cluster.md explains.

find_package(MPI REQUIRED COMPONENTS C CXX)
find_package(PkgConfig REQUIRED)

# --- PETSc -----------------------------------------------------------------------------------
# The PETSc way: PETSC_DIR (and PETSC_ARCH for an in-place build), as a CMake variable or in the
# environment, wins over the system's pkg-config. We then read PETSc's own build description,
# ${PETSC_DIR}/${PETSC_ARCH}/lib/pkgconfig/PETSc.pc, which every PETSc install writes.
set(PETSC_DIR "$ENV{PETSC_DIR}" CACHE PATH "PETSc installation (empty: find PETSc with pkg-config)")
set(PETSC_ARCH "$ENV{PETSC_ARCH}" CACHE STRING "PETSc architecture for an in-place PETSc build (empty for a prefix install)")
# A change of route re-runs the pkg-config lookup, which otherwise is cached by its arguments.
if(NOT "${PETSC_DIR}/${PETSC_ARCH}" STREQUAL "${GRADFRIC_PETSC_LOOKED_UP}")
  unset(__pkg_config_checked_PETSC CACHE)
  set(GRADFRIC_PETSC_LOOKED_UP "${PETSC_DIR}/${PETSC_ARCH}" CACHE INTERNAL "")
endif()
if(PETSC_DIR)
  set(petsc_pc_dir "${PETSC_DIR}/${PETSC_ARCH}/lib/pkgconfig")
  if(NOT EXISTS "${petsc_pc_dir}/PETSc.pc")
    message(FATAL_ERROR "PETSC_DIR=${PETSC_DIR} PETSC_ARCH=${PETSC_ARCH}: no ${petsc_pc_dir}/PETSc.pc. "
      "Set PETSC_DIR (and PETSC_ARCH for an in-place build) to a PETSc >= 3.18 installation, "
      "or leave PETSC_DIR empty to use the system's pkg-config.")
  endif()
  # PETSc's folder first, for this lookup only.
  set(saved_pkg_config_path "$ENV{PKG_CONFIG_PATH}")
  set(ENV{PKG_CONFIG_PATH} "${petsc_pc_dir}:$ENV{PKG_CONFIG_PATH}")
  pkg_check_modules(PETSC REQUIRED IMPORTED_TARGET PETSc>=3.18)
  pkg_get_variable(petsc_pc_used PETSc pcfiledir)
  set(ENV{PKG_CONFIG_PATH} "${saved_pkg_config_path}")
  get_filename_component(petsc_pc_used "${petsc_pc_used}" REALPATH)
  get_filename_component(petsc_pc_dir "${petsc_pc_dir}" REALPATH)
  if(NOT petsc_pc_used STREQUAL petsc_pc_dir)
    message(FATAL_ERROR "pkg-config read PETSc from ${petsc_pc_used}, not from PETSC_DIR (${petsc_pc_dir})")
  endif()
  set(GRADFRIC_PETSC_ROUTE "PETSC_DIR=${PETSC_DIR} PETSC_ARCH=${PETSC_ARCH}")
else()
  pkg_check_modules(PETSC REQUIRED IMPORTED_TARGET PETSc>=3.18)
  pkg_get_variable(petsc_pc_used PETSc pcfiledir)
  set(GRADFRIC_PETSC_ROUTE "pkg-config (${petsc_pc_used}/PETSc.pc)")
endif()
message(STATUS "gradfric: PETSc ${PETSC_VERSION} from ${GRADFRIC_PETSC_ROUTE}")
add_library(gradfric::petsc INTERFACE IMPORTED)
target_link_libraries(gradfric::petsc INTERFACE PkgConfig::PETSC)

# --- HDF5, parallel --------------------------------------------------------------------------
# Results are written collectively through MPI-IO, so a serial HDF5 cannot do. Debian installs
# both flavours; HDF5_PREFER_PARALLEL makes FindHDF5 take the MPI one (h5pcc).
# On a cluster point HDF5_ROOT (or the h5pcc on PATH) to the parallel HDF5 PETSc was built with.
set(HDF5_PREFER_PARALLEL TRUE)
find_package(HDF5 REQUIRED COMPONENTS C)
if(NOT HDF5_IS_PARALLEL)
  message(FATAL_ERROR "The HDF5 found (${HDF5_VERSION}: ${HDF5_C_INCLUDE_DIRS}) is serial; gradfric "
    "writes its results in parallel and needs an HDF5 built with MPI (Debian: libhdf5-openmpi-dev; "
    "Spack: hdf5+mpi). Point HDF5_ROOT or PATH (h5pcc) to it.")
endif()
message(STATUS "gradfric: parallel HDF5 ${HDF5_VERSION} from ${HDF5_C_INCLUDE_DIRS}")
# Two HDF5 libraries in one process (PETSc's and ours) misbehave: compare with PETSc's record.
set(petsc_variables "${PETSC_PREFIX}/lib/petsc/conf/petscvariables")
if(EXISTS "${petsc_variables}")
  file(STRINGS "${petsc_variables}" petsc_hdf5_include REGEX "^HDF5_INCLUDE *=")
  string(REGEX MATCHALL "-I[^ ]+" petsc_hdf5_include "${petsc_hdf5_include}")
  string(REPLACE "-I" "" petsc_hdf5_include "${petsc_hdf5_include}")
  if(petsc_hdf5_include)
    list(GET HDF5_C_INCLUDE_DIRS 0 our_hdf5_include)
    get_filename_component(our_hdf5_include "${our_hdf5_include}" REALPATH)
    list(GET petsc_hdf5_include 0 petsc_hdf5_include)
    get_filename_component(petsc_hdf5_include "${petsc_hdf5_include}" REALPATH)
    if(NOT our_hdf5_include STREQUAL petsc_hdf5_include)
      message(WARNING "PETSc was built with the HDF5 in ${petsc_hdf5_include}, but CMake found the one in "
        "${our_hdf5_include}. Set HDF5_ROOT to PETSc's HDF5 to link one HDF5 only.")
    endif()
  endif()
endif()
add_library(gradfric::hdf5 INTERFACE IMPORTED)
target_include_directories(gradfric::hdf5 SYSTEM INTERFACE ${HDF5_C_INCLUDE_DIRS})
target_compile_definitions(gradfric::hdf5 INTERFACE ${HDF5_C_DEFINITIONS})
target_link_libraries(gradfric::hdf5 INTERFACE ${HDF5_C_LIBRARIES} MPI::MPI_C)

# --- METIS and Random123 ---------------------------------------------------------------------
# METIS_DIR / RANDOM123_DIR (CMake variable or environment) are searched before system paths.
set(METIS_DIR "$ENV{METIS_DIR}" CACHE PATH "METIS installation prefix (empty: system paths)")
set(RANDOM123_DIR "$ENV{RANDOM123_DIR}" CACHE PATH "Random123 installation prefix (header-only; empty: system paths)")
find_path(METIS_INCLUDE_DIR metis.h HINTS ${METIS_DIR} PATH_SUFFIXES include REQUIRED)
find_library(METIS_LIBRARY metis HINTS ${METIS_DIR} PATH_SUFFIXES lib lib64 REQUIRED)
find_path(RANDOM123_INCLUDE_DIR Random123/philox.h HINTS ${RANDOM123_DIR} PATH_SUFFIXES include REQUIRED)
message(STATUS "gradfric: METIS ${METIS_LIBRARY}, Random123 ${RANDOM123_INCLUDE_DIR}")
add_library(gradfric::metis INTERFACE IMPORTED)
target_include_directories(gradfric::metis SYSTEM INTERFACE ${METIS_INCLUDE_DIR})
target_link_libraries(gradfric::metis INTERFACE ${METIS_LIBRARY})
add_library(gradfric::random123 INTERFACE IMPORTED)
target_include_directories(gradfric::random123 SYSTEM INTERFACE ${RANDOM123_INCLUDE_DIR})

# --- Optional: tests and benchmarks ----------------------------------------------------------
# Without GoogleTest the C++ tests are skipped (the script tests still run); without Google
# Benchmark the benchmarks are skipped. GRADFRIC_REQUIRE_ALL=ON (CI) turns either into an error.
option(GRADFRIC_REQUIRE_ALL "Fail when GoogleTest or Google Benchmark is missing instead of skipping" OFF)
if(GRADFRIC_TESTS)
  find_package(GTest)
  if(NOT GTest_FOUND)
    if(GRADFRIC_REQUIRE_ALL)
      message(FATAL_ERROR "GoogleTest not found (GRADFRIC_REQUIRE_ALL=ON): install it (Debian: googletest libgtest-dev; Spack: googletest) or set GTest_ROOT")
    endif()
    message(WARNING "GoogleTest not found: the C++ tests are skipped, the script tests still run. "
      "Install it (Debian: libgtest-dev; Spack: googletest) or set GTest_ROOT; -DGRADFRIC_TESTS=OFF silences this.")
  endif()
endif()
if(GRADFRIC_BENCHMARKS)
  find_package(benchmark QUIET)
  if(NOT benchmark_FOUND)
    if(GRADFRIC_REQUIRE_ALL)
      message(FATAL_ERROR "Google Benchmark not found (GRADFRIC_REQUIRE_ALL=ON): install it (Debian: libbenchmark-dev; Spack: benchmark) or set benchmark_ROOT")
    endif()
    message(WARNING "Google Benchmark not found: the benchmarks are not built. "
      "Install it (Debian: libbenchmark-dev; Spack: benchmark) or set benchmark_ROOT; -DGRADFRIC_BENCHMARKS=OFF silences this.")
    set(GRADFRIC_BENCHMARKS OFF)
  endif()
endif()
