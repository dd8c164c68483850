"""Verification C (UDEC manual (ICG1.5, 1989), Appendix A, Test C, "Crack
shear by reduced friction", Figs. C-1 and C-2): an embedded 10 m crack in an
elastic plane (boundary-element far field) slips when its friction drops
from 2.5 to 0.1667.

Reference (closed form, Test C text): the shear displacement along a crack
|x - 15| < a = 5 m in an infinite plane after a uniform stress drop tau is

    u_s(x) = 2 (1 - nu) / G * |tau| * sqrt(a^2 - (x - 15)^2),

G = 1e9 Pa, nu = 0.25, tau(drop) = 0.167 x 1.5e7 - 1e7 = -7.5e6 Pa, so
u_s(15) = 0.05625 m at the centre. The manual: "the difference in agreement
is 6 %" (Fig. C-2). Tolerance here: 6 %, as three measures of the printed
deck (nothing in it changed; one PRINT CONTACTS inserted just before the
friction drop so the slip can be measured from there), two measures:

* the centre contact (x = 15): its shear displacement since the drop
  within 6 % of 0.05625 m;
* every crack contact present before the drop (the contacts created while
  the crack slips start from zero shear displacement mid-slip and measure
  only part of it) with |x - 15| <= 3 m, where the closed form is at least
  80 % of its maximum: within 6 % of the closed-form maximum 0.05625 m
  (the scale of Fig. C-2).
Printed, not asserted: the relative L2 error over all 13 crack contacts,
tips included (6.5 %, measured 2026-11-25).

The two contacts nearest each tip are not asserted pointwise: there the
closed form falls to zero with an infinite slope and the crack of contacts
ends half-way between the last weak contact (x = 10.49) and the first pinned
one (9.75), at x = 10.12, not 10 (README, "measured"). Refining this deck
as printed does not converge to the closed form (the tips move with the
zoning, the single friction drop overshoots, the joint beyond the tips is
elastic; README, measured); refine.py (verification.C_refinement) fixes
those three and asserts the convergence.
"""
import math
import os
import sys
sys.path.insert(0, os.path.join(os.path.dirname(__file__), ".."))
from common import check, contacts, finish, workdir, deck_with, run_deck  # noqa: E402

udec = sys.argv[1]
here = os.path.dirname(os.path.abspath(__file__))
G, NU, TAU, A, XC = 1.0e9, 0.25, 7.5e6, 5.0, 15.0
UMAX = 2.0 * (1.0 - NU) / G * TAU * A


def closed_form(x):
    return 2.0 * (1.0 - NU) / G * TAU * math.sqrt(max(A * A - (x - XC) ** 2, 0.0))

folder = workdir()
drop = "PROP M=1 JF=0.1667\n"
text = deck_with(os.path.join(here, "C.dat"), [], replace=[(drop, "PRINT CONT\n" + drop)])
rc, out, sec = run_deck(udec, folder, "C.dat", text)
check(rc == 0, "C.dat as printed runs", out[-2000:] if rc else f"{sec:.2f} s")
if rc == 0:
    cut = out.index(drop.strip())
    geo0, dis0 = contacts(out[:cut])
    geo1, dis1 = contacts(out[cut:])
    crack = sorted((geo0[c][1], c) for c in geo0 if geo0[c][0] == 1)
    check(len(crack) >= 11, "crack contacts (JMAT 1) before the drop", f"{len(crack)}")
    rows = [(x, abs(dis1[c] - dis0[c]), closed_form(x)) for x, c in crack if c in dis1]
    for x, u, ex in rows:
        print(f"info: x = {x:7.3f}  slip {u:.5f} m  closed form {ex:.5f} m  "
              f"{100*(u-ex)/ex:+.2f} % of local, {100*(u-ex)/UMAX:+.2f} % of max")
    centre = min(rows, key=lambda r: abs(r[0] - XC))
    err = (centre[1] - UMAX) / UMAX
    check(abs(centre[0] - XC) < 0.1 and abs(err) <= 0.06,
          "crack centre: slip within 6 % of 2(1-nu)/G |tau| a = 0.05625 m",
          f"x = {centre[0]:.3f}: {centre[1]:.5f} m ({100*err:+.2f} %)")
    inner = [r for r in rows if abs(r[0] - XC) <= 3.0]
    worst = max(inner, key=lambda r: abs(r[1] - r[2]))
    check(len(inner) >= 7 and abs(worst[1] - worst[2]) <= 0.06 * UMAX,
          "|x - 15| <= 3 m: every contact within 6 % (of the maximum slip) of the closed form",
          f"{len(inner)} contacts, worst x = {worst[0]:.3f}: {worst[1]:.5f} vs {worst[2]:.5f} m "
          f"({100*(worst[1]-worst[2])/UMAX:+.2f} % of max, {100*(worst[1]-worst[2])/worst[2]:+.2f} % of local)")
    l2 = math.sqrt(sum((u - ex) ** 2 for _, u, ex in rows) / sum(ex * ex for _, _, ex in rows))
    print(f"info: whole crack, {len(rows)} contacts: relative L2 error {100*l2:.2f} % (not asserted)")
finish()
