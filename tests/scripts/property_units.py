"""Friction and dilation are coefficients (label e2e; manual Section 4.5
PROPERTY: JFRIC "joint friction coefficient [tangent of friction angle]",
likewise JDIL, CFRICTION, CDILATION, FRICTION and DILATION; JIF in radians).

A new user read "degrees" in HELP PROPERTY and docs/commands.md, wrote
JFRIC=30 and got a joint that held at 88 degrees. Checked: HELP PROPERTY
gives the unit tan(angle) for JFRIC and FRICTION and radians for JIF;
PROPERTY notes a value from 5 to 60 (an angle, probably) with its meaning and
the coefficient of that many degrees, and says nothing for 0.6 or 100 (the
manual's decks glue joints with 100; their 10 gets the note, harmlessly).
"""
import sys
from udec_test import check, finish, run, workdir, write

udec = sys.argv[1]
d = workdir()
write(d, "p.dat", "help property\nprop jmat=1 jkn=1e9 jfric=30\nprop jmat=2 jfric=0.6\n"
      "prop jmat=3 jfric=100\nprop mat=1 fric=35\nstop\n")
rc, out = run(udec, ["p.dat"], cwd=d)
check(rc == 0, "the deck runs", out[-1500:])
lines = out.splitlines()
jf = [l for l in lines if l.strip().startswith("JFRIC")]
check(jf and "tan(angle)" in jf[0], "HELP PROPERTY: JFRIC in tan(angle)", "\n".join(jf))
fr = [l for l in lines if l.strip().startswith("FRICTION")]
check(fr and "tan(angle)" in fr[0], "HELP PROPERTY: FRICTION in tan(angle)", "\n".join(fr))
ji = [l for l in lines if l.strip().startswith("JIF")]
check(ji and "radians" in ji[0], "HELP PROPERTY: JIF in radians", "\n".join(ji))
notes = [l for l in lines if l.startswith("note: PROPERTY")]
check(len(notes) == 2, "two notes: JFRIC=30 and FRIC=35 (not 0.6, not 100)", "\n".join(notes))
check(any("JFRIC" in n and "88.1 degrees" in n and "0.5774" in n for n in notes),
      "JFRIC=30: means 88.1 degrees; 30 degrees is 0.5774", "\n".join(notes))
finish()
