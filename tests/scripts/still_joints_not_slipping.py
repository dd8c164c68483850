"""A still, stressed jointed model shows no contact at slip.

A zoned 20 m square under gravity with INSITU stresses in equilibrium
(horizontal stress half the vertical), two joint sets with friction 30
degrees: the largest stress ratio on any plane is sin(phi_mob) = (1 - 0.5) /
(1 + 0.5), phi_mob = 19.5 degrees, well below the joints' friction, so no
joint may slip. Before the fix every corner-corner contact where a joint
ends (no length of its own, no INSITU force, but a CLEMIN stiffness) showed
as at slip: 278 of them in a 40 m model, the whole joint pattern red in
PLOT SLIP. Checks: the model stays still (gridpoint velocity below 1e-4 m/s)
and at most 1 % of the contacts are flagged at slip."""
import os
import re
import sys
sys.path.insert(0, os.path.dirname(__file__))
from udec_test import check, finish, run, tables, workdir, write  # noqa: E402

udec = sys.argv[1]
DECK = """ROUND 0.05
BLOCK 0,-20 0,0 20,0 20,-20
JSET 70,0 100,0 0,0 3,0 (10,-10)
JSET -20,0 100,0 0,0 4,0 (10,-10)
GEN EDGE 2.0
PROP MAT=1 D=2600 K=1.5e10 G=9e9
PROP JMAT=1 JKN=5e9 JKS=2e9 JFRIC=30 JCOH=0 JTEN=0
GRAV 0 -9.81
INSITU STRESS 0 0 0 YGRAD 12753 0 25506
BOUND -0.1 0.1 -21 1 XVEL 0
BOUND 19.9 20.1 -21 1 XVEL 0
BOUND -1 21 -20.1 -19.9 YVEL 0
DAMP AUTO
CYCLE 1000
PRINT CONTACT STATE
PRINT MAX
STOP
"""
d = workdir()
write(d, "still.dat", DECK)
rc, out = run(udec, ["still.dat"], cwd=d, timeout=300)
check(rc == 0 and "***" not in out, "the deck runs", out[-2000:])
rows = out.split("PRINT CONTACT STATE")[-1].split("PRINT MAX")[0].splitlines()
states = [ln.split()[-1] for ln in rows if re.match(r"\s+\d+\s+\d+\s+\d+\s", ln)]
slipping = sum(1 for s in states if s.startswith("S"))
check(len(states) > 200, f"contacts listed ({len(states)})")
check(slipping <= 0.01 * len(states), f"at most 1 % of the contacts at slip ({slipping} of {len(states)})")
m = re.search(r"max gridpoint velocity\s+(\S+)", out)
check(m is not None and float(m.group(1)) < 1e-4, "the model stays still",
      m.group(0) if m else out[-1000:])
finish()
