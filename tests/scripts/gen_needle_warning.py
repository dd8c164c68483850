"""GENERATE names the block whose needle-shaped corner sets the time step.

A tunnel ring nearly tangent to a joint (a joint at offset 3 m, the ring's
radius) leaves a 0.5-degree needle corner on one block: its zones are about a
thousand times smaller than the rest and the time step follows them. The run
is not wrong, only slow, so GENERATE warns, naming the block, the corner's
position and the zone sizes; the same deck with the ring 0.5 m off the joint
has no such corner and no warning."""
import os
import re
import sys
sys.path.insert(0, os.path.dirname(__file__))
from udec_test import check, finish, run, workdir, write  # noqa: E402

udec = sys.argv[1]
DECK = """ROUND 0.05
BLOCK -20,-20 -20,20 20,20 20,-20
JSET 50,0 100,0 0,0 3,0 (0,0)
JSET -40,0 100,0 0,0 4,0 (1,0)
TUNNEL {x} 0 3 20
CHANGE CONS=3
GEN EDGE 1.5
STOP
"""
d = workdir()
write(d, "needle.dat", DECK.format(x=0))
rc, out = run(udec, ["needle.dat"], cwd=d, timeout=120)
check(rc == 0, "needle deck runs", out[-1500:])
m = re.search(r"Warning: GENERATE: block (\d+) has a zone angle of\s*([\d.]+) degrees at "
              r"\(\s*(\S+),\s*(\S+)\), a zone of\s*(\S+) m2 where the mean is\s*(\S+) m2", out)
check(m is not None, "GENERATE warns about the needle corner", out[-1500:])
if m:
    ang, x, y = float(m.group(2)), float(m.group(3)), float(m.group(4))
    # the needle is where the -40 degree joint through (1, 0) meets the 50
    # degree joint at offset 3: (-1.885, 2.421), within 1 cm
    check(ang < 2.0, f"the warning gives the needle's angle ({ang} degrees)")
    check(abs(x + 1.885) < 0.01 and abs(y - 2.421) < 0.01,
          f"the warning gives the needle's position ({x}, {y})")
    check(float(m.group(5)) < 1e-2*float(m.group(6)), "its zone is far below the mean")
write(d, "clear.dat", DECK.format(x=0.5))
rc, out = run(udec, ["clear.dat"], cwd=d, timeout=120)
check(rc == 0 and "GENERATE:" in out, "deck without the needle runs", out[-1500:])
check("Warning: GENERATE" not in out, "no warning without a needle", out[-1500:])
finish()
