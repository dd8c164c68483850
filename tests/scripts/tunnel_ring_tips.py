"""A TUNNEL side across a block's tip (label e2e; session 44, task tunring;
docs/geometry.md, "A ring side across a block's tip"). Session 43's m5, a
100 m box cut by joints 1 m (35 degrees) and 1.2 m (-55 degrees) apart,
ROUND 0.02, TUNNEL 0 0 5 24: a side passed 3.7 cm inside a joint crossing,
meeting one joint at 17.5 degrees; the cut's end on the other joint, nearer
than EDGE to the crossing, moved onto it and the cut then ran along the
first joint and cut nothing: TUNNEL warned that the ring "still crosses 1
block(s)" and named none. The side now bends through the crossing. Checked:
1. m5: no straddle warning; DELETE ANN 0 0 0 4.99 takes exactly the blocks
   inside: the area deleted is the 24-gon's, 0.5 x 24 x 25 x sin(15 deg) =
   77.646 m2, within the bend's and the snapped corners' allowance (each
   moves the wall by less than ring_snap_reach = side x sin(3.75 deg), so
   the area by less than perimeter x reach; measured: see the printed
   ratio), and every block left has its centroid outside the ring.
2. Random rings (tools/ring_straddle_sweep.py, seed 44, 8 draws: two crossing
   persistent sets, radii 2 / 3.7 / 5, 12 to 48 sides, centres off the joint
   grid): at most one straddle (measured 1, draw 1; draw 5's tip, 3.8 cm
   from a ring corner, straddled until the corner moved onto it), and a
   straddle warning names the block and where ("block N centred at (x, y)").
"""
import math
import os
import re
import sys
from udec_test import check, finish, run_deck, workdir

udec = sys.argv[1]
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
import ring_straddle_sweep as sweep  # noqa: E402

d = workdir()

M5 = """round 0.02
block -50,-50 -50,50 50,50 50,-50
jset 35,0 200,0 0,0 1,0
jset -55,0 200,0 0,0 1.2,0
tunnel 0 0 5 24
print block
del ann 0 0 0 4.99
print block
"""


def blocks(text):
    rows = []
    for line in text.splitlines():
        f = line.split()
        if len(f) == 9 and f[0].isdigit() and f[1].isdigit():
            rows.append((int(f[0]), float(f[5]), float(f[6]), float(f[7])))
    return rows


rc, out = run_deck(udec, d, "m5", M5, timeout=120, forbidden=("*** Error",))
check("still crosses" not in out, "m5: the ring crosses no block",
      "\n".join(l for l in out.splitlines() if "TUNNEL" in l))
before, after = out.split("del ann", 1)
b0, b1 = blocks(before), blocks(after)
ring = 0.5 * 24 * 25.0 * math.sin(math.radians(15.0))
deleted = sum(a for _, a, _, _ in b0) - sum(a for _, a, _, _ in b1)
side = 2.0 * 5.0 * math.sin(math.pi / 24)
reach = side * math.sin(math.radians(90.0 / 24))
print(f"m5: deleted {deleted:.6f} m2, 24-gon {ring:.6f} m2, ratio {deleted / ring:.8f} "
      f"(allowance {24 * side * reach / ring:.2e})")
# every block deleted lay inside and every block kept outside: the areas add up
check(abs(deleted - ring) < 24 * side * reach, "m5: the area deleted is the 24-gon's within the snap reach",
      f"{deleted} vs {ring}")
kept_in = [b for b, _, x, y in b1 if math.hypot(x, y) < 4.99]
check(not kept_in, "m5: no block centred inside the ring is left", str(kept_in[:5]))
gone = {b for b, _, _, _ in b0} - {b for b, _, _, _ in b1}
inside = {b for b, _, x, y in b0 if math.hypot(x, y) < 4.99}
check(gone == inside and len(gone) > 0, "m5: DELETE took exactly the blocks centred inside",
      f"{len(gone)} deleted, {len(inside)} inside")
total0 = sum(a for _, a, _, _ in b0)
# PRINT BLOCK prints six digits: the sum of 8 600 rounded areas to 1e-6
check(abs(total0 - 1.0e4) < 1e-6 * 1.0e4, "m5: the blocks' areas add up to the box", str(total0))

# 3: random rings
import random  # noqa: E402
rng = random.Random(44)
total = 0
named = []
for k in range(8):
    p = sweep.draw(rng)
    n, ratio, out = sweep.run_one(os.path.abspath(udec), p, d)
    print(f"draw {k}: r {p['r']} n {p['n']}: straddles {n}, deleted/ring {ratio:.6f}")
    total += n
    for line in out.splitlines():
        if "still crosses" in line:
            named.append(line)
# a debt bounded at what this version does: draw 1 (18 sides, r 3.7) keeps one
# block whose corner lies 1.7 cm inside a side 6.9 cm from a ring corner that
# snap_to_edges moved (docs/geometry.md)
check(total <= 1, "random rings: at most one block straddles a ring in 8 draws", f"{total} straddles")
check(all(re.search(r"\(block \d+ centred at \([-0-9.E+]+, [-0-9.E+]+\)", l) for l in named),
      "random rings: a straddle warning names the block and where", "\n".join(named))
finish()
