#!/usr/bin/env bash
# One command: install what is missing, build, and run the default scene (input/default.opts).
# Builds only the driver and its libraries; scripts/run-tests.sh builds the rest in the same tree.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$here/scripts/setup.sh" --target gradfric_driver "$here/build"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mkdir -p "$here/results"
exec mpiexec --oversubscribe -n "${NP:-2}" "$here/build/drivers/gradfric" \
  -options_file "$here/input/default.opts" -output "$here/results/default.h5" -output_overwrite "$@"
