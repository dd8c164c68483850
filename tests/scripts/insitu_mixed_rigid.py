"""A rock mass of rigid and zoned blocks held by its in-situ stress stays
still (label `stability`).

The first model a new user writes with GENERATE in a range: zoned blocks
round the opening, rigid blocks outside, INSITU and the same BOUNDARY
STRESS. Before any excavation nothing may move: the stress field is uniform
and every block in equilibrium. At a rigid block's rounded corner the
contact point lies a rounding length from the zoned block's corner
gridpoint, along the joint, and the force pair has a moment (contact
mechanics' "moment balance of the pair"); that couple was given to block 2
of the contact, a zoned block's two gridpoints when block 1 was the rigid
one, which no INSITU force balanced: where a zoned-rigid joint leaves the
model the corner gridpoints were pushed 1.6e-5 to 4e-5 m and a four-block
junction 1.3e-5 m (random tunnels, nu-zoned seed 13: 3.6e-5 m, 3e-3 m/s
before excavation). A rigid side now takes the couple whole.

Check: a square cut by a steep and a gently dipping joint, once with the
left half zoned and once the right half (block 1 rigid or zoned: both
orders of the pair), 500 cycles of DAMP AUTO: every gridpoint and block
displacement below 1e-9 m (an all-zoned model stays within 1e-16 m; the
joint closure under these stresses is 7e-4 m).
"""
import re
import sys
from udec_test import check, finish, header_rows, run_deck, workdir

udec = sys.argv[1]
d = workdir()

DECK = """round 0.05
block -5,-5 -5,5 5,5 5,-5
crack 0.3,-6 -0.2,6
crack -6,1.1 6,0.7
gen {rng} auto 0.93
prop mat=1 dens=2600 k=1.083e+10 g=5e+09
prop jmat=1 jkn=2.69e+10 jks=1.345e+10 jfric=0.8 jcoh=1.83e+06 jtens=9.15e+05
insitu stress -1.28e+07 0 -1.83e+07
bound stress -1.28e+07 0 -1.83e+07
damp auto
cycle 500
print max
print grid
stop
"""
for name, rng in (("left", "-6,0 -6,6"), ("right", "0,6 -6,6")):
    rc, out = run_deck(udec, d, name, DECK.format(rng=rng))
    check("GENERATE: 2 block(s) zoned" in out, f"{name}: two blocks zoned, two rigid")
    rows = header_rows(out, "  GRIDPT   BLOCK             X             Y        X-DISP", 8)
    umax = max((abs(float(r[4])) + abs(float(r[5])) for r in rows), default=float("nan"))
    check(len(rows) > 100 and umax < 1e-9, f"{name}: gridpoints still (|u| < 1e-9 m)",
          f"{len(rows)} gridpoints, largest |ux| + |uy| {umax:.3e} m")
    m = re.search(r"max block displacement\s+(\S+)", out)
    check(bool(m) and float(m.group(1)) < 1e-9, f"{name}: rigid blocks still (< 1e-9 m)",
          m and m.group(0))
finish()
