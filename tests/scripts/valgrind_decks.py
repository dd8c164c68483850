"""Issue 20: udec under valgrind (memcheck) on the tutorial (manual Section 2.1,
the three decks in order: slope2 and slope3 restart from slope1's save),
verification B (manual Appendix A, Verification Test B) and application A1
(manual Appendix B, Application Problem A): no invalid read or write, no use of
an uninitialised value, no definite leak outside libOSMesa's own allocations
(tests/valgrind.supp). CYCLE counts are capped at 100 (memcheck runs the
program about 50 times slower; the answers are checked elsewhere, this checks
memory). Skipped, with status 77, when valgrind is not installed."""
import os
import re
import shutil
import subprocess
import sys
sys.path.insert(0, os.path.dirname(__file__))
from udec_test import check, finish, workdir  # noqa: E402

udec = sys.argv[1]
source = sys.argv[2]
valgrind = shutil.which("valgrind")
if valgrind is None:
    print("SKIPPED: valgrind is not installed (tools/install-deps.sh installs it)")
    sys.exit(77)
supp = os.path.join(source, "tests", "valgrind.supp")


def capped(text, limit=100):
    def cap(m):
        return m.group(1) + str(min(int(m.group(2)), limit))
    return re.sub(r"(?im)^(\s*(?:cycle|cyc|cy)\s+)(\d+)", cap, text)


def memcheck(folder, deck):
    log = os.path.join(folder, deck + ".vg")
    p = subprocess.run([valgrind, "--leak-check=full", "--errors-for-leak-kinds=definite",
                        "--error-exitcode=99", "--num-callers=30", "--suppressions=" + supp,
                        "--log-file=" + log, udec, deck],
                       cwd=folder, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=1200)
    report = open(log).read()
    out = p.stdout.decode("latin-1")
    errors = re.search(r"ERROR SUMMARY: (\d+) errors", report)
    lost = re.search(r"definitely lost: ([\d,]+) bytes", report)
    lost = lost.group(1) if lost else "0"     # no leak summary: nothing lost
    check(p.returncode == 0 and errors is not None and errors.group(1) == "0" and lost == "0",
          "%s under valgrind: status %d, %s errors, %s bytes definitely lost"
          % (deck, p.returncode, errors.group(1) if errors else "?", lost),
          report[-6000:] + "\n" + out[-1500:])


runs = [("examples/tutorial", ["slope1.dat", "slope2.dat", "slope3.dat"]),
        ("verification/B", ["B.dat"]),
        ("examples/application/A", ["A1_static_seismic_1p25MPa.dat"])]
for folder, deck_names in runs:
    d = workdir()
    for name in deck_names:
        with open(os.path.join(source, folder, name), encoding="latin-1") as f:
            text = f.read()
        with open(os.path.join(d, name), "w", encoding="latin-1") as f:
            f.write(capped(text))
    for name in deck_names:
        memcheck(d, name)
    shutil.rmtree(d, ignore_errors=True)
finish()
