"""Needle-shaped corners: a TUNNEL nearly tangent to a joint makes none, and
GENERATE names the block when a user's own geometry has one.

1. A tunnel ring of radius 3 beside a joint at offset 3 (its corner at 144
   degrees 7 mm inside the joint, ROUND 0.05) used to be cut between the
   joint and the ring's chord, leaving a 0.5-degree needle corner whose zones
   (7e-6 m2 where the mean is 0.46 m2) set the time step about a thousand
   times too small. Ring corners within ROUND of a joint are now moved onto
   it: the smallest zone angle must be at least 2 degrees (was 0.5).
2. A CRACK at 1.4 degrees to a block's edge is the user's geometry and is
   kept; GENERATE warns, naming the block, the corner's position and the zone
   sizes, because its zones set the time step of the whole model."""
import os
import re
import sys
sys.path.insert(0, os.path.dirname(__file__))
from udec_test import check, finish, run, workdir, write  # noqa: E402

udec = sys.argv[1]
TUNNEL = """ROUND 0.05
BLOCK -20,-20 -20,20 20,20 20,-20
JSET 50,0 100,0 0,0 3,0 (0,0)
JSET -40,0 100,0 0,0 4,0 (1,0)
TUNNEL 0 0 3 20
CHANGE CONS=3
GEN EDGE 1.5
STOP
"""
WEDGE = """ROUND 0.05
BLOCK 0,0 0,20 20,20 20,0
CRACK 0,0 20,0.5
GEN EDGE 2
STOP
"""
d = workdir()
write(d, "tunnel.dat", TUNNEL)
rc, out = run(udec, ["tunnel.dat"], cwd=d, timeout=120)
check(rc == 0, "tangent-tunnel deck runs", out[-1500:])
m = re.search(r"smallest zone angle\s*([\d.]+) degrees", out)
check(m is not None and float(m.group(1)) >= 2.0,
      "no needle corner beside the tangent joint (smallest zone angle >= 2 degrees)",
      m.group(0) if m else out[-1500:])
# (a small zone there, not a needle, is named by the small-zone warning)
check("has a zone angle of" not in out, "no needle warning for the tunnel deck", out[-1500:])

write(d, "wedge.dat", WEDGE)
rc, out = run(udec, ["wedge.dat"], cwd=d, timeout=120)
check(rc == 0, "wedge deck runs", out[-1500:])
m = re.search(r"Warning: GENERATE: block (\d+) has a zone angle of\s*([\d.]+) degrees at "
              r"\(\s*(\S+),\s*(\S+)\), a zone of\s*(\S+) m2 where the mean is\s*(\S+) m2", out)
check(m is not None, "GENERATE warns about the needle corner", out[-1500:])
if m:
    ang, x, y = float(m.group(2)), float(m.group(3)), float(m.group(4))
    # the crack meets the block's lower edge at (0, 0) at atan(0.5/20) = 1.43
    # degrees; the zone angle there cannot exceed it
    check(ang <= 1.44, f"the warning gives the needle's angle ({ang} degrees)")
    check(abs(x) < 1e-6 and abs(y) < 1e-6, f"the warning gives the needle's position ({x}, {y})")
    check(float(m.group(5)) < 1e-1*float(m.group(6)), "its zone is far below the mean")
finish()
