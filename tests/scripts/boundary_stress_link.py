"""BOUNDARY STRESS given side by side loads the segment where two lines meet
(label e2e).

A new user's square held by its in-situ stress (UDEC manual (ICG1.5, 1989),
Section 4.5, BOUNDARY and INSITU): INSITU -10.4 / -20.7 MPa, the same
STRESS on each side (the ranges taking the model's corners, y -9.2 to 9.2)
and on the top between them (x -9.1 to 9.1, leaving the corners to the
sides, so as not to load them twice), rollers under the base. A STRESS on a
range loads the segments with both ends in it, so the top segment from the
corner to the top's first gridpoint (2.04 m) was loaded by neither line: the
top heaved 1.5e-2 m in 500 cycles. It now stays still.

1. Sides, then top: largest gridpoint displacement below 1e-10 m (the model
   is in equilibrium exactly; round-off gives 4e-17 m).
2. Top, then sides: the same.
3. A footing (x -2 to 2) on the top of the model with stressed sides: only
   the segments inside its range are loaded, not those to the unloaded
   points beside it: the footing's force is -1e6 Pa times the 2.044 m
   between its outer gridpoints (x = +-1.0222), within the 1e-5 of
   PRINT's six digits.
4. A joint leaving the model at its corner (a CRACK along the diagonal, the
   campaign's seed 36 in small), sides y -9.2 to 9.2 and the top x -10.2 to
   10.2, both lines taking the corner: each block's corner there was a
   lone point of one line and took its other half edge too, so the corner's
   top and side half edges had twice the stress (7.8e-3 m in 500 cycles, and
   a note of stresses added). Now still below 1e-10 m, and no such note.
"""
import re
import sys
from udec_test import check, finish, run_deck, workdir

udec = sys.argv[1]
folder = workdir()
HEAD = """block -9.2,-9.2 -9.2,9.2 9.2,9.2 9.2,-9.2
gen edge 2.28
prop mat=1 dens=2600 k=8.333e+09 g=5e+09
insitu stress -1.04e+07 0 -2.07e+07
"""
SIDES = """bound -9.3,-9.1 -9.2,9.2 stress -1.04e+07 0 -2.07e+07
bound 9.1,9.3 -9.2,9.2 stress -1.04e+07 0 -2.07e+07
"""
TOP = "bound -9.1,9.1 9.1,9.3 stress -1.04e+07 0 -2.07e+07\n"
TAIL = """bound -10.2,10.2 -9.3,-9.1 yvel 0
damp auto
cycle 500
print max
stop
"""


def max_disp(out):
    m = re.search(r"max gridpoint displacement\s+(\S+)", out)
    return float(m.group(1)) if m else float("inf")


for name, body in (("sides_then_top", SIDES + TOP), ("top_then_sides", TOP + SIDES)):
    out = run_deck(udec, folder, name, HEAD + body + TAIL)[1]
    check(max_disp(out) < 1e-10, f"{name}: the model stays still", out[-1500:])

out = run_deck(udec, folder, "footing", HEAD + SIDES + "bound -2,2 9.1,9.3 stress 0 0 -1e6\n"
               "print boundary forces\nstop\n")[1]
fy = 0.0
for line in out.splitlines():
    p = line.split()
    if len(p) == 9 and p[0].isdigit() and abs(float(p[2]) - 9.2) < 1e-6 \
            and abs(float(p[1])) < 9.1:
        fy += float(p[8])
# (PRINT gives 6 digits: 1e-5 of the force)
check(abs(fy - (-1e6 * 2 * 1.0222222)) < 1e-5 * 2.0444e6,
      f"footing: force {fy} on its own segments only", out[-3000:])
out = run_deck(udec, folder, "joint_at_corner", HEAD.replace("gen edge", "crack -9.2,9.2 9.2,-9.2\ngen edge")
               + "prop jmat=1 jkn=1e12 jks=1e12 jfric=0.8 jcoh=1e7 jtens=1e6\n"
               + SIDES + "bound -10.2,10.2 9.1,9.3 stress -1.04e+07 0 -2.07e+07\n" + TAIL)[1]
check(max_disp(out) < 1e-10, "joint at the corner: the model stays still", out[-1500:])
check("adds to the boundary stress" not in out, "joint at the corner: no stacked note", out[-3000:])
finish()
