""""Contact Overlap Too Great" names what the contact shows (label e2e).

A block of rock on a soft joint: 10 m x 1 m (2700 kg/m^3, g 9.81: a normal
stress of 2.6487e4 Pa on its base joint) resting on a fixed block, ROUND
0.1 (OVTOL 0.05 m, UDEC manual (ICG1.5, 1989), Section 5.3: half the
rounding; a contact whose rounded corners allow it may overlap by up to the
rounding length, here 0.1: two right-angled corners, contact_overlap_limit).
The joint takes at most JKN x its tolerance of normal stress. Before, the message listed the manual's three causes and the
user could not tell which; a soft joint failing at cycle 2 looked like an
unbounded time step. It is not: with JKN 1e5 Pa/m the joint's equilibrium
closure is 2.6487e4 / 1e5 = 0.265 m, five times OVTOL, and no time step
reaches it. Now the message names how much the contact closed in the last
step, its normal stress and JKN x its tolerance (the stress change the joint
takes within it), so the load can be compared with it.

1. JKN 1e5: fails (cycle 1 or 2); JKN x its tolerance (0.1) = 1.000E+04
   is named (below the weight's 2.65e4: the joint is too soft for the load).
2. JKN 3e5 (3.0e4 within tolerance, the static load 2.65e4 below it: the
   dynamic overshoot of gravity switched on under DAMP AUTO crosses it):
   fails, "steadily" (closing by less than a tenth of OVTOL a step),
   3.000E+04 named, with the remedies (JKN, ROUND, SET OVTOL).
3. JKN 1e6 (1e5): balanced, no error.
4. Two blocks that meet corner to corner (a contact of zero length) pushed
   together: the message names the contact's normal force, not a normal
   stress of 0 (found on a new user's jointed tunnel: a zero-length contact
   at a joint's end carrying 3.0e7 N was reported at "normal stress 0").
5. Before the first cycle, a joint whose JKN x ROUND (the tolerance of a
   contact between right-angled corners unless SET OVTOL gives one) is below twice the largest
   stress of the model (an opening's hoop stress reaches 3 s1 - s3) gets a
   note naming it and the remedies: a new user's tunnel with ROUND 0.005 and
   JKN 5e9 (25 MPa) under an 18.3 MPa field. The note comes from INSITU's
   contact stresses and from BOUNDARY STRESS alone; with ROUND 0.05
   (250 MPa) there is none.
   Under GRAVITY the weight's stress at the model's foot (rho g H) counts
   too, so cases 1-3 get the note before the error (the checks read the
   error line itself).
6. Two wedges of 17.1 degrees pressed tip to tip: the message names the
   acute tip (block, place, angle) and the remedy, a larger ROUND (manual
   Section 5.3) or a joint moved; right-angled corners (case 4) are none.
"""
import re
import sys
from udec_test import check, finish, run, workdir, write

udec = sys.argv[1]
folder = workdir()
DECK = """round 0.1
block 0,0 0,2 10,2 10,0
crack 0,1 10,1
prop mat=1 d=2700
prop jmat=1 jkn={k} jks={k} jfric=0.6
grav 0 -9.81
fix 4 6 0 1
damp auto
cycle 1000
print max
stop
"""


def overlap_error(out):
    """The error line of Contact Overlap Too Great (not the notes that name it)."""
    return re.search(r"\*\*\* Error: Contact Overlap Too Great.*", out)


def go(name, k):
    write(folder, name + ".dat", DECK.format(k=k))
    return run(udec, [name + ".dat"], cwd=folder)


rc, out = go("soft", "1e5")
m = overlap_error(out)
check(rc == 1 and m is not None, "soft: fails", out[-1500:])
if m:
    check(re.search(r"overlap\s+\S+ >\s+1\.000E-01;", m.group(0)) is not None
          and "JKN x its tolerance (from its rounded corners, at most 2 ROUND) = 1.000E+04" in m.group(0),
          "soft: its tolerance, the rounding length, and JKN x it named", m.group(0))
    check("in the last step" in m.group(0) and "normal stress" in m.group(0),
          "soft: closure and normal stress named", m.group(0))

rc, out = go("overshoot", "3e5")
m = overlap_error(out)
check(rc == 1 and m is not None, "overshoot: fails", out[-1500:])
if m:
    check("steadily" in m.group(0) and "= 3.000E+04" in m.group(0)
          and "SET OVTOL" in m.group(0), "overshoot: steady closing and remedies named", m.group(0))

rc, out = go("stiff", "1e6")
check(rc == 0 and "*** Error" not in out, "stiff: runs", out[-1500:])

write(folder, "corner.dat", """round 0.05
block 0,0 0,2 2,2 2,0
crack 0,1 2,1
crack 1,0 1,2
delete 0,1 1,2
delete 1,2 0,1
prop mat=1 d=2000 jkn=1e6 jks=1e6 jfric=0.5
fix 0,1 0,1
load 1,2 1,2 -1e6 -1e6
damp auto
cycle 2000
stop
""")
rc, out = run(udec, ["corner.dat"], cwd=folder)
m = overlap_error(out)
check(rc == 1 and m is not None, "corner to corner: fails", out[-1500:])
if m:
    f = re.search(r"normal force (\S+) on a contact of zero length", m.group(0))
    check(f is not None and float(f.group(1)) > 0.0 and "normal stress 0" not in m.group(0),
          "corner to corner: the force of the zero-length contact named", m.group(0))
    check("acute tip" not in m.group(0), "corner to corner: right-angled corners are no acute tip",
          m.group(0))

# 6. Two wedges pressed tip to tip (physics campaign seeds 3 and 12): the tips
# of 2 atan(0.3 / 2) = 17.06 degrees meet at (0, 0); the message names the
# tip, its angle and the remedy of the manual's Section 5.3 (a larger ROUND
# for blocks with very acute angles).
write(folder, "wedges.dat", """round 0.05
block -2,-1 -2,1 2,1 2,-1
crack -2,0.3 2,-0.3
crack -2,-0.3 2,0.3
delete -1,1 0.2,1
delete -1,1 -1,-0.2
prop mat=1 d=2000 jkn=1e5 jks=1e5 jfric=0.5
fix -2,-1 -0.2,0.2
load 1,2 -0.2,0.2 -2e4 0
damp auto
cycle 2000
stop
""")
rc, out = run(udec, ["wedges.dat"], cwd=folder)
m = overlap_error(out)
check(rc == 1 and m is not None, "wedges tip to tip: fail", out[-1500:])
if m:
    t = re.search(r"corner at \((\S+), (\S+)\) is an acute tip of (\S+) degrees", m.group(0))
    # the tip named where it is when the run stops: the right wedge, pushed
    # by 2e4 N against JKN 1e5, has slid some 0.14 m on along the x axis
    check(t is not None and abs(float(t.group(1))) < 0.3 and abs(float(t.group(2))) < 0.05
          and abs(float(t.group(3)) - 17.1) <= 0.05 and "a larger ROUND" in m.group(0),
          "wedges tip to tip: the acute tip, its angle and the remedy named", m.group(0))

FIELD = """round {round}
block 0,0 0,20 20,20 20,0
jset 81.31,0 40,0 0,0 2.543,0 (10.894,9.671)
jset 131.79,0 40,0 0,0 2.439,0 (10.000,10.000)
prop mat=1 d=2600 k=20e9 g=12e9
prop jmat=1 jkn=5e+09 jks=2e+09 jfric=0.524 jcoh=0
bound stress -1.832e+07 -1.234e+05 -7.004e+06
{insitu}
damp auto
cycle 1
stop
"""
HEADROOM = re.compile(r"CYCLE: note: the joints of material 1 take a normal stress change of "
                      r"JKN x ROUND = 2\.500E\+07 \(ROUND 5\.000E-03\) before Contact Overlap "
                      r"Too Great stops the run .* \(1\.832E\+07\)")
for insitu in ("insitu stress -1.832e+07 -1.234e+05 -7.004e+06", ""):
    write(folder, "field.dat", FIELD.format(round=0.005, insitu=insitu))
    rc, out = run(udec, ["field.dat"], cwd=folder)
    check(rc == 0 and HEADROOM.search(out) is not None,
          "JKN x OVTOL below twice the field is noted " + ("(INSITU)" if insitu else "(BOUNDARY)"), out)
write(folder, "field.dat", FIELD.format(round=0.05, insitu="insitu stress -1.832e+07 -1.234e+05 -7.004e+06"))
rc, out = run(udec, ["field.dat"], cwd=folder)
check(rc == 0 and "take a normal stress change" not in out, "ROUND 0.05: room enough, no note", out)

finish()
