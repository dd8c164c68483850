"""A thin zoned wedge under a blunt rounded corner starts at rest (label `stability`).

The new user's tunnel deck of campaign seed 35: ROUND 0.25 over GEN EDGE
6.667 zones leaves a 7.8-degree wedge (block 86) inside the TUNNEL ring,
its edges along a neighbour's 0.51 m edge cut into 6.5 cm zone edges. The
neighbour's corner at the wedge's re-entrant gridpoint (a filled re-entrant
corner: one contact with each of its edges) is rounded over 0.25 m, so
each of its two contacts touches the wedge at the tangent point, four
gridpoints away from the vertex. The contact's force went to the gridpoint
at the end of the edge its circle meets (the vertex's projection clamped
to that edge, one neighbour edge looked at), not to the gridpoint at the
vertex, whose stretch of joint it stands for (model_geometry,
contact_side): 5.3e5 N out of balance at the first cycles, 1.3e-4 m of
drift in 200 cycles before any excavation.

The exact answer is the initial state (INSITU stresses equal to BOUNDARY
STRESS, elastic zones, no gravity): after 200 cycles no gridpoint has
moved beyond round-off, 1e-12 m (as stability.insitu_wedge). Before the
fix: 1.3e-4 m.
"""
import sys
from udec_test import check, finish, printed_number, run_deck, workdir

udec = sys.argv[1]

DECK = """round 0.25
block 0,0 0,100 100,100 100,0
jset -66.29,0 200,0 0,0 9.849,0 (49.733,50.435)
jset -5.86,0 200,0 0,0 13.181,0 (50.000,50.000)
tunnel 50.0,50.0 8.012 12
gen edge 6.667
prop mat=1 d=2600 k=20e9 g=12e9
prop jmat=1 jkn=5e+09 jks=2e+09 jfric=1.172 jcoh=0
bound stress -1.567e+07 1.597e+06 -1.747e+07
insitu stress -1.567e+07 1.597e+06 -1.747e+07
damp auto
cycle 200
print max
stop
"""

rc, out = run_deck(udec, workdir(), "seed35", DECK)
m = printed_number(out, "max gridpoint displacement")
check(m < 1e-12, "seed 35: the rock stays put before excavation (1e-12 m)", str(m))
check("INSITU: stresses set" in out and "Note: INSITU" not in out,
      "seed 35: INSITU sets the stresses, no joint past its strength")
finish()
