"""CITATION.cff names the version the tree builds and cites the paper it reproduces (no YAML
parser needed: the fields are plain `key: value` lines)."""
import re
import sys

text = open(sys.argv[1]).read()
version = re.search(r"^version:\s*(\S+)\s*$", text, re.M)
if not version or version.group(1) != sys.argv[2]:
    sys.exit(f"CITATION.cff version {version.group(1) if version else None}, the build says {sys.argv[2]}")
if not re.search(r"^\s+doi:\s*10\.3762/bjnano\.9\.229\s*$", text, re.M):
    sys.exit("CITATION.cff does not cite the paper (doi 10.3762/bjnano.9.229)")
if not re.search(r"^cff-version:\s*1\.2\.0\s*$", text, re.M):
    sys.exit("CITATION.cff: cff-version 1.2.0 expected")
print(f"citation OK: version {sys.argv[2]}, the paper's DOI")
