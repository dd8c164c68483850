"""BOUNDARY without a range acts on the outer boundary, not on the walls of
openings (label e2e; manual Section 4.5 BOUNDARY: "If the range is omitted,
the boundary condition applies to the entire boundary", and PLOT BOUNDARY:
"outer boundary"; the domain commands act on "all domains except the outer
domain").

A new user's first tunnel: rock cut by two joint sets, a TUNNEL deleted, then
`BOUND STRESS` and `INSITU STRESS` with no range. Before 2026-11-26 the
tunnel's wall took the boundary stress too, so the excavation was held shut
by its own in-situ stress and nothing moved. Checked:

1. DELETE then BOUND (no range) prints the same histories, digit for digit,
   as the manual's order BOUND then DELETE (verification E's decks): the wall
   is free in both (it failed before: the wall was loaded and the roof did
   not move);
2. the roof moves down and the floor up, by more than 1e-5 m in 1500 cycles
   (rigid blocks: the joints close, 3e-5 m by then; a loaded wall moves
   less than 1e-6 m);
3. BOUND with a range that covers the wall loads it as asked (a udec
   extension): the roof then moves less than a tenth as much.
"""
import sys
from udec_test import check, finish, history_rows, run, workdir, write

udec = sys.argv[1]

HEAD = """round 0.05
block -10,-10 -10,10 10,10 10,-10
jset 30,0 100,0 0,0 3,0 (0.3,0.2)
jset 120,0 100,0 0,0 3.5,0 (0.1,0.4)
tunnel 0 0 1.5 16
prop mat=1 dens=2500 k=1.6667e10 g=1e10
prop jmat=1 jkn=1e11 jks=5e10 jfric=40
"""
EXCAVATE = "delete ann 0 0 0 1.45\n"
LOAD = "bound stress -10e6 0 -10e6\ninsitu stress -10e6 0 -10e6\n"
RANGED = "bound -10.5,10.5 -10.5,10.5 stress -10e6 0 -10e6\ninsitu stress -10e6 0 -10e6\n"
TAIL = """hist ydis 0,1.5 ydis 0,-1.5
damp auto
cycle 1500
print hist 1 2
stop
"""


def last_row(out):
    rows = [r for r in history_rows(out, "print hist 1 2") if len(r) == 3]
    return rows[-1] if rows else None


def histories(out):
    return out.split("print hist 1 2", 1)[-1] if "print hist 1 2" in out else ""


d = workdir()
write(d, "manual_order.dat", HEAD + LOAD + EXCAVATE + TAIL)
write(d, "delete_first.dat", HEAD + EXCAVATE + LOAD + TAIL)
write(d, "ranged.dat", HEAD + EXCAVATE + RANGED + TAIL)
rc1, manual = run(udec, ["manual_order.dat"], cwd=d)
rc2, first = run(udec, ["delete_first.dat"], cwd=d)
rc3, ranged = run(udec, ["ranged.dat"], cwd=d)
check(rc1 == 0 and rc2 == 0 and rc3 == 0, "the three decks run", (manual + first + ranged)[-2000:])
check("walls of openings" in first, "the rangeless BOUNDARY says it left the opening's wall free",
      "\n".join(l for l in first.splitlines() if "BOUNDARY" in l))
check(histories(manual) != "" and histories(first) == histories(manual),
      "DELETE then BOUND prints the manual order's histories digit for digit",
      histories(first)[-600:] + "\n---\n" + histories(manual)[-600:])
row = last_row(first)
check(row is not None and row[1] < -1e-5 and row[2] > 1e-5,
      "the roof moves down and the floor up by more than 1e-5 m", str(row))
row3 = last_row(ranged)
check(row is not None and row3 is not None and abs(row3[1]) < 0.1 * abs(row[1]),
      "a range over the wall loads it: the roof moves less than a tenth as much", f"{row3} vs {row}")
finish()
