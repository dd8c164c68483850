"""A wedge on the model's boundary starts at rest (label `stability`).

A small triangular block with one edge on the model's boundary and two
joints into the rock (random tunnels, nu-zoned deck 4: a jointed tunnel
whose JSET left such wedges on both sides of the model). Its boundary edge
touches the neighbouring block at both ends (the two joints' mouths), and
INSITU's balance of the zoned joint gridpoints (contact_insitu,
zoned_contact_balance) took that edge for a joint: the wedge's gridpoints'
load from BOUNDARY STRESS (not part of that balance) went into the joint
contacts, 2e6 N of tension where 6.5e6 N of compression was due, the
contacts broke at the first step and the wedge was pushed 4.2e-2 m into the
model before any excavation.

The exact answer is the initial state (uniform INSITU stress, the same
BOUNDARY STRESS, elastic zones): after 500 cycles no gridpoint has moved
beyond round-off, 1e-12 m (as stability.insitu_junctions: forces ~1e7 N
summed to ~1e-15 relative give F dt^2 / m ~ 1e-18 m a step). Before the
fix: 4.2e-2 m (left wedge, both zonings), 1e-2 m and more for the others.
"""
import sys
from udec_test import check, finish, run_deck, workdir

udec = sys.argv[1]

DECK = """round 0.1
block -10,-10 -10,10 10,10 10,-10
{cracks}
{gen}
prop mat=1 dens=2600 k=1.083e10 g=5e9
prop jmat=1 jkn=7e8 jks=3.5e8 jfric=0.8 jcoh=2.41e6 jtens=1.205e6
{load}
damp auto
cycle 500
print max
stop
"""
LEFT = "crack -10,4.13 -9.77,4.5\ncrack -9.77,4.5 -10,4.7"
TOP = "crack -3,10 -2.2,9.4\ncrack -2.2,9.4 -1.7,10"
LOADS = ["insitu stress -4.1e7 0 -2.41e7\nbound stress -4.1e7 0 -2.41e7",
         "bound stress -4.1e7 0 -2.41e7\ninsitu stress -4.1e7 0 -2.41e7"]


def max_value(out, name):
    vals = [float(l.split()[-3]) for l in out.splitlines() if l.strip().startswith(name)]
    return vals[-1] if vals else None


d = workdir()
cases = [("left_coarse", LEFT, "gen auto 3.77", LOADS[0]),
         ("left_fine", LEFT, "gen auto 1", LOADS[0]),
         ("left_bound_first", LEFT, "gen edge 1", LOADS[1]),
         ("top", TOP, "gen auto 1.5", LOADS[0])]
for name, cracks, gen, load in cases:
    rc, out = run_deck(udec, d, name, DECK.format(cracks=cracks, gen=gen, load=load))
    m = max_value(out, "max gridpoint displacement")
    check(m is not None and m < 1e-12, f"{name}: the wedge stays put (1e-12 m)", str(m))
finish()
