"""Verification D (manual Appendix A, Test D): Prandtl's wedge, a rough
footing on a weightless cohesive (Tresca) material, zoned Mohr-Coulomb
blocks (CONS 3, c = 1e4 Pa, phi = 0) with glued elastic joints.

Reference: Prandtl's exact limit load q = (2 + pi) c = 5.14e4 Pa; the
manual's UDEC result is within 3 % of it. Tolerance here: 3 %.
The footing is the set of top gridpoints with a prescribed y-velocity
(0 <= x <= 2.8); its load is the sum of their reactions FY from PRINT
BOUNDARY (FORCES table), divided by the footing's tributary width: the
last loaded gridpoint's x plus half the distance to the next top gridpoint
(the edge zone is half dragged down by the footing).

What is asserted (see README.md):
* the deck as printed (GEN AUTO 1.5): the footing load at both of its
  prints (8000 and 10000 cycles) within 3 %;
* the same deck run on to 48000 cycles: the load has levelled off (a limit
  load, not a point on a rising branch) and is within 3 %;
* the deck with its zoning refined, GEN AUTO 0.375 and GEN QUAD 0.2875
  0.25, run until the load has levelled off (48000 cycles; the footing
  has then moved 12 and 17 mm), each within 3 %.
"""
import math
import os
import sys
sys.path.insert(0, os.path.join(os.path.dirname(__file__), ".."))
from common import check, finish, workdir, deck_with, run_deck, footing_loads  # noqa: E402

udec = sys.argv[1]
here = os.path.dirname(os.path.abspath(__file__))
q_exact = (2.0 + math.pi) * 1.0e4
deck_path = os.path.join(here, "D.dat")


folder = workdir()

# The deck as printed, and the same deck run on to 48000 cycles.
rc, out, sec = run_deck(udec, folder, "D.dat", deck_with(deck_path, []))
check(rc == 0, "D.dat as printed runs", out[-2000:] if rc else f"{sec:.1f} s")
if rc == 0:
    loads = footing_loads(out)
    check(len(loads) == 2, "D.dat: two footing-load prints found", f"{len(loads)}")
    for (q, force, width), n in zip(loads, (8000, 10000)):
        err = (q - q_exact) / q_exact
        check(abs(err) <= 0.03, f"D.dat as printed, {n} cycles: footing load within 3 % of (2 + pi) c",
              f"force {force:.4e} N/m over {width:.3f} m: {q:.4e} Pa, {100*err:+.2f} %")

# The printed zoning run on, and refined zonings: the same deck, GEN line
# changed (or not), the two CYCLE blocks replaced by 48000 cycles with a
# footing-load print every 8000.
for gen in ("GEN 0,12 0,10 AUTO 1.5", "GEN 0,12 0,10 AUTO 0.375", "GEN 0,12 0,10 QUAD 0.2875 0.25"):
    text = open(deck_path).read().replace("GEN 0,12 0,10 AUTO 1.5", gen)
    head = text[:text.index("CYC 8000")]
    text = head + "".join("CYC 8000\nPR BOU FORCES\n" for _ in range(6)) + "STOP\n"
    name = gen.split()[2] + "_" + gen.split()[3] + ".dat"
    rc, out, sec = run_deck(udec, folder, name, text)
    check(rc == 0, f"{gen} runs", out[-2000:] if rc else f"{sec:.1f} s")
    if rc:
        continue
    loads = footing_loads(out)
    check(len(loads) == 6, f"{gen}: six footing-load prints found", f"{len(loads)}")
    if len(loads) < 2:
        continue
    q, force, width = loads[-1]
    err = (q - q_exact) / q_exact
    # levelled off: the last 8000 cycles add less than 1 % (steady plastic flow)
    check(abs(loads[-1][0] / loads[-2][0] - 1.0) < 0.01, f"{gen}: the load has levelled off",
          f"{loads[-2][0]:.4e} -> {q:.4e}")
    check(abs(err) <= 0.03, f"{gen}: limit load within 3 % of (2 + pi) c = 5.14e4 Pa",
          f"force {force:.4e} N/m over {width:.3f} m: {q:.4e} Pa, {100*err:+.2f} %")
finish()
