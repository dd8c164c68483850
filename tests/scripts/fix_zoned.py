"""FIX and zoned blocks (label `e2e`).

"FDEF blocks cannot be fixed" (UDEC manual (ICG1.5, 1989), Section 4.5,
FIX). Before: FIX marked zoned blocks fixed, printed "FIX 6 block(s)" and
held nothing (gridpoints move by their own forces), so a new user's zoned
slope with its base "fixed" fell under gravity through a SOLVE of 100,000
cycles (3.5 m, 6.8 m/s). Now:
  1. FIX whose range holds only zoned blocks is refused with an error that
     names the reason and the remedy (BOUNDARY XVEL / YVEL), status 1;
  2. FIX over rigid and zoned blocks fixes the rigid ones and warns that
     the zoned ones are left free;
  3. GENERATE of a FIXed block releases it and warns; the block then
     balances on its base held by BOUNDARY YVEL 0 (SOLVE balances; its
     elastic settlement under its own weight is rho g h^2 / (2 M) ~ 1e-5 m,
     so no gridpoint moves more than 1e-4 m).
"""
import sys
from udec_test import check, finish, run, workdir, write

udec, source = sys.argv[1], sys.argv[2]
d = workdir()

ONLY = """ROUND 0.01
BLOCK 0,0 0,1 1,1 1,0
GEN EDGE 0.5
PROP MAT=1 DENS=2000 K=1e9 G=1e9
FIX -1,2 -1,2
PRINT BLOCK
STOP
"""
write(d, "only.dat", ONLY)
rc, out = run(udec, ["only.dat"], cwd=d)
check(rc == 1 and "FDEF blocks cannot be fixed" in out and "BOUNDARY XVEL 0 YVEL 0" in out,
      "FIX of zoned blocks only: refused with the reason and the remedy", out[-800:])

MIXED = """ROUND 0.01
BLOCK 0,0 0,1 2,1 2,0
CRACK 1,0 1,1
GEN EDGE 0.5 0,1 0,1
PROP MAT=1 DENS=2000 K=1e9 G=1e9
FIX -1,3 -1,2
STOP
"""
write(d, "mixed.dat", MIXED)
rc, out = run(udec, ["mixed.dat"], cwd=d)
check(rc == 0 and "FIX 1 block(s)" in out and "Warning: FIX: 1 zoned (FDEF) block(s)" in out,
      "FIX over a rigid and a zoned block: the rigid one fixed, a warning for the other", out[-800:])

LATER = """ROUND 0.01
BLOCK 0,0 0,1 1,1 1,0
FIX -1,2 -1,2
GEN EDGE 0.5
PROP MAT=1 DENS=2000 K=1e9 G=1e9
GRAV 0 -10
BOUND -1,2 -0.1,0.1 YVEL 0
BOUND -0.1,0.1 -1,2 XVEL 0
DAMP AUTO
SOLVE
PRINT MAX
STOP
"""
write(d, "later.dat", LATER)
rc, out = run(udec, ["later.dat"], cwd=d)
check(rc == 0 and "Warning: GENERATE: 1 FIXed block(s) zoned and so released" in out,
      "GENERATE of a FIXed block: released with a warning", out[-800:])
check("SOLVE: balanced" in out, "the released block balances on its base", out[-800:])
disp = [float(l.split()[-3]) for l in out.splitlines()
        if l.strip().startswith("max gridpoint displacement")]
check(disp and disp[-1] < 1e-4, "the released block rests: gridpoints within 1e-4 m", str(disp))
finish()
