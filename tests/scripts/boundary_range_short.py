"""BOUNDARY STRESS on a top range that stops short of the model's corners
loads the top edge on to the corners (label e2e).

A square held by its in-situ stress (UDEC manual (ICG1.5, 1989), Section
4.5, BOUNDARY and INSITU): INSITU -1 MPa all round, the same STRESS on the
sides with ranges that take the model's corners, and on the top with the
range x -9 to 9, which stops one segment (2.044 m) short of the corners at
x = +-9.2; rollers under the base. The segment from the corner to the first
top point had an end in each range and no line loaded it: the top carried
-1e6 Pa over 18.4 - 2 x 2.044 m only and the model rose. Now:

1. the top's forces sum to -1e6 Pa times the whole 18.4 m (closed form:
   sigma times the edge length), within the 1e-5 of PRINT's six digits,
   and a note names the extension;
2. the model held by its own in-situ stress stays still: max displacement
   below 1e-9 m after 500 cycles (before: 1.2e-4 m);
3. the same with the top line given before the sides (no double load);
4. a footing (x -2 to 2) on the straight top is not extended (its next
   point is in line, not a corner; e2e.boundary_stress_corner case 1).
"""
import sys
from udec_test import check, finish, printed_number, run_deck, workdir

udec = sys.argv[1]
folder = workdir()
HEAD = """block -9.2,-9.2 -9.2,9.2 9.2,9.2 9.2,-9.2
gen edge 2.28
prop mat=1 dens=2600 k=8.333e+09 g=5e+09
insitu stress -1e6 0 -1e6
"""
SIDES = """bound -9.3,-9.1 -9.3,9.3 stress -1e6 0 -1e6
bound 9.1,9.3 -9.3,9.3 stress -1e6 0 -1e6
"""
TOP = "bound -9.0,9.0 9.1,9.3 stress -1e6 0 -1e6\n"
TAIL = """bound -10.2,10.2 -9.3,-9.1 yvel 0
print boundary forces
damp auto
cycle 500
print max
stop
"""


def top_force(out):
    """Sum of DFY over the boundary points on the top (y = 9.2)."""
    fy = 0.0
    for line in out.split("print boundary forces")[1].splitlines():
        p = line.split()
        if len(p) == 9 and p[0].isdigit() and abs(float(p[2]) - 9.2) < 1e-6:
            fy += float(p[8])
    return fy


for name, deck in (("sides_first", HEAD + SIDES + TOP + TAIL),
                   ("top_first", HEAD + TOP + SIDES + TAIL)):
    out = run_deck(udec, folder, name, deck)[1]
    fy = top_force(out)
    # closed form: -1e6 Pa x 18.4 m; PRINT gives 6 digits (1e-5)
    check(abs(fy - (-1e6 * 18.4)) < 1e-5 * 18.4e6, f"{name}: top force {fy} over the whole top",
          out[-4000:])
    check("stops one segment short of 2 corner(s)" in out, f"{name}: note of the extension", out[-4000:])
    d = printed_number(out, "max gridpoint displacement", float("inf"))
    check(d < 1e-9, f"{name}: the model stays still (max displacement {d})", out[-1500:])
    check("adds to the boundary stress" not in out, f"{name}: no stacked stress", out[-3000:])

out = run_deck(udec, folder, "footing", HEAD + SIDES + "bound -2,2 9.1,9.3 stress 0 0 -1e6\n"
               "print boundary forces\nstop\n")[1]
fy = top_force(out)
check(abs(fy - (-1e6 * 2 * 1.0222222)) < 1e-5 * 2.0444e6, f"footing: force {fy} on its own segments", out[-3000:])
check("stops one segment short" not in out, "footing: not extended", out[-3000:])
finish()
