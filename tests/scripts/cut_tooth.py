"""A cut that would leave a tooth (label e2e; session 43, docs/geometry.md
"Short edges (EDGE)"). A new user's deck (l3: a 50 m square, ROUND 0.1, two
finite JSETs, TUNNEL, GEN QUAD 2) did not balance without MSCALE ON: a joint
ended on another 0.33 m from that joint's end, at 6.5 degrees, and left a
tooth of its block 0.038 m wide at that end, thinner than EDGE (0.2 m, twice
ROUND: UDEC manual (ICG1.5), Section 4, EDGE: "the minimum block edge");
GENERATE made zones of 2.3e-4 m2 in it (1/2315 of the mean) whose gridpoints
set the step. Now a cut end whose edge's nearer corner on the acute side lies
within EDGE of the cut's line moves onto that corner. Checked:
1. The same tooth drawn with three CRACKs in a 10 m square: the third CRACK
   moves its end onto the corner (5, 5) (no corner left at its end on the
   first CRACK); GENERATE EDGE 1 warns of no small zone; the smallest zone is
   above 1/20 of the mean (measured 1/3; before 1/1000) and the step above
   1e-5 s (measured 3.4e-5 s; before 1.76e-6 s, the tooth's zones).
2. The same deck with the third CRACK at 40 degrees to the first: the corner
   lies 0.214 m from its line, more than EDGE: the end stays where it is.
3. l3's set-up (JSETs, TUNNEL, GEN QUAD 2): GENERATE warns of no small zone
   and its smallest zone is above 1/500 of the mean (GENERATE's own bound for
   its warning; before 1/2315).
"""
import math
import re
import sys
from udec_test import check, finish, printed_number, run, workdir, write

udec = sys.argv[1]
d = workdir()
E = (5.0, 5.0)
TOP = (3.0, 10.0)


def tooth_deck(angle):
    """Joint A from the top to E, a joint from the left edge ending at E, and
    joint B ending on A 0.333 m above E at `angle` degrees to A (crossing it
    by 0.5 m, a partial piece GENERATE forgets)."""
    ax, ay = TOP[0] - E[0], TOP[1] - E[1]
    length = math.hypot(ax, ay)
    ux, uy = ax / length, ay / length
    p = (E[0] + 0.333 * ux, E[1] + 0.333 * uy)
    th = math.atan2(-uy, -ux) + math.radians(angle)
    dx, dy = math.cos(th), math.sin(th)
    t = p[1] / (-dy)
    b0 = (p[0] + t * dx, 0.0)
    b1 = (p[0] - 0.5 * dx, p[1] - 0.5 * dy)
    deck = f"""ROUND 0.1
BLOCK 0,0 0,10 10,10 10,0
CRACK {TOP[0]},{TOP[1]} {E[0]},{E[1]}
CRACK 0,2 {E[0]},{E[1]}
CRACK {b0[0]:.6f},{b0[1]:.6f} {b1[0]:.6f},{b1[1]:.6f}
PRINT CORNERS
GEN EDGE 1.0
PROP MAT 1 D 2700 K 30e9 G 18e9
PROP JMAT 1 JKN 2e10 JKS 1e10 JFRIC 0.6
CYCLE 1
PRINT MAX
PRINT STATUS
"""
    return deck, p


def corners(out):
    rows = []
    for line in out.splitlines():
        f = line.split()
        if len(f) == 8 and f[0].isdigit() and f[1].isdigit() and "E" in f[2]:
            rows.append((float(f[2]), float(f[3])))
    return rows


def near(rows, p, tol=1e-4):
    return any(math.hypot(x - p[0], y - p[1]) < tol for x, y in rows)


# 1. the tooth of 6.5 degrees
deck, p = tooth_deck(6.5)
write(d, "tooth.dat", deck)
rc, out = run(udec, ["tooth.dat"], cwd=d, timeout=120)
cracks = [l for l in out.splitlines() if l.startswith("CRACK:")]
check(rc == 0 and "***" not in out, "the tooth deck runs", out[-1500:])
check(len(cracks) == 3 and "1 cuts made, 1 cut ends moved onto corners" in cracks[2],
      "the third CRACK's end moves onto the corner of the first", "\n".join(cracks))
rows = corners(out)
check(near(rows, E) and not near(rows, p), "no corner where the third CRACK met the first",
      f"corner at E: {near(rows, E)}, at the crack's end {p}: {near(rows, p)}")
check("of the mean zone" not in out, "GENERATE warns of no small zone",
      "\n".join(l for l in out.splitlines() if "GENERATE" in l))
zmin = printed_number(out, "zone mass, minimum")
zmean = printed_number(out, "zone mass, average")
check(zmin > zmean / 20.0, "the smallest zone is above 1/20 of the mean (before 1/1000)",
      f"{zmin} / {zmean}")
m = re.search(r"^\s*time step\s+(\S+)", out, re.M)  # PRINT STATUS
step = float(m.group(1)) if m else float("nan")
check(step > 1.0e-5, "the step is above 1e-5 s (before 1.76e-6 s)", f"{step}")

# 2. at 40 degrees the corner is 0.214 m (> EDGE 0.2) from the crack: kept
deck, p = tooth_deck(40.0)
write(d, "wedge.dat", deck)
rc, out = run(udec, ["wedge.dat"], cwd=d, timeout=120)
cracks = [l for l in out.splitlines() if l.startswith("CRACK:")]
check(len(cracks) == 3 and "0 cut ends moved onto corners" in cracks[2] and near(corners(out), p),
      "a crack meeting the joint at 40 degrees ends where it was drawn", "\n".join(cracks))

# 3. l3's set-up
L3 = "\n".join(["ROUND 0.1", "BLOCK 0,0 0,50 50,50 50,0",
                "JSET 30,10 20,5 3,1 2.5,0.5 (0,0)", "JSET -60,10 20,5 3,1 2.5,0.5 (0,0)",
                "TUNNEL 25 25 3 24", "GEN QUAD 2", "CHANGE CONS 3",
                "PROP MAT 1 D 2700 K 30e9 G 18e9 COH 5e6 FRIC 35 TEN 1e6", "PRINT MAX", ""])
write(d, "l3.dat", L3)
rc, out = run(udec, ["l3.dat"], cwd=d, timeout=120)
check(rc == 0 and "of the mean zone" not in out, "l3: GENERATE warns of no small zone",
      "\n".join(l for l in out.splitlines() if "GENERATE" in l))
zmin = printed_number(out, "zone mass, minimum")
zmean = printed_number(out, "zone mass, average")
check(zmin > zmean / 500.0, "l3: the smallest zone is above 1/500 of the mean (before 1/2315)",
      f"{zmin} / {zmean}")
finish()
