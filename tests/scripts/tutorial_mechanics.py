"""The tutorial of manual Section 2.1 slides for the right reasons (issue 4).

The three decks of examples/tutorial are run as printed (slope1 saves
SLOPE.SAV, slope2 and slope3 restart from it), with histories added and
written with HIST WRITE so the test can read them. Acceptance
(issue 4 and manual Section 2.1, Figs. 2-2 / 2-3):
  stage 1 (equilibrium, 100 cycles): maximum unbalanced force below 1e-3 of
      the weight of the lightest block (the top block: 75 m^2 x 2000 kg/m^3 x
      10 m/s^2 = 1.5e6 N, so below 1500 N); the history point (10,20) is
      taken at (5,20) as the manual says;
  stage 2 (left block deleted, friction 0.35): only the top block slides
      (0.35 < slope 0.4 of the upper joint, > 0.3 of the lower one): top
      block faster than 0.5 m/s after 1000 cycles, middle block below 0.01 m/s;
  stage 3 (friction 0.2): both slide, the top one faster: middle block faster
      than 0.5 m/s, top block faster than the middle block.
"""
import math
import os
import re
import sys
sys.path.insert(0, os.path.dirname(__file__))
from udec_test import check, finish, run, workdir, write  # noqa: E402

udec, root = sys.argv[1], sys.argv[2]
tut = os.path.join(root, "examples", "tutorial")


def deck_lines(name, drop):
    with open(os.path.join(tut, name)) as f:
        return [ln.rstrip() for ln in f if ln.strip() and not re.match(drop, ln.strip(), re.I)]


def last_value(path):
    rows = [ln.split() for ln in open(path) if not ln.startswith("#") and ln.strip()]
    return float(rows[-1][1])


stage1 = deck_lines("slope1.dat", r"(STOP)\b")
stage1.insert(stage1.index(next(ln for ln in stage1 if ln.upper().startswith("CYCLE"))), "HIST UNBAL")
d = workdir()
write(d, "stage1.dat", "\n".join(stage1 + ["HIST WRITE 2 unbal.txt", "STOP"]) + "\n")
rc, out = run(udec, ["stage1.dat"], cwd=d)
check(rc == 0 and os.path.exists(os.path.join(d, "SLOPE.SAV")), "stage 1 runs and saves SLOPE.SAV",
      out[-2000:])
check(re.search(r"history 1: YVEL \(10\.0*,20\.0*\) taken at corner \d+ \(5\.0*,20\.0*\)", out)
      is not None, "stage 1: HIST YVEL(10,20) is taken at (5,20) as the manual says", out[:3000])
if rc == 0:
    unbal = last_value(os.path.join(d, "unbal.txt"))
    print(f"stage 1: unbalanced force after 100 cycles {unbal:.4g} N (limit 1500 N)")
    check(unbal < 1.0e-3 * 75 * 2000 * 10, "stage 1: unbalanced force below 1e-3 of the top block's weight")

probes = ["HIST XVEL 5.5,4 YVEL 5.5,4 XVEL 10,20 YVEL 10,20"]
# stage 1 defines histories 1 (YVEL) and 2 (UNBAL); the probes are 3 to 6
writes = ["HIST WRITE 3 mx.txt", "HIST WRITE 4 my.txt", "HIST WRITE 5 tx.txt", "HIST WRITE 6 ty.txt"]
speeds = {}
for name in ("slope2.dat", "slope3.dat"):
    later = deck_lines(name, r"(STOP)\b")
    cyc = next(i for i, ln in enumerate(later) if ln.upper().startswith("CYCLE"))
    lines = later[:cyc] + probes + later[cyc:] + writes + ["STOP"]
    write(d, name, "\n".join(lines) + "\n")
    rc, out = run(udec, [name], cwd=d)
    check(rc == 0, f"{name} runs", out[-2000:])
    if rc != 0:
        continue
    middle = math.hypot(last_value(os.path.join(d, "mx.txt")), last_value(os.path.join(d, "my.txt")))
    top = math.hypot(last_value(os.path.join(d, "tx.txt")), last_value(os.path.join(d, "ty.txt")))
    speeds[name] = (middle, top)
    print(f"{name}: middle block {middle:.4g} m/s, top block {top:.4g} m/s")

if "slope2.dat" in speeds:
    middle, top = speeds["slope2.dat"]
    check(top > 0.5, "friction 0.35: the top block slides")
    check(middle < 0.01, "friction 0.35: the middle block holds")
if "slope3.dat" in speeds:
    middle, top = speeds["slope3.dat"]
    check(middle > 0.5, "friction 0.2: the middle block slides")
    check(top > middle, "friction 0.2: the top block slides faster than the middle block")
finish()
