"""A zoned jointed model loaded from zero by BOUNDARY STRESS alone comes to
rest (label `stability`).

A joint reaches the base of the model with a kink 0.23 m above it: the block
below the joint has a convex corner filling the re-entrant corner of the
block above (a new user's 50 m square cut by two JSETs, TUNNEL, GEN QUAD 2,
CONS 3, BOUND STRESS -20e6 0 -15e6 and no INSITU, whose SOLVE never ended:
its corner at (45.36, 0) cut down to three CRACKs). That corner gets one contact per edge of the re-entrant corner; the
corner's vertex, pushed in by the joint closure, lies beyond both edges and
projects onto the gridpoint they share, so contact_side picks either edge
from step to step by round-off. The force goes to that gridpoint either way,
but the couple of the pair's moment (contact mechanics, "moment balance of
the pair") went to the edge picked: 1.5e3 N m jumping between two edges held
the light gridpoints there (35 kg) in a chatter that no damping removed
(force ratio 3e-4 after 100 000 cycles, 1.7e-3 m/s; at the default RATIO 1e-5
SOLVE stopped by luck after 4 380 cycles, hence RATIO 1e-7 here). The couple
now goes to the edge that starts at that gridpoint.

Checks: SOLVE RATIO 1e-7 ends balanced within 20 000 cycles (2 350 now); the
largest gridpoint velocity is below 1e-5 m/s (5.8e-7 now); the zones away
from the kink (y >= 3 m, and x <= 2 m below that: 2.8 m or more from it)
carry the applied field: the joints are straight and through from boundary
to boundary there, and none slips (tau / sigma_n 0.13 < JFRIC 0.6), so the
uniform stress is the exact answer (closed form); each component within 1 %
of the largest applied stress, 0.2 MPa (0.77 % at most now, from the kink's
mismatch of the two joint closures, which decays as 1 / r^2).
"""
import re
import sys
from udec_test import check, finish, header_rows, printed_number, run_deck, workdir

udec = sys.argv[1]
d = workdir()

SXX, SXY, SYY = -20e6, 0.0, -15e6
DECK = f"""ROUND 0.1
BLOCK 0,0 0,10 10,10 10,0
CRACK 5,0 4.885,0.2
CRACK 4.885,0.2 10,2.1
CRACK 0,5 10,6
GEN QUAD 2
CHANGE CONS 3
PROP MAT 1 D 2700 K 30e9 G 18e9 COH 5e6 FRIC 0.7 TEN 1e6
PROP JMAT 1 JKN 2e10 JKS 1e10 JFRIC 0.6 JCOH 1e5 JTEN 0
BOUND STRESS {SXX} {SXY} {SYY}
DAMP AUTO
SOLVE RATIO 1e-7 CYCLES 20000
PRINT MAX
PRINT 0 10 3 10 ZONES STRESS
PRINT 0 2 0 3 ZONES STRESS
STOP
"""
rc, out = run_deck(udec, d, "mouth", DECK)
m = re.search(r"SOLVE: balanced after (\d+) cycles", out)
check(bool(m), "SOLVE balances to RATIO 1e-7 within 20 000 cycles",
      "\n".join(line for line in out.splitlines() if line.startswith("SOLVE:")))
vmax = printed_number(out, "max gridpoint velocity")
check(vmax < 1e-5, "at rest: largest gridpoint velocity below 1e-5 m/s", f"{vmax:.3e} m/s")
rows = header_rows(out, "    ZONE   BLOCK           SXX", 9)
tol = 0.01*max(abs(SXX), abs(SYY))
worst = max((max(abs(float(r[2]) - SXX), abs(float(r[3]) - SXY), abs(float(r[4]) - SYY))
             for r in rows), default=float("nan"))
check(len(rows) >= 50 and worst < tol,
      "zones 2.8 m or more from the kink carry the applied field within 0.2 MPa",
      f"{len(rows)} zones, largest deviation {worst:.4e} Pa")
finish()
