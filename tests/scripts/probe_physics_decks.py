"""Decks a new user writes for the physics beyond the plain mechanical cycle
(joint fluid, free field, structures, SDEF blocks), from the syntax of the
UDEC manual (ICG1.5, 1989), Sections 3 and 4. Each case is a defect the
campaign of session 34 found, with the closed form or bound that shows it.

1. Transient joint flow between fully-deformable blocks (FLUID BULKW 2e9,
   water's bulk modulus): a 10 x 2 m model cut by a joint at y = 1, base
   held, top held in y, PP 1e5 at the left end of the joint. The fluid
   stiffens the joint by Kw / a = 2e13 Pa/m (Section 3.12, p. 3-57: "the
   fluid filling a joint increases the apparent stiffness by Kw/a"), 2000
   times JKN; the gridpoints' step ignored it and the model blew apart
   (Contact Overlap Too Great at cycle 56). Now 4000 cycles run, and no
   joint opens by more than its zero-stress aperture 1e-4 m: opening it
   that far against the held top needs a strain of 1e-4 over the 1 m block,
   1.8e6 Pa at K + 4G/3 = 1.8e10, eighteen times the water pressure.
2. Transient flow with every block fixed (a user studying the flow alone):
   nothing mechanical bounds the step, which stayed at an arbitrary 1 s,
   paid for with 8130 flow sub-steps a cycle (and 200 s of flow for
   CYCLE 200). Now the step is the stable flow step (Eq. 57, p. 3-57:
   "if less than the mechanical timestep, is used in the analysis"):
   V / (Kw sum k) for the one joint domain of a joint between two fixed
   blocks, V = a L / 2 = 5e-4 m2 (half of a l of each of its two contacts,
   a = 1e-4, l = 5), k = kj a^3 / l = 2e-11 each: 5e-4 / (1e9 * 4e-11) =
   1.25e-2 s (within 1 %), no sub-step note, and the joint at the mean of
   its end pressures 1e5 and 0 (within 1e-3).
3. FFIELD XVEL with a BOUNDARY history (Section 4.5 FFIELD: "Histories
   defined in the BOUNDARY command are also used here"): the free field's
   base took the velocity as a constant step. A shear wave from a base
   velocity 1e-3 sin(2 pi 10 t) for 0.1 s up a 50 m layer (cs = 1549 m/s,
   free-field sides): at the surface the side gridpoint (tied to the free
   field) and the middle reach 2e-3 at 0.025 + 50 / cs = 0.0573 s (1-D
   closed form: doubling at the free surface; peak within 2 %, arrival
   within 2 % of the period). Before the fix the side peaked 0.02 s early.
   After the CYCLE the base velocity keeps the history's last value (zero
   after the whole period), so the next CYCLE gives no second pulse (as the
   model's BOUNDARY XVEL).
4. STRUCTURE around a TUNNEL in rock cut by two joint sets, after 500
   cycles under in-situ stress: the ray of node 6 (180 degrees) meets the
   ring where a joint ends on it, between the two blocks' corners there,
   and missed both edges (the command refused: "no block edge facing").
   Within the corners' rounding length it now takes the nearer edge: 20
   elements are made.
5. An SDEF block between two fixed blocks with water at p = 1e6 in both
   joints (PFIX, no gravity): the joints open, so the block carries
   sxx = -p, syy = 0 (within 0.1 %: the pressure acts between the contact
   points at the rounded corners; measured -0.0125 %). The pressure did not
   reach the strain modes of SDEF blocks (sxx stayed 0).
6. Heat in rigid blocks around a TUNNEL (Section 7.2.2: "Blocks which are
   not fully deformable are also discretized for the thermal analysis"):
   the two blocks of a square with a hole do not see their edges from
   their centroids, and RUN refused them. They are now cut into ears, the
   ear holding the centroid fanned from it. A source S = 1000 W/m3 in
   insulated blocks (rho Cp = 1e6) heats every node, corners and
   centroids, by S t / (rho Cp) = 10.0164 K over t = 1.00164e4 s (the
   printed thermal time), all nodes alike (1e-9) and within the printed
   time's six figures of the closed form (1e-5 of the rise).
"""
import re
import sys
import udec_test
from udec_test import check, finish, header_rows as table_rows, run, workdir

udec = sys.argv[1]


def run_deck(name, text, timeout=300):
    return udec_test.run_deck(udec, workdir(), name, text, timeout, forbidden=("***",))[1]


def timesteps(out):
    return [float(x) for x in re.findall(r"timestep\s+([-+\d.E]+)", out)]


# 1. transient flow between zoned blocks, water's bulk modulus
out = run_deck("fdef_flow", """round 0.05
block 0,0 0,2 10,2 10,0
crack 0,1 10,1
gen edge 0.5
prop mat=1 dens=2600 k=1e10 g=6e9 jkn=1e10 jks=1e10 jperm=83.333 azero=1e-4 ares=1e-4
bound -1 11 -0.1 0.1 xvel 0 yvel 0
bound -1 11 1.9 2.1 yvel 0
fluid rhow 1000 bulkw 2e9
bound -0.1 0.1 -1 3 pp 1e5
bound 9.9 10.1 -1 3 pp 0
cycle 4000
print contact disp
stop
""")
rows = table_rows(out, " CONTACT  BLOCK1  BLOCK2             X             Y    SHEAR-DISP", 8)
check(len(rows) >= 20, "fdef_flow: the joint's contacts are printed", out[-2000:])
worst = max((abs(float(r[6])) for r in rows), default=float("nan"))
check(worst < 1e-4, "fdef_flow: no joint opens by more than its aperture 1e-4", f"{worst:.4e}")

# 2. transient flow with every block fixed: the step is the flow step
out = run_deck("fixed_flow", """round 0.05
block 0,0 0,2 10,2 10,0
crack 0,1 10,1
prop mat=1 dens=2600 jkn=1e10 jks=1e10 jperm=100 azero=1e-4 ares=1e-4
fix -1 11 -1 3
fluid rhow 1000 bulkw 1e9
bound -0.1 0.1 -1 3 pp 1e5
bound 9.9 10.1 -1 3 pp 0
cycle 200
print fluid
stop
""")
dt = timesteps(out)
check(len(dt) == 1 and abs(dt[0] / 1.25e-2 - 1.0) < 0.01,
      "fixed_flow: the step is the flow step V / (Kw sum k) = 1.25e-2", str(dt))
check("sub-steps" not in out, "fixed_flow: no flow sub-steps", out[-1500:])
doms = table_rows(out, "  DOMAIN      PRESSURE", 6)
check(len(doms) == 1 and abs(float(doms[0][1]) - 5e4) <= 1e-3 * 5e4,
      "fixed_flow: the joint at the mean of its end pressures", str(doms))

# 3. free-field base velocity with a BOUNDARY history
CS = (6e9 / 2500) ** 0.5
out = run_deck("ffield_history", """round 0.05
block 0,-50 0,0 20,0 20,-50
gen edge 5
prop mat=1 dens=2500 k=1e10 g=6e9
bound mat 1
bound -0.1 0.1 -51 1 xvisc yvisc ff
bound 19.9 20.1 -51 1 xvisc yvisc ff
bound -1 21 -50.1 -49.9 xvel 1e-3 yvel 0 xhist sine 10 0.1
ffield gen (-50,0) 21
ffield mat 1 cons 1
ffield xvel 1e-3 yvel 0
hist ncyc 1 xvel 10 0 xvel 0 0
cycle 600
print hist 1 2
print ff
cycle 100
print ff
stop
""")
text = out.split("print hist 1 2\n")[-1]
hist = []
for line in text.splitlines()[1:]:
    f = line.split()
    try:
        hist.append([float(x) for x in f])
    except ValueError:
        break
early = [r for r in hist if len(r) == 3 and r[0] < 0.09]
check(len(early) > 100, "ffield_history: histories to 0.09 s", text[:500])
t_ref = 0.025 + 50.0 / CS
for col, where in ((1, "middle"), (2, "side")):
    if not early:
        break
    t, v = max(((r[0], r[col]) for r in early), key=lambda x: x[1])
    check(abs(v / 2e-3 - 1.0) < 0.02, f"ffield_history: {where} surface peak 2e-3 (2 %)", f"{v:.5e}")
    check(abs(t - t_ref) < 0.02 * 0.1, f"ffield_history: {where} peak at {t_ref:.4f} s", f"{t:.5f}")
ff = out.split("print ff\n")
base = [l.split() for l in ff[-1].splitlines() if re.match(r"\s+1\s", l)]
check(len(base) >= 1 and abs(float(base[0][2])) < 1e-9,
      "ffield_history: the next CYCLE's base velocity stays at the history's end (0)", str(base[:1]))

# 4. STRUCTURE through the corner of TUNNEL's own cut
out = run_deck("liner_corner", """round 0.05
block -15,-15 -15,15 15,15 15,-15
tunnel 0,0 2.5 20
jset 30,0 100,0 0,0 3,0
jset -60,0 100,0 0,0 3,0
prop mat=1 dens=2600 k=1.5e10 g=9e9 jkn=5e9 jks=5e9 jfric=0.5
prop mat=5 dens=2400 k=1.4e10 g=1e10 kn=1e10 ks=1e10 cfric=0.6
gen edge 2
bound stress -5e6 0 -8e6
insitu stress -5e6 0 -8e6
damp auto
cycle 500
delete -2.4 2.4 -2.4 2.4
structure 0,0 90 2.6 20 5 0.3
cycle 10
stop
""")
check("STRUCTURE: 20 elements" in out, "liner_corner: the liner's 20 elements are made", out[-2000:])

# 5. water pressure on an SDEF block
out = run_deck("sdef_pressure", """round 0.01
block 0,0 0,1 3,1 3,0
crack 1,0 1,1
crack 2,0 2,1
prop mat=1 dens=2600 k=5e9 g=3e9 jkn=1e10 jks=1e10 jfric=0.7
change 1 2 0 1 sdef
fix -1 0.9 -1 2
fix 2.1 4 -1 2
fluid rhow 1000 bulkw 0
pfix 0.95 2.05 -0.5 1.5 pressure 1e6
damp auto
cycle 3000
print sdef
stop
""")
rows = table_rows(out, "   BLOCK CONS           EXX", 9)
check(len(rows) == 1, "sdef_pressure: one SDEF block", out[-1500:])
if rows:
    sxx, syy = float(rows[0][5]), float(rows[0][6])
    check(abs(sxx / -1e6 - 1.0) < 1e-3, "sdef_pressure: sxx = -p (0.1 %)", f"{sxx:.6e}")
    check(abs(syy) < 1e-3 * 1e6, "sdef_pressure: syy = 0", f"{syy:.6e}")

# 6. heat in rigid blocks that do not see their edges from their centroid
out = run_deck("heat_ring", """thermal
round 0.05
block -10,-10 -10,10 10,10 10,-10
tunnel 0,0 1.5 16
delete -1.4 1.4 -1.4 1.4
prop mat=1 dens=1000 k=1e10 g=6e9 jkn=5e9 jks=5e9 cond 3 spec 1000
initem 20 -11 11 -11 11
thapp -11 11 -11 11 source 1000 0
run age 1e4 step 100000 temp 1000
print temperature
stop
""")
m = re.search(r"thermal time\s+([-+\d.E]+)", out)
temps = [float(l.split()[4]) for l in out.split("print temperature")[-1].splitlines()
         if re.match(r"\s+\d+\s+\d+\s", l) and len(l.split()) >= 5]
check(m is not None and len(temps) >= 20, "heat_ring: RUN runs and prints corners and centroids",
      out[-1500:])
if m and temps:
    want = 20.0 + 1000.0 * float(m.group(1)) / 1.0e6
    check(max(temps) - min(temps) <= 1e-9 * want, "heat_ring: every node heats alike",
          f"{min(temps)} {max(temps)}")
    check(all(abs(t - want) <= 1e-5 * (want - 20.0) for t in temps),
          "heat_ring: the rise is S t / (rho Cp)", f"{want} {min(temps)} {max(temps)}")

finish()
