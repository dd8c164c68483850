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
"""
import re
import sys
from udec_test import check, finish, run, workdir, write

udec = sys.argv[1]
DECK = """round 0.05
block 0,0 0,10 10,10 10,0
split 0,2 10,{y2:.6f}
prop mat=1 dens=2500
prop jmat=1 jkn=2e10 jks=1e10 {joint}
insitu stress -2e6 0 -10e6
bound stress -2e6 0 -10e6
damp auto
cycle 200
print max
stop
"""
Y2 = 2.0 + 10.0 * 0.5773502691896258   # tan 30
d = workdir()


def max_disp(out):
    m = re.search(r"max block displacement\s+(\S+)", out)
    return float(m.group(1)) if m else None


write(d, "weak.dat", DECK.format(y2=Y2, joint="jfric=0.3"))
rc, out = run(udec, ["weak.dat"], cwd=d)
m = re.search(r"Note: INSITU: (\d+) of (\d+) contact\(s\) carry more shear.*?(\S+) times its strength", out)
check(rc == 0 and m is not None, "1. weak joint: INSITU notes the contacts beyond their strength", out[-1500:])
if m:
    check(abs(float(m.group(3)) - 0.43301 / 0.3) < 1e-3,
          f"1. worst ratio {m.group(3)} = 0.43301 / 0.3 = 1.4434 (closed form)")
u = max_disp(out)
check(u is not None and u > 1e-6, f"1. the weak joint slips ({u} m > 1e-6 m)")

write(d, "firm.dat", DECK.format(y2=Y2, joint="jfric=0.5"))
rc, out = run(udec, ["firm.dat"], cwd=d)
u = max_disp(out)
check(rc == 0 and "carry more shear" not in out, "2. JFRIC 0.5 holds the field: no note", out[-1500:])
check(u is not None and u < 1e-10, f"2. the model stays still ({u} m < 1e-10 m)")

write(d, "coh.dat", DECK.format(y2=Y2, joint="jfric=0.3 jcoh=1.5e6"))
rc, out = run(udec, ["coh.dat"], cwd=d)
u = max_disp(out)
check(rc == 0 and "carry more shear" not in out, "3. cohesion 1.5 MPa holds the field: no note",
      out[-1500:])
check(u is not None and u < 1e-10, f"3. the model stays still ({u} m < 1e-10 m)")
finish()
