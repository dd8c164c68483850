"""Rock reinforcement (UDEC manual (ICG1.5, 1989), Section 3.10; REINFORCE and
CABLE of Section 4.5) against closed forms. Label `verification`.

(a) Cable, rigid blocks: a 2 x 1.8 rigid block (rho 1000, m = 3600 kg,
    g = 10) hangs 0.2 m below a FIXed block on one vertical two-node cable
    (E = 2e11 from K, G; A = 1e-4) from (1, 3) to (1, 0.8), L = 2.2 m.
    Reference: the extension m g L / (E A) = 3.96e-3 m (Hooke). Tolerance
    1 %. The stiff grout (JKS 2e10 per unit length, per node 2.2e10 N/m)
    adds m g / JKS glen at each end, 0.08 % of the extension.
(b) Cable, zoned block: a grouted cable (EA = 2e7 N, JKS = 2e7 N/m/m,
    JCOH = 1e4 N/m, nodes every h = 0.05 m) runs from a hanging rigid plate
    across a 0.2 m gap into an elastic zoned block held at its top
    (E = 2e10: its strain is below 1e-3 of the cable's). Bonded length in
    the block Lb = 60.5 h = 3.025 m (the node nearest the block face lies
    h/2 inside it). Reference (shear lag, a bar on a bed of springs of
    stiffness k per unit length, free far end): the axial force at depth x
    is N(x) = P sinh(lam (Lb - x)) / sinh(lam Lb), lam = sqrt(k / EA) = 1/m.
    Checked at the element midpoints to x = 2 m, relative to P (the force
    carried across the gap): within 3 %. The lumped springs' error is
    O((lam h)^2) = 0.25 %. Pull-out: the plate's weight at 0.97 JCOH Lb
    holds (after 15000 cycles the plate moves less than 1e-5 m in 5000
    more; damping above critical so that the load comes on without
    overshoot); raised to 1.03 JCOH Lb (almost no damping) the cable pulls
    out (the plate falls more than 0.1 m in 40000 cycles): the capacity is JCOH Lb within 3 %.
(c) REINFORCE, rigid blocks: a 4 x 1 block (m = 8000 kg) on a FIXed base
    across a frictionless joint, one bolt perpendicular to the joint
    (RSSTIFF Ks = 1e7, RUSHEAR 2e5, RSEXP 1, RLENGTH 10 so the active
    length hardly turns), gravity (7.5, -10): the bolt alone carries the
    shear load H = m g_x = 6e4. Reference: the manual's law, Eqs. 41, 43,
    44: for a bolt perpendicular to the joint the bound is RUSHEAR / 2 = Fb;
    dF = Ks du (1 - F / Fb) integrates to F = Fb (1 - exp(-Ks u / Fb)), so
    the slip is u = -(Fb / Ks) ln(1 - H / Fb) = 9.163e-3 m. Tolerance 2 %
    (on the slip and on the bolt's shear force). Mass-proportional damping
    above critical keeps the loading monotonic (a reversal unloads along
    the elastic line and would leave the block off the loading curve).
    Without the bolt (and the damping) the block slides away (more than
    0.5 m in 6000 cycles).
(d) A bolted roof: an opening 4 m wide under a 1 m layer cut by
    frictionless vertical joints into three blocks that span it; the layer
    meets the FIXed rock above on a joint with no tensile strength.
    Unbolted, the blocks fall (more than 0.1 m after 10000 cycles); with one
    REINFORCE bolt through each block into the rock above, they stand
    (less than 5 mm: measured 1.85 mm) and the bolts are in tension. The deck is
    examples/reinforcement/bolted_roof.dat (docs/guide/reinforcement.md).
Also: PRINT REINFORCE / CABLE tables, PLOT CABLE REINFORCE AXIAL CFORCE
(no "not yet"), SAVE / RESTART of a cycled cable model continues the same
(bit for bit after 200 more cycles), and the stage list: a scene without
reinforcement never runs the reinforcement stage (PRINT CYCLE).
"""
import math
import os
import re
import sys
from udec_test import cable_elements, cable_nodes, check, finish, rows_after, run, workdir, write

udec = sys.argv[1]


def block_centres(out):
    """The last PRINT BLOCK table: {block: (x, y)}."""
    return {int(f[0]): (float(f[6]), float(f[7])) for f in rows_after(out, "BLOCK   MAT  CONS", 1, 8)}


def reinf_rows(out):
    text = out.split("Local reinforcement")[-1]
    rows = []
    for line in text.splitlines()[2:]:
        f = line.split()
        if len(f) < 12 or not f[0].isdigit():
            break
        rows.append([float(x) for x in f])
    return rows


def udec_run(deck, timeout=600):
    d = workdir()
    write(d, "DATA", deck)
    code, out = run(udec, ["DATA"], cwd=d, timeout=timeout)
    return code, out, d


# ---------------------------------------------------------------- (a)
HANG = """ROUND 0.01
BLOCK 0,0 0,4 2,4 2,0
CRACK -0.1,2 2.1,2
CRACK -0.1,1.8 2.1,1.8
DELETE 0,2 1.8,2
PROP MAT=1 DENS=1000
FIX 0,2 2,4
PROP MAT=2 K=1.333333333333e11 G=8e10 DENS=7800
PROP MAT=3 JKS=2e10 JCOH=1e9
CABLE 1,3 1,0.8 2 2 1e-4 3
GRAV 0 -10
DAMP 0.8 8.0 MASS
PRINT BLOCK
CYCLE 30000
PRINT CABLE
PRINT BLOCK
PRINT CYCLE
{extra}STOP
"""
code, out, dA = udec_run(HANG.format(extra="SAVE hang.sav\nCYCLE 200\nPRINT CABLE\n"))
check(code == 0 and "Error" not in out, "(a) runs", out[-2000:])
b0 = block_centres(out.split("CYCLE 30000")[0])
b1 = block_centres(out.split("CYCLE 30000")[1])
ext = b0[3][1] - b1[3][1]
ref = 3600 * 10 * 2.2 / (2e11 * 1e-4)
print(f"(a) extension {ext:.6e}, reference {ref:.6e}, {100 * (ext / ref - 1):+.3f} %")
check(abs(ext / ref - 1) < 0.01, "(a) extension m g L / (E A) within 1 %")
ax = cable_elements(out.split("CYCLE 30000")[1])[0][3]
print(f"(a) axial force {ax:.6e} (weight 36000)")
check(abs(ax / 36000 - 1) < 0.01, "(a) cable force = weight within 1 %")
check("reinforcement" in out.split("CYCLE 30000")[1].split("PRINT CYCLE")[1].split("Last CYCLE")[0],
      "(a) PRINT CYCLE lists the reinforcement stage")
# restart: 200 more cycles after RESTART give what the straight run gave
straight = out.split("CYCLE 200")[1]
write(dA, "R.dat", "RESTART hang.sav\nCYCLE 200\nPRINT CABLE\nSTOP\n")
code, out2 = run(udec, ["R.dat"], cwd=dA)
check(code == 0, "(a) restart runs", out2[-1500:])
t1 = (cable_nodes(straight), cable_elements(straight))
t2 = (cable_nodes(out2), cable_elements(out2))
check(t1 == t2 and len(t1[0]) == 2, "(a) SAVE / RESTART continues bit for bit", f"{t1}\n---\n{t2}")

# a scene without reinforcement never runs the stage
code, out = udec_run("""ROUND 0.01
BLOCK 0,0 0,4 2,4 2,0
CRACK -0.1,2 2.1,2
PROP MAT=1 DENS=1000 JKN=1e9 JKS=1e9
FIX 0,2 0,2
GRAV 0 -10
CYCLE 10
PRINT CYCLE
STOP
""")[:2]
check("contact forces" in out.split("PRINT CYCLE")[-1] and
      "reinforcement" not in out.split("PRINT CYCLE")[-1], "stage absent without reinforcement",
      out[-1500:])

# ---------------------------------------------------------------- (b)
PULL = """ROUND 0.01
BLOCK 0,-4 0,6 2,6 2,-4
CRACK -0.1,2 2.1,2
CRACK -0.1,1.8 2.1,1.8
DELETE 0,2 1.8,2
PROP MAT=1 DENS=2500 K=1.1e10 G=8.3e9
PROP MAT=4 DENS={dens}
CHANGE 0,2 2,6 FDEF MAT=1 CONS=1
GEN 0,2 2,6 QUAD 0.5
CHANGE 0,2 -4,1.8 MAT=4
BOUND -0.1,2.1 5.9,6.1 XVEL 0 YVEL 0
PROP MAT=2 K=1.333333333333e11 G=8e10 DENS=7800
PROP MAT=3 JKS=2e7 JCOH=1e4
CABLE 1,-3.475 1,5.025 171 2 1e-4 3
GRAV 0 -10
DAMP 0.8 8.0 MASS
PRINT BLOCK
CYCLE {n}
PRINT CABLE
PRINT BLOCK
PLOT CABLE CFORCE
COPY cable.ps
STOP
"""
AREA = 2 * 5.8
LB = 60.5 * 0.05
LAM = 1.0
code, out, dB = udec_run(PULL.format(dens=5000 / 10 / AREA, n=15000))
check(code == 0 and "Error" not in out, "(b) elastic run", out[-2000:])
check("not yet" not in out, "(b) PLOT CABLE CFORCE drawn", out[-1500:])
check(os.path.exists(os.path.join(dB, "cable.ps")), "(b) plot file written")
nodes = cable_nodes(out)
els = cable_elements(out)
ys = [n[1] for n in nodes]
gap = [e for e in els if ys[e[0] - 1] < 2.0 and ys[e[1] - 1] > 1.8]
P = sum(e[3] for e in gap) / len(gap)
worst = 0.0
for n1, n2, _, axial in els:
    ym = 0.5 * (ys[n1 - 1] + ys[n2 - 1])
    x = ym - 2.0
    if x < 0 or x > 2.0:
        continue
    ref = math.sinh(LAM * (LB - x)) / math.sinh(LAM * LB)
    worst = max(worst, abs(axial / P - ref))
print(f"(b) P = {P:.2f} N; largest |N/P - closed form| to 2 m: {worst:.4f}")
check(worst < 0.03, "(b) axial force along the bond = shear lag within 3 %")


cap = 1e4 * LB
deck = PULL.format(dens=0.97 * cap / 10 / AREA, n=15000).replace("PLOT CABLE CFORCE\nCOPY cable.ps\n", "")
deck = deck.replace("STOP\n", "CYCLE 5000\nPRINT BLOCK\n"
                    "PROP MAT=4 DENS=%.9g\nDAMP 0.001 30.0 MASS\nCYCLE 40000\nPRINT BLOCK\nSTOP\n"
                    % (1.03 * cap / 10 / AREA))
code, out, _ = udec_run(deck)
check(code == 0 and "Error" not in out, "(b) pull-out run", out[-1500:])
parts = out.split("CYCLE ")
b0 = block_centres(parts[0])
b1 = block_centres(parts[1])
b2 = block_centres(parts[2])
b3 = block_centres(parts[3])
plate = min(b0, key=lambda b: b0[b][1])
drop_lo = b0[plate][1] - b1[plate][1]
creep = b1[plate][1] - b2[plate][1]
drop_hi = b2[plate][1] - b3[plate][1]
print(f"(b) weight 0.97 JCOH Lb: plate drop {drop_lo:.4e} m, then {creep:.2e} m in 5000 more "
      f"cycles; raised to 1.03 JCOH Lb: {drop_hi:.4e} m in 40000 cycles")
check(abs(creep) < 1e-5, "(b) holds at 0.97 of JCOH Lb (the plate has stopped)")
check(drop_hi > 0.1, "(b) pulls out at 1.03 of JCOH Lb")

# ---------------------------------------------------------------- (c)
SHEAR = """ROUND 0.01
BLOCK 0,0 0,2 4,2 4,0
CRACK -0.1,1 4.1,1
PROP MAT=1 DENS=2000 JKN=1e10 JKS=1e10 JFRIC=0
FIX 0,4 0,1
PROP MAT=2 RASTIFF=1e8 RSSTIFF=1e7 RLENGTH=10 RUAXIAL=1e6 RUSHEAR=2e5 RSEXP=1 RAEXP=1 RRFAC=1
{bolt}GRAV 7.5 -10
DAMP 2.0 5.6 MASS
PRINT BLOCK
CYCLE {n}
PRINT REINF
PRINT BLOCK
{hist}PLOT BLOCKS REINFORCE AXIAL
COPY bolt.ps
STOP
"""
code, out, dC = udec_run(SHEAR.format(bolt="REINFORCE 2 2,0.5 2,1.5\nHIST NCYC 100 RSHEAR 1\n",
                                      hist="PRINT HIST 1\n", n=20000))
check(code == 0 and "Error" not in out and "not yet" not in out, "(c) runs", out[-2000:])
b0 = block_centres(out.split("CYCLE")[0])
b1 = block_centres(out.split("CYCLE")[-1])
slip = b1[1][0] - b0[1][0]
Fb, Ks, H = 1e5, 1e7, 8000 * 7.5
ref = -(Fb / Ks) * math.log(1 - H / Fb)
rows = reinf_rows(out)
fs = rows[-1][9]
print(f"(c) slip {slip:.6e}, law {ref:.6e} ({100 * (slip / ref - 1):+.3f} %); "
      f"joint shear force of the bolt {fs:.6e} against H = {H:.6e}")
check(abs(slip / ref - 1) < 0.02, "(c) slip of the bolted joint = the law's within 2 %")
check(abs(abs(fs) / H - 1) < 0.02, "(c) bolt shear resistance = load within 2 %")
hrows = [l.split() for l in out.split("PRINT HIST 1")[-1].splitlines()]
hrows = [r for r in hrows if len(r) == 2 and all(re.match(r"^[-+0-9.E]+$", x) for x in r)]
check(len(hrows) > 100 and abs(abs(float(hrows[-1][1])) / H - 1) < 0.02,
      "(c) HISTORY RSHEAR follows the bolt's shear force", out.split("PRINT HIST 1")[-1][-800:])
code, out, _ = udec_run(SHEAR.format(bolt="", hist="", n=6000).replace("PRINT REINF\n", "")
                        .replace("DAMP 2.0 5.6 MASS\n", "").replace("PLOT BLOCKS REINFORCE AXIAL\nCOPY bolt.ps\n", ""))
b0 = block_centres(out.split("CYCLE")[0])
b1 = block_centres(out.split("CYCLE")[-1])
print(f"(c) unbolted: slip {b1[1][0] - b0[1][0]:.4e} m")
check(b1[1][0] - b0[1][0] > 0.5, "(c) without the bolt the block slides away")

# ---------------------------------------------------------------- (d)
# the deck of docs/guide/reinforcement.md, as given and without its bolts
ROOF = open(os.path.join(sys.argv[2], "examples", "reinforcement", "bolted_roof.dat")).read()
UNBOLTED = "".join(l for l in ROOF.splitlines(True)
                   if not l.startswith(("REINFORCE", "HIST", "PRINT REINF", "PLOT", "COPY")))
for deck, label in ((UNBOLTED, "unbolted"), (ROOF, "bolted")):
    code, out, _ = udec_run(deck)
    check(code == 0 and "Error" not in out and "not yet" not in out, f"(d) {label} runs", out[-1500:])
    b0 = block_centres(out.split("CYCLE")[0])
    b1 = block_centres(out.split("CYCLE")[-1].split("PRINT REINF")[0])
    beam = [b for b in b0 if 5.0 < b0[b][1] < 6.0 and 3.0 < b0[b][0] < 7.0]
    drop = max(b0[b][1] - b1[b][1] for b in beam)
    print(f"(d) {label}: {len(beam)} roof blocks, largest drop {drop:.4e} m")
    check(len(beam) == 3, f"(d) {label}: three roof blocks")
    if label == "unbolted":
        check(drop > 0.1, "(d) the unbolted roof falls")
    else:
        check(drop < 5e-3, "(d) the bolted roof stands")
        rows = reinf_rows(out)
        check(len(rows) == 3 and all(r[8] > 0 for r in rows),
              "(d) the three bolts are in tension", out[-1500:])

# ---------------------------------------------------------------- input errors
# (interactive: a refused command does not end the run)
code, out = run(udec, [], cwd=workdir(), stdin_text="""ROUND 0.01
BLOCK 0,0 0,2 4,2 4,0
CRACK -0.1,1 4.1,1
PROP MAT=1 DENS=2000 JKN=1e10 JKS=1e10
FIX 0,4 0,1
REINFORCE 2 2,1.2 2,1.5
CABLE 1,0.5 1,1.5 1 2 1e-4 3
CABLE 1,0.5 1,1.5 3 2 0 3
PRINT CABLE
REINFORCE 2 2,0.5 2,1.5
CYCLE 1
PRINT REINF
STOP
""")
check("Warning: REINFORCE: the line (2, 1.2) - (2, 1.5) crosses no joint" in out
      and "REINFORCE: 1 elements across joints, 1 to 1" in out,
      "REINFORCE without a joint crossing: a warning, nothing made, the deck goes on", out)
check("CABLE: npoin" in out and "CABLE: argument 7 (asteel): expected a real number > 0, got '0'" in out, "CABLE: bad npoin / asteel refused", out)
check("PRINT CABLE: there is no reinforcement" in out, "a refused CABLE changes nothing", out)
check("needs RASTIFF, RSSTIFF, RLENGTH, RUAXIAL and RUSHEAR" in out and "PROPERTY MAT=2" in out,
      "CYCLE names the missing reinforcement properties", out)

finish()
