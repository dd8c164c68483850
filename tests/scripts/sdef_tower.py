"""A tower of five SDEF blocks on a fixed base, at the combined SDEF step
(label `stability`).

Five 1 m SDEF blocks (CONS 1, K 30 GPa, G 18 GPa, density 2600) stacked on
a FIXed base, joints JKN = JKS = 2e11 Pa/m (stiff: the joints, not the rock,
bound the step), gravity (UDEC manual (ICG1.5, 1989), Section 3.2 p. 3-2,
Section 4.5 CHANGE, DAMPING, FRACTION). The step is engine_sdef's combined
bound of the six modes of each block with its joints, half the critical
step of a block between fixed neighbours; in a stack the neighbours move.

Checks:
  1. undamped, 20,000 cycles from rest under gravity stay bounded: the
     last unbalanced force is not above the largest of the first 1,000
     cycles (an unstable step grows without bound within a few hundred);
  2. with DAMP AUTO, SOLVE RATIO 1e-6 balances within 3,000 cycles
     (measured 1,020);
  3. each block's stress SYY is the statics of the stack: its strain modes'
     equation (engine_sdef) with the load of the blocks above on its top
     edge and its reaction below gives A syy = -(n_above + 1/2) rho g A,
     to 0.5 % (measured to the printed 6 digits). (SXX is not 0: the stiff
     joints' shear restrains the blocks' Poisson expansion.)
"""
import re
import sys
from udec_test import check, finish, run, workdir, write

udec = sys.argv[1]

HEAD = """HEAD SDEF tower
ROUND 0.001
BLOCK 0,0 0,6 3,6 3,0
CRACK 0,1 3,1
CRACK 1,1 1,6
CRACK 2,1 2,6
CRACK 1,2 2,2
CRACK 1,3 2,3
CRACK 1,4 2,4
CRACK 1,5 2,5
DELETE 0 1 1 6
DELETE 2 3 1 6
PROP MAT 1 DENS 2600 K 30e9 G 18e9
PROP JMAT 1 JKN 2e11 JKS 2e11 JFRIC 0.7 JCOH 0 JTENS 0
CHANGE 1 2 1 6 SDEF
CHANGE 1 2 1 6 CONS 1
FIX 0 3 0 1
GRAV 0 -9.81
"""
RHOG = 2600.0 * 9.81

d = workdir()
write(d, "free.dat", HEAD + "CYCLE 20000\nSTOP\n")
rc, out = run(udec, ["free.dat"], cwd=d)
check(rc == 0 and "***" not in out, "the undamped tower cycles", out[-1500:])
hist = [(int(a), float(b)) for a, b in re.findall(r"^\s+(\d+)\s+([0-9.E+-]+)\s*$", out, re.M)]
early = [f for n, f in hist if n <= 1000]
m = re.findall(r"max unbalanced force\s+([0-9.E+-]+)", out)
check(bool(early) and bool(m), "the undamped run reports its unbalanced force", out[-1500:])
if early and m:
    check(float(m[-1]) <= max(early),
          f"undamped: last unbalanced force {float(m[-1]):.4e} <= peak of the first 1000 "
          f"cycles {max(early):.4e}")

write(d, "tower.dat", HEAD + "DAMP AUTO\nSOLVE RATIO 1e-6 CYCLES 3000\nPRINT BLOCK\nSTOP\n")
rc, out = run(udec, ["tower.dat"], cwd=d)
check(rc == 0 and "***" not in out, "the damped tower runs", out[-1500:])
check("SOLVE: balanced" in out, "SOLVE balances the tower within 3,000 cycles",
      "\n".join(l for l in out.splitlines() if "SOLVE" in l or l.startswith("cycle")))
yc = {int(b): float(y) for b, y in re.findall(
    r"^\s+(\d+)\s+1\s+1\s+4\s+\d+\s+1\.0+E\+00\s+\S+\s+(\S+)", out, re.M)}
rows = {int(r[0]): [float(x) for x in r[1:]] for r in re.findall(
    r"^\s+(\d+)\s+1" + r"\s+(\S+)" * 8 + r"\s+E\s*$", out, re.M)}
check(len(yc) == 5 and set(rows) == set(yc), "five SDEF blocks in the tower", out[-2500:])
for b, y in yc.items():
    n_above = round(5.5 - y)
    syy = -(n_above + 0.5) * RHOG
    s_yy = rows[b][4]
    check(abs(s_yy - syy) <= 0.005 * abs(syy),
          f"block {b} (y {y:.2f}): SYY {s_yy:.5e} = {syy:.5e} within 0.5 %")
finish()
