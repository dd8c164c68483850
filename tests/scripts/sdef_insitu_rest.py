"""A jointed box of SDEF blocks under its in-situ stress stays at rest (label
`stability`).

A 20 m box cut by three joint sets (one with gaps: T-junctions), CHANGE
SDEF, BOUNDARY STRESS and INSITU STRESS of the same field (-12, 0, -8 MPa),
DAMP AUTO, 500 cycles (UDEC manual (ICG1.5, 1989), Section 4.5, INSITU:
initial stresses in the blocks and joints; CHANGE SDEF). Nothing is
excavated, so nothing may move.

The SDEF strain modes are loaded by the first moment of a block's contact
forces about its centroid; a contact acts at its corner, not at the centre
of the stretch of joint it stands for, and carries INSITU's couples that
balance the rigid moments. With the field itself as the blocks' uniform
stress the strain modes started out of balance: 3.4e2 N, 1.6e-5 m/s at
cycle 500 here (a 40 m tunnel model of 531 blocks: 2.7e4 N, 1.3e-3 m/s),
while the same model of rigid blocks stayed still to 1e-12. Now INSITU
gives each SDEF block the difference of the two first moments over its area
(commands_boundary, sdef_insitu_moments).

Checks:
  1. after 500 cycles the largest block velocity is below 1e-9 m/s and the
     largest displacement below 1e-10 m (measured 2e-12 m/s, 4e-15 m; the
     rigid twin 1.8e-12 m/s, 4e-15 m);
  2. the same for the rigid twin (no CHANGE SDEF): the check's reference.
"""
import re
import sys
from udec_test import check, finish, run, workdir, write

udec = sys.argv[1]

DECK = """ROUND 0.05
BLOCK 0,0 0,20 20,20 20,0
JSET 0,0 40,0 0,0 3,0 (0,1)
JSET 90,0 40,0 0,0 3.5,0 (0.5,0)
JSET 45,0 15,5 3,1 4,1 (0,0)
{sdef}
PROP MAT 1 DENS 2700 K 25e9 G 15e9
PROP JMAT 1 JKN 20e9 JKS 10e9 JFRIC 0.7 JCOH 0.5e6 JTEN 0.1e6
BOUND STRESS -12e6 0 -8e6
INSITU STRESS -12e6 0 -8e6
DAMP AUTO
CYCLE 500
PRINT MAX
STOP
"""


def largest(out, what):
    m = re.findall(r"max block " + what + r"\s+([0-9.E+-]+)", out)
    return float(m[-1]) if m else None


d = workdir()
for name, sdef in (("SDEF", "CHANGE SDEF"), ("rigid", "")):
    write(d, "box.dat", DECK.format(sdef=sdef))
    rc, out = run(udec, ["box.dat"], cwd=d)
    vel, dis = largest(out, "velocity"), largest(out, "displacement")
    print(f"{name}: largest block velocity {vel} m/s, displacement {dis} m")
    check(rc == 0 and "*** Error" not in out and vel is not None and dis is not None
          and vel < 1e-9 and dis < 1e-10,
          f"{name} blocks under their in-situ stress stay at rest (1e-9 m/s, 1e-10 m)",
          out[-1500:])
    if name == "SDEF":
        check("INSITU: stresses set in 0 zone(s), 90 SDEF block(s)" in out,
              "INSITU sets the 90 SDEF blocks", out[-1500:])
finish()
