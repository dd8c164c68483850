"""New user's decks of campaign round 12: a tunnel in rock cut by crossing
joint sets, held by boundary stresses, written from the UDEC manual (ICG1.5,
1989) Sections 2 and 4 with the mistakes new users make (docs/closed_form.md,
"Round 12", lists every deck, its check and our number). Units SI.

Findings (fixed):
 1. A SOLVE before any BOUNDARY: the INSITU stresses sprang the model apart
    and SOLVE ended "nothing to balance ... or no load given?" with no word
    on where the given -5 MPa went. The first cycle now notes that no
    boundary condition holds the initial stresses; a model held by BOUNDARY
    STRESS (or a velocity) gets no such note.
 2. Stiff joints on soft zoned blocks (JKN 1E14, K 1E8): SOLVE ran its
    100 000 cycles to force ratio 4.6 without a word on why. A SOLVE that
    does not balance now names the joints-to-zones stiffness contrast (above
    1000) and the cycles it costs; rock-like properties get no note.
 3. GEN EDGE 0.05 in a 20 m square made 418 863 zones silently (CYCLE 10:
    17 s). GENERATE now notes a model of 200 000 zones or more.
Guards (hold):
 4. Joints parallel to the sides and a set through the corners (0, 90, 45
    degrees through (0,0)) around a circular opening under hydrostatic
    INSITU = BOUNDARY STRESS: the deck is its own mirror image in y = x, so
    the crown's YDIS equals the springline's XDIS.
 5. Lower case, abbreviations at their limits, a comment after a command and
    continuation lines ('&'): the deck runs without an error.
 6. A session at the UDEC> prompt with six mistyped lines (10O, RATION,
    JCONS=7, 0.4e, a short BOUND STRESS, RESTORE): each refused, nothing
    changed, SAVE / SOLVE / RESTART / SOLVE end on the same cycle line.
"""
import os
import sys
sys.path.insert(0, os.path.dirname(__file__))
from udec_test import check, finish, run, run_deck, workdir  # noqa: E402
from shared_decks import jointed_square  # noqa: E402

udec = sys.argv[1]

RIGID = jointed_square(20, ["30,0 40,0 0,0 3,0 (10,10)", "120,0 40,0 0,0 3,0 (10,10)"], "10,10 2,16",
                       "DENS=2600 JKN=1E10 JKS=1E10 JFRIC=0.6", "-5E6 0 -5E6", bound=False)

UNHELD_NOTE = "CYCLE: note: the model carries initial stresses (INSITU) and no boundary condition holds them"


def unheld():
    rc, out = run_deck(udec, workdir(), "unheld", RIGID + "SOLVE\nBOUND STRESS -5E6 0 -5E6\nSOLVE\nSTOP\n")
    check(out.count(UNHELD_NOTE) == 1 and out.index(UNHELD_NOTE) < out.index("SOLVE: nothing to balance"),
          "unheld: a SOLVE before any BOUNDARY notes the unheld INSITU stresses, once", out[-2500:])
    rc, out = run_deck(udec, workdir(), "held", RIGID + "BOUND STRESS -5E6 0 -5E6\nSOLVE\nSTOP\n")
    check(UNHELD_NOTE not in out and "SOLVE: balanced" in out,
          "unheld: the same model held by BOUNDARY STRESS gets no note", out[-1500:])
    rc, out = run_deck(udec, workdir(), "rollers", RIGID + "BOUND -0.1 20.1 -0.1 0.1 YVEL 0\nCYCLE 5\nSTOP\n")
    check(UNHELD_NOTE not in out, "unheld: a model held by a velocity boundary gets no note", out[-1500:])


ZONED = """ROUND 0.02
BLOCK 0,0 0,10 10,10 10,0
JSET 30,0 20,0 0,0 3,0 (5,5)
JSET 120,0 20,0 0,0 3,0 (5,5)
GEN EDGE 1.5
PROP MAT=1 DENS=2000 K={k} G={g} JKN={kn} JKS={kn} JFRIC=0.6
INSITU STRESS -1E6 0 -1E6
BOUND STRESS -1E6 0 -1E6
DAMP AUTO
SOLVE
BOUND STRESS 0 0 -5E5
SOLVE CYCLES 100
STOP
"""


def stiff_joints():
    rc, out = run_deck(udec, workdir(), "stiff", ZONED.format(k="1E8", g="6E7", kn="1E14"))
    note = [line for line in out.splitlines() if line.startswith("Note: SOLVE: the joints are ")]
    # contrast JKN x zone width / (K + 4G/3) = 1e14 x w / 1.8e8 with the mean
    # zone width w = sqrt(100 m2 / zones): printed, between 1e5 and 1e6
    contrast = float(note[0].split()[5]) if note else 0.0
    check(len(note) == 1 and "SOLVE: not balanced" in out and 1e5 < contrast < 1e6
          and "K + 4G/3 = 1.800E+08" in note[0],
          "stiff: an unbalanced SOLVE names the joints-to-zones stiffness contrast", out[-2500:])
    rc, out = run_deck(udec, workdir(), "rock", ZONED.format(k="2E10", g="1.2E10", kn="1E10"))
    check("SOLVE: not balanced" in out and "the joints are" not in out,
          "stiff: rock-like joints (contrast 0.3) get no note", out[-1500:])


def many_zones():
    rc, out = run_deck(udec, workdir(), "many", "ROUND 0.01\nBLOCK 0,0 0,20 20,20 20,0\nGEN EDGE 0.065\nSTOP\n")
    check("Note: GENERATE: the model now has 223152 zones" in out,
          "many: GEN EDGE 0.065 in a 20 m square (223 152 zones) is noted", out[-1500:])
    rc, out = run_deck(udec, workdir(), "few", "ROUND 0.01\nBLOCK 0,0 0,20 20,20 20,0\nGEN EDGE 0.5\nSTOP\n")
    check("GENERATE: 1 block(s) zoned" in out and "the model now has" not in out,
          "many: GEN EDGE 0.5 is not noted", out[-1500:])


MIRROR = jointed_square(20, ["0,0 40,0 0,0 5,0 (0,0)", "90,0 40,0 0,0 5,0 (0,0)",
                            "45,0 60,0 0,0 7.0710678,0 (0,0)"], "10,10 2,16",
                        "DENS=2600 JKN=1E10 JKS=1E10 JFRIC=0.6", "-5E6 0 -5E6") + """DAMP AUTO
SOLVE
DEL ANN 10 10 0 1.95
HIST YDIS 10,12 XDIS 12,10
SOLVE
PRINT HIST 1 2
STOP
"""


def mirror():
    rc, out = run_deck(udec, workdir(), "mirror", MIRROR)
    rows = [line.split() for line in out.split("PRINT HIST 1 2")[-1].splitlines()]
    rows = [[float(v) for v in r] for r in rows if len(r) == 3 and r[0][0].isdigit()]
    if not rows:
        check(False, "mirror: PRINT HIST table", out[-1500:])
        return
    _, crown, spring = rows[-1]
    print(f"mirror: crown YDIS {crown:.6g}, springline XDIS {spring:.6g}")
    # the deck is its own mirror image in y = x (sets 0 / 90 swap, 45 maps to
    # itself, hydrostatic field): the crown moves down as the springline moves
    # left, by the same amount (1e-6 relative; measured equal to 6 digits)
    check(crown < -1e-5 and abs(crown - spring) < 1e-6 * abs(crown),
          "mirror: crown YDIS = springline XDIS (1e-6)", str(rows[-1]))


ABBREV = """* lower case, abbreviations, a comment after a command, continuation lines
ro 0.05
bl 0,0 0,20 &
   20,20 20,0
js 30,0 40,0 0,0 3,0 (10,10)  * first set
js 120,0 40,0 0,0 3,0 (10,10)
tu 10,10 2,16
pro mat=1 d=2600 jkn=1e10 jks=1e10 jf=0.6 &
    jc=0 jt=0
ch jcons=2
ins st -5e6 0 -5e6
bo st -5e6 0 -5e6
da au
so
de ann 10 10 0 1.95
hi ydis 10,12 xdis 12,10
so r 1e-5
pr hi 1 2
sto
"""


def abbreviations():
    rc, out = run_deck(udec, workdir(), "abbrev", ABBREV)
    check(out.count("SOLVE: balanced") == 2 and "DELETE: 4 block(s) deleted" in out
          and "column 2 XDIS at" in out,
          "abbrev: the abbreviated, continued, commented deck runs through", out[-1500:])


SESSION = RIGID.lower() + """bound stress -5e6 0 -5e6
damp auto
solve
del ann 10 10 0 1.95
hist ydis 10,12 unbal
solv ratio 1e-5
cycle 10O
solve ration 1e-5
change jcons=7
prop mat=1 jfric=0.4e
bound stress -5e6 0
save s.sav
solve
print prop
restore s.sav
restart s.sav
solve
quit
"""


def session():
    folder = workdir()
    rc, out = run(udec, [], cwd=folder, stdin_text=SESSION)
    errors = [line for line in out.splitlines() if "*** Error" in line]
    check(rc == 0 and len(errors) == 6 and "'10O'" in errors[0] and "RATIO" in errors[1]
          and "RESTART" in errors[5],
          "session: six mistyped lines refused, each naming its token", "\n".join(errors) + out[-800:])
    # the refused PROP line changed nothing: JFRIC stays 0.6
    check("1  JFRIC         6.000000E-01" in out, "session: a refused PROP line changes nothing",
          out[-3000:])
    ends = [line for line in out.splitlines() if line.startswith("cycle ")]
    # the state saved, solved, restarted and solved again: the same cycle line
    same = len(ends) >= 2 and ends[-1].split(" max unbalanced force")[1].split(",")[0] == \
        ends[-2].split(" max unbalanced force")[1].split(",")[0] and \
        ends[-1].split(",")[0] == ends[-2].split(",")[0]
    check(same, "session: SOLVE after SAVE and after RESTART end on the same cycle and force",
          "\n".join(ends))


unheld()
stiff_joints()
many_zones()
mirror()
abbreviations()
session()
finish()
