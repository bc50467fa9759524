#!/usr/bin/env bash
# Regenerates the docs' tables of the convergence studies from the study tables themselves: every
# block between `<!-- BEGIN generated: gradfric-study -study_judge docs/X.tsv -->` and
# `<!-- END generated -->` in docs/*.md becomes that command's output (the one verification
# procedure, docs/verification.md). Nothing else in the docs is touched.
# Usage: scripts/regenerate_docs_tables.sh [build-dir] [--check]
#   --check  change nothing; exit 1 naming the stale blocks (the docs test runs this).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
source "$here/scripts/generated_file_args.sh"
judge=$build/drivers/gradfric-study
[ -x "$judge" ] || { echo "regenerate_docs_tables: $judge not built (cmake --build $build --target gradfric_study_driver)" >&2; exit 2; }
cd "$here"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
python3 - "$judge" "$check" docs/*.md <<'PY'
import re, subprocess, sys
judge, check, docs = sys.argv[1], sys.argv[2] == "1", sys.argv[3:]
block = re.compile(r"(<!-- BEGIN generated: gradfric-study -study_judge (\S+) -->\n)(.*?)(<!-- END generated -->)", re.S)
stale = []
for doc in docs:
    text = open(doc, encoding="utf-8").read()
    def fill(m):
        out = subprocess.run([judge, "-study_judge", m.group(2)], capture_output=True, text=True)
        if out.returncode != 0:
            sys.exit("regenerate_docs_tables: %s -study_judge %s failed:\n%s" % (judge, m.group(2), out.stdout + out.stderr))
        return m.group(1) + out.stdout + m.group(4)
    new = block.sub(fill, text)
    if new != text:
        stale.append(doc)
        if not check:
            open(doc, "w", encoding="utf-8").write(new)
if check and stale:
    sys.exit("stale generated tables in %s: run scripts/regenerate_docs_tables.sh" % ", ".join(stale))
print("generated tables %s: %s" % ("checked" if check else "regenerated", ", ".join(docs)))
PY
