"""A tunnel under gravity, water and overburden, excavated and bolted in stages,
saved and restarted (label `stability`; campaign round 5,
tools/support_campaign.py).

The deck a rock engineer writes from the UDEC manual (ICG1.5, 1989),
Sections 2 and 4: a 30 m square of rigid blocks cut by two joint sets, 200 m
below the surface (BOUNDARY STRESS of the overburden's weight on the top),
GRAVITY, the water table at the top (SET YWTAB, FLUID, joint permeability:
the manual's SET EFF logic puts buoyancy on the blocks, so the joints carry
the effective stress), INSITU STRESS with the effective-stress gradient
(YGRAD), rollers on the sides and base. Stages: 1000 cycles at rest; the
heading (upper half of a TUNNEL, SPLIT at the springline) DELETEd and its
domains drained (PFIX to the atmospheric pressure: the excess over
hydrostatic -rho_w g (ywt - y) of the manual's EFF convention, PRESSURE and
YGRAD), 600 cycles; three REINFORCE bolts in the roof;
600 cycles; the bench DELETEd and drained; 500 cycles, SAVE, 500 cycles.
A second run RESTARTs the save and cycles 500.
Checks:
- at rest before the excavation: largest displacement below 1e-6 x the
  model's size (the initial state is exact; measured round-off, ~1e-16 m);
- the same with the rollers given before the top stress: the manual's
  caution (Section 4.5, BOUNDARY: a STRESS after XVEL at the same points
  loses the XVEL) frees the two top corners, udec warns so and the corner
  blocks then move (3e-4 m); given again after the stress, as the warning
  advises, the rollers hold and the model is at rest;
- the restart continues the run exactly: PRINT MAX identical after the same
  cycles;
- the bolts carry tension below RUAXIAL (the printed digits);
- every run exits 0 without an error line.
"""
import math
import re
import sys
from udec_test import check, finish, printed_rows, run_deck, workdir

udec = sys.argv[1]
L, DEPTH, RHO, RHOW, GRAV, K0 = 30.0, 200.0, 2600.0, 1000.0, 10.0, 0.8
XC, YC, A = 15.0, 14.0, 2.5
FU = 2e5


def deck(top_first):
    reff = RHO - RHOW
    syy0 = -(RHO * GRAV * DEPTH + reff * GRAV * L)
    top = f"bound -0.05,30.05 29.95,30.05 stress 0 0 {-RHO * GRAV * DEPTH:g}"
    rollers = """bound -0.05,30.05 -0.05,0.05 yvel 0
bound -0.05,0.05 -0.05,30.05 xvel 0
bound 29.95,30.05 -0.05,30.05 xvel 0"""
    bolts = "\n".join(
        f"reinforce 5 {XC + (A - 0.2) * math.cos(t):.3f} {YC + (A - 0.2) * math.sin(t):.3f} "
        f"{XC + (A + 4) * math.cos(t):.3f} {YC + (A + 4) * math.sin(t):.3f}"
        for t in (math.radians(50), math.radians(90), math.radians(130)))
    pw = f"{-RHOW * GRAV * L:g} ygrad {RHOW * GRAV:g}"
    return f"""heading staged gravity tunnel
round 0.02
block 0,0 0,30 30,30 30,0
tunnel {XC:g},{YC:g} {A:g} 20
split {XC - A - 0.5:g},{YC:g} {XC + A + 0.5:g},{YC:g}
jset 30,0 60,0 0,0 3.1,0 (1.3,0.7)
jset -65,0 60,0 0,0 3.7,0 (0.4,2.2)
prop mat=1 dens={RHO:g} k=15e9 g=9e9
prop jmat=1 jkn=1e10 jks=1e9 jfric=0.7 jcoh=0 jtens=0 jperm=300 azero=5e-4 ares=2e-4
prop mat=5 rastiff=2e8 rsstiff=2e7 ruaxial={FU:g} rushear=1e5 rlength=0.5 rrfac=1 raexp=1 rsexp=1
grav 0 -{GRAV:g}
fluid rhow={RHOW:g} bulkw=2e7
set ywtab {L:g}
insitu stress {K0 * syy0:g} 0 {syy0:g} ygrad {K0 * reff * GRAV:g} 0 {reff * GRAV:g}
{top if top_first else rollers}
{rollers if top_first else top + chr(10) + rollers}
damp auto
hist ydis {XC:g},{YC + A:g}
cycle 1000
print max
delete {XC - A + 0.01:g},{XC + A - 0.01:g} {YC + 0.01:g},{YC + A - 0.01:g}
pfix {XC - A:g},{XC + A:g} {YC - A:g},{YC + A:g} pressure {pw}
cycle 600
print max
{bolts}
cycle 600
delete {XC - A + 0.01:g},{XC + A - 0.01:g} {YC - A + 0.01:g},{YC - 0.01:g}
pfix {XC - A:g},{XC + A:g} {YC - A:g},{YC + A:g} pressure {pw}
cycle 500
save staged.sav
cycle 500
print max
print reinforce
plot block disp
copy staged.png
stop
"""


def disp(block):
    m = re.search(r"max block displacement\s+(\S+)", block)
    return float(m.group(1)) if m else float("nan")


for top_first in (True, False):
    name = "top_first" if top_first else "rollers_first"
    folder = workdir()
    rc, out = run_deck(udec, folder, name, deck(top_first), timeout=300, forbidden=("*** Error",))
    if not top_first:
        check("replaces a prescribed XVEL" in out, f"{name}: the manual's caution is warned")
    parts = re.split(r"(?m)^print max\s*$", out)
    if len(parts) < 4:
        check(False, f"{name}: three PRINT MAX", out[-2000:])
        continue
    pre = disp(parts[1])
    print(f"{name}: before the excavation the largest displacement is {pre:.3g} m")
    check(pre < 1e-6 * L, f"{name}: at rest before the excavation (< 1e-6 L)", f"{pre}")
    rows = printed_rows(out, "print reinforce", 12)
    axial = [r[8] for r in rows]
    print(f"{name}: {len(rows)} bolt elements, axial forces {min(axial, default=0):.4g} .. "
          f"{max(axial, default=0):.4g} N")
    check(len(rows) >= 3, f"{name}: the bolts cross joints", f"{len(rows)}")
    check(all(abs(f) <= FU * (1 + 1e-4) for f in axial), f"{name}: bolt forces within RUAXIAL")
    check(max(axial, default=0) > 0, f"{name}: the roof loads its bolts in tension")
    rc2, out2 = run_deck(udec, folder, name + "_restart",
                         "restart staged.sav\ncycle 500\nprint max\nstop\n", timeout=300,
                         forbidden=("*** Error",))
    first = parts[3].split("print reinforce")[0]
    second = re.split(r"(?m)^print max\s*$", out2)[-1]

    def table(text):
        return [ln for ln in text.splitlines() if re.match(r"^\s{2}\S.*\s\S+E[+-]\d\d", ln)]
    t1, t2 = table(first), table(second)
    print(f"{name}: PRINT MAX after the restart: {len(t2)} rows, "
          f"largest displacement {disp(first):.6g} / {disp(second):.6g} m")
    check(t1 and t1 == t2, f"{name}: the restart continues the run exactly (PRINT MAX identical)",
          "\n".join(a + " | " + b for a, b in zip(t1, t2) if a != b))
finish()
