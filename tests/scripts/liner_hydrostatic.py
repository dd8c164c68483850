"""A liner round a circular tunnel under a hydrostatic field: uniform thrust,
and the closed form of a lined tunnel (UDEC manual (ICG1.5, 1989), Section
3.11 structural elements, Section 4.5 STRUCTURE; the form verification E and
application C use, Appendix A, Problem E, Eq. E-2).

The deck, as a rock engineer writes it: a 3 m tunnel (TUNNEL 0,0 3 24) in a
60 m box of elastic rock, a second ring at 6 m so the rock round the tunnel
can be zoned finer (GEN -6 6 -6 6 EDGE 0.75, then GEN EDGE 3 outside),
INSITU and BOUNDARY STRESS -10 MPa hydrostatic, DAMP AUTO. It is SAVEd,
the tunnel excavated and SOLVEd unlined (the wall's convergence u_inf);
then, twice from the save, the tunnel excavated with a 24-element liner
(0.3 m, E = 30 GPa) put in at once and SOLVEd: bonded (KN = KS = 1e12 N/m,
no slip), its nodes at the wall's 24 vertices, and in slip (KS = 1e7 N/m,
1e-5 of KN: slip in effect, but the ring cannot turn freely as it does
with CFRIC = 0 or KS = 1e3, a mode so slow that SOLVE does not balance it in
100 000 cycles), its nodes at the mid-edges (STRUCT 0,0 7.5 ..., R cos 7.5
degrees from the centre; why not at the vertices: below).

Closed form (thin ring, convergence-confinement, the liner in at
excavation; hydrostatic, so full slip and no slip give the same): the
rock's reaction line p = p0 (1 - u / u_inf), the support's p = Ks u with
Ks = 1 / (R^2 / (E A) + L / KN) per unit wall area, so
p = Ks u_inf / (1 + Ks u_inf / p0), thrust T = p R at every element, R the
nodes' radius. u_inf is measured (the mean radial convergence of the
unlined wall), so the box and the zoning's stiffness are in it. Asserted,
each case: the mean thrust within 5 % of p R (measured -1.3 % bonded,
-0.4 % slip) and every element's thrust within 3 % (bonded; measured -2.4
to +2.2 %) or 1 % (slip; measured +-0.02 %) of the mean.

Why the thrusts varied round the ring (camp7, session 40: +-7 %, GEN EDGE
1.5, bonded). Two causes, measured with this deck's geometry:
1. The zoning (bonded): constant-strain triangles of irregular shape give
   the unlined wall an irregular convergence (+-2.7 % at EDGE 1.5, +-1.7 %
   at 0.75) and the bonded ring takes the wall's hoop strain. Spread of the
   bonded thrusts: zones of 1.5 m at the wall -8.2 / +5.1 %, 0.75 m -2.4 /
   +2.2 % (this deck), 0.5 m -1.2 / +0.9 %: it converges with the zone
   size; nodes at mid-edges change it little (EDGE 1.5: -5.7 / +6.6 %).
2. The interface's normal at a vertex (NOT fixed, session 41): a node at a
   vertex of the wall takes the normal of one of its two edges, 7.5
   degrees off the radius here, so in slip its normal force pushes the
   ring along the wall by 0.13 of itself. In slip (KS 1e3) at EDGE 1.5 the
   thrusts vary -7.7 / +7.8 % with nodes at the vertices, -0.02 / +0.03 %
   with nodes at mid-edges. A normal that turns with the wall (the mean of
   the two edges' normals at a vertex) made the vertex case -0.6 / +0.5 %
   but moved Application C's service liner (an 8-sided wall, half its
   nodes at vertices) from +2.6 % to -5.5 % of the manual's 1.7e5 N and
   broke the main liner's proportionality to its weight at rest by 12 %:
   held back, a debt (docs/robustness.md).
"""
import math
import os
import sys

udec, src = sys.argv[1], sys.argv[2]
sys.path.insert(0, os.path.join(src, "verification"))
from common import check, finish, workdir, run_deck  # noqa: E402

P0 = 10e6           # Pa, hydrostatic field (compression)
R = 3.0             # m, the tunnel's radius (its 24 vertices)
K_L, G_L, THICK = 16.67e9, 12.5e9, 0.3
KN = 1e12           # N/m per node

DECK = f"""ROUND 0.02
BLOCK -30,-30 -30,30 30,30 30,-30
TUNNEL 0,0 3 24
TUNNEL 0,0 6 24
PROP MAT=1 DENS=2600 K=16.67E9 G=10E9
PROP JMAT=1 JKN=1E13 JKS=1E13 JFRIC=1 JCOH=1E9 JTEN=1E9
GEN -6 6 -6 6 EDGE 0.75
GEN EDGE 3
INSITU STRESS -10E6 0 -10E6
BOUND STRESS -10E6 0 -10E6
DAMP AUTO
SAVE pre.sav
DELETE -2.9 2.9 -2.9 2.9
SOLVE RATIO 1E-6
PRINT GRID DISP -3.2 3.2 -3.2 3.2
RESTART pre.sav
DELETE -2.9 2.9 -2.9 2.9
PROP MAT=5 DENS=2500 K=16.67E9 G=12.5E9 KN={KN:g} KS={KN:g} CFRIC=1 CCOH=1E9 CTENS=1E9
STRUCT 0,0 0 3.5 24 5 {THICK}
SOLVE RATIO 1E-6
PRINT STE
RESTART pre.sav
DELETE -2.9 2.9 -2.9 2.9
PROP MAT=6 DENS=2500 K=16.67E9 G=12.5E9 KN={KN:g} KS=1E7 CFRIC=1 CCOH=0 CTENS=1E9
STRUCT 0,0 7.5 3.5 24 6 {THICK}
SOLVE RATIO 1E-6
PRINT STE
STOP
"""

folder = workdir()
rc, out, secs = run_deck(udec, folder, "liner_hydrostatic.dat", DECK)
check(rc == 0 and out.count("SOLVE: balanced") == 3, "the deck runs, its three SOLVEs balance",
      f"rc={rc}, {secs:.1f} s")

# the unlined wall's mean radial convergence
grid = out.split("PRINT GRID DISP -3.2 3.2 -3.2 3.2", 1)[1]
ur = []
for line in grid.splitlines()[2:]:
    f = line.split()
    if len(f) != 8 or not f[0].isdigit():
        break
    x, y, dx, dy = (float(v) for v in f[2:6])
    r = math.hypot(x, y)
    if 2.95 < r < 3.05:
        ur.append(-(x * dx + y * dy) / r)
check(len(ur) >= 24, "the unlined wall's gridpoints", str(len(ur)))
u_inf = sum(ur) / len(ur)

E = 9 * K_L * G_L / (3 * K_L + G_L)


def liner(table, case, spread, R):
    """The 24 thrusts of one PRINT STE against the closed form and their mean."""
    thrust, length = [], []
    for line in table.splitlines()[2:]:
        f = line.split()
        if len(f) < 10 or not f[0].isdigit():
            break
        thrust.append(-float(f[6]))
        length.append(float(f[5]))
    check(len(thrust) == 24, f"{case}: 24 liner elements", str(len(thrust)))
    L = sum(length) / len(length)
    ks = 1.0 / (R * R / (E * THICK) + L / KN)
    p = ks * u_inf / (1 + ks * u_inf / P0)
    mean = sum(thrust) / len(thrust)
    check(abs(mean / (p * R) - 1) <= 0.05, f"{case}: mean thrust {mean:.4g} N within 5 % of the "
          f"closed form p R = {p * R:.4g} N (u_inf {u_inf:.4g} m, Ks {ks:.4g} Pa/m)",
          f"{100 * (mean / (p * R) - 1):+.2f} %")
    lo, hi = min(thrust), max(thrust)
    check(lo >= (1 - spread) * mean and hi <= (1 + spread) * mean,
          f"{case}: every element's thrust within {100 * spread:g} % of the mean",
          f"{100 * (lo / mean - 1):+.2f} to {100 * (hi / mean - 1):+.2f} %")


tables = out.split("Structural elements")[1:]
check(len(tables) == 2, "two PRINT STE tables")
liner(tables[0], "no slip (KS = KN), nodes at the wall's vertices", 0.03, R)
liner(tables[1], "slip (KS = 1e7 N/m), nodes at mid-edges", 0.01,
      R * math.cos(math.pi / 24))
finish()
