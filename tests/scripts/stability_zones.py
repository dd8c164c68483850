"""Hard cases of the deformable-block cycle stay numerically stable (label
`stability`, as tests/unit/test_stability_rigid.f90 for rigid blocks): a
zone stiffness contrast of 1000 across a stiff joint, an acute (10 degree)
zoned wedge, tiny rounding with many contacts on one zoned block, and a
long run. Each deck must run without error to static equilibrium (maximum
unbalanced force below 1e-6 of the weight, finite everywhere) and match a
closed form:
  1. contrast: a 1 m x 2 m column of two zoned blocks (K = 1e9 and 1e12 Pa,
     joint JKN = JKS = 1e13 Pa/m), rollers on the sides, base fixed,
     gravity: mean syy of the top block -rho g (2 - 1.5) = -1.0e4 Pa and of
     the bottom block -rho g (2 - 0.5) = -3.0e4 Pa (uniaxial strain: exact
     for constant-strain zones up to the linear variation; 1e-3).
  2. wedge: a triangle with a 10 degree corner zoned AUTO 0.3 on a fixed
     base: the base reactions of PRINT BOUNDARY FORCES add up to the weight
     rho g A (1e-6; the reaction includes the weight of the fixed
     gridpoints' own mass).
  3. many contacts: a 1 m x 0.5 m zoned block (AUTO 0.05, 655 zones, about
     30 contacts on it) resting on ten fixed rigid blocks, ROUND 0.001: the
     contact normal forces add up to its weight (1e-6).
  4. long run: verification E3 (fixed far-field boundary) run 8000 cycles
     past the deck's 400: the unbalanced force falls below 1e-8 and the
     wall displacement stays within 0.1 % of the deck's own result.
"""
import math
import os
import re
import shutil
import sys
from udec_test import check, finish, run, workdir, write

udec, source = sys.argv[1], sys.argv[2]
RHO, G = 2000.0, 10.0


def cycle_lines(out):
    return [l for l in out.splitlines() if l.startswith("cycle ")]


def last_unbalanced(out):
    lines = cycle_lines(out)
    if not lines:
        return float("nan")
    m = re.search(r"max unbalanced force\s+([-+0-9.Ee]+)", lines[-1])
    return float(m.group(1)) if m else float("nan")


def ran_clean(label, rc, out, weight):
    check(rc == 0 and "Error" not in out, f"{label}: runs without error", out[-1500:])
    u = last_unbalanced(out)
    check(math.isfinite(u) and u < 1.0e-6 * weight, f"{label}: static equilibrium (unbalanced < 1e-6 weight)",
          f"{u:.3e} vs weight {weight:.3e}")
    check("NaN" not in out and "Infinity" not in out, f"{label}: every printed number finite")


def rows(out, after, ncol):
    """Numeric rows with `ncol` fields (first an integer) after the line
    starting with `after`, up to the next command echo."""
    result, inside = [], False
    for line in out.splitlines():
        if line.startswith(after):
            inside = True
            continue
        if inside:
            f = line.split()
            if len(f) == ncol and re.fullmatch(r"\d+", f[0]):
                try:   # numeric fields (PRINT ZONE STRESS ends with a word)
                    result.append([float(v) for v in f if not v.isalpha()])
                except ValueError:
                    pass
            elif f and f[0].isalpha() and f[0].isupper() and len(f[0]) > 2 and not line.startswith(" "):
                inside = False
    return result


# 1. stiffness contrast 1000 across a stiff joint
d = workdir()
write(d, "contrast.dat", """ROUND 0.01
BLOCK 0,0 0,2 1,2 1,0
SPLIT -1,1 2,1
GEN QUAD 0.25
CHANGE 0 1 1 2 MAT=2
PROP MAT=1 D=2000 K=1E9 G=6E8
PROP MAT=2 D=2000 K=1E12 G=6E11
PROP JMAT=1 JKN=1E13 JKS=1E13 JFRIC=1 JCOH=1E8 JTENS=1E8
GRAV 0 -10
BOUND -0.1 0.1 -0.1 2.1 XVEL 0
BOUND 0.9 1.1 -0.1 2.1 XVEL 0
BOUND -0.1 1.1 -0.1 0.1 YVEL 0
DAMP AUTO
CYC 50000
PRINT ZONE STRESS
STOP
""")
rc, out = run(udec, ["contrast.dat"], cwd=d, timeout=300)
ran_clean("contrast", rc, out, RHO * G * 2.0)
zones = rows(out, "PRINT ZONE STRESS", 11)
for block, ref in ((1, -1.0e4), (2, -3.0e4)):
    syy = [r[4] for r in zones if int(r[1]) == block]
    mean = sum(syy) / len(syy) if syy else float("nan")
    check(len(syy) == 64 and abs(mean / ref - 1.0) < 1.0e-3,
          f"contrast: block {block} mean syy = {ref:.0e} Pa (closed form)", f"{mean:.6e} over {len(syy)} zones")

# 2. acute zoned wedge (10 degrees) on a fixed base
tip = 1.0 / math.tan(math.radians(10.0))
write(d, "wedge.dat", f"""ROUND 0.005
BLOCK 0,0 0,1 {tip:.6f},0
GEN AUTO 0.3
PROP MAT=1 D=2000 K=1E9 G=6E8
GRAV 0 -10
BOUND -0.1 {tip + 0.1:.3f} -0.01 0.01 XVEL 0 YVEL 0
DAMP AUTO
CYC 20000
PRINT BOUNDARY FORCES
STOP
""")
rc, out = run(udec, ["wedge.dat"], cwd=d, timeout=300)
weight = RHO * G * 0.5 * tip
ran_clean("wedge", rc, out, weight)
check("smallest zone angle 10.0" in out, "wedge: the 10 degree corner is kept in the zoning",
      "\n".join(l for l in out.splitlines() if "smallest zone angle" in l))
reactions = [r[6] for r in rows(out, "BOUNDARY FORCES", 9) if r[4] == 4]
check(len(reactions) > 10 and abs(-sum(reactions) / weight - 1.0) < 1.0e-6,
      "wedge: base reactions add up to the weight (closed form)", f"{-sum(reactions):.6e} vs {weight:.6e}")

# 3. tiny rounding, many contacts on one zoned block
splits = "".join(f"SPLIT {x/10:.1f},-1 {x/10:.1f},0.05\n" for x in range(1, 10))
write(d, "many.dat", f"""ROUND 0.001
BLOCK 0,0 0,0.6 1,0.6 1,0
SPLIT -1,0.1 2,0.1
{splits}GEN 0 1 0.1 0.6 AUTO 0.05
PROP MAT=1 D=2000 K=1E9 G=6E8
PROP JMAT=1 JKN=1E11 JKS=1E11 JFRIC=0.5
GRAV 0 -10
FIX 0 1 0 0.1
DAMP AUTO
CYC 20000
PRINT MAX
PRINT CONTACT FORCE
STOP
""")
rc, out = run(udec, ["many.dat"], cwd=d, timeout=300)
weight = RHO * G * 0.5
ran_clean("many contacts", rc, out, weight)
contacts = rows(out, "PRINT CONTACT FORCE", 8)
check(len(contacts) >= 30, "many contacts: at least 30 contacts", str(len(contacts)))
check(abs(sum(r[4] for r in contacts) / weight - 1.0) < 1.0e-6,
      "many contacts: normal forces add up to the zoned block's weight (closed form)",
      f"{sum(r[4] for r in contacts):.6e} vs {weight:.6e}")

# 4. long run: verification E3 8000 cycles past the deck
e = os.path.join(source, "verification", "E")
for name in ("E1_stress_bc_no_support.dat", "E3_zero_disp_no_support.dat"):
    shutil.copy(os.path.join(e, name), d)
rc, out = run(udec, ["E1_stress_bc_no_support.dat"], cwd=d, timeout=300)
check(rc == 0, "long run: E1 writes the VERIFY file", out[-1500:])
deck = open(os.path.join(e, "E3_zero_disp_no_support.dat")).read()
stop = deck.rstrip().rfind("STOP")
write(d, "e3.dat", deck[:stop] + "PRINT HIS 1\nSTOP\n")
write(d, "e3long.dat", deck[:stop] + "CYC 8000\nPRINT HIS 1\nSTOP\n")
rc0, out0 = run(udec, ["e3.dat"], cwd=d, timeout=300)
rc, out = run(udec, ["e3long.dat"], cwd=d, timeout=300)
check(rc == 0 and "Error" not in out, "long run: E3 + 8000 cycles without error", out[-1500:])
u = last_unbalanced(out)
check(math.isfinite(u) and u < 1.0e-8, "long run: unbalanced force below 1e-8", f"{u:.3e}")


def history_last(text):
    vals = [float(f[1]) for f in (l.split() for l in text.splitlines()) if len(f) == 2
            and re.fullmatch(r"[-+0-9.E]+", f[0]) and re.fullmatch(r"[-+0-9.E]+", f[1])]
    return vals[-1] if vals else float("nan")


a, b = history_last(out0), history_last(out)
check(math.isfinite(a) and math.isfinite(b) and abs(b / a - 1.0) < 1.0e-3,
      "long run: the wall displacement stays at the deck's result (0.1 %)", f"{a:.6e} -> {b:.6e}")
finish()
