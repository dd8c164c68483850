"""ARC of a full turn cuts a tunnel out as TUNNEL does (label e2e).

UDEC manual (ICG1.5, 1989), Section 4.5, ARC xc yc xb yb theta npoin:
npoin cracks along the arc from (xb, yb) turning theta degrees. A new user
cuts a tunnel with ARC xc yc xb yb 360 n. A ring lying wholly inside one
block could not cut it (a block cannot hold a hole): the cracks were kept
as partial cracks, deleted at the first CYCLE, and a DELETE of the tunnel's
range then took the whole block ("there are no blocks") or none. The full
turn is now keyed as TUNNEL's ring is (two horizontal cracks from its
sides to the block's edges), with the same note.

Checks (the ring is the regular n-gon of radius r, area n r^2 sin(2 pi / n)
/ 2, exact to the printed 6 digits):
1. ARC 5 5 6 5 360 24 in a 10 m square: 3 blocks, one of them the 24-gon
   (3.10583 m^2); DELETE ANN 5 5 0 0.99 removes it, 2 blocks remain.
2. The same far from the origin (x = 5000), ARC -360, start at 40 degrees:
   the 24-gon of radius 1.03 (3.29497 m^2).
3. A half turn (180) inside one block stays a partial crack (no key: it is
   not a ring), as before.
4. A ring that crosses a joint (CRACK through the centre first): cut by the
   joint, no key needed: the two half discs sum to the 24-gon's area and
   the note is absent.
5. TUNNEL keyed in a block a JSET with gaps crosses (a random new-user deck
   far from the origin): the ring's cracks completed a partial joint crack
   and cut a corner triangle off the enclosing block, which renumbered it;
   both key cuts were skipped and the ring never separated ("the ring still
   crosses 1 block"; DELETE then took 3 triangles, the model flew apart).
   Now each key finds the block outside the ring again: the opening is one
   block, its area within 0.2 % of the 20-gon's (47.092 m^2; bends moved
   onto joint crossings change it by 0.04 %), centred on the ring.
"""
import math
import re
import sys
from udec_test import check, finish, run_deck, workdir

udec = sys.argv[1]
folder = workdir()
NOTE = "Note: ARC: the ring lay inside one block"


def deck(name, body):
    return run_deck(udec, folder, name, "round 0.02\n" + body + "print block\nstop\n")[1]


def areas(out, last=True):
    blocks = re.split(r"\n\s*BLOCK\s+MAT", out)
    table = blocks[-1] if last else blocks[1]
    vals = []
    for line in table.splitlines()[1:]:
        f = line.split()
        if len(f) >= 9 and f[0].isdigit():
            vals.append(float(f[5]))
        elif vals:
            break
    return vals


def polygon(n, r):
    return 0.5 * n * r * r * math.sin(2 * math.pi / n)


out = deck("full", "block 0,0 0,10 10,10 10,0\narc 5 5 6 5 360 24\n"
                   "print block\ndelete ann 5 5 0 0.99\n")
a = areas(out, last=False)
check(len(a) == 3, "full: 3 blocks", str(a))
check(any(abs(x - polygon(24, 1.0)) < 1e-5 for x in a), "full: the 24-gon cut out", str(a))
check(NOTE in out, "full: the key note", out[-1500:])
check(len(areas(out)) == 2, "full: DELETE leaves 2 blocks", out[-800:])

xb = 5004.91 + 1.03 * math.cos(math.radians(40))
yb = 4.869 + 1.03 * math.sin(math.radians(40))
out = deck("far", f"block 5000,0 5000,10 5010,10 5010,0\narc 5004.91 4.869 {xb:.9f} {yb:.9f} -360 24\n")
a = areas(out)
check(len(a) == 3, "far: 3 blocks", str(a))
check(any(abs(x - polygon(24, 1.03)) < 1e-5 for x in a), "far: the 24-gon cut out", str(a))

out = deck("half", "block 0,0 0,10 10,10 10,0\narc 5 5 6 5 180 12\n")
check(len(areas(out)) == 1 and NOTE not in out, "half: no key, one block", out[-800:])

out = deck("jointed", "block 0,0 0,10 10,10 10,0\ncrack 0,5.3 10,5.3\narc 5 5 6 5 360 24\n")
a = areas(out)
check(NOTE not in out, "jointed: no key", out[-800:])
check(len(a) == 4, "jointed: 4 blocks", str(a))
small = sorted(a)[:2]
check(abs(sum(small) - polygon(24, 1.0)) < 2e-5, "jointed: the two half discs make the 24-gon", str(a))

out = deck("keyed_jset", "block -3000,-800 -3000,-760 -2960,-760 -2960,-800\n"
                         "jset 60,0 21.54,0 4.60494,0 6.42933,0 (-2978.84,-780.413)\n"
                         "tunnel -2979.36 -780.693 3.90376 20\n")
check("the ring still crosses" not in out, "keyed_jset: the ring separates", out[-1500:])
rows = []
for line in out.split("print block")[-1].splitlines():
    f = line.split()
    if len(f) >= 9 and f[0].isdigit():
        rows.append((float(f[5]), float(f[6]), float(f[7])))
ring = polygon(20, 3.90376)
hit = [r for r in rows if abs(r[0] - ring) <= 2e-3 * ring
       and math.hypot(r[1] + 2979.36, r[2] + 780.693) < 4e-3]
check(len(hit) == 1, "keyed_jset: the opening is one block of the 20-gon's area", str(rows))

short = ("block 0,0 0,20 20,20 20,0\njset 45,0 40,0 0,0 1.5,0\njset -30,0 40,0 0,0 2,0\n"
         "tunnel 10,10 2 24\n")
out = run_deck(udec, folder, "short", short + "stop\n")[1]
check("Warning: TUNNEL: its sides (0.522105) are shorter than EDGE (1; ROUND 0.5, the default)" in out
      and "give ROUND below 0.261052" in out, "short: TUNNEL warns of sides below EDGE", out[-1500:])
out = run_deck(udec, folder, "short_ok", "round 0.05\n" + short + "stop\n")[1]
check("are shorter than EDGE" not in out, "short: no warning under ROUND 0.05", out[-1500:])
out = run_deck(udec, folder, "arc_edge", "block 0,0 0,10 10,10 10,0\n"
               "arc 5 5 6 5 244 4\nstop\n")[1]
check("are shorter than EDGE" not in out, "short: a side just above EDGE (1.0065) is no warning", out[-800:])

finish()
