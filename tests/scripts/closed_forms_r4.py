"""Closed forms, round 4: decks written from the command syntax of the UDEC
manual (ICG1.5, 1989), Section 4.5, for cases the other closed-form scripts
(closed_forms.py, closed_forms_fields.py, closed_forms_hm.py,
closed_forms_r3.py, closed_forms_salencon.py, fluid_flow.py,
viscous_boundary.py, reinforcement.py, probe_*_decks.py, guide_decks.py) do
not cover (label `verification`). Each case states its reference and
tolerance; the figures measured when the script was written (Release,
2026-11-27) are given with it.

1. Uplift: a block on a joint with water pressure in it (effective stress;
   manual Section 3.12: the joint's fluid pressure acts on the blocks and
   the joint's strength follows the effective normal stress). A 2 x 1
   rigid block (m = 4000 kg) on a FIXed base, horizontal joint L = 2 m,
   JFRIC tan 30 degrees, no cohesion nor tension, gravity tilted by a = 20
   degrees (GRAV g sin a, -g cos a): N = m g cos a = 37588 N, T = m g sin a
   = 13681 N. FLUID RHOW 0 BULKW 0 (no buoyancy, no flow: the pressure is
   the PFIXed one) and PFIX p in the joint's domain. Reference
   (Mohr-Coulomb on the effective normal force N - p L, Section 3.3,
   Eq. 8; rigid-block limit equilibrium): the block slides when p > p* =
   (N - T / tan phi) / L = 6946 Pa, and then accelerates at g sin a - (g
   cos a - p L / m) tan phi. The joint is first held (JFRIC 100, JCOH and
   JTENS 1e9) under its pressure and the block settled (DAMP AUTO), then
   given its real properties with no damping (as closed_forms_r3.py case
   6). Checks: at 0.9 p* the contacts' normal forces sum to N - p L
   (equilibrium; 1e-4 relative, the printed digits and the joint's
   elastic shear) and the block moves less than 1e-6 m in 0.85 s
   (measured 5e-8); at 1.1 p* the acceleration (second difference of the
   displacement at three times 0.28 s apart) within 0.5 % of 0.2006 m/s^2
   (the net force is 1/17 of the slope force, 0.5 % of it is 3e-4 of the
   forces in balance; measured -0.01 %).
2. A heated block between two held blocks on spring joints (THERMAL,
   Section 7; joints Section 3.3): a 1 x 1 zoned block (K 5e9, G 3e9: E =
   7.5e9, nu = 0.25; THEXP alpha = 1e-5) between two FIXed rigid blocks on
   vertical frictionless joints JKN kn = 1.6e10 Pa/m, top and base free,
   heated uniformly by dT = 50 (TFIX; the engine's thermal strain is
   isotropic in plane strain, szz carrying the held ezz = 0, as
   closed_forms_hm.py case 4 checks). Reference (plane strain with syy = 0:
   exx = sxx (1 - nu^2) / E + (1 + nu) alpha dT; the block's growth closes
   each joint by -sxx / kn, so L exx = -2 sxx / kn): sxx = -(1 + nu)
   alpha dT / ((1 - nu^2) / E + 2 / (kn L)) = -2.5 MPa (half the fully
   held value), each joint closes by 1.5625e-4 m, szz = nu sxx - E alpha
   dT = -4.375 MPa, the block grows in y by eyy = (1 + nu) alpha dT - nu
   (1 + nu) sxx / E = 7.2917e-4. Tolerances: coordinates are updated
   (strains 7e-4: about 4e-4 relative), the joints' end contacts take the
   rounded corners: zone stresses sxx, szz within 0.5 % (measured 0.11 %),
   syy and sxy below 1e-3 of sxx, every contact's normal stress within 0.5 %
   of -sxx (measured 0.13 % at the end contacts), the joints' closure
   (block faces' x-displacement) and the height's growth within 0.5 %
   (measured 0.14 % and +0.05 %).
3. An S wave crossing a joint of shear stiffness ks (the displacement-
   discontinuity joint; Pyrak-Nolte, Myer and Cook 1990, "Transmission of
   seismic waves across single natural fractures", J. Geophys. Res. 95;
   the manual's Test A compares with Miller 1978): |T| = 1 / sqrt(1 +
   (omega Z / (2 ks))^2), Z = rho c_s. A column 1 m wide and 20 m high (rho
   2700, K 2e10, G 1.2e10: c_s = 2108.2 m/s, Z = 5.692e6), a horizontal
   joint at y = 10 (JKS 1.788e9, JKN 1e11, held from slipping), viscous
   base and top (BOUND MAT 1, XVISC YVISC), sides held in y, a continuous
   sine shear stress on the base (BOUND STRESS, HIST SINE f 1.0). At f =
   50 Hz omega Z / (2 ks) = 0.5 (|T| = 0.8944), at 200 Hz 2.0 (|T| =
   0.4472). Measured: the peak |x-velocity| at y = 15 from two periods
   after the wave's arrival (the joint's start-up transient decays as
   exp(-2 ks t / Z), time constant 1.6 ms: at 200 Hz 0.4508 of the
   incident wave in the second period, 0.4424 from the third on) to half a
   period before the run ends, against the same model without the joint
   (the incident wave, checked within 0.5 % of s / (2 Z), measured +0.4 %
   and -0.2 %): the ratio within 1 % of |T| at 50 Hz (QUAD
   0.25, 168 zones a wavelength; measured +0.32 %) and 2 % at 200 Hz (QUAD
   0.125, 84 zones a wavelength: the joint's two gridpoint rows of half a
   zone's mass each add inertia, an error of order (omega h / c_s)^2;
   measured -0.88 %, -2.8 % at QUAD 0.25 against the closed incident
   amplitude). Also: the transmitted amplitude at 200 Hz below that at 50
   Hz by the closed forms' ratio 0.5000 within 2 %.
4. A single plane of weakness (Jaeger 1960, "Shear failure of anisotropic
   rocks", Geological Magazine 97): a 2 x 4 m zoned
   sample (GEN AUTO 0.25; K 1e10, G 6e9) cut by one joint through its
   centre at beta = 60 degrees from the horizontal (its normal at beta to
   sigma1), JCOH c = 0.5 MPa, JFRIC tan 30 degrees, under sigma3 = 1 MPa
   (x) and sigma1 (y) given by BOUNDARY STRESS on its whole outline, the
   base then on rollers (YVEL 0) and its corner held in x. The joint is
   first held (JFRIC 100, JCOH and JTENS 1e9) and the sample brought to
   rest (DAMP AUTO), then given its strength. Reference: the stress is
   uniform, sn = (s1 + s3) / 2 + (s1 - s3) / 2 cos 2 beta, tau = (s1 - s3)
   / 2 sin 2 beta, and the joint slips when s1 - s3 = 2 (c + s3 tan phi) /
   ((1 - tan phi cot beta) sin 2 beta) = 3.732 MPa (s1 = 4.732 MPa).
   Checks: at s1 - s3 = 0.97 of the limit every contact is elastic (state
   ---) and carries sn and tau within 0.5 % (the joint's end contacts at
   the 30-degree corners: measured 0.33 %, the others 0.03 %), the top
   corner moves less than 1e-5 m while the joint gets its strength
   (measured 1.5e-6); at 1.03 of it every contact slips (state S) and the
   top corner moves down and to the left by more than 1 mm, every contact
   has slipped by more than 1 mm (the upper part slides down the joint;
   still accelerating under DAMP AUTO), and the slipping contacts sit at
   tau = c + sn tan phi within 1e-3 (measured 3.6 mm down, 4e-6).
5. A column of zoned blocks under gravity: a 1 x 4 m column (QUAD 0.25,
   rho 2000, K 1e9, G 6e8: M = K + 4 G / 3 = 1.8e9) cut by horizontal
   joints at y = 1, 2, 3 (JKN 1e9), rollers on its sides and base, GRAV
   0 -10, DAMP AUTO. Reference (oedometric column, exact for this
   boundary): syy = -rho g (4 - y), sxx = nu / (1 - nu) syy; each joint
   closes by rho g (4 - y) / JKN (2, 4 and 6e-5 m) and the top settles by
   the joints' closures plus rho g H^2 / (2 M): 1.2e-4 + 8.889e-5 =
   2.0889e-4 m. Checks: every contact's normal stress within 0.5 % of
   rho g (4 - y) and its normal displacement within 0.5 % of that over
   JKN (measured: equal to the printed digits, the joints carry the weight
   above them exactly); the top's settlement within 0.5 % (measured
   -0.001 %; strains 1e-4).
6. A block lifted by water pressure in its joint and held by one grouted
   cable (CABLE, Section 4.5; the grout's shear springs of Section 3.10): the
   2 x 1 block of case 1 (W = 40 kN) on its FIXed base under GRAV 0 -10,
   its joint without tensile strength, one vertical cable of two nodes at
   y = 0.3 (in the base) and y = 1.9 (in the block): one element L = 1.6
   m, E = 2e11 (from K, G), A = 1e-4, grout JKS 2e10 per metre over half
   the element at each node (1.6e10 N/m). PFIX p in the joint, DAMP AUTO.
   Reference (statics, series springs): at p L > W the joint opens and the
   cable carries F = p L - W; the block rises by F (L / (E A) + 2 / (1.6e10))
   = F x 8.0125e-8 m/N. At p = 3e4 Pa: F = 2e4 N, opening 1.6025e-3 m,
   each grout spring slipping F / 1.6e10. At p = 1.5e4 (p L < W) the joint
   stays closed carrying W - p L and the cable almost nothing (the joint's
   closure 5e-7 m shortens it: -6 N). Tolerances: axial force and
   opening 0.5 % (measured -0.04 %: the element's length, 1.6016 m, is
   updated); closed: contacts carry W - p L within 1e-4, the cable below
   1e-3 W.
7. The Brazilian test: an elastic disk R = 1 m (BLOCK CIRCULAR of 72
   sides, GEN AUTO 0.1; K 1e10, G 6e9) squeezed by a point load P = 1e6
   N/m (BOUNDARY YLOAD) at its top gridpoint against its bottom one held
   (XVEL 0 YVEL 0; the top held in x). Reference (Timoshenko and Goodier,
   Theory of Elasticity, 3rd ed., "Stresses in a circular disk"; Hondros
   1959: two Flamant point loads plus a uniform tension, plane elasticity): with r1^2 = x^2 + (R - y)^2, r2^2 =
   x^2 + (R + y)^2, sxx = -(2P/pi) (x^2 (R - y) / r1^4 + x^2 (R + y) /
   r2^4) + P / (pi R), syy = -(2P/pi) ((R - y)^3 / r1^4 + (R + y)^3 /
   r2^4) + P / (pi R), sxy = (2P/pi) (x (R - y)^2 / r1^4 - x (R + y)^2 /
   r2^4); at the centre the tension P / (pi R) = 2 P / (pi D) and syy = -3
   P / (pi R). Checks: sxx and syy averaged over the zones whose centroids
   lie within 0.3 m of the centre, against the closed form averaged over
   the same centroids, within 1 % (constant-strain triangles scatter by 4
   % of P / (pi R) in sxx and 12 % in syy zone by zone, so single zones are
   not compared; measured -0.23 % and -0.65 %), and sxy averaged over the
   zones with x > 0 and over those with x < 0 within 2 % of P / (pi R) of
   its closed-form averages (antisymmetric about the load axis; measured
   0.14 % and 0.21 %).
"""
import math
import sys
from shared_decks import BLOCK_ON_BASE
from udec_test import (cable_elements, check, check_acceleration, contact_parts, finish, printed_rows, run_clean,
                       tables, zone_rows)

udec = sys.argv[1]
GRAV = 10.0


# --- 1. uplift: water pressure in a joint ------------------------------------
UPLIFT = """HEAD uplift: a block on a joint with water pressure in it, p = {p:.1f}
""" + BLOCK_ON_BASE + """PROP MAT=1 DENS=2000 JKN=1E10 JKS=1E10 JFRIC=100 JCOH=1E9 JTENS=1E9
FIX 0,6 0,1
GRAV {gx:.8f} {gy:.8f}
FLUID RHOW 0 BULKW 0
PFIX 2.1,3.9 0.9,1.1 PRESSURE {p:.1f}
DAMP AUTO
CYCLE 3000
HIST NCYC 50 XDIS 3,1.5
PROP MAT=1 JFRIC=0.57735 JCOH=0 JTENS=0
DAMP 0 0
CYCLE 8000
PRINT CONTACT
PRINT HIST 1
STOP
"""
A, PHI, M, L = math.radians(20.0), math.radians(30.0), 4000.0, 2.0
N, T = M * GRAV * math.cos(A), M * GRAV * math.sin(A)
PSTAR = (N - T / math.tan(PHI)) / L
for frac in (0.9, 1.1):
    p = frac * PSTAR
    out = run_clean(udec, f"uplift_{frac:g}", UPLIFT.format(p=p, gx=GRAV * math.sin(A), gy=-GRAV * math.cos(A)))
    h = [r for r in printed_rows(out, "PRINT HIST 1", 2) if r[0] > 0.0]
    if len(h) < 150:
        check(False, f"uplift {frac:g}: history printed", out[-2000:])
        continue
    acc = GRAV * math.sin(A) - (GRAV * math.cos(A) - p * L / M) * math.tan(PHI)
    if acc < 0.0:
        forces = list(contact_parts(out, "NORMAL-FORCE").values())
        nsum = sum(r["NORMAL-FORCE"] for r in forces)
        moved = max(abs(r[1] - h[0][1]) for r in h)
        print(f"uplift {frac:g} p*: holds, moved {moved:.3g} m; normal forces {nsum:.6g} (N - p L {N - p * L:.6g})")
        check(len(forces) == 2 and abs(nsum / (N - p * L) - 1) < 1e-4,
              f"uplift {frac:g} p*: the contacts carry the effective normal force N - p L (1e-4)", str(forces))
        check(moved < 1e-6, f"uplift {frac:g} p*: below the effective-stress limit the block holds (< 1e-6 m)",
              f"{moved}")
    else:
        check_acceleration(f"uplift {frac:g} p*", h, acc, "g sin a - (g cos a - p L / m) tan phi")

# --- 2. a heated block between spring joints -----------------------------------
THJOINT = """HEAD a heated block between two held blocks, on spring joints
THERMAL
ROUND 0.01
BLOCK 0,0 0,1 3,1 3,0
CRACK 1,-1 1,2
CRACK 2,-1 2,2
GEN 1.1 1.9 -1 2 QUAD 0.25
PROP MAT 1 D 2000 K 5E9 G 3E9 SPEC 1000 COND 2 THEXP 1E-5
PROP JMAT 1 JKN 1.6E10 JKS 1.6E10 JFRIC 0 JCOH 0 JTENS 0
FIX 0 1 0 1
FIX 2 3 0 1
INITEM 0 -1 4 -1 2
TFIX 50 -1 4 -1 2
DAMP AUTO
CYCLE 3000
PRINT ZONE STRESS
PRINT CONTACT
PRINT GRID DISP
STOP
"""
KB, GB, ALPHA, DT, KN = 5e9, 3e9, 1e-5, 50.0, 1.6e10
E = 9 * KB * GB / (3 * KB + GB)
NU = (3 * KB - 2 * GB) / (2 * (3 * KB + GB))
SXX = -(1 + NU) * ALPHA * DT / ((1 - NU ** 2) / E + 2 / (KN * 1.0))
SZZ = NU * SXX - E * ALPHA * DT
EYY = (1 + NU) * ALPHA * DT - NU * (1 + NU) * SXX / E
out = run_clean(udec, "thermal_joints", THJOINT)
zs = tables(out, "PRINT ZONE STRESS")
cs = list(contact_parts(out, "NORMAL-STRESS").values())
gd = tables(out, "PRINT GRID DISP")
if zs and cs and gd:
    zs, gd = zs[-1], gd[-1]
    ws = max(max(abs(z["SXX"] / SXX - 1), abs(z["SZZ"] / SZZ - 1)) for z in zs)
    wo = max(max(abs(z["SYY"]), abs(z["SXY"])) for z in zs) / abs(SXX)
    wc = max(abs(c["NORMAL-STRESS"] / -SXX - 1) for c in cs)
    left = [g["X-DISP"] for g in gd if g["X"] < 1.01]
    right = [g["X-DISP"] for g in gd if g["X"] > 1.99]
    top = [g["Y-DISP"] for g in gd if g["Y"] > 0.99]
    base = [g["Y-DISP"] for g in gd if g["Y"] < 0.01]
    close = -SXX / KN
    wu = max(abs(-u / close - 1) for u in left) if left else 1.0
    wu = max([wu] + [abs(u / close - 1) for u in right])
    grow = (sum(top) / max(len(top), 1) - sum(base) / max(len(base), 1))
    print(f"thermal joints: sxx ref {SXX:.5g}, szz ref {SZZ:.5g}: {len(zs)} zones, worst {ws:.3g}; "
          f"syy, sxy {wo:.3g} of sxx; {len(cs)} contacts, worst {wc:.3g}; closure ({close:.5g}) worst {wu:.3g}; "
          f"growth {grow:.5g} ({EYY:.5g})")
    check(len(zs) == 64 and ws < 5e-3, "thermal joints: sxx = -(1+nu) alpha dT / ((1-nu^2)/E + 2/(kn L)), "
          "szz = nu sxx - E alpha dT (0.5 %)", f"worst {ws:.3g}")
    check(wo < 1e-3, "thermal joints: syy = sxy = 0 (1e-3 of sxx)", f"{wo:.3g}")
    check(len(cs) == 10 and wc < 5e-3, "thermal joints: every contact carries -sxx (0.5 %)", f"{wc:.3g}")
    check(len(left) == 5 and len(right) == 5 and wu < 5e-3,
          "thermal joints: each joint closes by -sxx / kn (0.5 %)", f"{wu:.3g}")
    check(len(top) == 5 and len(base) == 5 and abs(grow / EYY - 1) < 5e-3,
          "thermal joints: the free height grows by (1+nu) alpha dT - nu (1+nu) sxx / E (0.5 %)", f"{grow}")
else:
    check(False, "thermal joints: zones, contacts and gridpoints printed", out[-2000:])

# --- 3. an S wave across a joint of shear stiffness ks -------------------------
SWAVE = """HEAD an S wave of {f} Hz crosses a joint of shear stiffness 1.788 GPa/m
ROUND 0.01
BLOCK 0,0 0,20 1,20 1,0
{crack}GEN QUAD {h}
PROP MAT 1 D 2700 K 2E10 G 1.2E10
PROP JMAT 1 JKN 1E11 JKS 1.788E9 JFRIC 100 JCOH 1E9 JTEN 1E9
BOUND MAT 1
BOUND -0.1 1.1 -0.1 0.1 XVISC YVISC
BOUND -0.1 1.1 19.9 20.1 XVISC YVISC
BOUND -0.1 0.1 0.1 19.9 YVEL 0
BOUND 0.9 1.1 0.1 19.9 YVEL 0
BOUND -0.1 1.1 -0.1 0.1 STRESS 0 -1E6 0
BOUND HIST SINE {f} 1.0
HIST N {n} XVEL 0.5,15
CYCLE {ncyc}
PRINT HIST 1
STOP
"""
CS = math.sqrt(1.2e10 / 2700.0)
ZS, KS = 2700.0 * CS, 1.788e9


def s_peak(f, joint, h, n, ncyc):
    """Peak |x-velocity| at y = 15 from two periods after the wave's
    arrival to half a period before the run ends, and the samples taken."""
    out = run_clean(udec, f"swave_{f}_{'joint' if joint else 'none'}",
                    SWAVE.format(f=f, crack="CRACK -1,10 2,10\n" if joint else "", h=h, n=n, ncyc=ncyc))
    rows = [r for r in printed_rows(out, "PRINT HIST 1", 2) if r[0] > 0.0]
    period, arrive = 1.0 / f, 15.0 / CS
    end = rows[-1][0] if rows else 0.0
    seg = [abs(r[1]) for r in rows if arrive + 2 * period <= r[0] <= end - period / 2]
    return max(seg) if seg else float("nan"), len(seg)


amp = {}
for f, h, n, ncyc, tol in ((50, 0.25, 2, 4000, 0.01), (200, 0.125, 4, 3000, 0.02)):
    (vj, nj), (vn, nn) = s_peak(f, True, h, n, ncyc), s_peak(f, False, h, n, ncyc)
    ref = 1.0 / math.sqrt(1.0 + (2 * math.pi * f * ZS / (2 * KS)) ** 2)
    amp[f] = vj
    vi = 1e6 / (2 * ZS)
    print(f"S wave {f} Hz: transmitted {vj:.5g}, incident {vn:.5g} (s / 2Z {vi:.5g}); "
          f"ratio {vj / vn:.5g} (|T| {ref:.5g}, {100 * (vj / vn / ref - 1):+.2f} %)")
    check(nj > 50 and nn > 50 and abs(vn / vi - 1) < 5e-3,
          f"S wave {f} Hz: the incident wave s / (2 rho c_s) (0.5 %)", f"{vn} {vi} samples {nj} {nn}")
    check(abs(vj / vn / ref - 1) < tol,
          f"S wave {f} Hz: transmission 1 / sqrt(1 + (omega Z / 2 ks)^2) ({100 * tol:g} %)", f"{vj / vn} {ref}")
if len(amp) == 2:
    ratio = amp[200] / amp[50]
    ref = math.sqrt((1 + 0.5 ** 2) / (1 + 2.0 ** 2))
    check(abs(ratio / ref - 1) < 0.02, "S wave: 200 Hz transmits less than 50 Hz by the closed forms' ratio (2 %)",
          f"{ratio} {ref}")

# --- 4. a single plane of weakness ---------------------------------------------
WEAK = """HEAD a sample with one joint at 60 degrees, sigma1 = {s1:.1f}, sigma3 = 1E6
ROUND 0.01
BLOCK 0,0 0,4 2,4 2,0
CRACK 0,0.26794919 2,3.73205081
GEN AUTO 0.25
PROP MAT 1 D 2000 K 1E10 G 6E9
PROP JMAT 1 JKN 1E10 JKS 1E10 JFRIC 100 JCOH 1E9 JTENS 1E9
BOUND -0.1 2.1 -0.1 4.1 STRESS -1E6 0 {sy:.1f}
BOUND -0.1 2.1 -0.1 0.1 YVEL 0
BOUND -0.1 0.1 -0.1 0.1 XVEL 0
DAMP AUTO
CYCLE 3000
HIST N 10 XDIS 2,4 YDIS 2,4
PROP JMAT 1 JFRIC 0.57735 JCOH 5E5 JTENS 0
CYCLE 3000
PRINT CONTACT
PRINT HIST 1 2
STOP
"""
BETA, S3, CW, MU = math.radians(60.0), 1e6, 5e5, math.tan(math.radians(30.0))
DLIM = 2 * (CW + MU * S3) / ((1 - MU / math.tan(BETA)) * math.sin(2 * BETA))
for frac in (0.97, 1.03):
    s1 = S3 + frac * DLIM
    out = run_clean(udec, f"weakness_{frac:g}", WEAK.format(s1=s1, sy=-s1))
    sn = (s1 + S3) / 2 + (s1 - S3) / 2 * math.cos(2 * BETA)
    tau = (s1 - S3) / 2 * math.sin(2 * BETA)
    where = contact_parts(out, "SHEAR-DISP")
    stress = contact_parts(out, "NORMAL-STRESS")
    states = [line.split()[12] for line in out.split("PRINT CONTACT")[-1].splitlines()
              if len(line.split()) == 14 and line.split()[0].isdigit()]
    h = [r for r in printed_rows(out, "PRINT HIST 1 2", 3) if r[0] > 0.0]
    if not (stress and h and len(states) == len(stress)):
        check(False, f"weakness {frac:g}: contacts and history printed", out[-2000:])
        continue
    dx, dy = h[-1][1] - h[0][1], h[-1][2] - h[0][2]
    if frac < 1.0:
        worst = max(max(abs(r["NORMAL-STRESS"] / sn - 1), abs(abs(r["SHEAR-STRESS"]) / tau - 1))
                    for r in stress.values())
        moved = math.hypot(dx, dy)
        print(f"weakness {frac:g}: {len(stress)} contacts {sorted(set(states))}, sn {sn:.6g}, tau {tau:.6g}: "
              f"worst {worst:.3g}; the top moved {moved:.3g} m")
        check(set(states) == {"---"}, f"weakness {frac:g}: below the limit every contact is elastic", str(states))
        check(worst < 5e-3, f"weakness {frac:g}: sn and tau of the uniform stress on the joint (0.5 %)", f"{worst}")
        check(moved < 1e-5, f"weakness {frac:g}: below the limit the sample holds (< 1e-5 m)", f"{moved}")
    else:
        lim = max(abs(abs(r["SHEAR-STRESS"]) / (CW + r["NORMAL-STRESS"] * MU) - 1) for r in stress.values())
        print(f"weakness {frac:g}: {len(stress)} contacts {sorted(set(states))}; the top moved ({dx:.3g}, {dy:.3g}) m "
              f"; |tau / (c + sn tan phi) - 1| <= {lim:.3g}")
        check(all(st.startswith("S") for st in states), f"weakness {frac:g}: above the limit every contact slips",
              str(states))
        slip = min(abs(r["SHEAR-DISP"]) for r in where.values())
        print(f"weakness {frac:g}: least shear displacement of a contact {slip:.3g} m")
        check(dx < -1e-3 and dy < -1e-3 and slip > 1e-3,
              f"weakness {frac:g}: above the limit the upper part slides down the joint (> 1 mm at every contact)",
              f"{dx} {dy} {slip}")
        check(lim < 1e-3, f"weakness {frac:g}: the slipping contacts sit at tau = c + sn tan phi (1e-3)", f"{lim}")

# --- 5. a column of zoned blocks under gravity ----------------------------------
ZCOL = """HEAD a column of zoned blocks on joints under gravity
ROUND 0.01
BLOCK 0,0 0,4 1,4 1,0
CRACK -1,1 2,1
CRACK -1,2 2,2
CRACK -1,3 2,3
GEN QUAD 0.25
PROP MAT 1 D 2000 K 1E9 G 6E8
PROP JMAT 1 JKN 1E9 JKS 1E9 JFRIC 0.5 JCOH 0 JTENS 0
BOUND -0.1 1.1 -0.1 0.1 YVEL 0
BOUND -0.1 0.1 -0.1 4.1 XVEL 0
BOUND 0.9 1.1 -0.1 4.1 XVEL 0
GRAV 0 -10
DAMP AUTO
CYCLE 6000
PRINT CONTACT
PRINT GRID DISP
STOP
"""
out = run_clean(udec, "zoned_column", ZCOL)
where = contact_parts(out, "NORMAL-DISP")
stress = contact_parts(out, "NORMAL-STRESS")
gd = tables(out, "PRINT GRID DISP")
MZ = 1e9 + 4 * 6e8 / 3
if where and stress and gd:
    ws = wd = 0.0
    for c, r in where.items():
        load = 2000 * GRAV * (4.0 - round(r["Y"]))
        ws = max(ws, abs(stress[c]["NORMAL-STRESS"] / load - 1))
        wd = max(wd, abs(-r["NORMAL-DISP"] / (load / 1e9) - 1))
    top = [g["Y-DISP"] for g in gd[-1] if g["Y"] > 3.99]
    ref = -(2000 * GRAV * (3 + 2 + 1) / 1e9 + 2000 * GRAV * 16 / (2 * MZ))
    print(f"zoned column: {len(where)} contacts, stress worst {ws:.3g}, closure worst {wd:.3g}; "
          f"top {top[:1]} ({ref:.5g})")
    check(len(where) == 3 * 5 and ws < 5e-3, "zoned column: each joint carries rho g (H - y) (0.5 %)", f"{ws}")
    check(wd < 5e-3, "zoned column: each joint closes by rho g (H - y) / JKN (0.5 %)", f"{wd}")
    check(len(top) == 5 and all(abs(u / ref - 1) < 5e-3 for u in top),
          "zoned column: the top settles by the joints' closure plus rho g H^2 / (2 M) (0.5 %)", str(top))
else:
    check(False, "zoned column: contacts and gridpoints printed", out[-2000:])

# --- 6. a block lifted by joint water pressure, held by one cable ---------------
LIFT = """HEAD a block lifted by water pressure in its joint, held by one cable
""" + BLOCK_ON_BASE + """PROP MAT=1 DENS=2000 JKN=1E10 JKS=1E10 JFRIC=0.5 JCOH=0 JTENS=0
PROP MAT=2 K=1.333333333333E11 G=8E10 DENS=7800
PROP MAT=3 JKS=2E10 JCOH=1E9
FIX 0,6 0,1
CABLE 3,0.3 3,1.9 2 2 1E-4 3
GRAV 0 -10
FLUID RHOW 0 BULKW 0
PFIX 2.1,3.9 0.9,1.1 PRESSURE {p:.1f}
DAMP AUTO
CYCLE 20000
PRINT CABLE
PRINT CONTACT
STOP
"""
W = 2000 * GRAV * 2.0
for p in (3e4, 1.5e4):
    out = run_clean(udec, f"lift_{p:g}", LIFT.format(p=p))
    els = cable_elements(out)
    where = contact_parts(out, "NORMAL-DISP")
    forces = contact_parts(out, "NORMAL-FORCE")
    if len(els) != 1 or len(where) != 2 or len(forces) != 2:
        check(False, f"lift {p:g}: one cable element and two contacts printed", out[-2000:])
        continue
    axial = els[0][3]
    f_ref = p * 2.0 - W
    if f_ref > 0.0:
        opening = sum(r["NORMAL-DISP"] for r in where.values()) / 2
        u_ref = f_ref * (1.6 / (2e11 * 1e-4) + 2 / 1.6e10)
        print(f"lift {p:g}: cable {axial:.6g} N ({f_ref:.6g}), opening {opening:.6g} m ({u_ref:.6g})")
        check(abs(axial / f_ref - 1) < 5e-3, f"lift {p:g}: the cable carries p L - W (0.5 %)", f"{axial}")
        check(abs(opening / u_ref - 1) < 5e-3 and all(r["NORMAL-FORCE"] == 0.0 for r in forces.values()),
              f"lift {p:g}: the joint opens by (p L - W) (L / EA + 2 / k_grout) and carries nothing (0.5 %)",
              f"{opening} {list(forces.values())}")
    else:
        nsum = sum(r["NORMAL-FORCE"] for r in forces.values())
        print(f"lift {p:g}: contacts {nsum:.6g} N ({-f_ref:.6g}), cable {axial:.3g} N")
        check(abs(nsum / -f_ref - 1) < 1e-4 and abs(axial) < 1e-3 * W,
              f"lift {p:g}: below W / L the joint stays closed carrying W - p L (1e-4), the cable idle (1e-3 W)",
              f"{nsum} {axial}")

# --- 7. the Brazilian test -------------------------------------------------------
BRAZIL = """HEAD a disk under diametral point loads (Brazilian test)
ROUND 0.001
BLOCK CIRCULAR 0,0 1 72
GEN AUTO 0.1
PROP MAT 1 D 2000 K 1E10 G 6E9
BOUND -0.01 0.01 0.99 1.01 YLOAD -1E6
BOUND -0.01 0.01 -1.01 -0.99 XVEL 0 YVEL 0
BOUND -0.01 0.01 0.99 1.01 XVEL 0
DAMP AUTO
CYCLE 8000
PRINT ZONE STRESS
PRINT ZONE STATE
PRINT GRID
STOP
"""
PB, RB = 1e6, 1.0


def brazil(x, y):
    """Hondros' disk: (sxx, syy, sxy) at (x, y), loads P at (0, +-R)."""
    r1, r2 = x * x + (RB - y) ** 2, x * x + (RB + y) ** 2
    c, u = 2 * PB / math.pi, PB / (math.pi * RB)
    return (-c * (x * x * (RB - y) / r1 ** 2 + x * x * (RB + y) / r2 ** 2) + u,
            -c * ((RB - y) ** 3 / r1 ** 2 + (RB + y) ** 3 / r2 ** 2) + u,
            c * (x * (RB - y) ** 2 / r1 ** 2 - x * (RB + y) ** 2 / r2 ** 2))


out = run_clean(udec, "brazil", BRAZIL)
rows = zone_rows(out)
centre = [(z, brazil(x, y), x) for z, x, y, _ in rows if math.hypot(x, y) < 0.3]
if len(centre) > 30:
    s0 = PB / (math.pi * RB)
    got = [sum(z[k] for z, _, _ in centre) / len(centre) for k in ("SXX", "SYY")]
    ref = [sum(r[i] for _, r, _ in centre) / len(centre) for i in (0, 1)]
    print(f"brazil: {len(centre)} central zones, sxx {got[0]:.5g} ({ref[0]:.5g}, {100 * (got[0] / ref[0] - 1):+.2f} %), "
          f"syy {got[1]:.5g} ({ref[1]:.5g}, {100 * (got[1] / ref[1] - 1):+.2f} %); at the centre P / (pi R) {s0:.5g}")
    check(all(abs(g / r - 1) < 0.01 for g, r in zip(got, ref)),
          "brazil: sxx (the tension 2 P / (pi D) at the centre) and syy of Hondros' disk, central zones (1 %)",
          f"{got} {ref}")
    for side in (1, -1):
        part = [(z, r) for z, r, x in centre if side * x > 0]
        g = sum(z["SXY"] for z, _ in part) / len(part)
        r = sum(r[2] for _, r in part) / len(part)
        print(f"brazil: sxy for x {'>' if side > 0 else '<'} 0: {g:.5g} ({r:.5g})")
        check(abs(g - r) < 0.02 * s0, "brazil: sxy of Hondros' disk, each side of the load axis (2 % of P / (pi R))",
              f"{g} {r}")
else:
    check(False, "brazil: zones printed", out[-2000:])

finish()
