"""BOUNDARY STRESS given side by side loads each segment once where a joint
leaves the model at its corner (label e2e).

A new user's square held by its in-situ stress (UDEC manual (ICG1.5, 1989),
Section 4.5, BOUNDARY and INSITU): INSITU -10.4 / -20.7 MPa, the same
STRESS on each side (the ranges taking the model's corners) and on the top,
rollers under the base. A STRESS on a range loads the segments with both
ends in it; a selected point with no selected neighbour takes all its free
half edges.

1. A footing (x -2 to 2) on the top of the model with stressed sides: only
   the segments inside its range are loaded, not those to the unloaded
   points beside it: the footing's force is -1e6 Pa times the 2.044 m
   between its outer gridpoints (x = +-1.0222), within the 1e-5 of
   PRINT's six digits.
2. A joint leaving the model at its corner (a CRACK along the diagonal, the
   campaign's seed 36 in small), sides y -9.2 to 9.2 and the top x -10.2 to
   10.2, both lines taking the corner: each block's corner there was a
   lone point of one line and took its other half edge too, so the corner's
   top and side half edges had twice the stress (7.8e-3 m in 500 cycles, and
   a note of stresses added). Now still below 1e-10 m (round-off: 1e-16 m),
   and no such note.
"""
import sys
from udec_test import check, finish, printed_number, run_deck, workdir

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
TAIL = """bound -10.2,10.2 -9.3,-9.1 yvel 0
damp auto
cycle 500
print max
stop
"""


def max_disp(out):
    return printed_number(out, "max gridpoint displacement", float("inf"))


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
