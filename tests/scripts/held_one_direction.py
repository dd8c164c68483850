"""A model held in one direction only is told so (label e2e).

A new user's tunnel under gravity: rollers on both sides (BOUND XVEL 0)
and a FIX range on the base in which no block centroid lay (FIX said so,
among other lines). Nothing held the model vertically; it fell 525 m while
SOLVE ran 200 000 cycles, with no word why: the net-force note of a model
nothing holds (CYCLE: note: nothing holds the model in place) was skipped
as soon as any boundary velocity existed. The note now checks each
direction no FIX, velocity or viscous boundary holds.

Scene: two 10 x 5 m blocks (2700 kg/m^3, g 9.81: weight 2.6487e6 N), XVEL 0
on both sides.
1. CYCLE: the note names y, the weight -2.6487E+06 N and the remedy.
2. BOUND YVEL 0 on the base, CYCLE: no further note (held both ways).
3. The same model with the base held from the start: no note.
"""
import sys
from udec_test import check, finish, run_deck, workdir

udec = sys.argv[1]
folder = workdir()
HEAD = """round 0.05
block 0,0 0,10 10,10 10,0
crack 0,5 10,5
prop mat=1 d=2700
prop jmat=1 jkn=1e10 jks=1e10 jfric=0.6
grav 0 -9.81
bound -0.1 0.1 -1 11 xvel 0
bound 9.9 10.1 -1 11 xvel 0
damp auto
"""
NOTE = "CYCLE: note: nothing holds the model in y"


def deck(name, body):
    return run_deck(udec, folder, name, HEAD + body + "stop\n")[1]


out = deck("rollers", "cycle 50\nbound -1 11 -0.1 0.1 yvel 0\ncycle 50\n")
first, _, second = out.partition("bound -1 11 -0.1 0.1 yvel 0")
line = next((l for l in first.splitlines() if l.startswith(NOTE)), "")
check(line != "", "rollers: note in y", first[-1500:])
check("weight ( 0.0000E+00, -2.6487E+06) N" in line and "BOUND YVEL 0" in line,
      "rollers: weight and remedy named", line)
check(NOTE not in second, "rollers: held both ways after YVEL, no note", second[-1500:])

out = deck("held", "bound -1 11 -0.1 0.1 yvel 0\ncycle 50\n")
check("nothing holds" not in out, "held: no note", out[-1500:])

finish()
