"""A load given at once on a balanced zoned model under DAMP AUTO reaches its static
answer without the dynamic overshoot the adaptive damping let through at rest (label
stability; docs/robustness.md round 5a, docs/mechanics.md DAMP AUTO: the probe after a
load change on a zoned model, an extension beyond UDEC manual (ICG1.5, 1989), Section
4.5, DAMP).

Each model is balanced (SOLVE), a history of a boundary displacement starts, CYCLE 5 at
rest gives its value before the load, the load is given at once and SOLVE runs to RATIO
1e-5; a second SOLVE to RATIO 1e-6 gives the reference: the static increment is the
displacement at that balance less the one before the load. Overshoot = the largest change
of the history during the first SOLVE over that static increment.
  1. A 1 x 4 m elastic column (QUAD 0.25, K 2e9, G 1e9) on rollers, its top under a
     second -1 MPa: its top's y displacement. Before the probe 1.071 (alpha drifted at
     rest to 331 1/s; the column's first mode is about 420 rad/s); now 1.000. Bound 1.01:
     critical damping of the driven mode leaves no overshoot, 1 % for the higher modes.
  2. A quarter tunnel (a = 1 in an 8 m square, AUTO 0.3, elastic) whose wall pressure
     drops from 8 to 5 MPa at once: the wall's x displacement at (1, 0). Before 1.041,
     now 1.000; bound 1.01 as in 1.
  3. Session 42's jointed tunnel (24 m, two JSETs, TUNNEL r 2) zoned (GEN EDGE 1.5,
     1 590 zones), the boundary stress (-4, -6 MPa) doubled after the excavation's SOLVE:
     the wall's x displacement at (10, 12). Before 1.662 (alpha at rest 13 1/s), now
     1.174. Bound 1.25: the hump that remains is not the damping's: alpha held at 4 or 8
     times the estimate (overdamped) leaves 1.11 and 1.13 (the loads from the near and
     far sides reach the wall at different rates), so the bound guards the fix, not a
     critical value.
SOLVE's cycles to balance (RATIO 1e-5) are printed and may not exceed those before the
probe by more than 10 % (before: 465, 1 060, 6 030; now 390, 870, 6 375)."""
import os
import sys
sys.path.insert(0, os.path.dirname(__file__))
from udec_test import check, finish, histories, run_deck, workdir  # noqa: E402

udec = sys.argv[1]

LOADED = """hist ncyc 5 {hist}
cycle 5
{load}
solve ratio 1e-5
print hist 1
solve ratio 1e-6
print hist 1
stop
"""

COLUMN = """round 0.01
block 0,0 0,4 1,4 1,0
gen quad 0.25
prop mat 1 dens 2500 bulk 2e9 shear 1e9
bound -.01 1.01 -.01 .01 yvel 0
bound -.01 1.01 3.99 4.01 stress 0 0 -1e6
damp auto
solve
""" + LOADED.format(hist="ydis 0.5 4", load="bound -.01 1.01 3.99 4.01 stress 0 0 -1e6")

ROLL = "bound -.01 .01 -.01 8.01 xvel 0\nbound -.01 8.01 -.01 .01 yvel 0"
QUARTER = f"""round 0.01
block 0,0 0,8 8,8 8,0
tunnel 0,0 1,48
delete 0,0.6 0,0.6
gen auto 0.3
prop mat 1 dens 2500 bulk 2e9 shear 1e9
insitu stress -1e7 0 -1e7
bound -.01 8.01 7.99 8.01 stress -1e7 0 -1e7
bound 7.99 8.01 -.01 8.01 stress -1e7 0 -1e7
bound -1.1 1.1 -1.1 1.1 stress -1e7 0 -1e7
bound -1.1 1.1 -1.1 1.1 stress 2e6 0 2e6
{ROLL}
damp auto
solve
cycle 1000
""" + LOADED.format(hist="xdis 1 0", load="bound -1.1 1.1 -1.1 1.1 stress 3e6 0 3e6\n" + ROLL)

JOINTED = """round 0.05
block 0,0 0,24 24,24 24,0
jset 35 0 60 0 0 0 1.5 0 (0,0)
jset -55 0 60 0 0 0 1.8 0 (0,0)
tunnel 12 12 2 20
gen edge 1.5
prop mat 1 d 2500 k 15e9 g 9e9
prop jmat 1 jkn 8e9 jks 4e9 jfric 0.65 jcoh 2e5 jten 1e5
bound stress -4e6 0 -6e6
insitu stress -4e6 0 -6e6
damp auto
solve
del ann 12 12 0 1.95
solve
""" + LOADED.format(hist="xdis 10 12", load="bound stress -4e6 0 -6e6")

for name, deck, bound, before in (("column", COLUMN, 1.01, 465), ("quarter_tunnel", QUARTER, 1.01, 1060),
                                  ("jointed_tunnel", JOINTED, 1.25, 6030)):
    _, out = run_deck(udec, workdir(), name, deck, timeout=300)
    tabs = histories(out)
    solves = [int(l.split()[3]) for l in out.splitlines() if l.startswith("SOLVE: balanced after")]
    if len(tabs) < 2 or len(tabs[0]) < 3 or len(solves) < 2:
        check(False, f"{name}: the histories and both SOLVEs printed", out[-2000:])
        continue
    u0 = tabs[0][0][1]                       # after CYCLE 5 at rest, before the load
    static = tabs[-1][-1][1] - u0            # balanced to RATIO 1e-6
    peak = max((r[1] - u0 for r in tabs[0]), key=abs)
    ratio = peak / static
    n = solves[-2]                           # the SOLVE after the load, RATIO 1e-5
    print(f"{name}: static increment {static:.5e}, largest change {peak:.5e}, overshoot {ratio:.4f}, "
          f"{n} cycles to balance (before the probe {before})")
    check(abs(static) > 0 and 0.99 < ratio < bound,
          f"{name}: overshoot of the static increment below {bound}", f"{ratio:.4f}")
    check(n <= 1.1 * before, f"{name}: balanced within 10 % of the cycles before the probe", str(n))

finish()
