"""JCONS 3 long shear (label `stability`): direct shear tests of the
continuously-yielding joint, written from the manual's Section 4 syntax,
against an independent integration of its equations (manual Section 3.3,
Eqs. 10-18; Appendix B, Application E, Eqs. E-1 to E-12) in this script.

1. Direct shear (Application E's properties, MPa / m / s): a 2 x 1 elastic
   block (GEN QUAD: four boundary gridpoints, so BOUND XVEL holds its whole
   boundary and its two joint contacts carry the same normal stress) on a
   FIXed rigid base, normal stress 10 held by BOUND STRESS on its top edge,
   sheared by BOUND XVEL -0.005 for 22 000 cycles (10.9 mm), then back 3 mm
   and forward 3 mm. For JIF = 1.035 (Fig. E-1) and 0.700 (Fig. E-2):
   - no error; the shear stress rises to a peak and softens to the
     residual sigma_n tan(phi);
   - peak, the whole curve (forward, back, forward) and the dilation agree
     within 2 % with the equations integrated here at sigma_n = 10 along the
     joint's own shear-displacement history (steps of 1e-8 m): peak and
     curve relative to the peak, dilation relative to its value at 10 mm;
     the dilation is read as NDIS + NSTR / JKN (the opening not explained
     by the elastic closure of Eq. 10) and also as the raw change of NDIS;
   - the normal stress stays within 1 % of 10, and after the first peak the
     shear stress never exceeds the current bounding strength.
   The fit is limited by the code's shear step (5e-7 m per cycle against
   the elastic length tau_m / k_s = 1.7e-4 m: Euler's error about 0.15 %)
   and by the dynamics of the block (normal stress within 0.3 % of 10).
   Before the fix the joint never dilated (NDIS change 0), which fails the
   dilation check.
   The first case again with JEN = JES = 0.5 and JKN = JKS = 1e5 / sqrt(10)
   (the same stiffness at sigma_n = 10): the same curves, through the time
   step's scaling of the gridpoints' bound (smaller step, 26 000 cycles).
2. Time step with a stress-dependent stiffness (JEN = JES = 1, k = JKN
   sigma_n): a rigid 2 x 1 block on a FIXed base (two contacts of length 1,
   mass m = 4000), joints pre-stressed by INSITU (sigma_n^JEN is 0 at zero
   stress), LOAD raised tenfold four times. After each stage a CYCLE 1
   computes the step afresh: dt = FRACTION 2 sqrt(m / (1.05 k)) with
   k = JKN sigma_n L the current stiffness (1.05: the headroom of
   engine_cycle), within 1e-3; the step taken while loading is never above
   the stable step of the stiffness reached. Before the fix dt stayed at
   the value for JKN alone and the block went through its base.
3. Both blocks deformable and coarsely zoned (GEN AUTO 2.1: one or two
   zones a block), the base's upper half free, the top sheared at 0.05 m/s
   for 20 mm (Application E's properties, JIF 1.035, a brittle R = 1e-4).
   The joint's few contacts soften faster than the coarse blocks unload,
   so the slip is fast and Eq. 11's step k_s du_s exceeds tau_m (1 - r).
   At ROUND 0.003 and 0.01, and for 80 mm at 0.003:
   - no error (before the fix: "Contact Overlap Too Great" at cycle 2610,
     10.4 mm, a gridpoint at 42 m/s; ROUND 0.01 ended with an unbalanced
     force of 24);
   - the final unbalanced force is below 0.5 % of the joint's normal load
     (10 x 2 m = 20);
   - the contacts' normal forces add up to that load within 2 %;
   - no contact carries more shear than fn tan(JIF) (the bounding strength
     before any damage; relative 1e-6).
"""
import math
import sys
from udec_test import check, finish, run, workdir, write, NUM

udec = sys.argv[1]

# a 2 x 1 block on a 4 x 1 base, split by one horizontal joint
SPECIMEN = """block 0,0 0,2 4,2 4,0
crack -0.1,1 4.1,1
crack 1,1 1,2.1
crack 3,1 3,2.1
delete 0,1 1,2
delete 3,4 1,2
"""

SHEAR = "round 0.001\n" + SPECIMEN + """prop mat=1 d=2.6e-3 k=4000 g=3000
prop jmat=1 jkn={a} jks={a} jen={e} jes={e} jfric=0.577 jif={jif} jr=1e-4
change 1,3 1,2 fdef mat=1 cons=1
gen 1,3 1,2 quad 3
change jmat=1 jcons=3
fix 0,4 0,1
insitu stress 0,0,-10
bound 0.9,3.1 1.9,2.1 stress 0,0,-10
damp auto
cycle 200
bound 0.9,3.1 0.9,2.1 xvel=-0.005
hist ncyc 10 sdis 1 ndis 1 sstr 1 nstr 1 sdis 2 ndis 2 sstr 2 nstr 2
cycle {n}
bound 0.9,3.1 0.9,2.1 xvel=0.005
cycle 6000
bound 0.9,3.1 0.9,2.1 xvel=-0.005
cycle 6000
print hist 1 2 3 4 5 6 7 8
stop
"""

SN, KN, KS, PHI, R = 10.0, 1.0e5, 1.0e5, math.atan(0.577), 1.0e-4


def history(out, command):
    text = out.split(command)[-1]
    rows = []
    for line in text.splitlines()[2:]:
        f = line.split()
        if not f or not all(NUM.match(x) for x in f):
            break
        rows.append([float(x) for x in f])
    return rows


def integrate(path, phi0, h=1.0e-8):
    """Eqs. 11, 13-18 (E-4 to E-12) at constant sigma_n = SN along the shear
    displacement path (list of values): tau, phi_eff and the dilation
    integral of tan(i) |du| at each point of the path. Reversal: r =
    tau / tau_m (at most 0.75) when du changes sign; F at most 1."""
    tau, ph, dil, r, dold = 0.0, phi0, 0.0, 0.0, 0.0
    res = [(tau, ph, dil)]
    for a, b in zip(path[:-1], path[1:]):
        n = max(1, int(abs(b - a) / h + 0.5))
        du = (b - a) / n
        for _ in range(n if du != 0.0 else 0):
            tm = SN * math.tan(ph) * math.copysign(1.0, du)
            if dold != 0.0 and math.copysign(1.0, du) != math.copysign(1.0, dold):
                r = min(tau / tm, 0.75)
            f = min((1.0 - tau / tm) / (1.0 - r), 1.0)
            tau += f * KS * du
            ph = PHI + (ph - PHI) * math.exp(-max(0.0, 1.0 - f) * abs(du) / R)
            dil += abs(du) * math.tan(max(0.0, math.atan(abs(tau) / SN) - PHI))
            dold = du
        res.append((tau, ph, dil))
    return res


for jif, fig, e, ncyc in ((1.035, "E-1", 0.0, 22000), (0.700, "E-2", 0.0, 22000),
                          (1.035, "E-1", 0.5, 26000)):
    d = workdir()
    a = 1.0e5 / SN**e
    write(d, "shear.dat", SHEAR.format(jif=jif, a=a, e=e, n=ncyc))
    rc, out = run(udec, ["shear.dat"], cwd=d, timeout=300)
    name = f"JIF {jif} (Fig. {fig})" + (f" JEN = JES = {e}" if e else "")
    check(rc == 0 and "***" not in out, f"{name}: forward, back and forward shear run without error",
          "\n".join(l for l in out.splitlines() if "***" in l)[:2000])
    rows = history(out, "print hist 1 2 3 4 5 6 7 8")
    check(len(rows) >= 3000, f"{name}: history rows", str(len(rows)))
    if len(rows) < 3000:
        continue
    for c in (0, 4):
        label = f"{name} contact {c // 4 + 1}"
        sdis = [0.0] + [r[1 + c] for r in rows]
        ndis = [-SN / KN] + [r[2 + c] for r in rows]
        sstr = [0.0] + [r[3 + c] for r in rows]
        nstr = [SN] + [r[4 + c] for r in rows]
        ref = integrate(sdis, jif)
        i_fwd = max(range(len(sdis)), key=lambda i: sdis[i])
        check(sdis[i_fwd] >= 0.010, f"{label}: sheared at least 10 mm forward", str(sdis[i_fwd]))
        # peak and softening (Fig. E-1(a), E-2(a))
        peak = max(sstr[:i_fwd + 1])
        ref_peak = max(t for t, _, _ in ref[:i_fwd + 1])
        check(abs(peak - ref_peak) <= 0.02 * ref_peak,
              f"{label}: peak = integration of Eqs. 10-18 within 2 %", f"{peak} vs {ref_peak}")
        res = SN * 0.577
        check(peak - res >= 0.5 * (ref_peak - res) > 0.0,
              f"{label}: a peak above the residual strength", str(peak))
        check(abs(sstr[i_fwd] - res) <= 0.01 * res,
              f"{label}: softened to sigma_n tan(phi) at 10 mm (1 %)", str(sstr[i_fwd]))
        # the whole curve, through both reversals, relative to the peak
        err = max(abs(a - b[0]) for a, b in zip(sstr, ref))
        check(err <= 0.02 * ref_peak, f"{label}: shear stress curve within 2 % of the peak",
              f"max |tau - tau_ref| = {err}")
        check(min(sstr) < -0.99 * res and abs(sstr[-1] - res) <= 0.01 * res,
              f"{label}: back to -sigma_n tan(phi), forward to +sigma_n tan(phi) (1 %)",
              f"min {min(sstr)}, end {sstr[-1]}")
        # bounded: no second peak; once damaged (phi_eff = phi at 10 mm) the
        # stress approaches +-tau_m from inside through both reversals
        check(max(abs(t) for t in sstr[sstr.index(peak) + 1:]) <= peak,
              f"{label}: no stress above the first peak afterwards")
        check(abs(ref[i_fwd][1] - PHI) <= 1.0e-9 and
              max(abs(t) for t in sstr[i_fwd:]) <= 1.01 * res,
              f"{label}: after the reversals |tau| <= sigma_n tan(phi) (1 %)",
              str(max(abs(t) for t in sstr[i_fwd:])))
        check(max(abs(s - SN) for s in nstr) <= 0.01 * SN,
              f"{label}: normal stress constant within 1 %", f"{min(nstr)} .. {max(nstr)}")
        # dilation (Fig. E-1(b), E-2(b)): the law's own opening, and raw NDIS
        dil = [n + s / KN for n, s in zip(ndis, nstr)]
        ref_dil = ref[i_fwd][2]
        check(ref_dil > 1.0e-5, f"{label}: the equations dilate", str(ref_dil))
        derr = max(abs(a - b[2]) for a, b in zip(dil, ref))
        check(derr <= 0.02 * ref_dil, f"{label}: dilation curve within 2 %",
              f"max error {derr}, dilation at 10 mm {ref_dil}")
        raw = ndis[i_fwd] - ndis[0]
        check(abs(raw - ref_dil) <= 0.02 * ref_dil,
              f"{label}: normal displacement change at 10 mm within 2 %", f"{raw} vs {ref_dil}")
        print(f"{label}: peak {peak:.4f} (ref {ref_peak:.4f}), curve error {err / ref_peak:.2%}"
              f" of peak, dilation {raw:.4e} m (ref {ref_dil:.4e}), curve error "
              f"{derr / ref_dil:.2%}, sigma_n {min(nstr):.4f}..{max(nstr):.4f}")

# 2. time step with a stress-dependent stiffness
STIFF = "round 0.01\n" + SPECIMEN + """prop mat=1 dens=2000
prop jmat=1 jkn=1e4 jks=1e4 jen=1 jes=1 jfric=0.577
change jcons=3
fix 0,4 0,1
grav 0 -10
insitu stress 0,0,-2e4
damp auto
{stages}stop
"""
stages = "".join(f"{'' if f is None else f'load 1,3 1,2 0,{-f}' + chr(10)}cycle 3000\ncycle 1\n"
                 "print contact force\n" for f in (None, 2e5, 2e6, 2e7, 2e8))
d = workdir()
write(d, "stiff.dat", STIFF.format(stages=stages))
rc, out = run(udec, ["stiff.dat"], cwd=d, timeout=300)
check(rc == 0 and "***" not in out, "JEN 1: loading tenfold four times runs without error",
      "\n".join(l for l in out.splitlines() if "***" in l)[:2000])
steps = [float(l.split("timestep")[1].split(",")[0]) for l in out.splitlines()
         if l.startswith("cycle ") and "timestep" in l]
blocks = out.split("print contact force")[1:]
m = 2000.0 * 2.0
check(len(steps) == 10 and len(blocks) == 5, "JEN 1: five stages", f"{len(steps)} {len(blocks)}")
if len(steps) == 10 and len(blocks) == 5:
    for k, text in enumerate(blocks):
        sn = [float(l.split()[6]) for l in text.splitlines()[2:4]]
        kcur = 1.0e4 * max(sn) * 1.0
        expect = 0.1 * 2.0 * math.sqrt(m / (1.05 * kcur))
        check(abs(steps[2 * k + 1] - expect) <= 1.0e-3 * expect,
              f"JEN 1 stage {k}: dt = 0.2 sqrt(m / (1.05 JKN sigma_n L)) (1e-3)",
              f"{steps[2 * k + 1]} vs {expect} at sigma_n {max(sn)}")
        check(steps[2 * k] <= 0.2 * math.sqrt(m / kcur) * (1.0 + 1.0e-9),
              f"JEN 1 stage {k}: the step while loading is within the stable step",
              f"{steps[2 * k]} vs {0.2 * math.sqrt(m / kcur)}")
    check(steps[-1] < 0.05 * steps[1], "JEN 1: the step fell with the stiffness (5000 x stiffer)",
          f"{steps[1]} -> {steps[-1]}")

# 3. both blocks deformable, coarse zones, fast brittle slip
COARSE = """prop mat=1 d=2.60e-3 k=4000 g=3000
prop jmat=1 jkn=100000 jks=100000 jen=0.0 jes=0.0 jfric=0.577 jif=1.035 jr=1.0e-4
round {rnd}
block 0,0 0,2 2,2 2,0
crack -0.1,1 2.1,1
change 0,100 0,100 fdef mat=1 cons=1
gen 0,100 0,100 auto 2.1
change jmat=1 jcons=3
insitu stress 0, 0, -10
bound mat=1
bound -0.1,2.1 -0.1,0.1 yvel=0
bound -0.1,2.1 -0.1,2.1 stress 0, 0, -10
damp auto
frac 0.05 1.0
cyc 10
bound -0.1,2.1 -0.1,0.99 xvel=0 yvel=0
bound -0.1,2.1 1.01,2.1 xvel=-0.05
cyc {n}
print contact force
stop
"""
for rnd, n in ((0.003, 5000), (0.01, 5000), (0.003, 20000)):
    d = workdir()
    write(d, "coarse.dat", COARSE.format(rnd=rnd, n=n))
    rc, out = run(udec, ["coarse.dat"], cwd=d, timeout=300)
    name = f"FDEF on FDEF, ROUND {rnd}, {n * 8e-5 * 0.05 * 1e3:.0f} mm"
    check(rc == 0 and "***" not in out, f"{name}: runs without error",
          "\n".join(l for l in out.splitlines() if "***" in l)[:2000])
    cyc = [l for l in out.splitlines() if l.startswith("cycle ") and "unbalanced" in l]
    unbal = float(cyc[-1].split("unbalanced force")[1].split(",")[0]) if cyc else math.inf
    check(unbal < 0.005 * 20.0, f"{name}: final unbalanced force below 0.5 % of the load", str(unbal))
    rows = []
    for line in out.split("print contact force")[-1].splitlines()[2:]:
        f = line.split()
        if len(f) < 5 or not all(NUM.match(x) for x in f):
            break
        rows.append([float(x) for x in f])
    fn = sum(r[4] for r in rows)
    check(abs(fn - 20.0) <= 0.02 * 20.0, f"{name}: normal forces add up to the load (2 %)", str(fn))
    worst = max((abs(r[5]) - r[4] * math.tan(1.035) for r in rows), default=math.inf)
    check(worst <= 1.0e-6 * 20.0, f"{name}: no shear above fn tan(JIF)", str(worst))
    print(f"{name}: unbalanced {unbal:.3e}, sum fn {fn:.4f}, {len(rows)} contacts")
finish()
