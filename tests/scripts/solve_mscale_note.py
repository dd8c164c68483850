"""SOLVE that does not balance on a grid of very uneven masses says MSCALE ON.

A new user's zoned tunnel (two JSETs, ROUND 0.005, GEN EDGE 2.5; lead's
random tunnel seed 108) has a sliver zone on the base where a joint at 5
degrees meets it: its gridpoint weighs 1/37 761 of the average, sets a step
of 5.9e-7 s, and SOLVE ran 40 000 cycles without balancing (force ratio
1.1e-2). MSCALE ON (UDEC manual (ICG1.5, 1989), Section 4.5, MSCALE: "to
speed up convergence of static problems involving very non-uniform grids")
balances it in 770 cycles. SOLVE now names the lightest gridpoint and the
remedy when it ends unbalanced on such a grid, and says nothing on an even
one. GENERATE names the sliver's zone when it is made (1/37 315 of the mean
zone area; its smallest angle, 5 degrees, is no needle).

Checks: the deck's SOLVE CYCLES 2000 ends unbalanced with the note; with
MSCALE ON the same SOLVE balances (RATIO 1e-5) within its 2000 cycles and
prints no note; an even grid that is not balanced after 20 cycles gets no
note.

Rigid blocks (lead's random tunnel seed 215, 2026-11-27: a 50 m rigid
model in MPa units, a non-persistent joint set, ROUND 0.025): a sliver block
on the model's edge weighs 1/3985 of the average block; SOLVE ran 40 000
cycles unbalanced (ratio 1.2e-3), MSCALE ON balanced it in 780 (the same
largest displacement within 2 %). The same note names the lightest block
when the model has no grid to judge; a rigid wall of equal blocks not
balanced after 20 cycles gets none.
"""
import os
import re
import sys
sys.path.insert(0, os.path.dirname(__file__))
from udec_test import check, finish, run_deck, workdir  # noqa: E402

udec = sys.argv[1]
d = workdir()
DECK = """round 0.005
block 0,0 0,20 20,20 20,0
jset -74.71,0 40,0 0,0 3.348,0 (9.169,10.119)
jset 5.00,0 40,0 0,0 2.508,0 (10.000,10.000)
tunnel 10.0,10.0 2.058 24
gen edge 2.500
prop mat=1 d=2600 k=20e9 g=12e9
prop jmat=1 jkn=5e+10 jks=1e+10 jfric=0.659 jcoh=1e+06
bound stress -1.249e+07 8.032e+05 -9.508e+06
insitu stress -1.249e+07 8.032e+05 -9.508e+06
damp auto
{mscale}
cycle 200
delete 7.9622,12.0378 7.9622,12.0378
solve cycles 2000
stop
"""


def note(kind, entity):
    """SOLVE's note naming the lightest gridpoint or block and MSCALE ON."""
    return re.compile(r"Note: SOLVE: the time step is set by the lightest " + kind +
                      r" \(" + entity + r" \d+ at \([-0-9.E+]+,[-0-9.E+]+\), 1/(\d+) of the "
                      r"average mass\): if the model is settling rather than failing, MSCALE ON")


def scaled_pair(name, deck, pattern, what):
    """The deck ends SOLVE unbalanced with the note (the lightest over 1000
    times below the average); with MSCALE ON it balances, without the note.
    Returns the unscaled run's output."""
    rc, out = run_deck(udec, d, name, deck.format(mscale=""))
    m = pattern.search(out)
    check("SOLVE: not balanced" in out, f"{name}: not balanced in 2000 cycles", out[-2000:])
    check(bool(m) and int(m.group(1)) > 1000, f"{name}: SOLVE names the lightest {what} and MSCALE ON",
          out[-2000:])
    rc, scaled = run_deck(udec, d, name + "_scaled", deck.format(mscale="mscale on"))
    check(re.search(r"SOLVE: balanced after \d+ cycles", scaled) is not None and
          pattern.search(scaled) is None, f"{name}: with MSCALE ON the same SOLVE balances, no note",
          scaled[-2000:])
    return out


NOTE = note("gridpoints", "gridpoint")
out = scaled_pair("uneven", DECK, NOTE, "gridpoint")

# GENERATE already names that sliver: a zone 1/37 315 of the mean one (its
# smallest angle, 5 degrees, is no needle)
g = re.search(r"Warning: GENERATE: block \d+ has a zone of \S+ m2 at \(\S+, \S+\), 1/(\d+) of the "
              r"mean zone \(\S+ m2\): it sets the time step of the whole model", out)
check(bool(g) and int(g.group(1)) > 10000, "GENERATE names the sliver zone and MSCALE ON", out[:3000])

EVEN = """round 0.05
block 0,0 0,10 10,10 10,0
gen quad 1
prop mat=1 d=2600 k=2e10 g=1.2e10
grav 0 -10
bound -1,11 -0.1,0.1 yvel 0
damp auto
solve cycles 20
stop
"""
rc, out = run_deck(udec, d, "even", EVEN)
check("SOLVE: not balanced" in out and NOTE.search(out) is None,
      "an even grid not balanced after 20 cycles gets no note", out[-2000:])
RIGID = """round 0.025
block 0,0 0,50 50,50 50,0
jset -38.41,0 100,0 0,0 3.239,0 (24.883,25.220)
jset 2.99,5 16.501,3.300 3.648,0.730 5.256,0.526 (25.000,25.000)
tunnel 25.0,25.0 2.848 24
prop mat=1 d=0.0026 k=2e+04 g=1.2e+04
prop jmat=1 jkn=5e+03 jks=1e+03 jfric=0.560 jcoh=0
bound stress -19.87 -1.923 -25.64
insitu stress -19.87 -1.923 -25.64
damp auto
{mscale}
delete ann 25.0,25.0 0 2.8475
solve cycles 2000
stop
"""
BNOTE = note("blocks", "block")
scaled_pair("rigid", RIGID, BNOTE, "block")
rc, out = run_deck(udec, d, "rigid_even", """round 0.05
block 0,0 0,10 10,10 10,0
jset 0,0 20,0 0,0 1,0
jset 90,0 20,0 0,0 1,0
prop mat=1 d=2600 k=2e10 g=1.2e10
prop jmat=1 jkn=1e10 jks=1e10 jfric=0.5
grav 0 -10
fix 0,10 0,1
damp auto
solve cycles 20
stop
""")
check("SOLVE: not balanced" in out and BNOTE.search(out) is None,
      "an even rigid wall not balanced after 20 cycles gets no note", out[-2000:])
finish()
