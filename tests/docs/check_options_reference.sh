#!/usr/bin/env bash
# docs/options.md is what scripts/options_reference.sh writes from the drivers of this build: an
# option added, renamed, removed or given another default, unit or help without regenerating the
# reference fails here, with the command that regenerates it.
#   check_options_reference.sh <source-dir> <build-dir> <work-dir>
set -euo pipefail
source_dir=$1
build=$2
work=$3
mkdir -p "$work"
fresh=$work/options.md
bash "$source_dir/scripts/options_reference.sh" "$build" "$fresh" > /dev/null
if ! diff -u "$source_dir/docs/options.md" "$fresh" > "$work/options.diff"; then
  head -n 60 "$work/options.diff"
  echo "FAIL: docs/options.md is out of date with the drivers' options (full diff: $work/options.diff)." >&2
  echo "Regenerate it from the source folder with: bash scripts/options_reference.sh build" >&2
  exit 1
fi
echo "options reference OK: docs/options.md matches the drivers' -help"
