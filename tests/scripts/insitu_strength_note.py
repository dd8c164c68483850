"""INSITU says when the joints cannot hold the field it sets (label e2e).

A new user's first model (a square cut by joints, INSITU and the same
BOUNDARY STRESS) must stay still before excavation, unless the joints are
too weak for the field: then they slip at the first cycle, which is
physics (UDEC manual (ICG1.5, 1989), Section 3.3: the shear force is
limited to c L + Fn tan(phi)), but the user saw the model move with no
word why (random new-user tunnel decks: weak joints and a TUNNEL ring,
whose chords run at every angle). INSITU now counts the contacts whose
shear exceeds that limit and names the worst.

Scene: a 10 m square split along a joint at 30 degrees, sxx = -2 MPa,
syy = -10 MPa. Closed form on the joint (normal n = (-sin 30, cos 30)):
sigma_n = 8 MPa, |tau| = 3.4641 MPa, |tau| / sigma_n = 0.43301.
1. JFRIC 0.3, no cohesion: the note appears, the worst contact at
   0.43301 / 0.3 = 1.4434 times its strength (to the printed 4 digits;
   every contact of the straight joint sees the same traction), and the
   upper block slides (displacement above 1e-6 m after 200 cycles).
2. JFRIC 0.5: no note, and the model stays still (below 1e-10 m).
3. JFRIC 0.3 with JCOH 1.5 MPa (strength 0.3 x 8 + 1.5 = 3.9 MPa above
   3.46): no note.
4. Case 1 ten times larger and ten times more stressed (100 m, -20 / -100
   MPa): the same ratio 1.4434, whose contacts' strengths (about 1e9 N)
   overflowed a guard (strength x 1e300) in the Debug build (SIGFPE).
5. The field of case 2 with its signs turned (a new user's tension,
   stresses positive in tension, manual Section 4.1): every contact of the
   joint is pulled apart beyond JTEN 0 and INSITU says so, and BOUNDARY
   STRESS names the tensile principal stress; case 2 as given (compression)
   gets neither note.
"""
import re
import sys
from udec_test import check, finish, run, workdir, write

udec = sys.argv[1]
DECK = """round 0.05
block 0,0 0,{L:g} {L:g},{L:g} {L:g},0
split 0,{y1:g} {L:g},{y2:.6f}
prop mat=1 dens=2500
prop jmat=1 jkn=2e10 jks=1e10 {joint}
insitu stress {sxx:g} 0 {syy:g}
bound stress {sxx:g} 0 {syy:g}
damp auto
cycle 200
print max
stop
"""
Y2 = 2.0 + 10.0 * 0.5773502691896258   # tan 30
d = workdir()


def deck(joint, scale=1.0):
    """The scene of cases 1-3 (scale 1), or `scale` times larger with
    stresses `scale` times higher."""
    return DECK.format(L=10.0 * scale, y1=2.0 * scale, y2=Y2 * scale, joint=joint,
                       sxx=-2e6 * scale, syy=-1e7 * scale)


def max_disp(out):
    m = re.search(r"max block displacement\s+(\S+)", out)
    return float(m.group(1)) if m else None


write(d, "weak.dat", deck("jfric=0.3"))
rc, out = run(udec, ["weak.dat"], cwd=d)
m = re.search(r"Note: INSITU: (\d+) of (\d+) contact\(s\) carry more shear.*?(\S+) times its strength", out)
check(rc == 0 and m is not None, "1. weak joint: INSITU notes the contacts beyond their strength", out[-1500:])
if m:
    check(abs(float(m.group(3)) - 0.43301 / 0.3) < 1e-3,
          f"1. worst ratio {m.group(3)} = 0.43301 / 0.3 = 1.4434 (closed form)")
u = max_disp(out)
check(u is not None and u > 1e-6, f"1. the weak joint slips ({u} m > 1e-6 m)")

write(d, "firm.dat", deck("jfric=0.5"))
rc, out = run(udec, ["firm.dat"], cwd=d)
u = max_disp(out)
check(rc == 0 and "carry more shear" not in out, "2. JFRIC 0.5 holds the field: no note", out[-1500:])
check(u is not None and u < 1e-10, f"2. the model stays still ({u} m < 1e-10 m)")

write(d, "coh.dat", deck("jfric=0.3 jcoh=1.5e6"))
rc, out = run(udec, ["coh.dat"], cwd=d)
u = max_disp(out)
check(rc == 0 and "carry more shear" not in out, "3. cohesion 1.5 MPa holds the field: no note",
      out[-1500:])
check(u is not None and u < 1e-10, f"3. the model stays still ({u} m < 1e-10 m)")

BIG = deck("jfric=0.3", scale=10.0)
write(d, "big.dat", BIG)
rc, out = run(udec, ["big.dat"], cwd=d)
m = re.search(r"INSITU: (\d+) of (\d+) contact\(s\) carry more shear.*?, ([0-9.E+-]+) times its strength",
              out)
check(rc == 0 and m is not None, "4. a large model: INSITU notes the contacts beyond their strength",
      out[-1500:])
if m:
    check(abs(float(m.group(3)) - 0.43301 / 0.3) < 1e-3,
          f"4. the worst ratio {m.group(3)} is tau / (sigma_n tan phi) = 1.4434")

write(d, "tens.dat", DECK.format(L=10.0, y1=2.0, y2=Y2, joint="jfric=0.5", sxx=2e6, syy=1e7))
rc, out = run(udec, ["tens.dat"], cwd=d)
m = re.search(r"Note: INSITU: (\d+) of (\d+) contact\(s\) are pulled apart beyond their joint's tensile "
              r"strength and open at the first cycle: stresses are positive in tension", out)
check(m is not None and m.group(1) == m.group(2), "5. a tensile field: every contact of the joint "
      "is pulled apart, and INSITU says so", out[-2000:])
check("note: BOUNDARY STRESS: the stress pulls on the boundary (largest principal stress 1E+07 tensile"
      in out, "5. BOUNDARY STRESS 2e6 0 1e7: the boundary note names the tensile principal stress",
      out[-2000:])
# a positive STRESS added to a compressive one unloads it (an increment, manual
# Section 4.5, BOUNDARY, Note): no tension note
write(d, "unload.dat", "block 0 0 0 10 10 10 10 0\nbound stress -5e6 0 -5e6\n"
      "bound stress 1e6 0 1e6\nstop\n")
rc, out = run(udec, ["unload.dat"], cwd=d)
check(rc == 0 and "adds to the boundary stress" in out and "pulls on the boundary" not in out,
      "5. an unloading increment: the stacked note, no tension note", out[-1500:])
# 6. the rigid-block note: a model of rigid blocks only (as the user made
# it) gets none; rigid blocks beside zoned ones get it (GENERATE is refused
# once INSITU has loaded the joints, so they stay rigid)
check("are rigid (not zoned)" not in out, "6. rigid blocks only: no rigid-block note", out[-1500:])
write(d, "mixed.dat", "block 0 0 0 10 10 10 10 0\ncrack 0 5 10 5\ngen 0 10 0 5 edge 2\n"
      "insitu stress -1e6 0 -1e6\nstop\n")
rc, out = run(udec, ["mixed.dat"], cwd=d)
check(rc == 0 and "Note: 1 block(s) in the range are rigid (not zoned) beside zoned ones" in out,
      "6. a rigid block beside a zoned one: the note", out[-1500:])
write(d, "firm2.dat", deck("jfric=0.5"))
rc, out = run(udec, ["firm2.dat"], cwd=d)
check("pulled apart" not in out and "pulls on the boundary" not in out,
      "5. the compressive field: no tension note", out[-1500:])
finish()
