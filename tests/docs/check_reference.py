#!/usr/bin/env python3
"""Checks that the README and the reference docs read as a reference, not as a notebook:

- no internal milestone numbers ("stop 33", "Stops 40") and no machine loads ("at load 5",
  "load average 0.8") in README.md or docs/*.md (the dated records in docs/studies/ may keep them);
- README.md has at most 200 lines, docs/accuracy_fem.md and docs/accuracy.md at most 300 each;
- CHANGES.md and CONTRIBUTING.md exist;
- every study in docs/studies/ says at its top that its bars are those of its date.

    check_reference.py <repository>     exit 1 and one line per finding if anything is wrong
    check_reference.py --self-test      shows that each kind of finding is caught
"""
import glob
import os
import re
import sys
import tempfile

import docs_check

MILESTONE = re.compile(r"\b[Ss]tops? [0-9]+\b")
LOAD = re.compile(r"\b[Ll]oad( average)? [0-9]")
MAX_LINES = {"README.md": 200, "docs/accuracy_fem.md": 300, "docs/accuracy.md": 300}
REQUIRED = ["CHANGES.md", "CONTRIBUTING.md"]
STUDY_NOTE = re.compile(r"rule of its date")  # the note every study carries near its top
STUDY_NOTE_LINES = 20


def reference_files(root):
    names = ["README.md"] + sorted(os.path.relpath(p, root) for p in glob.glob(os.path.join(root, "docs", "*.md")))
    return [n for n in names if os.path.isfile(os.path.join(root, n))]


def check(root):
    findings = []
    for name in reference_files(root):
        with open(os.path.join(root, name), encoding="utf-8") as f:
            lines = f.read().splitlines()
        for number, line in enumerate(lines, 1):
            for kind, pattern in (("an internal milestone number", MILESTONE), ("a machine load", LOAD)):
                match = pattern.search(line)
                if match:
                    findings.append(f"{name}:{number}: names {kind} ({match.group(0)!r}): {line.strip()}")
        limit = MAX_LINES.get(name)
        if limit is not None and len(lines) > limit:
            findings.append(f"{name}: {len(lines)} lines, at most {limit}")
    for name in MAX_LINES:
        if not os.path.isfile(os.path.join(root, name)):
            findings.append(f"{name}: missing")
    for name in REQUIRED:
        if not os.path.isfile(os.path.join(root, name)):
            findings.append(f"{name}: missing")
    for path in sorted(glob.glob(os.path.join(root, "docs", "studies", "*.md"))):
        name = os.path.relpath(path, root)
        if os.path.basename(path) == "README.md":
            continue  # the index
        with open(path, encoding="utf-8") as f:
            top = "\n".join(f.read().splitlines()[:STUDY_NOTE_LINES])
        if not STUDY_NOTE.search(top):
            findings.append(f"{name}: its first {STUDY_NOTE_LINES} lines do not say that its bars were computed "
                            "by the rule of its date (and that the current bars are in the reference docs)")
    return findings


def write(root, files):
    for name, text in files.items():
        path = os.path.join(root, name)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, "w", encoding="utf-8") as f:
            f.write(text)


def self_test():
    note = "> Its bars were computed by the rule of its date; the current bars are in the reference docs.\n"
    good = {
        "README.md": "# tool\n\nloading 5 times, a load of 2 N, downloads 150 MB, nonstop 3\n",
        "docs/accuracy.md": "# a\n" * 10,
        "docs/accuracy_fem.md": "# b\n" * 300,
        "docs/studies/README.md": "# index\n",
        "docs/studies/fem-x.md": "# x\n\n" + note + "at stop 33, load average 4\n",
        "CHANGES.md": "# Changes\n",
        "CONTRIBUTING.md": "# Contributing\n",
    }
    status = 0
    with tempfile.TemporaryDirectory() as root:
        write(root, good)
        findings = check(root)
        for f in findings:
            print("self-test: false finding on a good tree:", f)
            status = 1
    bad = dict(good)
    bad.update({
        "README.md": "# tool\n" + "line\n" * 200,
        "docs/accuracy_fem.md": "# b\n" * 301,
        "docs/fem.md": "measured at stop 33\nStops 40-42 decided it\nat load 5 it took\nload average 0.8\nLoad 1.2 before\n",
        "docs/studies/fem-y.md": "# y\n\nno note here\n",
    })
    del bad["CHANGES.md"]
    del bad["CONTRIBUTING.md"]
    del bad["docs/accuracy.md"]
    expected = ["README.md: 201 lines", "docs/accuracy_fem.md: 301 lines", "docs/fem.md:1: names an internal milestone",
                "docs/fem.md:2: names an internal milestone", "docs/fem.md:3: names a machine load",
                "docs/fem.md:4: names a machine load", "docs/fem.md:5: names a machine load",
                "docs/accuracy.md: missing", "CHANGES.md: missing", "CONTRIBUTING.md: missing",
                "docs/studies/fem-y.md: its first"]
    with tempfile.TemporaryDirectory() as root:
        write(root, bad)
        findings = check(root)
    return 1 if docs_check.compare_findings(findings, expected) or status else 0


if __name__ == "__main__":
    sys.exit(docs_check.run(check, self_test, lambda findings: f"reference {'OK' if not findings else 'NOT OK'}: "
                                                               f"{len(findings)} finding(s)", usage=__doc__))
