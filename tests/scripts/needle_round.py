"""A sliver along the model's top: bedding at 2.7 degrees meets the top
boundary and leaves a needle 0.03 m thick, zoned finely (label stability;
reference: the in-situ state with the same boundary stress is the exact
answer, so a model of any shape stays at rest).

Found writing a new user's model (40 m square, two joint sets, GEN EDGE 3,
INSITU and BOUND STRESS at 20 MPa): with ROUND 0.1 the block under the
needle has one rounded corner whose contact spans several of the needle's
gridpoints (zone edges of 0.03-0.06 m): its force lands where the needle's
zones do not carry it, and the needle rang at 5 m/s (the run stopped later
on an overlap). With ROUND 0.05 the same model is at rest.

Checked:
- ROUND 0.05: after 500 cycles the largest gridpoint velocity is below
  1e-6 m/s (ROUND 0.1 gave 4.8 m/s when found and is at rest now too;
  stability.needle_excavation cycles it through an excavation) and GENERATE
  gives no short-edge warning;
- ROUND 0.1: GENERATE warns that zone edges on block edges are shorter than
  half of ROUND and names the block and place of the shortest (block 159 at
  about (34.3, 40.0)), so the user learns why before cycling.
"""
import re
import sys
from udec_test import check, finish, run, workdir, write

udec = sys.argv[1]
DECK = """ROUND {r}
BLOCK 0,0 0,40 40,40 40,0
JSET 2.72,0 200,0 0,0 1.80,0 (20.57,5.09)
JSET 49.54,0 200,0 0,0 2.27,0 (32.90,17.54)
GEN EDGE 3.00
PROP MAT=1 D=2600 K=2e10 G=1.2e10
PROP JMAT=1 JKN=2e+11 JKS=1e+11 JFRIC=0.8
INSITU STRESS -2.17836e+07 0 -1.86345e+07
BOUND STRESS -2.17836e+07 0 -1.86345e+07
DAMP AUTO
{cyc}
PRINT MAX
STOP
"""
d = workdir()
write(d, "fine.dat", DECK.format(r=0.05, cyc="CYCLE 500"))
rc, out = run(udec, ["fine.dat"], cwd=d, timeout=600)
check(rc == 0, "ROUND 0.05: the run completes", out[-1500:])
m = re.search(r"max gridpoint velocity\s+(\S+)", out)
check(m is not None and float(m.group(1)) < 1e-6,
      "ROUND 0.05: the in-situ state stays at rest (max gridpoint velocity %s < 1e-6)"
      % (m.group(1) if m else None), out[-2500:])
check("shorter than half of ROUND" not in out, "ROUND 0.05: no short-edge warning", out[-2500:])

write(d, "coarse.dat", DECK.format(r=0.1, cyc=""))
rc, out = run(udec, ["coarse.dat"], cwd=d, timeout=600)
m = re.search(r"Warning: GENERATE: (\d+) zone edge\(s\) on block edges are shorter than half "
              r"of ROUND.*?is on block (\d+) at \(\s*(\S+),\s*(\S+)\)", out)
check(rc == 0 and m is not None, "ROUND 0.1: GENERATE warns about zone edges shorter than ROUND/2",
      out[-2500:])
if m:
    check(abs(float(m.group(3)) - 34.3) < 0.5 and abs(float(m.group(4)) - 40.0) < 0.1,
          "the warning names the needle at the top (%s, %s)" % (m.group(3), m.group(4)))
finish()
