"""Joints closing elastically past OVTOL run on; interpenetration stops (label stability).

UDEC manual (ICG1.5, 1989), Section 5.3 stops a run when a contact overlaps
by more than OVTOL, one-half the rounding length d. A joint under a normal
stress change s closes elastically by s / JKN, which passes OVTOL as soon as
JKN x OVTOL < s: a new user's tunnel (ROUND 0.005, JKN 5e9: 12.5 MPa, in an
18.3 MPa field) stopped at cycle 451 after its excavation, overlap 2.501e-3,
though nothing passes through anything. Each contact now has its own
tolerance from its rounded corners (contact_overlap_limit: half the sum of
the radii of the corners its normal depends on, at most 2 d and a quarter of
the shortest edge at the contact, never below OVTOL); SET OVTOL t makes t
the limit of every contact.

1. A 2 x 4 m column cut by three parallel joints at 30 degrees (corners of
   60 and 120 degrees where the joints meet the sides: radii d tan 30 and
   d tan 60; the joints' end contacts are corner-edge, whose normal is
   their edge's at any overlap: tolerance 0.9 d (tan 30 + tan 60) = 2.078e-2,
   capped at 2 d = 2e-2 at d = 0.01; until session 42 half the sum,
   1.1547e-2, for either kind)
   under a hydrostatic BOUNDARY STRESS p = 1 MPa, JKN = p / (1.4 OVTOL):
   SOLVE balances with one note naming a contact past OVTOL and its
   tolerance; statics (a uniform stress p on every joint): each contact's
   normal force is p x its half of the joint, 1 / cos 30 m, within 1 %
   (measured 1e-6), and its overlap the closure p / JKN = 1.4 OVTOL within
   1 % (measured 1e-3).
2. The same with SET OVTOL 0.005 (the default's value, given by the user):
   the user's limit holds, stops at 5.000E-03.
3. JKN = p / (5 OVTOL): the joints would close by 2.5 d, past their
   tolerance: stops at 2.000E-02 naming the contact, its position, its
   load and the bound (2 ROUND: the corner pressed past its rounding).
4. The new user's tunnel (the deck of the report): runs to SOLVE's balance,
   with one note and no error.
"""
import math
import re
import sys
from udec_test import check, finish, run, workdir, write

udec = sys.argv[1]
folder = workdir()
P, D = 1.0e6, 0.01
OVTOL = 0.5 * D
T30 = math.tan(math.radians(30.0))
# the joints' end contacts are corner-edge: 0.9 of the radii's sum, 2.078e-2, capped at 2 d
TOL = min(0.9 * D * (T30 + math.tan(math.radians(60.0))), 2.0 * D)
CRACKS = "\n".join(f"crack 0,{y} 2,{y + 2.0 * T30:.9f}" for y in (0.6, 1.5, 2.4))
COLUMN = """round 0.01
{ovtol}block 0,0 0,4 2,4 2,0
{cracks}
prop mat=1 d=2600 k=2e10 g=1.2e10
prop jmat=1 jkn={k:.8g} jks={k:.8g} jfric=0.6
bound stress -1e6 0 -1e6
damp auto
solve ratio 1e-6 cycles 20000
print contacts
stop
"""
NOTE = re.compile(r"CYCLE: note: contact \d+ between blocks \d+ and \d+ at \(.*?\) overlaps by (\S+), "
                  r"past OVTOL (\S+), under a normal (?:stress|force) .*? tolerance of its rounded "
                  r"corners, (\S+) ")
STOP = re.compile(r"Contact Overlap Too Great: contact \d+ between blocks \d+ and \d+ at \(.*?\), "
                  r"overlap\s+(\S+) >\s+(\S+);.*")


def contacts(out):
    """contact -> {gap, fn} from PRINT CONTACTS (its displacement and force tables)."""
    rows, mode = {}, None
    for line in out.splitlines():
        if "CONTACT" in line and "BLOCK1" in line:
            mode = "gap" if "GAP" in line else ("force" if "NORMAL-FORCE" in line else None)
            continue
        f = line.split()
        if mode and len(f) == 8 and f[0].isdigit():
            r = rows.setdefault(int(f[0]), {})
            if mode == "gap":
                r["gap"] = float(f[7])
            else:
                r["fn"] = float(f[4])
    return rows


# 1. joints past OVTOL within their tolerance: balance, statics, one note
k = P / (1.4 * OVTOL)
write(folder, "column.dat", COLUMN.format(ovtol="", cracks=CRACKS, k=k))
rc, out = run(udec, ["column.dat"], cwd=folder)
check(rc == 0 and "*** Error" not in out and "SOLVE: balanced" in out,
      "column: balances past OVTOL, no error", out[-2000:])
notes = NOTE.findall(out)
check(len(notes) == 1, "column: one note", out[-3000:])
if notes:
    ov, base, tol = (float(v) for v in notes[0])
    check(ov > OVTOL and base == OVTOL and abs(tol - TOL) <= 1e-6 * TOL,
          f"column: the note names the overlap {ov} past OVTOL and the tolerance {tol} = {TOL:.6g}",
          str(notes))
rows = contacts(out)
check(len(rows) == 6 and all("gap" in r and "fn" in r for r in rows.values()),
      "column: two contacts on each of the three joints", str(rows))
for c, r in rows.items():
    fn, gap = r.get("fn", 0.0), r.get("gap", 0.0)
    check(abs(fn - P / math.cos(math.radians(30.0))) <= 1e-2 * P,
          f"column: contact {c} normal force {fn:.7g} = p x 1 / cos 30", str(r))
    check(abs(-gap - P / k) <= 1e-2 * P / k and -gap > OVTOL,
          f"column: contact {c} overlap {-gap:.6g} = p / JKN = 1.4 OVTOL", str(r))

# 2. SET OVTOL: the user's limit for every contact
write(folder, "user.dat", COLUMN.format(ovtol="set ovtol 0.005\n", cracks=CRACKS, k=k))
rc, out = run(udec, ["user.dat"], cwd=folder)
m = STOP.search(out)
check(rc == 1 and m is not None and m.group(2) == "5.000E-03",
      "SET OVTOL 0.005: stops at the user's limit", out[-2000:])

# 3. joints too soft for the load: stop at the contact's own tolerance
write(folder, "soft.dat", COLUMN.format(ovtol="", cracks=CRACKS, k=P / (5.0 * OVTOL)))
rc, out = run(udec, ["soft.dat"], cwd=folder)
m = STOP.search(out)
check(rc == 1 and m is not None, "soft joints: stop", out[-2000:])
if m:
    check(m.group(2) == f"{TOL:.3E}" and float(m.group(1)) > TOL,
          f"soft joints: past the contact's tolerance {TOL:.4g}", m.group(0))
    # the stopping contact's load named: its normal stress, JKN times the overlap of the
    # step its force was computed in (the overlap less its last step's closure), within
    # 1 %. Until round 5 of the jointed tunnel fuzz (docs/robustness.md) the joint's
    # far end contact was not taken as its neighbour once the corner had pressed in by
    # more than the margin, its length fell to zero and the stop said "on a contact of
    # zero length"; the neighbour test is now the same from either contact's line
    ms = re.search(r"closed by (\S+) in the last step.*?normal stress (\S+)\)", m.group(0))
    kso = P / (5.0 * OVTOL)
    check(ms is not None and abs(float(ms.group(2)) - kso * (float(m.group(1)) - float(ms.group(1))))
          <= 1e-2 * float(ms.group(2)),
          "soft joints: the joint's end contact's load named: JKN x its overlap", m.group(0))
    check("its tolerance is 2 ROUND" in m.group(0), "soft joints: the bound named (2 ROUND)",
          m.group(0))

# 4. the new user's tunnel: ROUND 0.005, JKN 5e9 in an 18.3 MPa field
write(folder, "tunnel.dat", """round 0.005
block 0,0 0,20 20,20 20,0
jset 81.31,0 40,0 0,0 2.543,0 (10.894,9.671)
jset 131.79,0 40,0 0,0 2.439,0 (10.000,10.000)
tunnel 10.0,10.0 1.751 20
prop mat=1 d=2600 k=20e9 g=12e9
prop jmat=1 jkn=5e+09 jks=2e+09 jfric=0.524 jcoh=0
bound stress -1.832e+07 -1.234e+05 -7.004e+06
insitu stress -1.832e+07 -1.234e+05 -7.004e+06
damp auto
cycle 200
delete 8.2661,11.7339 8.2661,11.7339
solve cycles 40000
stop
""")
rc, out = run(udec, ["tunnel.dat"], cwd=folder)
check(rc == 0 and "*** Error" not in out and "SOLVE: balanced" in out,
      "tunnel: balances after the excavation", out[-2000:])
check(len(NOTE.findall(out)) == 1, "tunnel: one note of a contact past OVTOL", out[-3000:])
finish()
