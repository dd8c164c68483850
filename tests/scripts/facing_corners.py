"""Corners of different blocks facing each other across a short stretch of
joint (label `stability`).

Two corners of different blocks lie on one straight joint, each on the
other block's edge, closer than the sum of their rounding lengths (ROUND,
UDEC manual (ICG1.5, 1989), Section 4, ROUND; the rounded corner of
Section 3.3, Fig 3-3d: an arc tangent to both edges at d from the
vertex). Before the fix the two arcs left no straight part: the blocks
touched only where the arcs faced each other, one corner-corner contact
leaning 14 degrees off the joint, of length 0 and gap 1.23 cm under
gravity, and the joint stretch carried a shear stress of 0.49 MPa under a
uniform isotropic INSITU field of 1 MPa. Now each such corner's rounding
is cut to 0.4 of the stretch (geometry_round_facing; docs/mechanics.md,
"Facing corners").

  1. the brief's deck (blocks 3 and 4 share y = 4 between x = 4 and 4.3,
     ROUND 0.2), one cycle under gravity on a fixed base: exactly two
     contacts of the pair, each of length 0.15 (half the 0.3 m stretch,
     the half-spacing of Fig 3-3b, to 1e-9 relative), normal at 90
     degrees, gap below 1e-4 m (the elastic closure of one step is
     ~1e-8 m; before: one contact, length 0, gap 1.23e-2 m).
  2. the same blocks held by INSITU STRESS -1e6 0 -1e6 and the same
     BOUNDARY STRESS, 2000 cycles: the exact answer is the initial state.
     No block moves beyond 1e-9 m, and every contact carries the field:
     normal stress 1e6 Pa to 1e-6 relative, shear stress below 1 Pa
     (1e-6 of the field) (before: 0.49 MPa on the pair's contact).
  3. T-junctions (a joint ending on a joint from above, from below, and
     two from either side 5 cm apart), rigid, uniform INSITU: no contact
     of length 0, every contact carries the field, and no block moves
     beyond 1e-9 m in 2000 cycles (before: three contacts of length 0 at
     the near-T, blocks moving 6e-8 m).
  4. random: joint sets of random near-T and near-facing ends in a box
     (seeded), uniform INSITU, 10 cycles: every pair of blocks that share
     a stretch of joint longer than 1e-3 m (from PRINT CORNER, six
     significant digits) has a contact with |gap| < 1e-6 m and none of
     length 0 along it.
"""
import random
import sys
from udec_test import check, finish, header_rows, run_clean

udec = sys.argv[1]

REPRO = """round 0.2
block -2,0 -2,8 8,8 8,0
crack -2,4 8,4
crack 4,0 4,4
crack 0.8,4 4.6,8
crack 4.3,4 4.3,8
prop mat=1 d=2000 jkn=1e10 jks=1e10 jfric=0.5774
"""
GRAVITY = """grav 0 -10
bound yvel 0 -3,9 -0.1,0.1
cycle 1
print contact
stop
"""
INSITU = """insitu stress -1e6 0 -1e6
bound stress -1e6 0 -1e6
damp auto
cycle {n}
print max
print contact
stop
"""


def contacts(out):
    """id -> dict(b1, b2, kind, length, angle, gap, sn, ss) from PRINT CONTACT."""
    table = {}
    for f in header_rows(out, " CONTACT  BLOCK1  BLOCK2 TYPE", 14):
        table[int(f[0])] = dict(b1=int(f[1]), b2=int(f[2]), kind=int(f[3]),
                                length=float(f[6]), angle=float(f[7]))
    for f in header_rows(out, " CONTACT  BLOCK1  BLOCK2             X", 8):
        table[int(f[0])]["gap"] = float(f[7])
    for f in header_rows(out, " CONTACT  BLOCK1  BLOCK2        LENGTH", 8):
        table[int(f[0])]["sn"] = float(f[6])
        table[int(f[0])]["ss"] = float(f[7])
    return table


def max_disp(out):
    vals = [float(l.split()[3]) for l in out.splitlines() if l.strip().startswith("max block displacement")]
    return vals[-1] if vals else None


def check_held(name, out):
    m = max_disp(out)
    check(m is not None and m < 1e-9, f"{name}: no block moves beyond 1e-9 m", str(m))
    table = contacts(out)
    check(len(table) > 0, f"{name}: contacts printed")
    # a contact of length 0 prints no stresses (its forces: before, contact
    # 13 of case 2 held 2.9e5 N normal, 7.3e4 N shear)
    bad = [(k, c.get("sn"), c.get("ss")) for k, c in table.items()
           if "sn" not in c or abs(abs(c["sn"]) - 1e6) > 1e-6 * 1e6 or abs(c["ss"]) > 1.0]
    check(not bad, f"{name}: every contact carries the field (1e6 Pa to 1e-6, shear below 1 Pa)",
          str(bad[:6]))
    zero = [k for k, c in table.items() if c["length"] <= 0.0]
    check(not zero, f"{name}: no contact of length 0", str(zero))


# 1. the brief's deck under gravity
out = run_clean(udec, "repro", REPRO + GRAVITY)
pair = [c for c in contacts(out).values() if (c["b1"], c["b2"]) == (3, 4)]
check(len(pair) == 2, "repro: two contacts between blocks 3 and 4", str(pair))
for c in pair:
    check(abs(c["length"] - 0.15) < 1e-9 * 0.15, "repro: each has half the 0.3 m stretch", str(c))
    check(abs(c["angle"] - 90.0) < 1e-6, "repro: normal across the joint (90 degrees)", str(c))
    check(abs(c["gap"]) < 1e-4, "repro: gap closed (below 1e-4 m)", str(c))

# 2. held by INSITU
check_held("insitu", run_clean(udec, "insitu", REPRO + INSITU.format(n=2000)))

# 3. T-junctions, exact and near, from above and from below
T = """round 0.1
block 0,0 0,10 10,10 10,0
crack 0,5 10,5
crack 3,5 3,10
crack 6,5 6,10
crack 6.05,0 6.05,5
crack 8,0 8,5
prop mat=1 d=2000 jkn=1e10 jks=1e10 jfric=0.5774
"""
check_held("tee", run_clean(udec, "tee", T + INSITU.format(n=2000)))


# 4. random near-T and near-facing ends
def random_deck(seed):
    rng = random.Random(seed)
    lines = ["round 0.1", "block 0,0 0,10 10,10 10,0"]
    ys = sorted(rng.uniform(1.5, 8.5) for _ in range(2))
    ys[1] = max(ys[1], ys[0] + 1.0)
    for y in ys:
        lines.append(f"crack 0,{y:.4f} 10,{y:.4f}")
    bands = [(0.0, ys[0]), (ys[0], ys[1]), (ys[1], 10.0)]
    for lo, hi in bands:
        for _ in range(2):
            x = rng.uniform(1.0, 9.0)
            # a joint of the band above or below ends within 0 to 0.25 m
            lines.append(f"crack {x:.4f},{lo:.4f} {x + rng.uniform(-0.5, 0.5):.4f},{hi:.4f}")
    for lo, hi in bands[1:]:
        x = rng.uniform(1.0, 9.0)
        lines.append(f"crack {x + rng.uniform(-0.25, 0.25):.4f},{lo:.4f} {x:.4f},{lo - 0.9:.4f}")
    lines.append("prop mat=1 d=2000 jkn=1e10 jks=1e10 jfric=0.5774")
    lines.append("print corner")
    return "\n".join(lines) + "\n"


def polygons(out):
    rings = {}
    for f in header_rows(out, "  CORNER   BLOCK", 8):
        rings.setdefault(int(f[1]), []).append((float(f[2]), float(f[3])))
    return rings


def shared(pa, pb):
    """Length of joint shared by two clockwise polygons: overlaps of their
    edges that lie on one line, running opposite ways."""
    total = 0.0
    for i in range(len(pa)):
        (ax, ay), (bx, by) = pa[i], pa[(i + 1) % len(pa)]
        la = ((bx - ax) ** 2 + (by - ay) ** 2) ** 0.5
        if la == 0.0:
            continue
        ux, uy = (bx - ax) / la, (by - ay) / la
        for j in range(len(pb)):
            (cx, cy), (dx, dy) = pb[j], pb[(j + 1) % len(pb)]
            off = lambda px, py: abs((px - ax) * uy - (py - ay) * ux)
            if off(cx, cy) > 1e-4 or off(dx, dy) > 1e-4:
                continue
            s1 = (cx - ax) * ux + (cy - ay) * uy
            s2 = (dx - ax) * ux + (dy - ay) * uy
            if s2 >= s1:
                continue
            total += max(0.0, min(la, s1) - max(0.0, s2))
    return total


npairs = 0
for seed in range(1, 7):
    deck = random_deck(seed)
    out = run_clean(udec, f"random{seed}", deck + INSITU.format(n=10))
    rings = polygons(out)
    table = contacts(out)
    ids = sorted(rings)
    for a in range(len(ids)):
        for b in range(a + 1, len(ids)):
            s = shared(rings[ids[a]], rings[ids[b]])
            if s <= 1e-3:
                continue
            npairs += 1
            mine = [c for c in table.values() if (c["b1"], c["b2"]) == (ids[a], ids[b])]
            check(any(abs(c["gap"]) < 1e-6 for c in mine),
                  f"random {seed}: blocks {ids[a]} and {ids[b]} (sharing {s:.4f} m) touch with zero gap",
                  str(mine))
            check(all(c["length"] > 0.0 for c in mine),
                  f"random {seed}: blocks {ids[a]} and {ids[b]}: no contact of length 0", str(mine))
check(npairs > 60, f"random: enough shared stretches checked ({npairs})")
finish()
