"""A tunnel cut in one deformable block: the wall around the key cuts
(label stability; closed form: Kirsch / Lame, a circular hole in an elastic
plane under hydrostatic stress p, wall displacement u = p a / (2 G)).

TUNNEL in a single block cuts it along two horizontal key cuts from the
ring's sides to the block's edges (a block cannot hold a hole), so the two
halves share two joints on one line, one each side of the opening. The
contact lengths of a line of contacts were shared out between neighbours
along the line, and the nearest neighbour of the mouth contact at the wall
was the one across the opening: the mouth contact took half the tunnel's
width as its length (1.6 m where 0.1 m is right), its stiffness was 16 times
too large, and the model blew up at cycle 4 ("Contact Overlap Too Great",
jkn = 2e11) or, stiffer (jkn = 1e12), ran with 7e8 Pa in the zones at the
mouth and a 7 mm spike in the wall. Now the neighbour must lie across a
stretch both blocks share.

Checked, a = 1.5 m, p = 10 MPa, G = 10 GPa (p a / 2G = 7.5e-4 m), a 16 m
square held by BOUNDARY STRESS, zones of 0.4 m, 3000 cycles (converged: 6000
give the same four digits):
- the run completes with no error;
- roof and side-wall displacements inward, each within 6 % of p a / (2G):
  the square's edge at 5.3 radii adds about 3 % (thick cylinder, b^2 /
  (b^2 - a^2) with b = 8 m), the 0.4 m zones about 2 %;
- the largest compressive zone stress within 25 % of the wall's 2 p
  (coarse zones average the peak): not the 7e8 Pa of the bug.
"""
import sys
from udec_test import check, finish, history_rows, run, workdir, write

udec = sys.argv[1]
DECK = """round 0.02
block -8,-8 -8,8 8,8 8,-8
tunnel 0 0 1.5 24
delete ann 0 0 0 1.45
prop mat=1 dens=2500 k=1.6667e10 g=1e10 jkn=2e11 jks=2e11 jfric=40 jcoh=1e9 jten=1e9
gen edge 0.4
bound stress -10e6 0 -10e6
insitu stress -10e6 0 -10e6
hist ydis 0,1.5 xdis 1.5,0
damp auto
cycle 3000
print hist 1 2
print max
stop
"""
d = workdir()
write(d, "key_cut.dat", DECK)
rc, out = run(udec, ["key_cut.dat"], cwd=d, timeout=600)
check(rc == 0 and "***" not in out, "the tunnel in one block cycles 3000 times without error",
      "\n".join(l for l in out.splitlines() if "***" in l or "cycle " in l)[-1500:])
rows = [r for r in history_rows(out, "print hist 1 2") if len(r) == 3]
u_ref = 10e6 * 1.5 / (2 * 1e10)
last = rows[-1] if rows else [0, 0, 0]
check(rows and abs(-last[1] - u_ref) <= 0.06 * u_ref, f"roof moves down p a / 2G = {u_ref:.3g} m within 6 %",
      str(last))
check(rows and abs(-last[2] - u_ref) <= 0.06 * u_ref, f"side wall moves in p a / 2G = {u_ref:.3g} m within 6 %",
      str(last))
smin = None
for line in out.splitlines():
    if "min principal stress (SMIN)" in line:
        smin = float(line.split()[4])
check(smin is not None and abs(-smin - 2e7) <= 0.25 * 2e7, "largest compression within 25 % of 2 p at the wall",
      str(smin))
finish()
