"""PRINT CONTACT DISP: the normal displacement of a contact follows the
opening of its joint (label `e2e`).

The normal displacement un (PRINT CONTACT DISP "NORMAL-DISP", HISTORY NDIS,
and the hydraulic aperture a0 + un of the manual's Eq. 55, Section 3.9) is
the relative normal displacement of the two sides, opening positive: its
change is the change of the gap between them. The joint law took only the
closing part of a step that closes an open contact, and nothing while it
was open; un kept that and stopped following the joint: a block lifted
13 mm off its joint showed 8.3e-7 m, and the trailing contact of a zoned
block sliding down a slope, opening and closing by a micrometre, gained
the difference at each chatter (6.4e-5 m open, where the gap was 1.9e-6 m
closed, after 3.6 m of slide; the s34 lead's debt).

Checks (exact up to PRINT's six digits: un - un0 = gap - gap0):
- a rigid block and a zoned block (QUAD) resting on a fixed block, then
  pulled up by GRAVITY 0 10: both contacts open by more than 1 mm, and
  NORMAL-DISP equals GAP (both start at the same closure, un0 = gap0);
- a zoned block sliding 0.7 m down a 30-degree joint (friction 20
  degrees, no damping): NORMAL-DISP equals GAP on every contact at every
  print.
"""
import math
import re
import sys
from shared_decks import turned
from udec_test import check, finish, run_deck, workdir

udec = sys.argv[1]
d = workdir()

LIFT = """round 0.01
block 0,0 0,2 4,2 4,0
crack -1,1 5,1
prop mat=1 dens=2000 k=1e10 g=1e10
prop jmat=1 jkn=1e10 jks=1e10 jfric=0.5
fix 0,4 0,1
{gen}
grav 0 -10
damp auto
cycle 2000
grav 0 10
damp 0 1
cycle 400
print contact disp
stop
"""


def disp_rows(out):
    rows = []
    for block in re.split(r"\n CONTACT  BLOCK1  BLOCK2             X             Y    SHEAR-DISP", out)[1:]:
        for ln in block.splitlines()[1:]:
            f = ln.split()
            if len(f) != 8 or not f[0].isdigit():
                break
            rows.append((int(f[0]), float(f[6]), float(f[7])))
    return rows


def same(un, gap):
    return abs(un - gap) <= 2e-6 * max(abs(gap), 1e-6)


for name, gen in (("rigid", ""), ("zoned", "gen 0,4 1,2 quad 0.5")):
    rc, out = run_deck(udec, d, "lift_" + name, LIFT.format(gen=gen))
    rows = disp_rows(out)
    check(len(rows) >= 2 and all(g > 1e-3 for _, _, g in rows),
          f"{name} block lifted: its contacts open by more than 1 mm", str(rows))
    bad = [r for r in rows if not same(r[1], r[2])]
    check(rows and not bad, f"{name} block lifted: NORMAL-DISP = GAP", str(bad))

# a zoned block sliding down a 30 degree joint (the slope of
# verification.closed_forms, undamped)
p, box = turned(math.radians(30))

SLIDE = "\n".join([
    "round 0.01",
    "block " + " ".join(p(*q) for q in [(0, -1), (0, 1), (10, 1), (10, -1)]),
    f"crack {p(-1, 0)} {p(11, 0)}",
    f"crack {p(4, -0.5)} {p(4, 1.5)}",
    f"crack {p(6, -0.5)} {p(6, 1.5)}",
    f"delete {box(2, 0.5)}",
    f"delete {box(8, 0.5)}",
    "prop mat=1 dens=2000 k=1e10 g=1e10",
    "prop jmat=1 jkn=1e10 jks=1e10 jfric=100 jcoh=1e9 jtens=1e9",
    f"fix {box(5, -0.5)}",
    f"gen {box(5, 0.5)} quad 0.5",
    "grav 0 -10",
    "damp auto",
    "cycle 3000",
    f"prop jmat=1 jfric={math.tan(math.radians(20)):.6f} jcoh=0 jten=0",
    "damp 0 1"] + ["cycle 2000", "print contact disp"] * 11 + ["stop", ""])
rc, out = run_deck(udec, d, "slide", SLIDE)
rows = disp_rows(out)
check(len(rows) >= 40, "sliding: contacts printed at each stage", str(len(rows)))
bad = [r for r in rows if not same(r[1], r[2])]
check(rows and not bad, "sliding zoned block: NORMAL-DISP = GAP on every contact", str(bad[:5]))
finish()
