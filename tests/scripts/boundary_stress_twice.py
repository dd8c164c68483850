"""BOUNDARY STRESS given twice adds, and says so (label e2e).

UDEC manual (ICG1.5, 1989), Section 4.5, BOUNDARY, Note: loads and
stresses given after a CYCLE are increments ("a change in a boundary stress
condition must be input as a stress incremental change"), and udec adds
two STRESS lines given before a CYCLE as well. A new user who repeats the
line to "make sure", or gives a top stress after the whole-boundary one to
"replace" it, doubles the load without a word. BOUNDARY now prints a note
with the count of points that carried a stress and the total on the first.

Scene: a 10 m square, sxx -1 MPa, syy -2 MPa on the whole boundary.
1. Given once: no note.
2. Given twice: the note names 4 of 4 points and the total (sxx -2e6,
   syy -4e6, exact sums).
3. A top-only -0.5 MPa after it: 2 of 2 points, syy -2.5e6 at a top corner.
4. Under SET -FUP (fixed forces), a second STRESS on the base: the note
   names the force, the sum of the two equal forces, (0, 2e7) N (exact).
5. One stress per side (verification B's form), under FUP and -FUP: the
   sides meet at the corners but no side is loaded twice: no note.
"""
import re
import sys
from udec_test import check, finish, run_deck, workdir

udec = sys.argv[1]
HEAD = """round 0.05
block 0,0 0,10 10,10 10,0
prop mat=1 d=2700
"""
NOTE = re.compile(r"note: BOUNDARY STRESS adds to the boundary stress already on (\d+) of "
                  r"the (\d+) points .* it is now (.*); to replace")

folder = workdir()


def deck(name, body):
    return run_deck(udec, folder, name, HEAD + body + "stop\n")[1]


out = deck("once", "bound stress -1e6 0 -2e6\n")
check(not NOTE.search(out), "once: no note", out[-800:])

def noted(name, body, count, total):
    """The note of deck `name`: `count` of `count` points, `total` named."""
    out = deck(name, body)
    m = NOTE.search(out)
    check(m is not None, f"{name}: note", out[-800:])
    if m:
        check(m.group(1) == count and m.group(2) == count, f"{name}: {count} of {count} points",
              m.group(0))
        check(total in m.group(3), f"{name}: the total named", m.group(0))


noted("twice", "bound stress -1e6 0 -2e6\nbound stress -1e6 0 -2e6\n", "4",
      "sxx -2000000, sxy 0, syy -4000000")
noted("top", "bound stress -1e6 0 -2e6\nbound stress 0 0 -5e5 -1 11 9.9 10.1\n", "2",
      "syy -2500000")

out = deck("fixed", "set -fup\nbound stress -1e6 0 -2e6 -1 11 -0.1 0.1\n"
                    "bound stress -1e6 0 -2e6 -1 11 -0.1 0.1\n")
m = NOTE.search(out)
check(m is not None, "fixed: note", out[-800:])
if m:
    # the range holds the base's two corners; the stress loads the base
    # between them: corner (0, 0) carries half of it, syy 2e6 x 5 m pushing
    # in (+y), 1e7 once, 2e7 after the second line; no x force
    check("the force (0, 2E+07)" in m.group(3), "fixed: the summed force named", m.group(0))

# verification B's form: one stress per side; the sides meet at the
# corners, each line loads its own half edges: nothing adds, no note
out = deck("sides", "bound stress -1e6 0 0 -0.1 0.1 -1 11\n"
                    "bound stress 0 0 -2e6 -1 11 9.9 10.1\n"
                    "bound stress -1e6 0 0 9.9 10.1 -1 11\n"
                    "bound stress 0 0 -2e6 -1 11 -0.1 0.1\n")
check(not NOTE.search(out), "sides: no note", out[-1500:])
out = deck("sides_fixed", "set -fup\nbound stress -1e6 0 0 -0.1 0.1 -1 11\n"
                          "bound stress 0 0 -2e6 -1 11 9.9 10.1\n")
check(not NOTE.search(out), "sides_fixed: no note", out[-1500:])

finish()
