"""A needle of SDEF blocks comes to rest (label `stability`).

A 6 x 0.1 m needle (60:1) between SDEF blocks of 3 x 1.45 m, INSITU
stress -10 MPa and a boundary stress of -12 MPa in x (CHANGE SDEF, CONS 1,
DAMP AUTO; UDEC manual (ICG1.5, 1989), Section 3.2 p. 3-2 and Section 4.5
CHANGE, DAMPING, FRACTION). The step of the strain modes used to take the
blocks' FRACTION fb = 0.1 on top of a bound that multiplied the largest
row of M^-1 by the largest of K (the needle's long-axis joint stiffness
against its thin-axis mass): 1.1e-6 s, and SOLVE needed 16,920 cycles
(jointed SDEF tunnels: 10 - 15 times the cycles of the same rigid model, so
that they "never balanced" in 20,000). The strain modes are a deformation,
like a zone's, and now take FRACTION fz (default 1) on half the critical
step of the block's six modes with the joints at its corners (engine_sdef,
sdef_timestep).

Checks:
  1. the timestep does not exceed the critical step of the needle's
     thin-axis mode (the closed form of engine_sdef's equations: generalized
     mass rho L h^3 / 12, stiffness L h D11, so dt_crit = 2 / omega =
     h sqrt(rho / (3 D11)) = 1.267e-5 s, D11 = K + 4G/3 = 54 GPa): a step
     above it would be unstable; and it is at least a quarter of it
     (measured 6.22e-6; 5.41e-6 with the earlier norm bound; before 1.10e-6);
  2. SOLVE (RATIO 1e-5) balances within 6,000 cycles (measured 2,360;
     before the change "not balanced", it took 16,920);
  3. INSITU's note on unzoned rigid blocks (their zones from a later
     GENERATE get no stress) does not count the SDEF blocks it set.
"""
import math
import re
import sys
from udec_test import check, finish, run, workdir, write

udec = sys.argv[1]

DECK = """HEAD SDEF needle between two blocks
ROUND 0.01
BLOCK 0,0 0,3 6,3 6,0
CRACK 0,1.45 6,1.45
CRACK 0,1.55 6,1.55
CRACK 3,0 3,1.45
PROP MAT 1 DENS 2600 K 30e9 G 18e9
PROP JMAT 1 JKN 20e9 JKS 2e9 JFRIC 0.7 JCOH 0 JTENS 0
CHANGE SDEF
CHANGE CONS 1
INSITU STRESS -10e6 0 -10e6
BOUND STRESS -12e6 0 -10e6
DAMP AUTO
SOLVE RATIO 1e-5 CYCLES 6000
STOP
"""

RHO, D11, H = 2600.0, 30e9 + 4.0 * 18e9 / 3.0, 0.1
DT_CRIT = H * math.sqrt(RHO / (3.0 * D11))

d = workdir()
write(d, "needle.dat", DECK)
rc, out = run(udec, ["needle.dat"], cwd=d)
check(rc == 0 and "*** Error" not in out, "the needle deck runs", out[-1500:])
# INSITU gives the SDEF blocks their stress: its note on blocks left without
# (unzoned rigid ones) must not count them (before: "4 block(s) in the range
# are rigid (not zoned)" beside "4 SDEF block(s)")
check("INSITU: stresses set in 0 zone(s), 4 SDEF block(s)" in out
      and "are rigid (not zoned)" not in out,
      "INSITU names the SDEF blocks it set and calls none of them rigid",
      "\n".join(l for l in out.splitlines() if "INSITU" in l or "rigid" in l))
m = re.search(r"timestep\s+([0-9.E+-]+)", out)
check(m is not None, "the cycle line gives the timestep", out[-1500:])
if m:
    dt = float(m.group(1))
    check(dt <= DT_CRIT, f"timestep {dt:.4e} <= critical {DT_CRIT:.4e} of the thin-axis mode")
    check(dt >= 0.25 * DT_CRIT, f"timestep {dt:.4e} >= a quarter of the critical {DT_CRIT:.4e}")
check("SOLVE: balanced" in out, "SOLVE balances the needle within 6,000 cycles",
      "\n".join(l for l in out.splitlines() if "SOLVE" in l or l.startswith("cycle")))
finish()
