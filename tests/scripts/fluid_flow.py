"""Joint fluid flow (manual Section 3.12) against closed forms.

1. One joint between two reservoirs (parallel-plate flow): rigid blocks
   fixed, constant aperture a = 1e-4, kj = 1e8, pressures 1 and 0 at the ends
   of a joint of length L = 2 (no gravity): q = kj a^3 dp / L = 5e-5 in every
   contact, the joint domain at 0.5 - both exactly (tolerance 1e-5 relative,
   the printed digits). Steady state (SET SFLOW) and transient flow
   (Kw = 100) must agree.
2. Hydrostatic pressure in a vertical joint under gravity (SET -EFF, total
   pressures, rhow g = 10): sides and base impermeable, the top end open to a
   reservoir at p = 45 - 10 y: at rest every domain has p = 45 - 10 y
   (tolerance 1e-3 of the largest pressure, 40).
3. A pressurised joint opens by p / kn: upper block free, lower block
   fixed, PFIX p = 1 in the joint, JKN = 100: normal displacement 0.01
   (tolerance 0.1 %).
   The same with fully-deformable blocks (GENERATE, pressures shared by the
   edge gridpoints): 2 % (measured +0.8 %: the zoned joint's contact lengths
   and the blocks' own deformation enter).
4. Buoyancy under SET EFF: a rigid block (density 2.5, area 0.5) resting on
   a fixed one, gravity 10, rhow 1: contact normal force (2.5 - 1) 10 0.5 =
   7.5 with the water table above the centroid, 12.5 (no buoyancy) with it
   below (tolerance 1e-6 relative, equilibrium).
5. A deck without FLUID has no fluid part: PRINT FLOWS says so.
6. Bingham fluid (FLUID ... COHW, manual Section 3.13): the joint of case 1
   (two contacts of length l = 1, a = 1e-4, dp = 1 between the reservoirs)
   with a yield strength tau. A contact flows only above the threshold
   gradient J0 = 2 tau / a (Eq. 63), i.e. when |dp_i| > 2 tau l / a, and
   then q = kj a^3 (|dp_i| - 2 tau l / a) / l (Fig. 3-24):
   - tau = 1.25e-5 (threshold 0.25 per contact): q = kj a^3 (dp - 2 tau L
     / a) / L = 2.5e-5 through both contacts, the joint domain at 0.5;
   - tau = 3e-5 (threshold 0.6 per contact, 1.2 > dp in all): no steady
     flow; the joint domain fills until the upstream contact stops,
     p = 1 - 0.6 = 0.4, and the downstream contact (dp 0.4 < 0.6) never
     flows;
   - tau = 1e-4 (threshold 2 per contact): nothing flows, p stays 0.
   Steady state and transient, tolerance 1e-5 relative (printed digits).
7. Buoyancy of a fully-deformable block (GENERATE EDGE 0.25) under SET EFF:
   the block of case 4 on a lower block held by BOUNDARY XVEL 0 YVEL 0,
   water table above it: the joint's normal forces add up to
   (2.5 - 1) 10 0.5 = 7.5; water table at y = 0.4, below every zone of the
   upper block: 12.5 (tolerance 0.1 %; measured +0.01 % after 4000 damped
   steps).
8. PLOT layers for flow (manual 4.6 keyword table: APERTURE, FLOW, PP,
   VFLOW, FVEL), written to PostScript: the joint of case 1 gives the
   layer titles and the closed-form maxima in the legend (flow rate 5e-5,
   joint pressure 0.5, aperture 1e-4, fluid velocity q / a = 0.5); without
   FLUID the layer says so.
"""
import os
import sys
sys.path.insert(0, os.path.dirname(__file__))
from shared_decks import JOINT_FLOW as JOINT  # noqa: E402
from udec_test import check, finish, header_rows as table, run, workdir, write  # noqa: E402

udec = sys.argv[1]
folder = workdir()


for mode in ("set sflow", "set -sflow"):
    write(folder, "joint.dat", JOINT.format(set=mode))
    rc, out = run(udec, ["joint.dat"], cwd=folder)
    check(rc == 0, f"joint deck runs ({mode})", out[-2000:])
    flows = table(out, " CONTACT    DOM1", 7)
    check(len(flows) == 2, f"two joint contacts carry flow ({mode})", out[-2000:])
    for f in flows:
        q = abs(float(f[6]))
        check(abs(q - 5e-5) <= 1e-5 * 5e-5, f"cubic law q = kj a^3 dp / L ({mode})", str(f))
    doms = table(out, "  DOMAIN      PRESSURE", 6)
    check(len(doms) == 1 and abs(float(doms[0][1]) - 0.5) <= 1e-5,
          f"joint domain at the mean pressure ({mode})", str(doms))

write(folder, "hydro.dat", """round 0.01
bl 0 0 0 4 1 4 1 0
crack 0.5 0 0.5 4
crack 0 1 1 1
crack 0 2 1 2
crack 0 3 1 3
prop mat=1 d=1 jkn=100 jks=100 jperm=1e8 azero=1e-4 ares=1e-4
fix -1 3 -1 5
gravity 0 -10
fluid 1.0 100
set -eff sflow
bound -0.1 0.1 -1 5 imperm
bound 0.9 1.1 -1 5 imperm
bound -1 2 -0.1 0.1 imperm
bound -1 2 3.9 4.1 pp 45 pgrad -10
cycle 5000
print fluid
stop
""")
rc, out = run(udec, ["hydro.dat"], cwd=folder)
check(rc == 0, "hydrostatic deck runs", out[-2000:])
doms = table(out, "  DOMAIN      PRESSURE", 6)
check(len(doms) >= 10, "hydrostatic deck has its domains", out[-2000:])
for f in doms:
    p, y = float(f[1]), float(f[4])
    check(abs(p - (45 - 10 * y)) <= 1e-3 * 40, "hydrostatic p = 45 - 10 y", str(f))

write(folder, "open.dat", """round 0.01
bl 0 0 0 1 1 1 1 0
crack 0 0.5 1 0.5
prop mat=1 d=1 jkn=100 jks=100 jten=1e10 jcoh=1e10
fix -1 2 0 0.4
fluid 1.0 0.0
pfix pressure 1.0
damp auto
cycle 3000
print contact disp
stop
""")
rc, out = run(udec, ["open.dat"], cwd=folder)
check(rc == 0, "pressurised joint deck runs", out[-2000:])
rows = table(out, " CONTACT  BLOCK1  BLOCK2             X             Y    SHEAR-DISP", 8)
check(len(rows) == 2, "two joint contacts", out[-2000:])
for f in rows:
    check(abs(float(f[6]) - 0.01) <= 1e-3 * 0.01, "joint opens by p / kn", str(f))

write(folder, "open2.dat", """round 0.01
bl 0 0 0 1 1 1 1 0
crack 0 0.5 1 0.5
gen edge 0.25
prop mat=1 d=1 k=1e4 g=1e4 jkn=100 jks=100 jten=1e10 jcoh=1e10
bound -1 2 -0.1 0.1 xvel 0 yvel 0
fluid 1.0 0.0
pfix pressure 1.0
damp auto
cycle 6000
print contact disp
stop
""")
rc, out = run(udec, ["open2.dat"], cwd=folder)
check(rc == 0, "pressurised joint deck (FDEF) runs", out[-2000:])
rows = table(out, " CONTACT  BLOCK1  BLOCK2             X             Y    SHEAR-DISP", 8)
check(len(rows) >= 4, "FDEF joint contacts", out[-2000:])
for f in rows:
    check(abs(float(f[6]) - 0.01) <= 2e-2 * 0.01, "FDEF joint opens by p / kn", str(f))

for ywtab, force in ((2.0, 3.75), (0.6, 6.25)):
    write(folder, "buoy.dat", f"""round 0.01
bl 0 0 0 1 1 1 1 0
crack 0 0.5 1 0.5
prop mat=1 d=2.5 jkn=1e5 jks=1e5 jfric=0.5
fix -1 2 0 0.4
gravity 0 -10
fluid 1.0 0.0
set ywtab {ywtab}
damp auto
cycle 3000
print contact force
stop
""")
    rc, out = run(udec, ["buoy.dat"], cwd=folder)
    check(rc == 0, "buoyancy deck runs", out[-2000:])
    rows = table(out, " CONTACT  BLOCK1  BLOCK2        LENGTH  NORMAL-FORCE", 6)
    check(len(rows) == 2, "two contacts carry the block", out[-2000:])
    for f in rows:
        check(abs(float(f[4]) - force) <= 1e-6 * force, f"buoyancy, YWTAB {ywtab}", str(f))

write(folder, "dry.dat", """round 0.01
bl 0 0 0 1 1 1 1 0
crack 0 0.5 1 0.5
print flows
stop
""")
rc, out = run(udec, ["dry.dat"], cwd=folder)
check(rc == 0 and "no fluid in the model" in out, "no FLUID: no fluid part", out[-1000:])

BINGHAM = JOINT.replace("fluid 1.0 100\n", "fluid 1.0 100 {tau}\n").replace("cycle 50", "cycle 200")
for mode in ("set sflow", "set -sflow"):
    for tau, qref, pref in ((1.25e-5, 2.5e-5, 0.5), (3e-5, 0.0, 0.4), (1e-4, 0.0, 0.0)):
        write(folder, "bingham.dat", BINGHAM.format(set=mode, tau=tau))
        rc, out = run(udec, ["bingham.dat"], cwd=folder)
        check(rc == 0 and "Bingham" in out, f"Bingham deck runs ({mode}, tau {tau})", out[-2000:])
        flows = table(out, " CONTACT    DOM1", 7)
        if qref > 0.0:
            check(len(flows) == 2, f"Bingham: both contacts flow ({mode})", out[-2000:])
            for f in flows:
                q = abs(float(f[6]))
                check(abs(q - qref) <= 1e-5 * qref,
                      f"Bingham q = kj a^3 (dp - 2 tau L / a) / L ({mode})", str(f))
        else:
            check(len(flows) == 0, f"Bingham below the threshold: no flow ({mode}, tau {tau})",
                  out[-2000:])
        doms = table(out, "  DOMAIN      PRESSURE", 6)
        check(len(doms) == 1 and abs(float(doms[0][1]) - pref) <= 1e-5,
              f"Bingham joint domain at {pref} ({mode}, tau {tau})", str(doms))

for ywtab, total in ((2.0, 7.5), (0.4, 12.5)):
    write(folder, "buoyf.dat", f"""round 0.01
bl 0 0 0 1 1 1 1 0
crack 0 0.5 1 0.5
gen edge 0.25
prop mat=1 d=2.5 k=1e4 g=1e4 jkn=1e5 jks=1e5 jfric=0.5
bound -1 2 -0.1 0.1 xvel 0 yvel 0
gravity 0 -10
fluid 1.0 0.0
set ywtab {ywtab}
damp auto
cycle 4000
print contact force
stop
""")
    rc, out = run(udec, ["buoyf.dat"], cwd=folder)
    check(rc == 0, "FDEF buoyancy deck runs", out[-2000:])
    rows = table(out, " CONTACT  BLOCK1  BLOCK2        LENGTH  NORMAL-FORCE", 6)
    check(len(rows) >= 4, "FDEF: the joint's contacts carry the block", out[-2000:])
    fn = sum(float(f[4]) for f in rows)
    check(abs(fn - total) <= 1e-3 * total, f"FDEF buoyancy, YWTAB {ywtab}: sum fn = {total}",
          f"sum {fn}")

PLOTS = JOINT.format(set="set sflow").replace("print flows\nprint fluid\n", """plot blocks flow
copy flow.ps
plot blocks pp aperture
copy pp.ps
plot blocks vflow fvel
copy vflow.ps
""")
write(folder, "plots.dat", PLOTS)
rc, out = run(udec, ["plots.dat"], cwd=folder)
check(rc == 0 and "*** PLOT" not in out, "fluid PLOT layers run", out[-2000:])


def ps_text(name):
    path = os.path.join(folder, name)
    return open(path).read() if os.path.exists(path) else ""


for name, title, maximum in (("flow.ps", "joint flow rate (m2/s)", "5.000E-05"),
                             ("pp.ps", "joint fluid pressure (Pa)", "5.000E-01"),
                             ("pp.ps", "joint hydraulic aperture (m)", "1.000E-04"),
                             ("vflow.ps", "flow vectors", "5.000E-05"),
                             ("vflow.ps", "fluid velocity in joints (m/s)", "5.000E-01")):
    text = ps_text(name)
    shown = "(" + title.replace("(", "\\(").replace(")", "\\)") + ")"   # a PostScript string
    check(shown in text, f"PLOT layer '{title}' in {name}", text[-500:])
    # the legend line after the title: maximum = closed form (4 digits)
    after = text[text.find(shown):]
    check(f"(maximum = {maximum})" in "".join(after.splitlines()[1:4]),
          f"'{title}' maximum = {maximum}", after[:300])

write(folder, "plotdry.dat", """round 0.01
bl 0 0 0 1 1 1 1 0
plot blocks flow
copy dry.ps
stop
""")
rc, out = run(udec, ["plotdry.dat"], cwd=folder)
check(rc == 0 and r"(\(no fluid: give FLUID first\))" in ps_text("dry.ps"),
      "PLOT FLOW without FLUID: says so in the legend", out[-1000:])
finish()
