#!/bin/bash
# Submits a chain of resumable jobs for one scene, for clusters where a job cannot requeue
# itself: job k+1 starts after job k ends (whatever its end: completed, failed or timed out) and
# continues the results file; once the file is complete the remaining jobs only print the
# statistics and exit within seconds.
#
#   slurm/submit_chain.sh <jobs> <scene.opts> <output.h5> [sbatch options --] [gradfric options...]
#   e.g. slurm/submit_chain.sh 4 input/sbm_fig8.opts results/sbm_fig8.h5 --nodes=4 --time=01:00:00 --
set -euo pipefail
if [ $# -lt 3 ]; then
  echo "usage: slurm/submit_chain.sh <jobs> <scene.opts> <output.h5> [sbatch options --] [gradfric options...]" >&2
  exit 2
fi
jobs=$1
scene=$2
output=$3
shift 3
sbatch_options=()
if [[ " $* " == *" -- "* ]]; then
  while [ $# -gt 0 ] && [ "$1" != "--" ]; do
    sbatch_options+=("$1")
    shift
  done
  shift
fi
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
previous=""
for k in $(seq 1 "$jobs"); do
  dependency=()
  [ -z "$previous" ] || dependency=(--dependency=afterany:"$previous")
  previous=$(sbatch --parsable --no-requeue "${dependency[@]}" "${sbatch_options[@]}" \
    --export=ALL,GRADFRIC_NO_REQUEUE=1 "$here/sbm_ensemble.sbatch" "$scene" "$output" "$@")
  echo "job $k of $jobs: $previous"
done
