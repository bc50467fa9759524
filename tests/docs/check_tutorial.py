"""Runs the commands of docs/tutorial.md (steps 2 to 6: every ```sh block after the first) in a
scratch folder laid out like the repository (build, input, scripts, python linked), and checks
that each succeeds and prints the tutorial's key lines: the same labels and, for the values shown,
the same numbers to the digits printed (the scenes are seeded)."""
import os
import re
import subprocess
import sys

source, build, scratch = sys.argv[1:4]
text = open(os.path.join(source, "docs", "tutorial.md")).read()
blocks = re.findall(r"```(sh|text)\n(.*?)```", text, re.S)
os.makedirs(scratch, exist_ok=True)
for name, target in (("build", build), ("input", os.path.join(source, "input")),
                     ("scripts", os.path.join(source, "scripts")), ("python", os.path.join(source, "python"))):
    link = os.path.join(scratch, name)
    if os.path.lexists(link):
        os.remove(link)
    os.symlink(target, link)
os.makedirs(os.path.join(scratch, "results"), exist_ok=True)
env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
           OMPI_MCA_rmaps_base_oversubscribe="1", PYTHONPATH=os.path.join(source, "python"))
sh_blocks = [i for i, (kind, _) in enumerate(blocks) if kind == "sh"]
runs = 0
for i in sh_blocks[1:]:  # the first block is setup.sh itself
    output = ""
    for command in blocks[i][1].strip().splitlines():
        command = command.split("  #")[0].strip()
        if not command:
            continue
        if os.path.exists(os.path.join(scratch, "results")) and "-output " in command:
            command += " -output_overwrite"
        r = subprocess.run(["bash", "-c", command], cwd=scratch, env=env, capture_output=True, text=True, timeout=600)
        if r.returncode != 0:
            sys.exit(f"tutorial command failed (exit {r.returncode}): {command}\n{r.stdout[-1500:]}{r.stderr[-1500:]}")
        output += r.stdout + r.stderr
        runs += 1
    expected = blocks[i + 1][1] if i + 1 < len(blocks) and blocks[i + 1][0] == "text" else ""
    for line in expected.splitlines():
        key = line.split("...")[0].strip()
        if not key:
            continue
        if key not in output:
            sys.exit(f"tutorial: the output of block {i} lacks the line starting {key!r}")
print(f"tutorial OK: {runs} commands ran and printed what docs/tutorial.md shows")
