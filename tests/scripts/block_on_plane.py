"""A block on an inclined plane, drawn as a new user draws it (label e2e).

The only BLOCK is the ground with the block standing on its inclined surface
(corners clockwise, computed on the incline and typed to four decimals);
one SPLIT along the plane separates them (UDEC manual (ICG1.5, 1989),
Section 4.5, BLOCK: "further blocks may be created with a ... SPLIT";
SPLIT: "all blocks in the path of a line ... are split into two").

Before the fix the typed corners missed the typed line by a few 1e-5 and the
line crossed the block's own edges there (tolerance 1e-9 of the model): the
SPLIT was refused ("pieces would not be simple polygons": the sliding block
of the inch deck never existed), or made the column and a strip of no width
along the plane one block, whose rounding (radius 2.9 m) and overlaps threw
it off the slope. Now a corner within 1 % of the minimum edge of a cut's
line lies on it (cut_line_tol, src/geometry/geometry_cutting.f90).

Checks:
1. 12 planes (dip 10-40 degrees), block b x h on the plane: SPLIT makes 2
   blocks, the upper one of area b h (within 1e-4: four typed decimals);
2. sliding, inch-snail-psi units (Table 4-1): an 8 x 4 in block on a 30
   degree plane, friction 0.5, no damping, after 2000 steps moves at
   v = g (sin 30 - cos 30 tan phi) t (rigid block on a frictional plane;
   within 1 %: the first steps load the contact springs);
3. toppling (Hoek and Bray, Rock Slope Engineering: a block of base b and
   height h on a plane of dip psi below its friction angle topples when
   b / h < tan psi): 2 x 6 m on 25 degrees (b/h 0.333 < 0.466), friction
   0.9, turns past 0.5 rad in 12 000 steps (before: 4e-7 rad); on 15
   degrees (0.333 > 0.268) it stands (turn below 1e-4 rad, at rest).
"""
import math
import random
import re
import sys
from udec_test import check, finish, run, workdir, write

udec = sys.argv[1]


def plane_deck(psi, b, h, a=10.0, length=30.0, y0=5.0):
    """BLOCK (ground + block of b x h on a plane of dip psi rising to the
    right from (0, y0)) and the SPLIT along the plane, typed to 4 decimals;
    returns (text, centre of the block's top edge, height of the plane
    under the block's lower corner)."""
    t, s, c = (f(math.radians(psi)) for f in (math.tan, math.sin, math.cos))
    ya = y0 + a * t
    p = [(0, 0), (0, y0), (a, ya), (a - h * s, ya + h * c), (a - h * s + b * c, ya + h * c + b * s),
         (a + b * c, ya + b * s), (length, y0 + length * t), (length, 0)]
    text = "block " + " ".join(f"{x:.4f},{y:.4f}" for x, y in p) + "\n"
    text += f"split -1,{y0 - t:.4f} {length + 1:g},{y0 + (length + 1) * t:.4f}\n"
    return text, (a - h * s + b * c / 2, ya + h * c + b * s / 2), ya


def blocks(out):
    m = re.findall(r"SPLIT: \d+ -> (\d+) blocks", out)
    return int(m[-1]) if m else None


def rigid_rows(out):
    """PRINT RIGID rows of the last table: block -> list of floats."""
    rows = {}
    for line in out.splitlines():
        f = line.split()
        if len(f) == 9 and f[0].isdigit() and f[-1] in ("T", "F"):
            rows[int(f[0])] = [float(v) for v in f[1:8]]
    return rows


d = workdir()
rng = random.Random(20261127)
bad = []
for i in range(12):
    psi = rng.uniform(10.0, 40.0)
    b, h = rng.uniform(1.0, 4.0), rng.uniform(1.0, 4.0)
    geo, _, _ = plane_deck(psi, b, h)
    write(d, "s.dat", "round 0.02\n" + geo + "print block\n")
    rc, out = run(udec, ["s.dat"], cwd=d)
    rows = (line.split() for line in out.splitlines())
    areas = [float(f[5]) for f in rows if len(f) == 9 and f[0] in ("1", "2")]
    if rc != 0 or blocks(out) != 2 or not any(abs(a - b * h) < 1e-4 * b * h for a in areas):
        bad.append((round(psi, 2), round(b, 3), round(h, 3), out[-400:]))
check(not bad, "1. SPLIT along an inclined plane separates the block on it "
      f"({12 - len(bad)} of 12)",
      str(bad[:2]))

def plane_run(name, psi, b, h, rnd, mat, joint, grav, steps, **where):
    """Run the block on the plane (plane_deck) under gravity, the ground
    FIXed; returns (rc, output, PRINT RIGID rows)."""
    geo, _, ya = plane_deck(psi, b, h, **where)
    length = where.get("length", 30.0)
    deck = (f"round {rnd}\n" + geo + f"prop mat=1 {mat}\nprop jmat=1 {joint} jcoh=0 jten=0\n"
            f"grav 0,-{grav}\nfix 0,{length:g} 0,{ya - 0.5:.3f}\n{steps}print rigid\nstop\n")
    write(d, name, deck)
    rc, out = run(udec, [name], cwd=d)
    return rc, out, rigid_rows(out)


# 2. sliding, inch units: block 8 in along the plane, 4 in high, 30 degrees
g, mu = 386.1, 0.5
rc, out, rows = plane_run("slide.dat", 30.0, 8.0, 4.0, 0.05, "dens=2.48e-4 k=7.0e6 g=4.5e6",
                          f"jkn=1.0e6 jks=1.0e6 jfric={mu}", g, "cycle 2000\n", a=12.0, length=40.0)
tm = re.findall(r"cycle 2000, time +([0-9.E+-]+)", out)
ok = rc == 0 and tm and len(rows) == 2
if ok:
    t = float(tm[-1])
    v_ref = g * (math.sin(math.radians(30.0)) - math.cos(math.radians(30.0)) * mu) * t
    moving = [r for r in rows.values() if abs(r[1]) > 0.0]
    v = math.hypot(moving[0][1], moving[0][2]) if moving else 0.0
    print(f"2. sliding block: v = {v:.5g} in/s at t = {t:.5g} s, closed form {v_ref:.5g}")
    ok = abs(v - v_ref) < 0.01 * v_ref
check(ok, "2. a block on a 30 degree plane (inch units) slides at "
      "g (sin a - cos a tan phi) t (1 %)",
      out[-800:])

# 3. toppling and standing columns (2 x 6 m), friction 0.9 (42 degrees)
for psi, topples in ((25.0, True), (15.0, False)):
    rc, out, rows = plane_run("top.dat", psi, 2.0, 6.0, 0.02, "dens=2600 k=2e10 g=1.2e10",
                              "jkn=1e10 jks=1e10 jfric=0.9", 9.81, "damp auto\ncycle 12000\n")
    turn = max((abs(r[6]) for r in rows.values()), default=None)
    vel = max((abs(r[1]) + abs(r[2]) for r in rows.values()), default=None)
    print(f"3. column on {psi:g} degrees: rotation {turn} rad, velocity {vel}")
    if topples:
        check(rc == 0 and turn is not None and turn > 0.5,
              "3. a 2 x 6 m column on 25 degrees (b/h < tan psi) topples", out[-800:])
    else:
        check(rc == 0 and turn is not None and turn < 1e-4 and vel < 1e-6,
              "3. a 2 x 6 m column on 15 degrees (b/h > tan psi) stands", out[-800:])
finish()
