"""Excavation of fully-deformable blocks: DELETE and CHANGE CONS=0 (the
null model, manual Section 4.5 CHANGE: "used to model excavated material")
must both leave an opening whose walls carry no load.

Model: a 2 m x 1 m body cut at x = 1 into two zoned blocks (GEN QUAD 0.25,
K = 1e9, G = 6e8 Pa), in-situ stress sxx = syy = -1e6 Pa, rollers on top
and bottom (vy = 0), the right face x = 2 fixed in x. The left block is
excavated; the right block's face x = 1 becomes free and the block unloads
in uniaxial strain.
Closed form: sxx -> 0, so d eps_xx = 1e6 / M with M = K + 4G/3 = 1.8e9 Pa,
the face moves by ux = -1e6 / 1.8e9 * 1 m = -5.5556e-4 m, and
syy = -1e6 + (K - 2G/3) d eps_xx = -6.6667e5 Pa. Tolerance 1e-3 relative
(damped static run, unbalanced force below 1e-9 N at the end).
With CONS=0 the excavated block stays in place as inert material: its
contacts carry no force (before this rule its corner gridpoints stayed
wedged against the wall of an opening and propped it), so both ways give
the same answer, to 1e-9 relative.
"""
import re
import sys
from udec_test import check, finish, run, workdir, write

udec = sys.argv[1]
DECK = """ROUND 0.01
BLOCK 0,0 0,1 2,1 2,0
SPLIT 1,-1 1,2
GEN QUAD 0.25
PROP MAT=1 D=2000 K=1E9 G=6E8
PROP JMAT=1 JKN=1E11 JKS=1E11 JFRIC=1 JCOH=1E7 JTENS=1E7
INSITU STRESS -1E6 0 -1E6
BOUND 1.9 2.1 -0.1 1.1 XVEL 0
BOUND -0.1 2.1 -0.1 0.1 YVEL 0
BOUND -0.1 2.1 0.9 1.1 YVEL 0
{excavate}
DAMP AUTO
CYC 3000
PRINT GRIDPOINT DISP
PRINT ZONE STRESS
STOP
"""
M = 1.0e9 + 4.0 * 6.0e8 / 3.0
ux_exact = -1.0e6 / M
syy_exact = -1.0e6 + (1.0e9 - 2.0 * 6.0e8 / 3.0) * 1.0e6 / M

results = {}
for label, line in (("DELETE", "DEL -0.1 0.9 -0.1 1.1"), ("CONS=0", "CHANGE -0.1 0.9 -0.1 1.1 CONS=0")):
    d = workdir()
    write(d, "x.dat", DECK.format(excavate=line))
    rc, out = run(udec, ["x.dat"], cwd=d)
    check(rc == 0, f"{label}: deck runs", out[-2000:])
    if rc:
        continue
    # gridpoints of the remaining block (block 2) on its face x = 1
    face = [float(f[4]) for f in (l.split() for l in out.splitlines())
            if len(f) == 8 and re.fullmatch(r"\d+", f[0]) and f[1] == "2" and abs(float(f[2]) - 1.0) < 0.01]
    check(len(face) == 5, f"{label}: five gridpoints on the wall x = 1", str(face))
    # zones of block 2: SXX and SYY columns of PRINT ZONE STRESS
    zones = [(float(f[2]), float(f[4])) for f in (l.split() for l in out.splitlines())
             if len(f) == 11 and re.fullmatch(r"\d+", f[0]) and f[1] == "2"]
    check(len(zones) == 64, f"{label}: 64 zones left in block 2", str(len(zones)))
    if face and zones:
        ux = sum(face) / len(face)
        check(abs(ux / ux_exact - 1.0) < 1.0e-3, f"{label}: wall moves by 1e6/M (closed form)",
              f"{ux:.6e} vs {ux_exact:.6e}")
        check(max(abs(sxx) for sxx, _ in zones) < 1.0e-3 * 1.0e6, f"{label}: sxx unloaded to 0",
              str(max(abs(sxx) for sxx, _ in zones)))
        check(all(abs(syy / syy_exact - 1.0) < 1.0e-3 for _, syy in zones),
              f"{label}: syy = -1e6 + (K - 2G/3) 1e6/M (closed form)",
              f"{min(s for _, s in zones):.6e} .. {max(s for _, s in zones):.6e} vs {syy_exact:.6e}")
        results[label] = ux
if len(results) == 2:
    check(abs(results["CONS=0"] / results["DELETE"] - 1.0) < 1.0e-9, "CONS=0 and DELETE give the same wall",
          f"{results['CONS=0']:.9e} vs {results['DELETE']:.9e}")

# A square opening in a 6 m x 6 m body cut into 3 x 3 zoned blocks, the
# centre block excavated, outer faces on rollers: the two ways must agree
# (1e-6 relative) at the wall point (1, 0). Here the excavated block's
# corners sit in the re-entrant corners of the opening; with contact forces
# on them they propped the opening and the wall moved 0.8 % less.
HOLE = """ROUND 0.01
BLOCK -3,-3 -3,3 3,3 3,-3
SPLIT -1,-4 -1,4
SPLIT 1,-4 1,4
SPLIT -4,-1 4,-1
SPLIT -4,1 4,1
GEN QUAD 0.25
PROP MAT=1 D=2000 K=1E9 G=6E8
PROP JMAT=1 JKN=1E11 JKS=1E11 JFRIC=1 JCOH=1E7 JTENS=1E7
INSITU STRESS -1E6 0 -1E6
BOUND -3.1 -2.9 -3.1 3.1 XVEL 0
BOUND 2.9 3.1 -3.1 3.1 XVEL 0
BOUND -3.1 3.1 -3.1 -2.9 YVEL 0
BOUND -3.1 3.1 2.9 3.1 YVEL 0
{excavate}
DAMP AUTO
CYC 6000
PRINT GRIDPOINT DISP
STOP
"""
wall = {}
for label, line in (("DELETE", "DEL -0.9 0.9 -0.9 0.9"), ("CONS=0", "CHANGE -0.9 0.9 -0.9 0.9 CONS=0")):
    d = workdir()
    write(d, "h.dat", HOLE.format(excavate=line))
    rc, out = run(udec, ["h.dat"], cwd=d)
    check(rc == 0, f"opening, {label}: deck runs", out[-2000:])
    if rc:
        continue
    # the wall gridpoint at (1, 0) of the block right of the opening (it
    # has moved inward; the excavated block's own gridpoint there has not)
    pts = [float(f[4]) for f in (l.split() for l in out.splitlines())
           if len(f) == 8 and re.fullmatch(r"\d+", f[0]) and abs(float(f[2]) - 1.0) < 0.01
           and abs(float(f[3])) < 0.01 and float(f[4]) != 0.0]
    check(len(pts) == 1, f"opening, {label}: one moving wall gridpoint at (1, 0)", str(pts))
    if pts:
        check(pts[0] < 0.0, f"opening, {label}: the wall moves into the opening", f"{pts[0]:.6e}")
        wall[label] = pts[0]
if len(wall) == 2:
    check(abs(wall["CONS=0"] / wall["DELETE"] - 1.0) < 1.0e-6, "opening: CONS=0 and DELETE give the same wall",
          f"{wall['CONS=0']:.9e} vs {wall['DELETE']:.9e}")
finish()
