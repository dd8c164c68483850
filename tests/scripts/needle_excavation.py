"""The needle of stability.needle_round at ROUND 0.1, with a tunnel excavated
below it (label stability).

A new user's model: 40 m square, bedding at 2.72 degrees and a set at 49.54
degrees, a TUNNEL of radius 4.56 m, GEN EDGE 3, INSITU + BOUND STRESS at
about 20 MPa, DAMP AUTO, excavation by DELETE. The bedding meets the top
boundary at a shallow angle and leaves a needle 0.03 m thick whose root is
a re-entrant gridpoint filled by the rounded corner of the block below. That
corner's contact with the next edge of the needle (two zone edges on) took
the force to the needle's gridpoint it lies on only while the corner's
vertex projected onto the edge before by at least +0.0; at -1e-16 (the
first motion the excavation sends up) the force jumped 0.077 m along the
needle to the far gridpoint, with its couple, every other step: the needle
tore off the block below (2e-2 m at cycle 2500, 3 m/s, an overlap error
further on), 20 m from a tunnel whose wall moves 1e-2 m.

Checked (reference: the joint between the needle and the block below stays
closed under about 19 MPa; its elastic closure or opening is at most the
whole normal stress over JKN, 2e7 / 2e11 = 1e-4 m, so the two blocks'
gridpoints that start at the same place stay within 1e-4 m of each other;
before the fix 1.6e-3 m at cycle 1500):
- before excavation, after 500 cycles, the largest gridpoint velocity is
  below 1e-6 m/s (the in-situ state is the exact answer);
- the run completes without error 1000 cycles after the excavation;
- at every place of the needle's root and tip (within 0.7 m of (34.4, 40))
  where gridpoints of two blocks start together, their displacements differ
  by less than 1e-4 m.
"""
import math
import re
import sys
from udec_test import check, finish, run, workdir, write

udec = sys.argv[1]
DECK = """ROUND 0.1
BLOCK 0,0 0,40 40,40 40,0
JSET 2.72,0 200,0 0,0 1.80,0 (20.57,5.09)
JSET 49.54,0 200,0 0,0 2.27,0 (32.90,17.54)
TUNNEL 19.703 19.883 4.564 12
GEN EDGE 3.00
CHANGE CONS=3
PROP MAT=1 D=2600 K=2e10 G=1.2e10 COH=1.08918e+07 FRIC=0.7 TEN=1e6
PROP JMAT=1 JKN=2e+11 JKS=1e+11 JFRIC=0.8
INSITU STRESS -2.17836e+07 0 -1.86345e+07
BOUND STRESS -2.17836e+07 0 -1.86345e+07
DAMP AUTO
CYCLE 500
PRINT MAX
DEL ANN 19.703 19.883 0 4.427
CYCLE 1000
PRINT ANN 34.4 40.0 0 0.7 GRID DISP
STOP
"""
d = workdir()
write(d, "needle.dat", DECK)
rc, out = run(udec, ["needle.dat"], cwd=d, timeout=600)
check(rc == 0 and "Error" not in out, "the run completes without error", out[-2000:])
m = re.search(r"max gridpoint velocity\s+(\S+)", out)
check(m is not None and float(m.group(1)) < 1e-6,
      "before excavation the in-situ state stays at rest (max gridpoint velocity %s < 1e-6 m/s)"
      % (m.group(1) if m else None), out[-2500:])

# gridpoints by their starting place (current position minus displacement)
places = {}
i = out.find("PRINT ANN 34.4 40.0 0 0.7 GRID DISP")
for line in out[i:].splitlines()[1:]:
    f = line.split()
    if len(f) != 8 or not f[0].isdigit():
        continue
    x, y, ux, uy = (float(v) for v in f[2:6])
    key = (round(x - ux, 3), round(y - uy, 3))
    places.setdefault(key, []).append((int(f[1]), ux, uy))
worst, where, npairs = 0.0, None, 0
for key, gps in places.items():
    for a in range(len(gps)):
        for b in range(a + 1, len(gps)):
            if gps[a][0] == gps[b][0]:
                continue
            npairs += 1
            du = math.hypot(gps[a][1] - gps[b][1], gps[a][2] - gps[b][2])
            if du > worst:
                worst, where = du, key
check(npairs >= 2, "gridpoints of two blocks start together at the needle's root and tip (%d pairs)"
      % npairs, out[i:i + 3000])
check(worst < 1e-4, "across the needle's joint the displacements differ by %.3e m at %s (< 1e-4 m)"
      % (worst, where), out[i:i + 3000])
print("largest difference across the joint %.3e m at %s over %d pairs" % (worst, where, npairs))
finish()
