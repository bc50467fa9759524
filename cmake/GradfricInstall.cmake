# `cmake --install build [--prefix P]`: the drivers into P/bin, the scenes, plotting scripts and
# slurm scripts into P/share/gradfric, the documentation into P/share/doc/gradfric (optional).
# The library is linked statically into the drivers and is not installed.
include(GNUInstallDirs)
option(GRADFRIC_INSTALL_DOCS "Install README.md and docs/ into share/doc/gradfric" ON)

foreach(driver gradfric_driver gradfric_fem_driver gradfric_study_driver gradfric_design_driver gradfric_calibrate_driver)
  if(TARGET ${driver})
    install(TARGETS ${driver} RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  endif()
endforeach()

set(GRADFRIC_INSTALL_DATADIR ${CMAKE_INSTALL_DATADIR}/gradfric)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/input/ DESTINATION ${GRADFRIC_INSTALL_DATADIR}/input
        FILES_MATCHING PATTERN "*.opts" PATTERN "*.yaml" PATTERN "*.h5" PATTERN "*.png")
# The convergence studies' measurements, read at run time by the error bars (core/study_table.hpp).
install(FILES ${PROJECT_SOURCE_DIR}/docs/fem_study.tsv ${PROJECT_SOURCE_DIR}/docs/sbm_study.tsv
        DESTINATION ${GRADFRIC_INSTALL_DATADIR}/studies)
# The plotting scripts work on any results file; scripts/setup.sh, run-*.sh and
# reproduce_paper.sh drive a source tree and stay there.
install(PROGRAMS ${PROJECT_SOURCE_DIR}/scripts/gradfric_plot.py ${PROJECT_SOURCE_DIR}/scripts/gradfric_plot_data.py
                 ${PROJECT_SOURCE_DIR}/scripts/plot_accuracy.py
                 ${PROJECT_SOURCE_DIR}/scripts/plot_design.py
                 ${PROJECT_SOURCE_DIR}/scripts/plot_calibration.py
        DESTINATION ${GRADFRIC_INSTALL_DATADIR}/scripts)
# python/gradfric (gradfric.open) beside the scripts, which import it from ../python: not into a
# Python site folder, whose name depends on the Python of the machine that installs (a cluster's
# module Python is rarely the build's); users add P/share/gradfric/python to PYTHONPATH.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/python/gradfric DESTINATION ${GRADFRIC_INSTALL_DATADIR}/python
        FILES_MATCHING PATTERN "*.py" PATTERN "__pycache__" EXCLUDE)
install(PROGRAMS ${PROJECT_SOURCE_DIR}/slurm/sbm_ensemble.sbatch ${PROJECT_SOURCE_DIR}/slurm/submit_chain.sh
                 ${PROJECT_SOURCE_DIR}/slurm/fem_sweep.sbatch ${PROJECT_SOURCE_DIR}/slurm/design.sbatch
        DESTINATION ${GRADFRIC_INSTALL_DATADIR}/slurm)

if(GRADFRIC_INSTALL_DOCS)
  install(FILES ${PROJECT_SOURCE_DIR}/README.md DESTINATION ${CMAKE_INSTALL_DOCDIR})
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR}/docs)
endif()

# An Lmod modulefile, P/share/modulefiles/gradfric/<version>.lua (`module use P/share/modulefiles`,
# `module load gradfric`): PATH, PYTHONPATH (the reader above), GRADFRIC_ROOT, GRADFRIC_DATA.
# Configured from cmake/gradfric.lua.in now; the prefix is only known at install time
# (`cmake --install --prefix P`), so it is filled in then. The modulefile derives the prefix from
# its own path (a moved tree still works) and falls back to that install prefix when copied or
# linked into a site's central modulefile tree. GRADFRIC_INSTALL_MODULEFILEDIR may be absolute
# (that central tree itself). Modules the build used (PETSc, HDF5, MPI from the site or Spack):
# -DGRADFRIC_MODULEFILE_DEPENDS="openmpi/4.1;petsc/3.18" writes a depends_on() line for each.
option(GRADFRIC_INSTALL_MODULEFILE "Install an Lmod modulefile for gradfric" ON)
set(GRADFRIC_INSTALL_MODULEFILEDIR ${CMAKE_INSTALL_DATADIR}/modulefiles CACHE STRING
    "Folder of the Lmod modulefile (the modulefile is <dir>/gradfric/<version>.lua); relative: to the prefix")
set(GRADFRIC_MODULEFILE_DEPENDS "" CACHE STRING
    "Modules the gradfric modulefile loads with depends_on(), ;-separated (e.g. openmpi/4.1;petsc/3.18)")
if(GRADFRIC_INSTALL_MODULEFILE)
  set(GRADFRIC_MODULE_VERSION ${PROJECT_VERSION})
  set(GRADFRIC_MODULE_DIR ${GRADFRIC_INSTALL_MODULEFILEDIR})
  set(GRADFRIC_MODULE_BINDIR ${CMAKE_INSTALL_BINDIR})
  set(GRADFRIC_MODULE_DATADIR ${GRADFRIC_INSTALL_DATADIR})
  # Folders from the modulefile's folder (<dir>/gradfric) up to the prefix: share/modulefiles/gradfric -> 3.
  set(GRADFRIC_MODULE_LEVELS 0)
  if(NOT IS_ABSOLUTE "${GRADFRIC_INSTALL_MODULEFILEDIR}" AND NOT GRADFRIC_INSTALL_MODULEFILEDIR MATCHES "(^|/)\\.\\.?(/|$)")
    string(REGEX REPLACE "/+$" "" module_dir "${GRADFRIC_INSTALL_MODULEFILEDIR}/gradfric")
    string(REGEX MATCHALL "[^/]+" module_dir_parts "${module_dir}")
    list(LENGTH module_dir_parts GRADFRIC_MODULE_LEVELS)
  endif()
  set(GRADFRIC_MODULE_DEPENDS_LINES "")
  foreach(dependency IN LISTS GRADFRIC_MODULEFILE_DEPENDS)
    string(APPEND GRADFRIC_MODULE_DEPENDS_LINES "depends_on(\"${dependency}\")\n")
  endforeach()
  # Replaced at install time (below), not by configure_file.
  set(GRADFRIC_MODULE_INSTALLED_PREFIX "@GRADFRIC_MODULE_INSTALLED_PREFIX@")
  set(module_template ${PROJECT_BINARY_DIR}/generated/gradfric-${PROJECT_VERSION}.lua.in)
  configure_file(${PROJECT_SOURCE_DIR}/cmake/gradfric.lua.in ${module_template} @ONLY)
  # At install time: the prefix into the text, the file under $DESTDIR, listed in install_manifest.txt.
  install(CODE "set(gradfric_module_template \"${module_template}\")
set(gradfric_module_dir \"${GRADFRIC_INSTALL_MODULEFILEDIR}/gradfric\")
set(gradfric_module_name \"${PROJECT_VERSION}.lua\")")
  install(CODE [[
get_filename_component(gradfric_module_prefix "${CMAKE_INSTALL_PREFIX}" ABSOLUTE)
if(NOT IS_ABSOLUTE "${gradfric_module_dir}")
  set(gradfric_module_dir "${gradfric_module_prefix}/${gradfric_module_dir}")
endif()
set(gradfric_module_file "$ENV{DESTDIR}${gradfric_module_dir}/${gradfric_module_name}")
file(READ "${gradfric_module_template}" gradfric_module_text)
string(REPLACE "@GRADFRIC_MODULE_INSTALLED_PREFIX@" "${gradfric_module_prefix}" gradfric_module_text "${gradfric_module_text}")
message(STATUS "Installing: ${gradfric_module_file}")
file(WRITE "${gradfric_module_file}" "${gradfric_module_text}")
list(APPEND CMAKE_INSTALL_MANIFEST_FILES "${gradfric_module_file}")
]])
endif()
