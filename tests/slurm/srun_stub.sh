#!/bin/bash
# Stand-in srun for the Slurm script tests (copied into their bin/ as srun): records its
# arguments in $STUB_DIR/calls, then waits for $STUB_DIR/finish unless STUB_WAIT=0, and exits
# $STUB_STATUS; on SIGTERM it records it and exits 143, as a stopped srun does.
echo "srun $*" >> "$STUB_DIR/calls"
trap 'echo "srun terminated" >> "$STUB_DIR/calls"; exit 143' TERM
echo started > "$STUB_DIR/started"
while [ "${STUB_WAIT:-1}" = 1 ] && [ ! -e "$STUB_DIR/finish" ]; do sleep 0.1; done
exit "${STUB_STATUS:-0}"
