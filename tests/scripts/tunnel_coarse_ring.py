"""A TUNNEL ring against a large ROUND (label e2e; session 45, task tunring2;
docs/geometry.md, "A coarse ring against a large ROUND"). Session 44's a4: ROUND
0.5 (so EDGE 1.0) in blocks 2-2.5 m across (JSETs at 20 and 100 degrees, 2 m
and 2.5 m apart), TUNNEL 0 0 2.5 12 (side 1.294 m). The snap reach is 2 ROUND
= 1.0 m, so every ring corner moves onto a joint (no point lies farther than
1.0 m from one of joints 2 m apart), and a piece of a side shorter than EDGE
cannot be cut (manual Section 4, EDGE: the minimum block edge): the opening
follows the joints. Before, TUNNEL said nothing of it (blocks 158, 161, 190
keep 0.5-0.9 m2 inside the true 12-gon). Checked:
1. a4: TUNNEL warns that the opening departs from the ring drawn, naming
   blocks with the area each holds on the wrong side, the total against the
   12-gon's area 0.5 x 12 x 2.5^2 x sin(30 deg) = 18.75 m2 (printed to three
   digits: 18.8), and the manual's advice on ROUND (Section 4, ROUND: about
   one percent of the typical block edge).
2. The warning's total matches the model: the blocks DELETE ANN 0 0 0 2.49
   takes (centroids inside the ring) against the 12-gon: |deleted - 18.75|
   <= total (the total counts rock taken outside plus rock left inside; the
   area deleted differs from the ring's by their difference).
3. The same deck with ROUND 0.02 (the manual's advice): no such warning, and
   the area deleted is the 12-gon's within the snapped corners' allowance:
   12 x side x side sin(5 deg) (each corner moves the wall by less than a
   triangle of two half sides and the reach side x sin(5 deg)).
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

DECK = """round {round}
block -20,-20 -20,20 20,20 20,-20
jset 20,0 100,0 0,0 2,0
jset 100,0 100,0 0,0 2.5,0
tunnel 0,0 2.5 12
print block
del ann 0,0 0 2.49
print block
"""
RING = 0.5 * 12 * 2.5 ** 2 * math.sin(math.radians(30.0))
SIDE = 2.0 * 2.5 * math.sin(math.pi / 12)


def deleted_area(out):
    before, after = out.split("del ann", 1)
    return sweep.block_area_total(before) - sweep.block_area_total(after)


rc, out = run_deck(udec, d, "a4", DECK.format(round=0.5), timeout=120)
warn = [l for l in out.splitlines() if "departs from the ring drawn" in l]
print("\n".join(l for l in out.splitlines() if l.startswith(("TUNNEL", "Warning: TUNNEL", "DELETE"))))
check(len(warn) == 1, "a4: TUNNEL warns that the opening departs from the ring drawn", str(len(warn)))
if warn:
    w = warn[0]
    m = re.search(r"by (\S+) m2 in all \((\S+) % of its (\S+) m2\)", w)
    check(m is not None and abs(float(m.group(3)) - RING) < 0.06,  # printed to three digits
          "a4: the warning gives the total against the 12-gon's area (18.75 m2)", w)
    named = re.findall(r"block (\d+) centred at \([-0-9.E+]+, [-0-9.E+]+\) (leaves|takes) (\S+) m2", w)
    check(len(named) >= 1, "a4: the warning names blocks, where, and the area on the wrong side", w)
    check("Section 4, ROUND" in w and "ROUND 0.5" in w, "a4: the warning gives the manual's advice on ROUND", w)
    if m:
        total = float(m.group(1))
        dele = deleted_area(out)
        print(f"a4: deleted {dele:.4f} m2, 12-gon {RING:.4f} m2, warned total {total} m2")
        # the total is printed to three digits: 0.5 % slack
        check(abs(dele - RING) <= 1.005 * total, "a4: the warned total bounds the deleted area's miss",
              f"{dele} vs {RING}, total {total}")

rc, out = run_deck(udec, d, "a4r", DECK.format(round=0.02), timeout=120)
check("departs from the ring" not in out and "still crosses" not in out,
      "ROUND 0.02: the opening follows the ring (no warning)",
      "\n".join(l for l in out.splitlines() if "TUNNEL" in l))
dele = deleted_area(out)
allow = 12 * SIDE * SIDE * math.sin(math.radians(5.0))
print(f"ROUND 0.02: deleted {dele:.6f} m2, 12-gon {RING:.6f} m2, allowance {allow:.4f} m2")
check(abs(dele - RING) <= allow, "ROUND 0.02: the area deleted is the 12-gon's within the snap allowance",
      f"{dele} vs {RING}")
finish()
