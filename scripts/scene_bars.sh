#!/usr/bin/env bash
# The discretisation bars of every shipped scene (input/*.opts run by gradfric or gradfric-fem), from
# their dry runs (the bars depend on the settings only): the golden file tests/golden/scene_bars.txt.
# A change to the procedure, to a study table or to a scene shows up there as a diff to review.
# Usage: scripts/scene_bars.sh [build-dir] [--check]
#   --check  change nothing; exit 1 with the diff if the golden file is stale (a ctest runs this).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
source "$here/scripts/generated_file_args.sh"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
golden=$here/tests/golden/scene_bars.txt
out=$(mktemp)
trap 'rm -f "$out"' EXIT
{
  echo "# The discretisation bars of the shipped scenes (scripts/scene_bars.sh; docs/verification.md)."
  for scene in "$here"/input/*.opts; do
    name=$(basename "$scene")
    case $name in
      design_*|calibrate_*|study_*) continue ;;                      # other drivers: no bars of their own
      sbm_variant_*) continue ;;                                     # design variants: laid over a scene
      fem_*) command=("$build/drivers/gradfric-fem" -options_file "$scene" -fem_dry_run) ;;
      *) command=("$build/drivers/gradfric" -options_file "$scene" -ensemble_dry_run) ;;
    esac
    if ! text=$("${command[@]}" 2>&1); then
      echo "scene_bars: ${command[*]} failed:" >&2
      echo "$text" >&2
      exit 2
    fi
    grep '^  bar point ' <<<"$text" | sed -e "s|^  bar|$name:|" -e "s|$here/|<checkout>/|g"  # any clone alike
  done
} >"$out"
if [ "$check" = 1 ]; then
  if ! diff -u "$golden" "$out"; then
    echo "scene_bars: tests/golden/scene_bars.txt is stale: review the diff above, then run scripts/scene_bars.sh" >&2
    exit 1
  fi
  echo "scene bars checked: $(grep -vc '^#' "$golden") bars"
else
  cp "$out" "$golden"
  echo "scene bars written: $(grep -vc '^#' "$golden") bars into tests/golden/scene_bars.txt"
fi
