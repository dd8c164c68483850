"""Near-T junctions start at rest (label `stability`).

A joint ending on another joint (a T-junction) with a gridpoint of the
block across the joint lying within the rounding length of the T: the
upper blocks' corners at the T are rounded (ROUND 0.05), the lower block's
gridpoint is a corner without rounding. Before the fix that gridpoint's
corner-edge contact walked onto the rounded corner (corner-corner, then
the rounded corner against the gridpoint's edge), became a twin of the
rounded corner's own contact and was dropped at the first scan with the
force INSITU had given it for its half-spacing of joint; and a contact
whose corner's vertex lay across a gridpoint from its edge put its whole
force on that gridpoint with a couple for the offset. Found on a new
user's model (finite joint set, GEN EDGE 2): 8e6 N out of balance, 0.38
mm in 1000 cycles with no excavation.

Decks: a 10 x 10 m block, a joint at 2.3 degrees, a joint from the top
ending on it at x_T; GEN EDGE 1.0 puts the lower block's gridpoints every
0.4545 m, one at x = 4.0909. x_T = 4.0709, 4.0859, 4.1109, 4.1209: the
gridpoint 2, 0.5, -2, -3 cm from the T (either side).
  1. uniform INSITU and the same BOUNDARY STRESS, elastic zones: the
     exact answer is the initial state, so after 1000 cycles no gridpoint
     has moved beyond round-off: 1e-12 m (forces ~1e7 N summed to ~1e-15
     relative give F dt^2 / m ~ 1e-18 m a step; measured 4e-14 to 1.3e-13;
     before the fix 2e-6 to 2e-4 m).
  2. gravity with INSITU YGRAD balancing it and the same BOUNDARY STRESS:
     constant-stress zones under a gradient leave a residual at the model
     corners (the same deck with the T 0.23 m from any gridpoint moves
     8.7e-7 m, at other T positions up to 1.2e-6 m; tests/scripts/
     joint_ends.py case 2), so the bound is 2e-6 m (measured 8.9e-7 and
     1.2e-6; before the fix 1.9e-4 and 8.2e-6 m).
  3. rigid blocks (no GEN), uniform INSITU: no block moves beyond 1e-12 m
     (no gridpoints, so no near-T; a guard that the contact changes leave
     rigid blocks alone; passes before the fix as well).
  4. the user's model (finite joint set, gravity, INSITU YGRAD, BOUNDARY
     STRESS YGRAD): below 1e-6 m after 1000 cycles. Reference: the same
     deck with both sets continuous moves 2.6e-7 m (corner residual of
     case 2); measured 2.7e-7 m, 3.8e-4 m before the fix.
"""
import re
import sys
from udec_test import check, finish, run, workdir, write

udec, source = sys.argv[1], sys.argv[2]

DECK = """round 0.05
block 0,0 0,10 10,10 10,0
split 0,5 10,5.4
crack {x},10 {x},4.5
jdelete
{gen}
prop mat=1 dens=2700 k=2e10 g=1.2e10
prop jmat=1 jkn=1e10 jks=5e9 jfric=0.9
{load}
damp auto
cycle 1000
print max
stop
"""
UNIFORM = """insitu stress -9e6 1e6 -1.1e7
bound stress -9e6 1e6 -1.1e7"""
GRAVITY = """grav 0 -9.81
insitu stress -9.26487e6 0 -1.12649e7 ygrad 2.08467e4 0 2.6487e4
bound stress -9.26487e6 0 -1.12649e7 ygrad 2.08467e4 0 2.6487e4"""

USER = """HEAD near-T junctions of a finite joint set
ROUND 0.05
BLOCK 0,0 0,30 40,30 40,0
JSET -6.68,0 200,0 0,0 2.40,0 (31.25,19.24)
JSET 87.92,4.0 9.37217,0.239282 2.22552,0.998953 2.45,0.15 (20.47,7.47)
GEN EDGE 2.00
PROP MAT=1 D=2700 K=2e10 G=1.2e10
PROP JMAT=1 JKN=1e+10 JKS=5e+09 JFRIC=0.9
GRAVITY 0 -9.81
INSITU STRESS -9.08877e+06 0 -1.15476e+07 YGRAD 20847 0 26487
BOUND STRESS -9.08877e+06 0 -1.15476e+07 YGRAD 20847 0 26487
DAMP AUTO
CYCLE 1000
PRINT MAX
STOP
"""


def max_value(out, name):
    vals = [float(l.split()[-3]) for l in out.splitlines() if l.strip().startswith(name)]
    return vals[-1] if vals else None


def run_deck(d, name, text):
    write(d, name + ".dat", text)
    rc, out = run(udec, [name + ".dat"], cwd=d, timeout=300)
    check(rc == 0 and "Error" not in out, f"{name}: runs without error", out[-1500:])
    check("NaN" not in out and "Infinity" not in out, f"{name}: every printed number finite")
    return out


d = workdir()
for x in ("4.0709", "4.0859", "4.1109", "4.1209"):
    out = run_deck(d, f"uniform_{x}", DECK.format(x=x, gen="gen edge 1.0", load=UNIFORM))
    m = max_value(out, "max gridpoint displacement")
    check(m is not None and m < 1e-12, f"uniform, T at x = {x}: no gridpoint moves (1e-12 m)", str(m))
for x in ("4.0709", "4.1109"):
    out = run_deck(d, f"gravity_{x}", DECK.format(x=x, gen="gen edge 1.0", load=GRAVITY))
    m = max_value(out, "max gridpoint displacement")
    check(m is not None and m < 2e-6, f"gravity, T at x = {x}: gridpoints within 2e-6 m", str(m))
out = run_deck(d, "rigid", DECK.format(x="4.0709", gen="", load=UNIFORM))
m = max_value(out, "max block displacement")
check(m is not None and m < 1e-12, "rigid, uniform: no block moves (1e-12 m)", str(m))
out = run_deck(d, "user", USER)
m = max_value(out, "max gridpoint displacement")
check(m is not None and m < 1e-6, "user's finite joint set: gridpoints within 1e-6 m", str(m))
finish()
