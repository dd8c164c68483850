"""A roof wedge hanging on rock bolts: statics and the bolt's law (label
`verification`; campaign round 5, tools/support_campaign.py).

The roof of a rectangular opening (x 6..14, y 5..8 in a 20 x 20 m model) holds
a wedge cut by two SPLITs crossing at the apex (10, 8 + h), h = 3 m, meeting
the roof y = 8 at x = 10 -+ b, b = 1.5 m: a triangle of area b h = 4.5 m2,
W = rho g b h = 2600 x 10 x 4.5 = 1.17e5 N per metre. Every other block is
FIXed, the wedge FREEd; its faces are joints without cohesion or tension, so
once the opening is DELETEd only the bolts hold it. n = 4 vertical REINFORCE
bolts (x = 10 -+ 0.4 b, 10 -+ 0.8 b) from inside the opening through the
wedge's faces into the fixed rock, installed after the excavation.
References:
- statics: the wedge's faces open, so the sum of the bolts' axial forces
  (vertical) equals W;
- the bolt's axial law, UDEC manual (ICG1.5, 1989), Section 3.10.1, Eqs.
  43-44 with RAEXP = 0: elastic-perfectly plastic, F = min(k d, RUAXIAL),
  d the wedge's drop along the bolt (a vertical translation: symmetric bolts,
  no turn; the shear spring, perpendicular to the bolt, takes nothing):
  F = W / n and d = W / (n k) while W / n < RUAXIAL;
- with RAEXP = 1 the force seeks RUAXIAL asymptotically and depends on the
  path (a reversal unloads at RRFAC k): statics only;
- beyond the capacity (n RUAXIAL = W / 2) the bolts yield at RUAXIAL and the
  wedge falls.
Tolerances: sum of forces and each F = k d within 1 % (the wedge rings down
under DAMP AUTO; measured below 0.01 %); falling: more than 0.5 m in 20 000
cycles and no bolt above RUAXIAL beyond the printed digits (1e-4).
"""
import re
import sys
from udec_test import check, finish, printed_rows, run_clean

udec = sys.argv[1]
H_APEX, B = 3.0, 1.5
RHO, GRAV = 2600.0, 10.0
W = RHO * GRAV * B * H_APEX
N_BOLTS = 4
K = 5e7


def deck(fu, exp):
    xs = [10 - 0.8 * B, 10 - 0.4 * B, 10 + 0.4 * B, 10 + 0.8 * B]
    bolts = "\n".join(f"reinforce 5 {x:.3f} 7.5 {x:.3f} {8 + H_APEX + 2:.3f}" for x in xs)
    t = B / H_APEX
    return f"""round 0.01
block 0,0 0,20 20,20 20,0
split 0,8 20,8
split 0,5 20,5
split 6,0 6,20
split 14,0 14,20
split {10 - t * (8 + H_APEX):.6f},0 {10 + t * (20 - 8 - H_APEX):.6f},20
split {10 + t * (8 + H_APEX):.6f},0 {10 - t * (20 - 8 - H_APEX):.6f},20
prop mat=1 dens={RHO:g} k=10e9 g=6e9
prop jmat=1 jkn=1e10 jks=1e9 jfric=0.5 jcoh=0 jtens=0
prop mat=5 rastiff={K:g} rsstiff={K:g} ruaxial={fu:.6g} rushear={fu:.6g} rlength=0.2 rrfac=1 raexp={exp} rsexp={exp}
grav 0 -{GRAV:g}
damp auto
fix 0,20 0,20
free 9.5,10.5 8,{8 + H_APEX:g}
delete 6.01,13.99 5.01,7.99
{bolts}
cycle 20000
print max
print reinforce
stop
"""


for name, fu, exp, holds in (("elastic_plastic", 3 * W / N_BOLTS, 0, True),
                             ("continuously_yielding", 3 * W / N_BOLTS, 1, True),
                             ("beyond_capacity", 0.5 * W / N_BOLTS, 0, False)):
    out = run_clean(udec, name, deck(fu, exp))
    rows = printed_rows(out, "print reinforce", 12)
    moved = [float(x) for x in re.findall(r"max block displacement\s+(\S+)", out)]
    if not moved or len(rows) < N_BOLTS:
        check(False, f"{name}: PRINT MAX and PRINT REINFORCE printed", out[-2000:])
        continue
    d = moved[-1]
    # elements whose axial force is not zero: the ones across the wedge's faces
    fa = [r[8] for r in rows if abs(r[8]) > 0.0]
    print(f"{name}: RUAXIAL {fu:.5g}, drop {d:.6g} m, bolt forces {[f'{f:.6g}' for f in fa]}, "
          f"sum {sum(fa):.6g} (W {W:.6g})")
    check(len(fa) == N_BOLTS, f"{name}: {N_BOLTS} loaded bolt elements", f"{len(fa)}")
    if holds:
        check(abs(sum(fa) - W) < 0.01 * W, f"{name}: sum of bolt forces = W within 1 %",
              f"{sum(fa)} vs {W}")
        if exp == 0:
            ref = min(K * d, fu)
            check(abs(d - W / (N_BOLTS * K)) < 0.01 * W / (N_BOLTS * K),
                  f"{name}: drop = W / (n k) within 1 %", f"{d} vs {W / (N_BOLTS * K)}")
            check(all(abs(f - ref) < 0.01 * ref for f in fa),
                  f"{name}: each bolt F = k d within 1 %", f"{fa} vs {ref}")
    else:
        check(d > 0.5, f"{name}: the wedge falls (drop > 0.5 m)", f"{d}")
        check(all(f <= fu * (1 + 1e-4) for f in fa), f"{name}: no bolt above RUAXIAL", f"{fa} vs {fu}")
        check(all(f >= fu * (1 - 1e-4) for f in fa), f"{name}: the bolts carry RUAXIAL", f"{fa} vs {fu}")
finish()
