"""A BOUNDARY STRESS that pulls a jointed model (label e2e; session 44, task
tunring). Stresses are positive in tension (UDEC manual (ICG1.5), Section
4.1); joints have no tensile strength unless JTENSILE is given (Section 4,
PROPERTY), so a jointed box pulled on every side comes apart: the boundary
blocks fly off and collide. Session 43's m4 (a new user who forgot that
compression is negative: BOUNDARY STRESS 5e6 0 5e6 round a tunnel in two
joint sets) stopped after 5015 cycles on Contact Overlap Too Great 3.7 m
outside the model, and the stop's advice spoke of JKN, ROUND and INSITU (a
step load on unloaded joints) but not of the tension. Checked:
1. The first CYCLE (and each later one while the pull lasts) notes that the BOUNDARY STRESS pulls the model in tension
   beyond the joints' tensile strength (JTENSILE 0, the default), naming the
   stress (5e6) and a boundary point.
2. SOLVE stops on Contact Overlap Too Great (the blocks collide) and the stop
   names the tension first and does not give INSITU's step-load advice.
3. After the stop (interactive session) the model prints and saves, and the
   save restores.
4. The same model with compressive BOUNDARY STRESS -5e6 0 -5e6 gets no such
   note (CYCLE 10), nor a model whose joints hold the pull (JTENSILE 1e7).
"""
import os
import sys
from udec_test import check, finish, run, workdir

udec = sys.argv[1]
d = workdir()

SETUP = """round 0.05
block 0,0 0,10 10,10 10,0
jset 45,0 20,0 0,0 2,0
jset -45,0 20,0 0,0 2,0
tunnel 5 5 1 12
prop mat 1 dens 2500 jkn 1e10 jks 1e10 jfric 0.5{jtens}
boundary stress {s} 0 {s}
damp auto
"""

# 1, 2, 3: interactive, so that the session goes on after the stop
rc, out = run(udec, [], cwd=d, timeout=120,
              stdin_text=SETUP.format(s="5e6", jtens="") +
              "cycle 10\nsolve\nprint max\nsave pulled.sav\nrestart pulled.sav\nprint max\nSTOP\n")
first = out.split("cycle 10,", 1)[0]
notes = [l for l in first.splitlines() if "CYCLE: note: the BOUNDARY STRESS pulls the model in tension" in l]
check(len(notes) == 1 and "5.000E+06" in notes[0] and "JTENSILE 0.000E+00, the default" in notes[0]
      and "boundary point at (" in notes[0],
      "tension: the first CYCLE notes the pull, its stress and the joints' tensile strength",
      "\n".join(notes) or out[-3000:])
stops = [l for l in out.splitlines() if "Contact Overlap Too Great" in l and "*** Error" in l]
check(len(stops) == 1, "tension: SOLVE stops on Contact Overlap Too Great (the blocks fly apart)",
      out[-3000:])
if stops:
    s = stops[0]
    check("pulls the model in tension" in s and s.index("pulls the model") < s.index("it closed by"),
          "tension: the stop names the tension first", s[:1500])
    check("INSITU STRESS with the field" not in s and "carried no stress when this CYCLE" not in s,
          "tension: the stop gives no step-load (INSITU) advice", s[:3000])
after = out.split("Contact Overlap Too Great", 1)[-1]
check("*** Error" not in after.split("\n", 1)[-1],
      "tension: PRINT MAX, SAVE and RESTART after the stop run without error", after[-3000:])
check(os.path.exists(os.path.join(d, "pulled.sav")), "tension: the stopped model is saved")

# 4: no note under compression, nor with joints that hold the pull
for s, jtens, label in (("-5e6", "", "compression"), ("5e6", " jtens 1e7", "JTENSILE 1e7")):
    rc, out = run(udec, [], cwd=d, timeout=60,
                  stdin_text=SETUP.format(s=s, jtens=jtens) + "cycle 10\nSTOP\n")
    check("cycle 10" in out and "pulls the model in tension" not in out,
          f"{label}: no tension note at the first CYCLE", out[-2000:])
finish()
