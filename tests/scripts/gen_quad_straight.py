"""GENERATE QUAD on blocks with a corner on a straight edge (label `e2e`).

A corner at a straight angle (180 degrees) is left where a joint ends on a
block's edge, or a user types one in BLOCK. QUAD refused such a block
("QUAD needs a quadrilateral block (4 corners)"; random tunnels, nu-zoned,
seed 6: a JSET grid zoned with QUAD stopped at GENERATE). Now the four
other corners make the quadrilateral and the straight corner is a
gridpoint of its edge.

Check: a square with a corner at x = 3.3 on its top edge (the top cut
3 + 7 cells, the bottom 10 evenly: a skewed grid) under uniaxial
compression on rollers. Plane strain, sxx = 0: u_y(top) = -p H (1 - nu^2) / E
and u_x(x) = p x nu (1 + nu) / E (Hooke's law; E 3e10 Pa, nu 0.25 from
K 2e10, G 1.2e10), within 0.1 % (SOLVE to a force ratio of 1e-8; linear
triangles carry a uniform strain exactly on any grid).
"""
import re
import sys
from udec_test import check, finish, header_rows, run_deck, workdir

udec = sys.argv[1]
d = workdir()

UNIAXIAL = """round 0.05
block 0,0 0,10 3.3,10 10,10 10,0
gen quad 1
prop mat=1 dens=2600 k=2e10 g=1.2e10
bound -1,11 -0.1,0.1 yvel 0
bound -0.1,0.1 -1,11 xvel 0
bound -1,11 9.9,10.1 stress 0 0 -1e6
damp auto
solve ratio 1e-8
print -1,11 9.9,10.1 grid
stop
"""
rc, out = run_deck(udec, d, "uniaxial", UNIAXIAL)
m = re.search(r"GENERATE: 1 block\(s\) zoned, (\d+) zones, (\d+) gridpoints", out)
check(bool(m) and m.groups() == ("400", "221"), "QUAD: 10 x 10 cells of 4 zones", m and m.group(0))
K, G, p, H = 2e10, 1.2e10, 1e6, 10.0
E = 9 * K * G / (3 * K + G)
nu = (3 * K - 2 * G) / (2 * (3 * K + G))
rows = [r for r in header_rows(out, "  GRIDPT   BLOCK             X             Y        X-DISP", 8)]
top = [(float(r[2]), float(r[4]), float(r[5])) for r in rows]
check(len(top) == 11, "eleven gridpoints on the top edge", str(top))
check(any(abs(x - 3.3) < 1e-3 for x, _, _ in top), "the corner at x = 3.3 is a gridpoint", str(top))
uy = -p * H * (1 - nu ** 2) / E
for x, ux, uyy in top:
    uxx = p * x * nu * (1 + nu) / E
    check(abs(uyy - uy) < 1e-3 * abs(uy), f"u_y at x = {x:.2f} (closed form {uy:.4e})", f"{uyy:.5e}")
    check(abs(ux - uxx) < 1e-3 * abs(p * H * nu * (1 + nu) / E), f"u_x at x = {x:.2f} "
          f"(closed form {uxx:.4e})", f"{ux:.5e}")

# the campaign's deck: a JSET grid over a square, QUAD
JSET = """round 0.02
block -24.5,-24.5 -24.5,24.5 24.5,24.5 24.5,-24.5
jset 0.0,0 100,0 0,0 2.7,0 2.22,0
jset 90.0,0 100,0 0,0 2.38,0 0.95,0
gen quad 1.74
stop
"""
rc, out = run_deck(udec, d, "jset", JSET)
m = re.search(r"GENERATE: (\d+) block\(s\) zoned", out)
n = re.findall(r"number of blocks\s+(\d+)", out)
check(bool(m) and int(m.group(1)) >= 400, "every block of the JSET grid zoned by QUAD",
      m and m.group(0))

# A new user's jointed tunnel model is mostly triangles and pentagons: QUAD
# refused the whole GENERATE for its first triangle. Now the convex
# quadrilaterals get QUAD's crossed diagonals and the others EDGE zoning at
# the same size, with a note naming how many and the first.
MIXED = """round 0.02
block 0,0 0,10 10,10 10,0
crack 5,0 5,10
crack 0,8 2,10
gen quad 1
prop mat=1 dens=2600 k=2e10 g=1.2e10
print max
stop
"""
rc, out = run_deck(udec, d, "mixed", MIXED)
m = re.search(r"GENERATE: 3 block\(s\) zoned, (\d+) zones", out)
note = re.search(r"Note: GENERATE QUAD: 2 of the 3 block\(s\) \(the first: block (\d+)\) are not "
                 r"convex quadrilaterals", out)
check(rc == 0 and "*** Error" not in out, "QUAD over a triangle and a pentagon runs", out)
check(bool(note), "the note names the blocks zoned as by EDGE", out)
# the quadrilateral 5 x 10 gets 5 x 10 cells of 4 zones: 200 zones; the
# others (areas 48 and 2 m2 at edges <= 1 m) at least one zone per 0.5 m2
check(bool(m) and int(m.group(1)) >= 200 + 50 // 0.5, "every block zoned", m and m.group(0))
finish()
