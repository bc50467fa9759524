"""The command line every docs check shares: `<check> <repository>` prints one line per finding
and exits 1 if there is any; `<check> --self-test` shows that each kind of finding is caught."""
import sys


def run(check, self_test, verdict=lambda findings: f"{len(findings)} finding(s)", usage=None):
    if sys.argv[1:] == ["--self-test"]:
        status = self_test()
        print("self-test", "failed" if status else "passed")
        return status
    if len(sys.argv) != 2:
        print(usage or "usage: %s <repository> | --self-test" % sys.argv[0])
        return 2
    findings = check(sys.argv[1])
    for f in findings:
        print(f)
    print(verdict(findings))
    return 1 if findings else 0


def compare_findings(findings, expected):
    """A self-test's verdict: 0 if every expected finding (a prefix) was made and no other; each
    miss and each false finding printed."""
    missed = [e for e in expected if not any(f.startswith(e) for f in findings)]
    extra = [f for f in findings if not any(f.startswith(e) for e in expected)]
    for m in missed:
        print("self-test: not caught:", m)
    for e in extra:
        print("self-test: false finding:", e)
    return 1 if missed or extra else 0
