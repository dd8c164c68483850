"""Closed forms, round 3: decks written from the command syntax of the UDEC
manual (ICG1.5, 1989), Section 4.5, for cases the other closed-form scripts
(closed_forms.py, closed_forms_fields.py, closed_forms_hm.py,
closed_forms_salencon.py, fluid_flow.py, viscous_boundary.py, reinforcement.py,
probe_*_decks.py) do not cover (label `verification`). Each case states its
reference and tolerance; the figures measured when the script was written
(Release, 2026-11-26) are given with it.

1. A column of five rigid blocks (1 x 1 m, density 2000: m = 2000 kg) stacked
   on a FIXed base block, horizontal joints JKN = JKS = 1e9 (each joint's two
   corner contacts take half its length: k = JKN x 1 m = 1e9 N/m), gravity
   switched on at t = 0, no damping (DAMP 0 0), then DAMP AUTO to rest.
   a. Statics (equilibrium, exact): the joint under block i carries the
      weight of the blocks above it and block i, (6 - i) m g, shared equally
      by its two contacts, and closes by that force over k. Tolerance 1e-6
      relative (printed digits).
   b. Dynamics (a chain of N = 5 equal masses on equal springs, fixed at its
      base, free at its top; e.g. Clough and Penzien, Dynamics of
      Structures, the shear building): the modes are phi_j(i) =
      sin((2 j - 1) i pi / (2 N + 1)), omega_j = 2 sqrt(k / m) sin((2 j - 1)
      pi / (2 (2 N + 1))), so the first mode's period is T1 = 2 pi / omega_1
      = 31.23 ms. The modes decouple, so the projection of the five block
      displacements on phi_1, q1(t) = sum phi_1(i) u_i / sum phi_1(i)^2,
      swings as q1s (1 - cos omega_1 t) about its static value q1s. Checks:
      the period from the first and the last upward crossing of q1s over 21
      periods within 0.1 % of T1 (the central-difference scheme shortens
      it by (omega_1 dt)^2 / 24 = 1.4e-4 at the step of 2.83e-4 s; the
      crossings are interpolated between samples 2 steps apart, and the
      first step's loads start the motion half a step early, 0.3 % of a
      period, which cancels in the difference; measured -0.013 %); every
      trough of q1 within 0.5 % of 2 q1s (no damping: measured 0.06 %).
      The joints are given a tensile strength (JTENS, JCOH 1e9): the linear
      chain's response to sudden gravity pulls the upper joints (a
      simulation of the chain gives -0.38, -1.06, -1.11 and -1.14 x 1e4 N at
      joints 2 to 5, about the weight they carry), so joints without one
      open and the closed form does not apply (the period came out 10 %
      long and the troughs 36 % short).
2. Lame's thick-walled cylinder under internal pressure: a quarter of a ring
   a = 1, b = 3 m (TUNNEL of 72 sides at both radii, the plug and the rock
   outside deleted, rollers on the axes), K = 1.66667e9, G = 1e9 (nu =
   0.25), zones GEN AUTO 0.1, p = 1 MPa by BOUNDARY STRESS on the bore,
   the outer surface free, DAMP AUTO. Reference (Lame; Timoshenko and
   Goodier, Theory of Elasticity, Section 28; plane strain), c = p a^2 /
   (b^2 - a^2): s_rr = c (1 - b^2 / r^2), s_tt = c (1 + b^2 / r^2), s_rt =
   0, u = (1 + nu) c / E ((1 - 2 nu) r + b^2 / r): 0.5937 mm at the bore,
   0.2812 mm at the outer surface. Checks: the four wall displacements (x
   and y axis, bore and outside) within 0.5 % (the 72-sided polygons have
   the area of circles 6e-4 smaller in radius; strain 6e-4 with updated
   coordinates; measured -0.15 % to +0.06 %); s_rr, s_tt and s_rt averaged
   over the zones of each ring 0.2 m wide, against the closed form averaged
   over the same centroids, within 1.5 % of p (constant-strain triangles;
   the ring at the bore, where s_tt falls by 2.25 p per metre, measured
   0.74 %, the others below 0.22 %). At p = 10 MPa (strain 6e-3) the wall
   moves 0.6 to 0.8 % more: the pressure acts on the grown bore (large
   strain), not a defect; hence 1 MPa here.
3. Two parallel joints (cubic law; manual Section 3.12, Eq. 55): three
   FIXed rigid blocks 2 m long separated by joints at y = 0.5 (JMAT 1,
   aperture 1e-4) and y = 1.0 (JMAT 2, aperture 2e-4), jperm kj = 1e8,
   reservoirs p = 1 at x = 0 and 0 at x = 2, SET SFLOW. Reference: each
   joint carries q = kj a^3 dp / L independently (5e-5 and 4e-4), the
   model's inflow their sum 4.5e-4. Tolerance 1e-5 relative (the printed
   digits; exact).
4. A joint network: the same three layers with the middle one cut at x = 1
   by a vertical joint (all apertures 1e-4), water in at the left end of the
   lower joint (p = 1e5 Pa; FLUID 1000 2E9) and out at the right end of the
   upper one (p = 0), the two other ends closed (BOUNDARY IMPERMEABLE).
   Reference (the cubic law through resistances in series, L / (kj a^3)
   each): the path lower-left (1 m), vertical (0.5 m), upper-right (1 m)
   carries q = kj a^3 dp / 2.5 = 4.0, the junctions sit at 6e4 and 4e4 Pa,
   the two dead-end branches carry nothing (PRINT FLOWS leaves out the
   contacts whose flow is exactly 0; any it lists must carry < 1e-5 q) and
   sit at their junction's pressure, the pressure falls linearly along the path (the domain in the
   middle of the vertical joint at 5e4). Tolerance 1e-5 relative (printed
   digits; exact). The default SET PTOL (0.01) is below 1e-4 of these
   pressures, so each cycle makes one Jacobi sweep (CYCLE says so): the
   deck runs 500 cycles (after 50 the inflow was still 5 % above the
   outflow).
5. A cantilever under its own weight: a zoned beam L = 10 m, h = 1 m (GEN
   QUAD 0.25 and 0.125: 4 and 8 zones through the depth), density 2000, K =
   6.6667e9, G = 4e9 (E = 1e10, nu = 0.25), every gridpoint of the root x = 0
   held (XVEL = 0 YVEL = 0), GRAV 0 -10: q = rho g h = 2e4 N/m. Reference
   (Timoshenko beam, plane strain E' = E / (1 - nu^2), I = h^3 / 12, shear
   coefficient 5/6): tip deflection q L^4 / (8 E' I) + q L^2 / (2 (5/6) G h)
   = 28.125 + 0.300 = 28.425 mm; bending stress sxx = M y / I, M = q (L -
   x)^2 / 2, y from the mid-depth. The zones (constant-strain triangles,
   Section 3.2's finite difference triangles) are stiff in bending: measured
   -4.58 % at QUAD 0.25, -1.42 % at QUAD 0.125 (-15 % at QUAD 0.5), an
   error falling by 3.2 for a zone half as large (second order, plus the
   root's corners). Checks: the error falls by at least 2.5 from the coarse
   to the fine run; the fine run's deflection extrapolated to zero zone size
   (Richardson, second order: u_f + (u_f - u_c) / 3) within 1 % of the
   closed form (beam theory against plane elasticity with a held root: the
   root's local compliance and the stress sy, terms of order (h / L)^2 =
   1 %; measured -0.37 %); sxx averaged over the four triangles of each
   quadrilateral of the fine run, two beam depths or more from the root
   and the tip (2 <= x <= 8), within 2 % of the section's largest
   bending stress M h / (2 I) (measured 1.5 %, the largest near x = 8).
   Settling: DAMP AUTO leaves the first bending mode (3.73 Hz, 16 000 steps
   a period at QUAD 0.125) swinging by 0.6 % after 70 000 cycles; mass
   damping at 0.8 of critical at that frequency (DAMP 0.8 3.73 MASS) settles
   it within 1e-5 in 40 000, to the same state (static equilibrium does not
   depend on the damping); the check asks that the tip moves by less than
   1e-4 of its deflection over the last 5000 cycles.
6. A block on a joint with cohesion and friction, both sides of the limit,
   under tilted gravity (GRAV g sin a, -g cos a on a horizontal joint, as a
   user may tilt the load rather than the model): a 2 x 1 rigid block (m =
   4000 kg) on a FIXed base, JFRIC tan 30 degrees, JCOH c = 4000 Pa over L =
   2 m (JCONS 2). Reference (Mohr-Coulomb, Section 3.3, Eq. 8; rigid-block
   limit equilibrium): it slides when m g sin a > c L + m g cos a tan phi,
   i.e. above a = 39.974 degrees, and then accelerates at g sin a - g cos a
   tan phi - c L / m. The joint is first held (JFRIC 100, JCOH 1e9) and the
   block settled (DAMP AUTO), then given its real properties with no
   damping, as in closed_forms.py case 1 (loaded suddenly with its real
   properties and no damping, the forces overshoot the static ones and the
   block at 39 degrees slips 1.2 mm before it stops; under DAMP AUTO from
   the start it moves only its elastic 1.7e-6 m). Checks: at
   39 degrees (3 % of the shear capacity to spare) it moves less than
   1e-6 m in 0.85 s (measured 8.5e-8: the uphill corner, carrying 9.3 of
   the 31.1 kN under the moment of the slope force, slips first and sheds its
   share to the downhill one); at 41 degrees the acceleration from the
   second difference of the displacement at three times 0.28 s apart within
   0.5 % of 0.2033 m/s^2 (1 degree past the limit the net force is a
   thirty-second of the slope force: 0.5 % of it is 1.5e-4 of the forces
   in balance; measured below 1e-4 relative).
"""
import collections
import math
import sys
from shared_decks import BLOCK_ON_BASE, COLUMN_FIVE
from udec_test import (check, check_acceleration, contact_parts, finish, polar_stress, printed_rows, run_clean,
                       tables, zone_rows)

udec = sys.argv[1]

# --- 1. a column of five rigid blocks ---------------------------------------
N, MASS, KJ, GRAV = 5, 2000.0, 1e9, 10.0
COLUMN = COLUMN_FIVE + """FIX 0,1 0,1
GRAV 0 -10
DAMP 0 0
HIST NCYC 2 YDIS 0.5,1.5 YDIS 0.5,2.5 YDIS 0.5,3.5 YDIS 0.5,4.5 YDIS 0.5,5.5
CYCLE 2400
PRINT HIST 1 2 3 4 5
DAMP AUTO
CYCLE 4000
PRINT CONTACT
STOP
"""


out = run_clean(udec, "column_chain", COLUMN)
where = contact_parts(out, "NORMAL-DISP")
force = contact_parts(out, "NORMAL-FORCE")
joints = collections.defaultdict(list)
for c, r in where.items():
    if c in force:
        joints[round(r["Y"])].append((force[c]["NORMAL-FORCE"], r["NORMAL-DISP"]))
print(f"column: joints {sorted(joints)}, contacts {[len(joints[y]) for y in sorted(joints)]}")
worst = 0.0
for y in range(1, N + 1):
    w = (N + 1 - y) * MASS * GRAV  # the blocks above the joint at height y
    for fn, dn in joints.get(y, []):
        worst = max(worst, abs(fn - w / 2) / (w / 2), abs(-dn - w / KJ) / (w / KJ))
print(f"column: normal forces and closures, worst relative error {worst:.2g}")
check(sorted(joints) == list(range(1, N + 1)) and all(len(joints[y]) == 2 for y in joints) and worst < 1e-6,
      "column: each joint carries the weight above it and closes by it over JKN L (1e-6)",
      str(dict(joints)))

hist = printed_rows(out, "PRINT HIST 1 2 3 4 5", N + 1)
phi = [math.sin(i * math.pi / (2 * N + 1)) for i in range(1, N + 1)]
w1 = 2 * math.sqrt(KJ / MASS) * math.sin(math.pi / (2 * (2 * N + 1)))
T1 = 2 * math.pi / w1
# static displacements of the chain: joint y closes by (N + 1 - y) m g / k
static, u = [], 0.0
for y in range(1, N + 1):
    u -= (N + 1 - y) * MASS * GRAV / KJ
    static.append(u)
norm = sum(f * f for f in phi)
q1s = sum(f * s for f, s in zip(phi, static)) / norm
if len(hist) > 1000:
    q1 = [(r[0], sum(f * v for f, v in zip(phi, r[1:])) / norm) for r in hist]
    ups = [t0 + (t1 - t0) * (q1s - a) / (b - a) for (t0, a), (t1, b) in zip(q1, q1[1:]) if a < q1s <= b]
    period = (ups[-1] - ups[0]) / (len(ups) - 1)
    troughs = [b for (_, a), (_, b), (_, c) in zip(q1, q1[1:], q1[2:]) if b < a and b <= c]
    worst_trough = max(abs(p - 2 * q1s) for p in troughs) / abs(2 * q1s)
    print(f"column: first mode period {1e3 * period:.5g} ms over {len(ups) - 1} periods "
          f"({1e3 * T1:.5g} ms, {100 * (period / T1 - 1):+.3f} %), {len(troughs)} troughs within "
          f"{100 * worst_trough:.3f} % of twice the static {2 * q1s:.5g}")
    check(len(ups) >= 20 and abs(period / T1 - 1) < 1e-3,
          "column: first mode period 2 pi / (2 sqrt(k/m) sin(pi / (2 (2N + 1)))) (0.1 %)", f"{period} {T1}")
    check(len(troughs) >= 20 and worst_trough < 5e-3, "column: the first mode swings to twice its static value (0.5 %)",
          f"worst {worst_trough:.3g}")
else:
    check(False, "column: histories printed", out[-2000:])

# --- 2. Lame's thick-walled cylinder ----------------------------------------
LAME = """HEAD thick-walled cylinder under internal pressure
ROUND 0.01
BLOCK 0,0 0,4 4,4 4,0
TUNNEL 0,0 1,72
TUNNEL 0,0 3,72
DELETE 0,0.6 0,0.6
DELETE 2.5,4 2.5,4
GEN 0,3 0,3 AUTO 0.1
PROP MAT=1 DENS=2500 BULK=1.66667E9 SHEAR=1E9
BOUND -.01 1.01 -.01 1.01 STRESS -1E6 0 -1E6
BOUND -.01 .01 -.01 3.01 XVEL=0
BOUND -.01 3.01 -.01 .01 YVEL=0
DAMP AUTO
HIST NCYC 100 XDIS 1,0 YDIS 0,1 XDIS 3,0 YDIS 0,3
CYC 8000
PRINT HIST 1 2 3 4
PRINT ZONE STRESS
PRINT ZONE STATE
PRINT GRID
STOP
"""
PL, A, B, KB, GB = 1e6, 1.0, 3.0, 1.66667e9, 1e9
NU = (3 * KB - 2 * GB) / (2 * (3 * KB + GB))
EB = 9 * KB * GB / (3 * KB + GB)
CL = PL * A * A / (B * B - A * A)


def lame(r):
    return CL * (1 - B * B / (r * r)), CL * (1 + B * B / (r * r))


def lame_u(r):
    return (1 + NU) * CL / EB * ((1 - 2 * NU) * r + B * B / r)


out = run_clean(udec, "lame", LAME)
hist = printed_rows(out, "PRINT HIST 1 2 3 4", 5)
if hist and tables(out, "PRINT GRID") and tables(out, "PRINT ZONE STATE"):
    walls = hist[-1][1:]
    refs = [lame_u(A), lame_u(A), lame_u(B), lame_u(B)]
    errs = [w / r - 1 for w, r in zip(walls, refs)]
    print(f"lame: walls {walls} against {lame_u(A):.5g}, {lame_u(B):.5g}: "
          + ", ".join(f"{100 * e:+.3f} %" for e in errs))
    check(all(abs(e) < 5e-3 for e in errs), "lame: bore and outer surface move by u(r) of Lame (0.5 %)", str(errs))
    rings = collections.defaultdict(list)
    for z, x, y, _ in zone_rows(out):
        r = math.hypot(x, y)
        rings[int((r - A) / 0.2)].append((r, *polar_stress(z, math.atan2(y, x))))
    worst = (0.0, "")
    for key in sorted(rings):
        v = rings[key]
        got = [sum(q[j] for q in v) / len(v) for j in (1, 2, 3)]
        ref = [sum(lame(q[0])[j] for q in v) / len(v) for j in (0, 1)] + [0.0]
        err = max(abs(g - f) for g, f in zip(got, ref)) / PL
        if err >= worst[0]:
            worst = (err, f"ring {key} ({len(v)} zones): s_rr {got[0]:.4g} ({ref[0]:.4g}), "
                          f"s_tt {got[1]:.4g} ({ref[1]:.4g}), s_rt {got[2]:.3g}")
    print(f"lame: {sum(len(v) for v in rings.values())} zones in {len(rings)} rings, worst {100 * worst[0]:.2f} % of p ({worst[1]})")
    check(len(rings) == 10 and worst[0] < 0.015, "lame: ring-averaged s_rr, s_tt, s_rt within 1.5 % of p",
          worst[1])
else:
    check(False, "lame: histories, grid and zones printed", out[-2000:])

# --- 3. two parallel joints ---------------------------------------------------
LAYERS = """ROUND 0.01
BLOCK 0,0 0,1.5 2,1.5 2,0
CRACK -1,0.5 3,0.5
CRACK -1,1.0 3,1.0
"""
PARALLEL = LAYERS + """PROP MAT=1 DENS=1 JKN=100 JKS=100 JPERM=1E8 AZERO=1E-4 ARES=1E-4
PROP JMAT=2 JKN=100 JKS=100 JPERM=1E8 AZERO=2E-4 ARES=2E-4
CHANGE -1 3 0.9 1.1 JMAT 2
FIX -1 3 -1 2
FLUID 1.0 100
SET SFLOW
BOUND -0.1 0.1 -1 2 PP 1.0
BOUND 1.9 2.1 -1 2 PP 0.0
CYCLE 50
PRINT FLOWS
STOP
"""
out = run_clean(udec, "parallel_joints", PARALLEL)
flows = printed_rows(out, "PRINT FLOWS", 7) + printed_rows(out, "PRINT FLOWS", 8)
inflow = [float(l.split()[-1]) for l in out.splitlines() if l.startswith("total boundary inflow")]
q_ref = {0.5: 1e8 * 1e-4 ** 3 / 2, 1.0: 1e8 * 2e-4 ** 3 / 2}
bad = [f for f in flows if abs(abs(f[6]) - q_ref.get(f[4], 0.0)) > 1e-5 * q_ref.get(f[4], 1.0)]
print(f"parallel joints: {len(flows)} contacts, inflow {inflow} ({sum(q_ref.values()):.6g})")
check(len(flows) == 4 and not bad, "parallel joints: each joint carries kj a^3 dp / L (1e-5)", str(flows))
check(inflow and abs(inflow[-1] - sum(q_ref.values())) < 1e-5 * sum(q_ref.values()),
      "parallel joints: the inflow is the sum of the joints' flows (1e-5)", str(inflow))

# --- 4. a joint network with dead ends ---------------------------------------
NETWORK = LAYERS + """CRACK 1,0.4 1,1.1
PROP MAT=1 DENS=1000 JKN=1E9 JKS=1E9 JPERM=1E8 AZERO=1E-4 ARES=1E-4
FIX -1 3 -1 2
FLUID 1000 2E9
SET SFLOW
BOUND -0.1 0.1 0.4 0.6 PP 1E5
BOUND 1.9 2.1 0.4 0.6 IMP
BOUND -0.1 0.1 0.9 1.1 IMP
BOUND 1.9 2.1 0.9 1.1 PP 0
CYCLE 500
PRINT FLOWS
PRINT FLUID
STOP
"""
out = run_clean(udec, "network", NETWORK)
flows = printed_rows(out, "PRINT FLOWS", 7) + printed_rows(out, "PRINT FLOWS", 8)
doms = printed_rows(out, "PRINT FLUID", 5, flag=True)
KA3, DP, LPATH = 1e8 * 1e-4 ** 3, 1e5, 2.5
q_net = KA3 * DP / LPATH


def p_ref(x, y):
    """The pressure along the path (lower joint to x = 1, up the vertical
    joint, upper joint to x = 2); a dead end at its junction's."""
    if abs(y - 0.5) < 0.05:
        return DP * (1 - min(x, 1.0) / LPATH)
    if abs(y - 1.0) < 0.05:
        return DP * (1 - (1.5 + max(x - 1.0, 0.0)) / LPATH)
    return DP * (1 - (1.0 + (y - 0.5)) / LPATH)


on_path = [f for f in flows if not (abs(f[4] - 0.5) < 0.05 and f[3] > 1.005)
           and not (abs(f[4] - 1.0) < 0.05 and f[3] < 0.995)]
dead = [f for f in flows if f not in on_path]
worst_q = max((abs(abs(f[6]) - q_net) / q_net for f in on_path), default=1.0)
worst_dead = max((abs(f[6]) / q_net for f in dead), default=0.0)
worst_p = max((abs(d[1] - p_ref(d[3], d[4])) / DP for d in doms), default=1.0)
print(f"network: {len(on_path)} contacts on the path within {worst_q:.2g} of {q_net:.6g}, "
      f"{len(dead)} printed on the dead ends (at most {worst_dead:.2g} of q), "
      f"{len(doms)} domains within {worst_p:.2g} of dp")
check(len(on_path) == 6 and worst_q < 1e-5, "network: the path carries kj a^3 dp / (L1 + L2 + L3) (1e-5)",
      str(flows))
check(worst_dead < 1e-5, "network: the dead-end branches carry nothing", str(dead))
check(len(doms) == 7 and worst_p < 1e-5, "network: the pressure falls linearly along the path, dead ends at "
      "their junction's (1e-5 of dp)", str(doms))

# --- 5. a cantilever under its own weight -----------------------------------
BEAM = """HEAD cantilever under its own weight, zones {zone}
ROUND 0.01
BLOCK 0,0 0,1 10,1 10,0
GEN QUAD {zone}
PROP MAT=1 DENS=2000 K=6.6667E9 G=4E9
BOUND -0.01 0.01 -0.01 1.01 XVEL=0 YVEL=0
GRAV 0 -10
DAMP 0.8 3.73 MASS
HIST NCYC 100 YDIS 10,0.5
CYCLE {cycles}
PRINT HIST 1
{prints}STOP
"""
QB, LB, HB, EBM, NUB, GBM = 2e4, 10.0, 1.0, 1e10, 0.25, 4e9
IB = HB ** 3 / 12
EP = EBM / (1 - NUB ** 2)
TIP = QB * LB ** 4 / (8 * EP * IB) + QB * LB ** 2 / (2 * (5.0 / 6.0) * GBM * HB)
tips, settled = {}, {}
for zone, cycles in ((0.25, 25000), (0.125, 50000)):
    prints = "PRINT ZONE STRESS\nPRINT ZONE STATE\nPRINT GRID\n" if zone == 0.125 else ""
    out = run_clean(udec, f"cantilever_{zone}", BEAM.format(zone=zone, cycles=cycles, prints=prints))
    h = [r for r in printed_rows(out, "PRINT HIST 1", 2) if r[0] > 0.0]
    if len(h) > 60:
        tips[zone] = -h[-1][1]
        settled[zone] = max(abs(r[1] - h[-1][1]) for r in h[-50:]) / abs(h[-1][1])
    fine_out = out
if len(tips) == 2:
    uc, uf = tips[0.25], tips[0.125]
    extra = uf + (uf - uc) / 3
    ratio = (TIP - uc) / (TIP - uf)
    print(f"cantilever: tip {1e3 * uc:.5g} / {1e3 * uf:.5g} mm at QUAD 0.25 / 0.125 ({1e3 * TIP:.5g}: "
          f"{100 * (uc / TIP - 1):+.2f} / {100 * (uf / TIP - 1):+.2f} %), error ratio {ratio:.3g}, "
          f"extrapolated {1e3 * extra:.5g} mm ({100 * (extra / TIP - 1):+.2f} %), moved {settled}")
    check(all(v < 1e-4 for v in settled.values()), "cantilever: settled (the tip moves < 1e-4 over 5000 cycles)",
          str(settled))
    check(ratio > 2.5, "cantilever: the deflection's error falls by at least 2.5 when the zones halve", f"{ratio:.3g}")
    check(abs(extra / TIP - 1) < 0.01,
          "cantilever: extrapolated tip deflection q L^4 / (8 E' I) + q L^2 / (2 k G h) within 1 %", f"{extra:.6g}")
    cells = collections.defaultdict(list)
    for z, x, y, _ in zone_rows(fine_out):
        cells[(int(x / 0.125), int(y / 0.125))].append(z["SXX"])
    worst = (0.0, "")
    for (i, j), v in cells.items():
        xc, yc = (i + 0.5) * 0.125, (j + 0.5) * 0.125
        if 2.0 <= xc <= 8.0:
            m = QB * (LB - xc) ** 2 / 2
            err = abs(sum(v) / len(v) - m * (yc - 0.5 * HB) / IB) / (m * 0.5 * HB / IB)
            if err >= worst[0]:
                worst = (err, f"x {xc}, y {yc}: {sum(v) / len(v):.5g} ({m * (yc - 0.5 * HB) / IB:.5g})")
    print(f"cantilever: bending stress in {len(cells)} cells, worst {100 * worst[0]:.2f} % of M h / (2 I) "
          f"({worst[1]})")
    check(len(cells) == 640 and worst[0] < 0.02, "cantilever: sxx = M y / I within 2 % of the section's largest",
          worst[1])
else:
    check(False, "cantilever: histories printed")

# --- 6. cohesion and friction, both sides of the limit ------------------------
TILT = """HEAD block on a joint under tilted gravity, {adeg} degrees
""" + BLOCK_ON_BASE + """PROP MAT=1 DENS=2000 JKN=1E10 JKS=1E10 JFRIC=100 JCOH=1E9 JTENS=1E9
FIX 0,6 0,1
GRAV {gx:.8f} {gy:.8f}
DAMP AUTO
CYCLE 3000
HIST NCYC 50 XDIS 3,1.5
PROP MAT=1 JFRIC=0.57735 JCOH=4000 JTENS=0
DAMP 0 0
CYCLE 8000
PRINT HIST 1
STOP
"""
PHI, COH, MB = math.radians(30.0), 4000.0, 4000.0
for adeg in (39.0, 41.0):
    a = math.radians(adeg)
    out = run_clean(udec, f"tilt_{adeg:g}", TILT.format(adeg=adeg, gx=GRAV * math.sin(a), gy=-GRAV * math.cos(a)))
    h = [r for r in printed_rows(out, "PRINT HIST 1", 2) if r[0] > 0.0]
    if len(h) < 150:
        check(False, f"tilt {adeg:g}: history printed", out[-2000:])
        continue
    acc = GRAV * (math.sin(a) - math.cos(a) * math.tan(PHI)) - COH * 2.0 / MB
    if acc < 0.0:
        moved = max(abs(r[1] - h[0][1]) for r in h)
        print(f"tilt {adeg:g}: holds, moved {moved:.3g} m in {h[-1][0] - h[0][0]:.3g} s")
        check(moved < 1e-6, f"tilt {adeg:g}: below the Mohr-Coulomb limit the block holds (< 1e-6 m)", f"{moved}")
    else:
        check_acceleration(f"tilt {adeg:g}", h, acc, "g sin a - g cos a tan phi - c L / m")

finish()
