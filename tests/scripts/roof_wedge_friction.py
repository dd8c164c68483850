"""A frictional roof wedge stays or falls where the closed form says
(label `verification`; campaign round 4, tools/physics_campaign.py).

The roof of an opening: a 20 x 10 m rigid block whose bottom edge (y = 0)
is free, cut by two CRACKs crossing at (10, 5), so a wedge with its apex up
sits in the roof, base 4 m on y = 0, height 5 m, each face at
alpha = atan(2 / 5) = 21.80 degrees from the vertical (face length
l = sqrt(29) m). The other three blocks are fixed. INSITU STRESS
sxx = -10 MPa (syy = 0: the free roof is in balance), gravity 9.81, rho 2600
(W = 2600 x 9.81 x 10 m2 = 2.551e5 N per metre), joints JKN = JKS = 1e10,
no cohesion or tension.
Closed form (limit equilibrium of a symmetric roof wedge clamped by a
horizontal stress; Brady and Brown, Rock Mechanics for Underground Mining,
Section 9.5): the in-situ stress puts on each face the normal force
N = sh cos^2(alpha) l = 4.642e7 N and the shear force N tan(alpha); the
weight adds, per face, W / 2 along the vertical. The wedge stays if and only
if tan(phi) >= tan(alpha) + W / (2 N cos(alpha)) = 0.4 + 0.00296 = 0.40296
(the elastic settlement, W / (2 l (ks cos^2 + kn sin^2)) ~ 2.4e-6 m, changes
N by 1e-3 %: the joints' stiffness does not move the limit).
Checks, 9000 cycles (DAMP AUTO; the zoned wedge's time step is 1/10 of
the rigid one's, so it has fallen less far by then):
tan(phi) = 1.02 x 0.40296: the wedge's base moves less than 1e-5 m;
tan(phi) = 0.98 x 0.40296: it falls, more than 0.05 m (measured 0.129 m
zoned, 8.2 m rigid; the staying wedge settles 2.4e-6 m rigid, 5.0e-6 m zoned).
The same with the wedge turned into a zoned block (GEN AUTO 0.5 on the
wedge only, elastic, K 20 GPa, G 12 GPa): the same limit (the zones carry the
uniform stress exactly).
"""
import math
import sys
from udec_test import check, finish, history_rows, run_clean

udec = sys.argv[1]
ALPHA = math.atan(2.0 / 5.0)
L_FACE = math.sqrt(29.0)
W = 2600 * 9.81 * 10.0
N = 10e6 * math.cos(ALPHA) ** 2 * L_FACE
TAN_LIMIT = math.tan(ALPHA) + W / (2 * N * math.cos(ALPHA))


def deck(fric, gen):
    return f"""round 0.02
block 0,0 0,10 20,10 20,0
crack 8,0 12,10
crack 12,0 8,10
{gen}
prop mat=1 dens=2600 k=20e9 g=12e9
prop jmat=1 jkn=1e10 jks=1e10 jfric={fric:.5f} jcoh=0 jtens=0
fix 0,9 0,10
fix 11,20 0,10
fix 9,11 6,10
insitu stress -10e6 0 0
grav 0 -9.81
damp auto
hist ncyc 20 ydis 10,0
cycle 9000
print hist 1
stop
"""


print(f"closed form: tan(phi) limit {TAN_LIMIT:.5f} (tan alpha {math.tan(ALPHA):.5f}, N {N:.4g} N, W {W:.4g} N)")
for zoning, gen in (("rigid", ""), ("zoned", "gen 9,11 0,3 auto 0.5")):
    for factor, stays in ((1.02, True), (0.98, False)):
        name = f"{zoning}_{'stays' if stays else 'falls'}"
        out = run_clean(udec, name, deck(factor * TAN_LIMIT, gen))
        rows = history_rows(out, "print hist 1")
        if not rows:
            check(False, f"{name}: history printed")
            continue
        drop = -rows[-1][1]
        print(f"{name}: tan(phi) = {factor} x limit, the wedge's base moved {drop:.4g} m down")
        if stays:
            check(abs(drop) < 1e-5, f"{name}: the wedge stays (|drop| < 1e-5 m)", f"{drop}")
        else:
            check(drop > 0.05, f"{name}: the wedge falls (drop > 0.05 m)", f"{drop}")
finish()
