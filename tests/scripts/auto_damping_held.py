"""DAMP AUTO in a rigid model held by BOUNDARY velocities (label `stability`).

BOUNDARY XVEL / YVEL on the corners of rigid blocks holds those blocks by a
projection after their free update (engine_rigid_velocity). The free update
of a held block is driven by its reaction, and the adaptive damping used to
count it as kinetic energy change: with velocity v = F dt / m (1 + a dt/2)
the damping work of that block is a dt / 2 of its energy change, below the
ratio 0.5 of DAMP AUTO (UDEC manual (ICG1.5, 1989), Section 4.5, DAMPING:
"energy is absorbed in proportion to the rate of change of kinetic
energy"), so every step raised the damping constant until it met its limit
1/dt. The model then crept at the terminal velocity of an overdamped
system: found on a new user's jointed slope (rollers on the sides, the base
held in x and y), which SOLVE could not balance in 100,000 cycles (force
ratio 0.30; 4e-4 m/s at the crest) and whose PRINT MAX named the base
block's 5.7e6 N reaction as the largest unbalanced force.

Checks:
  1. the slope balances under SOLVE's defaults (RATIO 1e-5): measured 19,500
     cycles; before the fix "not balanced" at the 100,000-cycle limit;
  2. the damping constant stays far below its limit: median of HIST DAMP
     times the timestep below 0.1 (measured 1.8e-3; before 0.99);
  3. PRINT MAX leaves the held directions out, as the cycle does: below
     100 N at balance (measured 1.9 N; before 5.7e6 N, the base reaction);
  4. a block resting on a block held at its base corners: the joint carries
     the upper block's weight, 2600 x 2 x 1 x 9.81 = 51,012 N, within 0.1 %
     (closed form), and PRINT MAX's unbalanced force is below 1 N (before:
     the lower block's reaction, 1.0e5 N).
"""
import re
import sys
from udec_test import check, finish, run, workdir, write

udec, source = sys.argv[1], sys.argv[2]

SLOPE = """HEAD jointed rock slope, rigid blocks, held by boundary velocities
ROUND 0.05
BLOCK 0,0 0,30 20,30 35,10 60,10 60,0
JSET 60,0 100,0 0,0 4,0 (0,0)
JSET -30,0 100,0 0,0 5,0 (3,1)
PROP MAT=1 D=2600
PROP JMAT=1 JKN=5e9 JKS=2e9 JFRIC=0.8391
GRAV 0 -9.81
BOUND -0.1,0.1 -1,31 XVEL 0
BOUND 59.9,60.1 -1,31 XVEL 0
BOUND -1,61 -0.1,0.1 XVEL 0 YVEL 0
DAMP AUTO
HIST NCYC 100 DAMP
SOLVE
PRINT MAX
HIST WRITE 1 damp.his
STOP
"""

STACK = """ROUND 0.01
BLOCK 0,0 0,2 2,2 2,0
CRACK 0,1 2,1
PROP MAT=1 D=2600
PROP JMAT=1 JKN=1e10 JKS=1e10 JFRIC=0.5
GRAV 0 -9.81
BOUND -1,3 -0.1,0.1 XVEL 0 YVEL 0
DAMP AUTO
SOLVE
PRINT CONTACTS
PRINT MAX
STOP
"""


def max_unbalanced(out):
    vals = [float(l.split()[-3]) for l in out.splitlines()
            if l.strip().startswith("max unbalanced force")]
    return vals[-1] if vals else None


d = workdir()
write(d, "slope.dat", SLOPE)
rc, out = run(udec, ["slope.dat"], cwd=d, timeout=300)
check(rc == 0 and "Error" not in out, "slope: runs without error", out[-1500:])
m = re.search(r"SOLVE: balanced after (\d+) cycles", out)
check(m is not None, "slope: SOLVE balances (RATIO 1e-5, limit 100,000 cycles)",
      "\n".join(l for l in out.splitlines() if "SOLVE" in l or l.startswith("cycle ")))
dt = re.findall(r"timestep\s+([0-9.E+-]+)", out)
damp = []
try:
    with open(d + "/damp.his") as f:
        damp = sorted(float(l.split()[1]) for l in f if not l.startswith("#") and l.split())
except OSError:
    pass
check(bool(damp) and bool(dt), "slope: HIST DAMP written and a timestep printed")
if damp and dt:
    med = damp[len(damp) // 2] * float(dt[-1])
    check(med < 0.1, "slope: DAMP AUTO stays below its limit (median alpha dt < 0.1)", str(med))
u = max_unbalanced(out)
check(u is not None and u < 100.0, "slope: PRINT MAX leaves the held directions out (< 100 N)", str(u))

write(d, "stack.dat", STACK)
rc, out = run(udec, ["stack.dat"], cwd=d, timeout=120)
check(rc == 0 and "Error" not in out and "SOLVE: balanced" in out, "stack: balances", out[-1500:])
lines = out.splitlines()
fn = []
for i, l in enumerate(lines):
    if "NORMAL-FORCE" in l.split():
        col = l.split().index("NORMAL-FORCE")
        for r in lines[i + 1:]:
            if not re.match(r"\s+\d+\s", r):
                break
            fn.append(float(r.split()[col]))
w = 2600.0 * 2.0 * 1.0 * 9.81
check(len(fn) >= 1 and abs(sum(fn) - w) < 1e-3 * w, "stack: the joint carries the upper block's weight (0.1 %)",
      f"{fn} vs {w}")
u = max_unbalanced(out)
check(u is not None and u < 1.0, "stack: PRINT MAX unbalanced force below 1 N", str(u))
finish()
