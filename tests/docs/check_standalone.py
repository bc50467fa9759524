#!/usr/bin/env python3
"""Checks that the repository stands alone, as a user's clone sees it: no file links to or names
the project's planning folder outside the repository, no file refers to the tracker's issue
numbers, and every relative link in a Markdown file points to a file inside the repository.

    check_standalone.py <repository>      exit 1 and one line per finding if anything is wrong
    check_standalone.py --self-test       shows that each kind of finding is caught
"""
import os
import re
import subprocess
import sys
import tempfile

import docs_check

# Written so that this file does not match itself.
OUTSIDE = re.compile(r"\.\./" + "shared" + r"\b|\b" + "shared" + r"/(notes|reference)/")
ISSUE = re.compile(r"\b[Ii]ssues?\s+#?\d+|/issues/\d+|\b(?:PR|pull request)\s+#?\d+")
LINK = re.compile(r"!?\[[^\]]*\]\(\s*<?([^)\s>]+)>?(?:\s+\"[^\"]*\")?\s*\)")
HTML_SOURCE = re.compile(r"<(?:img|a)\s[^>]*(?:src|href)=\"([^\"]+)\"")


def tracked_files(root):
    try:
        out = subprocess.run(["git", "-C", root, "ls-files", "-z"], capture_output=True, check=True)
        names = [n for n in out.stdout.decode().split("\0") if n]
        if names:
            return names
    except (OSError, subprocess.CalledProcessError):
        pass
    names = []  # not a git checkout (a release tarball): every file but build trees
    for folder, subfolders, files in os.walk(root):
        subfolders[:] = [d for d in subfolders if d != ".git" and not d.startswith("build")]
        names += [os.path.relpath(os.path.join(folder, f), root) for f in files]
    return names


def external(target):
    return re.match(r"^[a-z][a-z0-9+.-]*:", target) is not None or target.startswith("#")


def check(root):
    root = os.path.realpath(root)
    findings = []
    for name in tracked_files(root):
        path = os.path.join(root, name)
        try:
            with open(path, encoding="utf-8") as f:
                text = f.read()
        except (UnicodeDecodeError, OSError):
            continue  # binary (figures) or unreadable: nothing to check
        for number, line in enumerate(text.splitlines(), 1):
            if OUTSIDE.search(line):
                findings.append(f"{name}:{number}: refers to a folder outside the repository: {line.strip()}")
            if ISSUE.search(line):
                findings.append(f"{name}:{number}: names an issue number: {line.strip()}")
            if not name.endswith(".md"):
                continue
            for match in list(LINK.finditer(line)) + list(HTML_SOURCE.finditer(line)):
                target = match.group(1)
                if external(target):
                    continue
                file_part = target.split("#", 1)[0]
                resolved = os.path.realpath(os.path.join(os.path.dirname(path), file_part))
                if not (resolved == root or resolved.startswith(root + os.sep)):
                    findings.append(f"{name}:{number}: link leaves the repository: {target}")
                elif not os.path.exists(resolved):
                    findings.append(f"{name}:{number}: link to a missing file: {target}")
    return findings


def self_test():
    with tempfile.TemporaryDirectory() as root:
        os.makedirs(os.path.join(root, "docs"))
        files = {
            "README.md": "[ok](docs/a.md) [ok too](https://doi.org/x) [anchor](#top)\n",
            "docs/a.md": "fine [back](../README.md)\n",
            "docs/outside.md": "see [notes](../../" + "sha" + "red/no" + "tes/model.md)\n",
            "docs/missing.md": "see [gone](nothing.md) and ![figure](fig.png)\n",
            "docs/issue.md": "done in " + "iss" + "ue 7\n",
            "src/code.cpp": "// as " + "sha" + "red/no" + "tes/model.md says\n",
        }
        for name, text in files.items():
            os.makedirs(os.path.dirname(os.path.join(root, name)), exist_ok=True)
            with open(os.path.join(root, name), "w") as f:
                f.write(text)
        findings = check(root)
        expected = ["docs/outside.md:1: refers", "docs/outside.md:1: link leaves", "docs/missing.md:1: link to a missing file: nothing.md",
                    "docs/missing.md:1: link to a missing file: fig.png", "docs/issue.md:1: names an issue", "src/code.cpp:1: refers"]
        return docs_check.compare_findings(findings, expected)


if __name__ == "__main__":
    sys.exit(docs_check.run(check, self_test))
