#!/bin/bash
# Stand-in srun for the Slurm script tests (copied into their bin/ as srun): records its
# arguments in $STUB_DIR/calls, then waits for $STUB_DIR/finish unless STUB_WAIT=0, and exits
# $STUB_STATUS; on SIGTERM it records it and exits 143, as a stopped srun does.
# `srun --mpi=list` answers as Slurm 22.05 does, with the plugins in STUB_MPI_PLUGINS
# (default "pmix none pmi2"; a pmix_vN alone is listed as a specific version).
if [ "${1:-}" = --mpi=list ]; then
  echo "srun --mpi=list" >> "$STUB_DIR/calls"
  echo "MPI plugin types are..."
  for plugin in ${STUB_MPI_PLUGINS-pmix none pmi2}; do
    case $plugin in
      pmix_v*) echo "specific pmix plugin versions available: $plugin" ;;
      *) printf '\t%s\n' "$plugin" ;;
    esac
  done
  exit 0
fi
echo "srun $*" >> "$STUB_DIR/calls"
trap 'echo "srun terminated" >> "$STUB_DIR/calls"; exit 143' TERM
echo started > "$STUB_DIR/started"
while [ "${STUB_WAIT:-1}" = 1 ] && [ ! -e "$STUB_DIR/finish" ]; do sleep 0.1; done
exit "${STUB_STATUS:-0}"
