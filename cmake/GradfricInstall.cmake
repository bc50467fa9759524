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
