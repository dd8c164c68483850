"""An open contact carries no shear (label `stability`).

A contact whose surfaces are apart (normal force 0, gap above the closing
tolerance before and after the step) has nothing to transmit: UDEC manual
(ICG1.5, 1989), Section 3.3, the contact forces come from the relative
displacement of surfaces in touch, and a joint that opens in tension
carries no force. Before the fix, the increment of shear kept being added
to such a contact up to its strength, so a joint with cohesion (JCOH) held
a block across an open gap: a new user's open-pit deck kept a crest block
hanging on a 1 mm open joint, creeping at 5e-3 m/s instead of sliding.

Scene: a 1 x 2 m block beside a fixed one on a vertical joint with JCOH
1 MPa and no tensile strength (JCONS 2, which keeps cohesion after a
tensile failure), loaded by its weight only. Nothing presses the joint
shut, so the block turns off its lower corner and falls. Checks, for a
rigid and a zoned block (the rigid kernel and the general force pass):
  - after 1000 steps the block has fallen at least half the free-fall
    distance g t^2 / 2 (before: 6e-4 m of 0.071 m, hanging);
  - no contact printed with a gap above 1e-5 m carries a shear force
    (before: 6.0e4 N across a 0.19 mm gap).
"""
import re
import sys
from udec_test import check, finish, run, workdir, write

udec, source = sys.argv[1], sys.argv[2]
d = workdir()

DECK = """ROUND 0.01
BLOCK 0,0 0,2 2,2 2,0
CRACK 1,-1 1,3
{zones}
PROP MAT=1 D=2500 K=1e10 G=1e10
PROP JMAT=1 JKN=1e10 JKS=1e10 JFRIC=0.5 JCOH=1e6 JTEN=0
GRAV 0 -10
{hold}
HIST YDIS 1.5 1
CYCLE 1000
PRINT CONTACT
PRINT HIST 1
STOP
"""
SCENES = {
    "rigid": ("", "FIX 0 1 0 2"),
    "zoned": ("GEN EDGE 0.5", "BOUND -0.1 0.1 -1 3 XVEL 0 YVEL 0"),
}
for name, (zones, hold) in SCENES.items():
    write(d, name + ".dat", DECK.format(zones=zones, hold=hold))
    rc, out = run(udec, [name + ".dat"], cwd=d)
    check(rc == 0, name + ": the deck runs", out[-800:])
    rows = []
    for line in out.split("PRINT HIST 1", 1)[-1].splitlines():
        f = line.split()
        if len(f) == 2:
            try:
                rows.append((float(f[0]), float(f[1])))
            except ValueError:
                pass
    if not rows:
        check(False, name + ": a history was printed", out[-800:])
        continue
    t, ydis = rows[-1]
    fall = 0.5 * 10.0 * t * t
    check(ydis < -0.5 * fall,
          f"{name}: the block falls (YDIS {ydis:.3e} m at t {t:.3e} s; free fall {-fall:.3e} m)")
    # PRINT CONTACT's second table has GAP, its third SHEAR-FORCE, by contact
    gap, shear = {}, {}
    block = out.split("PRINT CONTACT", 1)[-1].split("PRINT HIST", 1)[0]
    table = None
    for line in block.splitlines():
        f = line.split()
        if f and f[0] == "CONTACT":
            table = "gap" if "GAP" in f else ("force" if "SHEAR-FORCE" in f else None)
            continue
        if table and len(f) >= 5 and re.fullmatch(r"\d+", f[0]):
            if table == "gap":
                gap[f[0]] = float(f[-1])
            else:
                shear[f[0]] = float(f[5])
    check(len(gap) > 0 and set(gap) == set(shear), name + ": PRINT CONTACT tables read", block[:800])
    held = [(c, gap[c], shear[c]) for c in gap if gap[c] > 1e-5 and shear.get(c, 0.0) != 0.0]
    check(not held, f"{name}: open contacts carry no shear force", str(held))
finish()
