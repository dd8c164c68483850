"""Applied boundary loads at gridpoints that later get a prescribed velocity
(manual Section 4.5 BOUNDARY; docs/zones.md "Loads under a prescribed
velocity").

A load (STRESS, XLOAD, YLOAD) at a gridpoint stays stored when XVEL / YVEL
is given there afterwards: the velocity wins while it holds, the load goes
straight into the support, so PRINT BOUNDARY FORCES' reaction at that point
includes it, and XFREE / YFREE (or a STRESS / load: the manual's Caution)
brings it back into action. A second XFREE removes the load.

PRINT BOUNDARY FORCES lists at a velocity point the force the body exerts on
the support. For a body at rest: sum of those rows = sum of the applied
loads + the weight.

Deck: an FDEF column 1 m wide, 2 m high (GEN QUAD 0.25), density 2000,
gravity 10 (weight 4e4 N), top face BOUNDARY STRESS syy = -1e5 (resultant
-1e5 N in y), left face STRESS sxx = -5e4 (traction +5e4 in x over 2 m:
+1e5 N). Given AFTER those: base pinned (XVEL 0 YVEL 0), left side on
rollers (XVEL 0), top-right corner held in y (YVEL 0; its share of the top
load, half an edge: 1e5 * 0.125 = 12500 N). Before the fix the base and
corner reactions summed to 0 in x (every left-face load was dropped) and
-127500 in y (the corner share dropped).
SET -FUP: the loads are checked as the forces fixed when given (under FUP
they follow the deformed edges, a relative change of order 1e-4).
"""
import re
import sys
from udec_test import check, finish, run, workdir, write, tables, rel

udec = sys.argv[1]

DECK = """start
round 0.01
block 0,0 0,2 1,2 1,0
gen quad 0.25
prop mat=1 dens=2000 k=1e9 g=5e8
change cons 1
grav 0 -10
set -fup
bound -.1 1.1 1.9 2.1 stress 0 0 -1e5
bound -.1 .1 -.1 2.1 stress -5e4 0 0
bound -.1 1.1 -.1 .1 xvel 0 yvel 0
bound -.1 .1 .1 2.1 xvel 0
bound .9 1.1 1.9 2.1 yvel 0
damp auto
cycle 4000
print bound forces
print grid disp
bound -.1 .1 .1 2.1 xfree
cycle 4000
print bound forces
print grid disp
print bound state
bound .9 1.1 1.9 2.1 yfree
cycle 4000
print bound forces
print bound state
bound .9 1.1 1.9 2.1 yfree
print bound forces
print bound state
save held.sav
restart held.sav
print bound forces
stop
"""

d = workdir()
write(d, "held.dat", DECK)
rc, out = run(udec, ["held.dat"], cwd=d, timeout=300)
check(rc == 0, "deck runs (exit 0)", out[-3000:])
check("***" not in out and "Error" not in out, "no error or refusal in the output",
      "\n".join(l for l in out.splitlines() if "***" in l or "Error" in l)[:2000])

TOP, LEFT_X, WEIGHT, CORNER = -1.0e5, 1.0e5, 2000 * 10 * 2 * 1, 0.125 * 1.0e5


FORCES = tables(out, "print bound forces")    # five tables, in deck order
NOTES = [l for l in out.splitlines() if "hold a stored load" in l]
GRID = tables(out, "print grid disp")         # two
STATE = tables(out, "print bound state")      # three


def table(n):
    return FORCES[n - 1] if len(FORCES) >= n else []


def held_sums(bf):
    return (sum(r["FX"] for r in bf if r["IX"] == 4), sum(r["FY"] for r in bf if r["IY"] == 4))


def corner(rows):
    return next((r for r in rows if r["X"] > 0.99 and r["Y"] > 1.99), None)


# Stage 1: every load given before the velocities. Statics of the column at
# rest (0.5 %: the residual of 4000 damped steps is far below it; the sums
# are exact for the uniform stresses, half edges at the face ends):
# x: the whole left-face load 1e5 goes into the rollers and pins;
# y: top load + weight = -1.4e5 into the base and the held corner.
bf = table(1)
fx, fy = held_sums(bf)
check(bf and rel(fx, LEFT_X) < 5e-3, "held: x reactions = left-face load 1e5 (0.5 %)", f"{fx}")
check(bf and rel(fy, TOP - WEIGHT) < 5e-3, "held: y reactions = top load + weight -1.4e5 (0.5 %)", f"{fy}")
# the stored loads are listed under the table: the left face's 9 points in x
# (1e5 in all) and the corner in y (-12500), exact shares printed to 6 digits
nums = [float(v) for v in re.findall(r"[-+]?\d\.\d+E[-+]\d+", NOTES[0])] if NOTES else []
check(NOTES and "10 velocity direction" in NOTES[0] and len(nums) == 2 and rel(nums[0], LEFT_X) < 1e-5
      and rel(nums[1], -CORNER) < 1e-5, "held: PRINT BOUND FORCES notes the stored loads 1e5, -12500",
      str(NOTES[:1]))
left1 = [r["X-DISP"] for r in GRID[0] if r["X"] < 0.01] if GRID else []
check(left1 and max(abs(u) for u in left1) == 0.0, "held: left side does not move in x (rollers)", str(left1))

# Stage 2: XFREE on the left side above the base: the stored left-face
# loads act again, the column bends in +x, and the x reaction (now the base
# pins alone, with the base corner's own stored share 0.125 * 5e4 = 6250)
# is still the whole face load 1e5 (0.5 %).
bf = table(2)
fx, fy = held_sums(bf)
check(bf and rel(fx, LEFT_X) < 5e-3, "xfree: base x reactions = left-face load 1e5 (0.5 %)", f"{fx}")
check(bf and rel(fy, TOP - WEIGHT) < 5e-3, "xfree: y reactions unchanged -1.4e5 (0.5 %)", f"{fy}")
left_rows = [r for r in bf if r["X"] < 0.01 and r["Y"] > 0.01]
# the freed points show code 1 and their applied share: 0.25 * 5e4 = 12500
# along the side, 6250 at the top-left end (printed to 6 digits)
check(left_rows and all(r["IX"] == 1 for r in left_rows), "xfree: freed points show code 1 (load acting)",
      str([(r["Y"], r["IX"]) for r in left_rows]))
check(left_rows and abs(sum(r["FX"] for r in left_rows) - (LEFT_X - 6250.0)) < 1.0,
      "xfree: freed points carry the left-face load less the base corner's 6250", str(left_rows))
top_left = [r["X-DISP"] for r in GRID[1] if r["X"] < 0.01 and r["Y"] > 1.99] if len(GRID) > 1 else []
# the load acts: the column bends in +x (held at 0 before). A free 1 x 2
# cantilever under 5e4 N/m would bend to about 1.2e-3 m at its top (beam
# theory, bending + shear); the held top-right corner resists the rotation
# here (measured 5.3e-4 m). Sanity bounds only, 3e-4 .. 3e-3 m: the check
# is that the stored load acts again at all.
check(top_left and 3e-4 < top_left[0] < 3e-3, "xfree: the column now bends in +x (5e-4 m)", str(top_left))

# Stage 3: YFREE at the top-right corner: its stored 12500 acts again; the
# base alone carries top load + weight (0.5 %).
bf = table(3)
fx, fy = held_sums(bf)
base_only = all(r["Y"] < 0.01 for r in bf if r["IY"] == 4)
check(bf and base_only and rel(fy, TOP - WEIGHT) < 5e-3,
      "yfree: base y reactions = top load + weight -1.4e5 (0.5 %)", f"{fy} base only {base_only}")
c = corner(bf)
check(c is not None and c["IY"] == 1 and abs(c["FY"] + CORNER) < 1.0,
      "yfree: the corner shows code 1 and its stored share -12500 acting", str(c))
c = corner(STATE[1]) if len(STATE) > 1 else None
check(c is not None and c["IY"] == 1, "yfree: PRINT BOUND STATE shows code 1 at the corner", str(c))

# Stage 4: a second YFREE removes the load itself (the manual: XFREE / YFREE
# remove the boundary condition): code 0, no force.
bf = table(4)
c = corner(bf)
check(c is not None and c["IY"] == 0 and c["FY"] == 0.0, "second yfree: corner code 0, no load", str(c))
c = corner(STATE[2]) if len(STATE) > 2 else None
check(c is not None and c["IY"] == 0, "second yfree: PRINT BOUND STATE shows code 0 at the corner", str(c))

# SAVE / RESTORE keeps the stored loads and codes: the same table
bf5 = table(5)
check(bf5 and len(bf5) == len(bf) and all(a == b for a, b in zip(bf, bf5)),
      "save / restore: PRINT BOUND FORCES unchanged")


# The manual's Caution the other way round (Section 4.5, BOUNDARY: "STRESS
# affects all degrees of freedom"): a STRESS given after YVEL frees those
# points, the usual reason a model's held corner slides out. BOUNDARY says
# so, with the count, and says nothing when the velocity comes last. Deck:
# the column above; base held in y, then a side stress over x in [0.9, 1.1],
# which takes the base's right-hand gridpoint (1, 0): 1 point freed.
COLUMN = "".join(DECK.splitlines(True)[:6])   # the column, unloaded
CAUTION = COLUMN + """bound -.1 1.1 -.1 .1 yvel 0
bound .9 1.1 -.1 2.1 stress -5e4 0 0
bound -.1 1.1 -.1 .1 yvel 0
bound .9 1.1 -.1 2.1 stress -5e4 0 0
stop
"""
d = workdir()
write(d, "caution.dat", CAUTION)
rc, out = run(udec, ["caution.dat"], cwd=d, timeout=60)
warn = [l for l in out.splitlines() if l.startswith("Warning: BOUNDARY")]
check(rc == 0 and len(warn) == 2 and all("XVEL / YVEL at 1 points" in w for w in warn)
      and "(1.00000E+00, 0.00000E+00)" in warn[0],
      "a STRESS after YVEL warns that it frees that point (1 point, at (1, 0)), each time", str(warn))
ORDER = COLUMN + """bound .9 1.1 -.1 2.1 stress -5e4 0 0
bound -.1 1.1 -.1 .1 yvel 0
stop
"""
d = workdir()
write(d, "order.dat", ORDER)
rc, out = run(udec, ["order.dat"], cwd=d, timeout=60)
check(rc == 0 and "Warning" not in out, "no warning when the velocity is given after the stress",
      out[-1500:])

finish()
