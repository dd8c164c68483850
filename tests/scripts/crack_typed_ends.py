"""CRACK and SPLIT ends typed to six decimals on an inclined edge (label e2e).

A rock engineer computes the point where a crack meets an inclined edge (or
a joint) and types it to six decimals, as the manual's decks do. The typed
point misses the edge by up to 5e-7 m, and half the time it lies inside the
block: before the fix the crack then stopped short of the edge (geometric
tolerance 1e-9 of the model's size) and cut nothing ("no block cut yet;
1 partial crack segment kept"), SPLIT changed no block. Now the end of a
cut within 1e-6 of the model's size of an edge is a point of that edge
(`geometry_end_rel`, src/model/model_geometry.f90).

Checks (UDEC manual (ICG1.5, 1989), Section 4.5, CRACK: "A crack is
created between points (x1,y1) and (x2,y2)"; SPLIT: blocks the segment
crosses are split):
1. 24 random quadrilaterals with an inclined right edge, a crack from the
   left edge (an exact point) to a point of the inclined edge rounded to
   six decimals: every CRACK cuts the block in two (before: 10 of 24 did
   not; the ends that rounded outwards cut).
2. the same with SPLIT from 0.5 beyond the left edge to the rounded point.
3. a crack ending inside a block 6 decimals short of a joint made by an
   earlier inclined CRACK (the point rounded up, into the block) reaches
   it: 3 blocks (before: 2, the crack kept partial).
4. a crack ending 1e-3 m short of the edge (a genuine partial crack, 1e-4
   of the model's size) stays partial: 1 block.
5. SPLIT along that line changes nothing and says why.
6. the note of the first CYCLE counts only crack segments still ending inside
   a block, not those a later crack completed.
"""
import math
import random
import re
import sys
from udec_test import check, finish, run, workdir, write

udec = sys.argv[1]


def blocks_after(out, command):
    """Block count after the last `command` summary line ('CMD: a -> b blocks')."""
    m = re.findall(command + r": \d+ -> (\d+) blocks", out)
    return int(m[-1]) if m else None


def quad(r):
    """A block with an inclined right edge from (10, 0) to (10 + d, 10)."""
    d = r.uniform(-6.0, 6.0)
    while abs(d) < 0.5:
        d = r.uniform(-6.0, 6.0)
    return d


def edge_point(d, t):
    return 10.0 + d * t, 10.0 * t


rng = random.Random(20261126)
d = workdir()
failed = {"CRACK": [], "SPLIT": []}
for i in range(24):
    dd = quad(rng)
    t = rng.uniform(0.15, 0.85)
    ex, ey = edge_point(dd, t)
    sy = rng.uniform(2.0, 8.0)          # start on the left edge x = 0
    block = f"round 0.05\nblock 0,0 0,10 {10.0 + dd:.6f},10 10,0\n"
    # CRACK from the left edge, SPLIT from 0.5 beyond it
    for command, x0 in (("CRACK", 0.0), ("SPLIT", -0.5)):
        write(d, "c.dat", block + f"{command.lower()} {x0},{sy:.6f} {ex:.6f},{ey:.6f}\n")
        rc, out = run(udec, ["c.dat"], cwd=d)
        if blocks_after(out, command) != 2:
            failed[command].append((round(dd, 6), round(t, 6), out[-300:]))
for k, (command, what) in enumerate((("CRACK", "cuts"), ("SPLIT", "splits")), start=1):
    check(not failed[command], f"{k}. {command} to a six-decimal point of an inclined edge {what} "
          f"({24 - len(failed[command])} of 24)", str(failed[command][:2]))

# 3. a crack ending on a joint made by an earlier crack (inclined, 30 deg)
jx0, jy0, ang = 4.0, 0.0, math.radians(60.0)
jx1, jy1 = jx0 + 10.0 / math.tan(ang) * 1.2, 12.0
deck = (f"round 0.05\nblock 0,0 0,10 10,10 10,0\n"
        f"crack {jx0},{jy0} {jx1:.6f},{jy1}\n")
# the joint's point at y = 5.123457, typed to six decimals, approached from the right
yj = 5.123457
xj = jx0 + (yj - jy0) / math.tan(ang)
# rounded up: the typed point lies inside the right-hand block, 1e-7 to 1e-6 short
xj = math.ceil(xj * 1e6) / 1e6
deck += f"crack 10,7.5 {xj:.6f},{yj:.6f}\n"
write(d, "j.dat", deck)
rc, out = run(udec, ["j.dat"], cwd=d)
check(rc == 0 and blocks_after(out, "CRACK") == 3,
      "3. a crack typed to six decimals onto a joint reaches it (3 blocks)", out[-600:])

# 4. a crack 1e-3 m short of the inclined edge stays a partial crack
ex, ey = edge_point(3.0, 0.5)
write(d, "p.dat", f"round 0.05\nblock 0,0 0,10 13,10 10,0\ncrack 0,5 {ex - 1e-3:.6f},{ey:.6f}\n")
rc, out = run(udec, ["p.dat"], cwd=d)
check(rc == 0 and "no block cut yet; 1 partial crack segment" in out,
      "4. a crack 1e-3 m short of the edge stays partial", out[-400:])

# 5. the same line given to SPLIT cuts nothing (SPLIT neglects joints that do
# not separate a block in two, manual Section 4), and the warning says why
write(d, "s.dat", f"round 0.05\nblock 0,0 0,10 13,10 10,0\nsplit 0,5 {ex - 1e-3:.6f},{ey:.6f}\n")
rc, out = run(udec, ["s.dat"], cwd=d)
check(rc == 0 and "SPLIT changed no block (1 blocks): its line crosses no block from edge to edge" in out,
      "5. a SPLIT ending inside a block is dropped with the reason", out[-400:])

# 6. two cracks that together cut a V (the first kept partial until the second
# completes it) are no partial cracks when the first CYCLE forgets the pending
# ones; a third crack that ends inside a block is (before: "2 partial crack
# segment(s) not separating blocks deleted" for the V alone)
props = ("prop mat=1 d=2500 k=1e9 g=1e9\nprop jmat=1 jkn=1e9 jks=1e9\n"
         "fix 0,4 -1,3\ncycle 1\nstop\n")
write(d, "v.dat", "round 0.01\nblock 0,0 0,3 4,3 4,0\ncrack 0,3 2,1\ncrack 2,1 4,3\n" + props)
rc, out = run(udec, ["v.dat"], cwd=d)
check(rc == 0 and blocks_after(out, "CRACK") == 2 and "not separating blocks" not in out,
      "6. a V cut by two cracks leaves no partial crack", out[-600:])
write(d, "w.dat", "round 0.01\nblock 0,0 0,3 4,3 4,0\ncrack 0,3 2,1\ncrack 2,1 4,3\n"
      "crack 0,0.5 1,0.5\n" + props)
rc, out = run(udec, ["w.dat"], cwd=d)
check(rc == 0 and "Note: 1 partial crack segment(s) not separating blocks deleted" in out,
      "6. a crack ending inside a block is counted as partial", out[-600:])
finish()
