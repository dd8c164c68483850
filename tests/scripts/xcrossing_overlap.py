"""Contact overlap at a joint crossing (label stability).

Two joints crossing at 30 degrees in a 10 m square (y - 5 = +-tan 15 deg
(x - 5), ROUND d = 0.01, OVTOL = d / 2 = 5e-3: UDEC manual (ICG1.5, 1989),
Section 5.3): the blunt blocks (150 degrees) above and below meet only at
their rounded corners, a corner-corner contact of length 0 between the two
wedges' tips. Under a hydrostatic BOUNDARY STRESS p = 1e6 every joint closes
by delta = p / JKN and the blunt corners approach by 2 delta cos 15 deg
along their common bisector (manual Section 3.3, Fig. 3-3d: the normal of a
corner-corner contact is the line of the circle centres), less 2 s sin 15
deg where the wedges slid by s towards the crossing; their circles start
g0 = 2 d (1 - sin 75) / cos 75 = 2.632e-3 apart. With delta = 0.9 OVTOL
the corners overlap by about 1.2 OVTOL while no joint reaches OVTOL: the
elastic closure of the joints, not blocks passing through each other. Until
2026-11-27 the run stopped there (Contact Overlap Too Great at cycle 15);
the new user's tunnel deck of campaign round 4, seed 13, stopped the same
way on two blunt corners pressed tip to tip. Each contact now has its own
tolerance from its rounded corners (contact_overlap_limit: half the sum of
the radii of the corners its normal depends on, at most 2 d, never below
OVTOL). Here the joint contacts at the crossing (a 30 degree tip, radius
d tan 15, against the 150 degree block's edge, radius d tan 75 at its end)
get d (tan 15 + tan 75) / 2 = 2 d, those at the box's sides (corners of 75
and 105 degrees) d (tan 37.5 + tan 52.5) / 2 = 1.035 d, the diagonal
min(d tan 75, 2 d) = 2 d.

1. JKN = p / (0.9 OVTOL): SOLVE balances; every joint contact carries
   sigma_n = p (uniform stress: each joint's normal force = p x its length)
   within 1e-3 (the contacts' lengths and normals move with the blocks by
   the closure's order, delta / L = 5e-4; measured 2e-4); the diagonal's
   overlap is past OVTOL and equals 2 delta cos 15 - 2 s sin 15 - g0
   (delta, s read from the joints' contacts) within 1e-4 relative (the
   blocks' small turns; measured 2e-6).
2. JKN = p / (1.2 OVTOL): the joints themselves close past OVTOL, within
   their tolerance: balances as in 1 (sigma_n = p within 1e-3), with one
   note naming a contact past OVTOL and its tolerance. Until this session
   it stopped on a joint contact at OVTOL.
3. JKN = p / (3 OVTOL): the joints would close by 1.5 d, and the blunt
   corners approach by 2 x 1.5 d cos 15 - g0 = 2.6 d: stops on the blunt
   blocks' corner-corner contact at (5, 5) (blocks 1 and 3) at its 2 d
   (2.000E-02). Until session 42 the joint contacts at the box's sides
   stopped first at 1.035 d; they are corner-edge contacts, whose normal is
   their edge's at any overlap, and now take 0.9 of their radii's sum
   (contact_overlap_limit: 1.863 d here), so the joints' own closure of
   1.5 d holds and the stop is where the geometry is lost.
4. The wedges deleted, the lower blunt block fixed and 1e7 N pushed down on
   the upper one (CLEMIN 0.1: the tips' spring takes 2.2e7 N/m, the load
   needs 0.45 m of overlap): the tips really pass into each other; stops at
   2 d (2.000E-02), naming the contact between blocks 1 and 3 at (5, 5).
   The model's OVTOL, d / 2, is the manual's default (Section 5.3).
"""
import math
import re
import sys
from udec_test import check, finish, run, workdir, write

udec = sys.argv[1]
folder = workdir()
P, D = 1.0e6, 0.01
OVTOL = 0.5 * D
T15 = math.radians(15.0)
SIDE = D * (math.tan(math.radians(37.5)) + math.tan(math.radians(52.5))) / 2.0
G0 = 2.0 * D * (1.0 - math.sin(math.radians(75.0))) / math.cos(math.radians(75.0))
HEAD = """round 0.01
block 0,0 0,10 10,10 10,0
crack 0,3.660254038 10,6.339745962
crack 0,6.339745962 10,3.660254038
"""
LOADED = HEAD + """prop mat=1 d=2600 k=2e10 g=1.2e10
prop jmat=1 jkn={k:.8g} jks={k:.8g} jfric=0.6
set clemin 1e-4
bound stress -1e6 0 -1e6
damp auto
solve ratio 1e-6 cycles 20000
print contacts
stop
"""
NUM = r"\s+(-?[0-9.]+E[+-][0-9]+)"


def contacts(out):
    """id -> dict of the PRINT CONTACTS tables (blocks, length, disps, gap, fn)."""
    rows = {}
    for m in re.finditer(r"(?m)^\s+(\d+)\s+(\d+)\s+(\d+)\s+(\d)\s+\d+\s+\d+" + NUM, out):
        rows[int(m.group(1))] = {"b": (int(m.group(2)), int(m.group(3))), "kind": int(m.group(4)),
                                 "len": float(m.group(5))}
    for m in re.finditer(r"(?m)^\s+(\d+)\s+\d+\s+\d+" + NUM * 5 + r"\s*$", out):
        c = int(m.group(1))
        if c in rows and "gap" not in rows[c]:
            rows[c].update(us=float(m.group(4)), un=float(m.group(5)), gap=float(m.group(6)))
        elif c in rows:
            rows[c].update(fn=float(m.group(3)))
    for m in re.finditer(r"(?m)^\s+(\d+)\s+\d+\s+\d+" + NUM * 3 + r"\s*$", out):
        c = int(m.group(1))
        if c in rows:
            rows[c].update(fn=float(m.group(3)))
    return rows


# 1. joints within OVTOL, the diagonal past it: runs to balance
write(folder, "elastic.dat", LOADED.format(k=P / (0.9 * OVTOL)))
rc, out = run(udec, ["elastic.dat"], cwd=folder)
check(rc == 0 and "*** Error" not in out and re.search(r"SOLVE: balanced", out) is not None,
      "elastic closure: balances, no error", out[-2000:])
rows = contacts(out)
joints = {c: r for c, r in rows.items() if r["len"] > 0.0}
diag = [c for c, r in rows.items() if r["len"] == 0.0 and r["b"] == (1, 3)]
check(len(joints) == 8, "elastic closure: two contacts on each of the four joint stretches",
      str(rows))
for c, r in joints.items():
    check(abs(r.get("fn", 0.0) / r["len"] - P) <= 1e-3 * P,
          f"elastic closure: contact {c} normal stress {r.get('fn', 0.0) / r['len']:.6g} = p",
          str(r))
check(len(diag) == 1, "elastic closure: the blunt corners' contact (blocks 1 and 3)", str(rows))
if diag and joints:
    d = rows[diag[0]]
    delta = max(-r["un"] for r in joints.values())
    s = max(abs(r["us"]) for r in joints.values())
    expect = 2.0 * delta * math.cos(T15) - 2.0 * s * math.sin(T15) - G0
    check(-d["gap"] > OVTOL, f"elastic closure: diagonal overlap {-d['gap']:.4g} past OVTOL", str(d))
    check(delta < OVTOL, f"elastic closure: joint closure {delta:.4g} within OVTOL")
    check(abs(-d["gap"] - expect) <= 1e-4 * expect,
          f"elastic closure: diagonal overlap {-d['gap']:.6g} = closed form {expect:.6g}", str(d))

# 2. the joints past OVTOL, within their own tolerance d: runs on, noted once
write(folder, "past.dat", LOADED.format(k=P / (1.2 * OVTOL)))
rc, out = run(udec, ["past.dat"], cwd=folder)
check(rc == 0 and "*** Error" not in out and re.search(r"SOLVE: balanced", out) is not None,
      "joints past OVTOL: balances, no error", out[-2000:])
# the first contact past OVTOL: the diagonal (tolerance 2 d) or a joint's (d)
notes = re.findall(r"CYCLE: note: contact \d+ between blocks (\d+) and (\d+) at .*? overlaps by "
                   r"(\S+), past OVTOL 0\.005, under a normal (stress|force) .*? tolerance of its "
                   r"rounded corners, (\S+) ", out)
check(len(notes) == 1, "joints past OVTOL: one note", out[-3000:])
if notes:
    b1, b2, ov, kind, tol = notes[0]
    check(float(ov) > OVTOL and (abs(float(tol) - 2.0 * D) < 1e-9 or abs(float(tol) - SIDE) < 1e-6),
          "joints past OVTOL: the note's overlap past OVTOL, its tolerance", str(notes))
rows = contacts(out)
joints = {c: r for c, r in rows.items() if r["len"] > 0.0}
check(len(joints) == 8, "joints past OVTOL: eight joint contacts", str(rows))
for c, r in joints.items():
    check(abs(r.get("fn", 0.0) / r["len"] - P) <= 1e-3 * P,
          f"joints past OVTOL: contact {c} normal stress {r.get('fn', 0.0) / r['len']:.6g} = p", str(r))
check(max((-r["gap"] for r in joints.values()), default=0.0) > OVTOL,
      "joints past OVTOL: a joint contact overlaps past OVTOL", str(joints))

# 3. the joints past their tolerance: the blunt corners' contact stops at 2 d
write(folder, "soft.dat", LOADED.format(k=P / (3.0 * OVTOL)))
rc, out = run(udec, ["soft.dat"], cwd=folder)
m = re.search(r"Contact Overlap Too Great: contact \d+ between blocks 1 and 3 at "
              r"\(\s*5\.00000E\+00,\s*(\S+)\), overlap\s+(\S+) >\s+2\.000E-02;.*", out)
check(rc == 1 and m is not None, "soft joints: stop on the blunt corners' contact at (5, 5) at 2 d",
      out[-2000:])
if m:
    check(abs(float(m.group(1)) - 5.0) < 0.05, "soft joints: at (5, 5)", m.group(0))
    check("its tolerance is 2 ROUND" in m.group(0), "soft joints: the bound named (2 ROUND)",
          m.group(0))

# 4. the blunt tips pushed through each other: stops at 2 d
write(folder, "tips.dat", HEAD + """delete 1,2.5 4,6
delete 7.5,9 4,6
prop mat=1 d=2600 k=2e10 g=1.2e10
prop jmat=1 jkn=2.2222222e8 jks=2.2222222e8 jfric=0.6
set clemin 0.1
fix 0,10 0,4
load 0,10 6,10 0 -1e7
damp auto
cycle 2000
stop
""")
rc, out = run(udec, ["tips.dat"], cwd=folder)
m = re.search(r"Contact Overlap Too Great: contact \d+ between blocks 1 and 3 at "
              r"\(\s*5\.00000E\+00,\s*(\S+)\), overlap\s+(\S+) >\s+(\S+);.*", out)
check(rc == 1 and m is not None, "tips: stop on the blunt corners' contact at (5, 5)", out[-2000:])
if m:
    check(abs(float(m.group(1)) - 5.0) < 0.05, "tips: at (5, 5)", m.group(0))
    check(float(m.group(3)) == 2.0 * D and float(m.group(2)) > 2.0 * D,
          "tips: past 2 d", m.group(0))
    check("on a contact of zero length" in m.group(0), "tips: the zero-length contact's force named",
          m.group(0))
finish()
