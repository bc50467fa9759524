#!/usr/bin/env bash
# Writes docs/options.md, the reference of every driver's options, from the drivers themselves:
# each built driver is run with -help and GRADFRIC_HELP_FORMAT=tsv (src/core/options.cpp), which
# prints one line per option read through OptionReader: section, name, default, unit, help.
#   bash scripts/options_reference.sh [build-dir] [output]    (defaults: build, docs/options.md)
# One section per driver, one table per option section. The output depends on the sources only:
# one rank, no options files (-skip_petscrc, no PETSC_OPTIONS), run in an empty folder, no paths.
# tests/docs/check_options_reference.sh fails when docs/options.md is not what this writes.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${1:-build}
output=${2:-$here/docs/options.md}
fail() { echo "options_reference: $*" >&2; exit 1; }
[ -d "$build/drivers" ] || fail "no $build/drivers: give the build folder (bash scripts/options_reference.sh build)"
build=$(cd "$build" && pwd)

# The drivers, in this order (drivers/CMakeLists.txt names them; a driver added there and not
# listed here is refused below, so the reference cannot silently miss one). Per driver, the extra
# -help runs whose choices read options the default run does not (their options are merged in,
# each listed once, with the default of the first run that lists it); several runs: separated by ;.
drivers=(gradfric gradfric-fem gradfric-study gradfric-design gradfric-calibrate)
declare -A variants=(
  [gradfric-study]="-study_model fem"
)
for name in $(sed -n 's/.*OUTPUT_NAME \([A-Za-z0-9_-]*\).*/\1/p' "$here/drivers/CMakeLists.txt"); do
  [[ " ${drivers[*]} " == *" $name "* ]] || fail "driver $name (drivers/CMakeLists.txt) is not listed in $0"
done

# Open MPI refuses to run as root without these; harmless otherwise (as in scripts/setup.sh).
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir "$work/run"
for driver in "${drivers[@]}"; do
  exe=$build/drivers/$driver
  [ -x "$exe" ] || fail "$exe not built (cmake --build $build --target <its target>)"
  runs=("")
  if [ -n "${variants[$driver]:-}" ]; then
    IFS=';' read -r -a more <<< "${variants[$driver]}"
    runs+=("${more[@]}")
    printf '%s\n' "${more[@]}" > "$work/$driver.variants"
  fi
  : > "$work/$driver.tsv"
  for extra in "${runs[@]}"; do
    # shellcheck disable=SC2086  # the extra options are words
    if ! (cd "$work/run" && env -u PETSC_OPTIONS GRADFRIC_HELP_FORMAT=tsv HOME="$work/run" \
            "$exe" -help -skip_petscrc $extra > "$work/out" 2> "$work/err"); then
      cat "$work/err" >&2
      fail "$driver -help $extra failed"
    fi
    # Our lines only: five tab-separated fields, the second an option (PETSc's own help has no tabs).
    awk -F'\t' 'NF == 5 && $2 ~ /^-[A-Za-z]/' "$work/out" >> "$work/$driver.tsv"
    [ -s "$work/$driver.tsv" ] || fail "$driver -help $extra printed no option line (GRADFRIC_HELP_FORMAT=tsv unknown to it?)"
  done
done

/usr/bin/env python3 - "$work" "$build" "$here" "$output" "${drivers[@]}" <<'EOF'
import os
import re
import sys

work, build, source, output, drivers = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4], sys.argv[5:]


def cell(text):
    # Markdown table cells: | escaped; <name> would be read as an HTML tag (<= and < 1 are left).
    text = text.replace("\\", "\\\\").replace("|", "\\|")
    return re.sub(r"<(?=[A-Za-z/])", "&lt;", text)


def code(text):
    if text == "":
        return "(empty)"
    if "`" in text:
        return cell(text)
    return "`" + text.replace("|", "\\|") + "`"


lines = [
    "# Options of the drivers",
    "",
    "Generated from the drivers' `-help` by `scripts/options_reference.sh`; do not edit by hand.",
    "After a change to any option (name, default, unit or help), regenerate it from a build:",
    "",
    "    bash scripts/options_reference.sh build",
    "",
    "The test `docs_options_reference` fails while this file differs from what the drivers print.",
    "Every option is read by `OptionReader` (include/gradfric/core/options.hpp). The default is",
    "the built-in one; one written as a formula (`L/10`, `0.5 t_load`) follows from other options.",
    "Unit `1`: dimensionless; no unit: a word, a flag or a file.",
    "PETSc's own options (-ts_, -tao_, -dm_, ...) are not listed: `-help` shows them.",
    "",
]
lines.append("Drivers: " + ", ".join(f"[{d}](#{d})" for d in drivers) + ".")
for driver in drivers:
    sections, rows, seen = [], {}, set()
    with open(f"{work}/{driver}.tsv", encoding="utf-8") as f:
        for raw in f:
            section, name, default, unit, help_text = raw.rstrip("\n").split("\t")
            for path, placeholder in ((build, "<build>"), (source, "<source>")):
                default = default.replace(path, placeholder)
                help_text = help_text.replace(path, placeholder)
            if name in seen:
                continue
            seen.add(name)
            if section not in rows:
                sections.append(section)
                rows[section] = []
            rows[section].append((name, default, unit, help_text))
    lines += ["", f"## {driver}", "", f"{len(seen)} options in {len(sections)} sections."]
    if os.path.exists(f"{work}/{driver}.variants"):
        with open(f"{work}/{driver}.variants", encoding="utf-8") as f:
            extra = " and ".join(f"`{v.strip()}`" for v in f if v.strip())
        lines[-1] = (f"{len(seen)} options in {len(sections)} sections, including those `-help` lists only "
                     f"under {extra} (with their defaults there).")
    for section in sections:
        lines += ["", f"### {cell(section)}", "", "| option | default | unit | description |",
                  "|---|---|---|---|"]
        for name, default, unit, help_text in rows[section]:
            lines.append(f"| `{name}` | {code(default)} | {cell(unit)} | {cell(help_text)} |")
with open(output, "w", encoding="utf-8") as f:
    f.write("\n".join(lines) + "\n")
EOF
echo "options_reference: wrote $output"
