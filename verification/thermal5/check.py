"""Thermal verification Case 5 (manual Section 7.8.6, Table 7-6): transient
temperature in an orthotropic bar cooled by convection on all faces (quarter
model), at t = 8.3333e-4 s.

Both decks run as printed; `print temperature` is added before STOP. Points A-D are the gridpoints at the corners of the quarter model.

Tolerances:
* Against Schneider's analytical values: within 2.5 %. The manual's own UDEC
  column is off by 0.76-2.21 % (zone size 0.02 m against a 0.083 m half-width,
  and the time discretisation); our mesh is of the same size.
* Against the manual's UDEC column: within 1 %, for both the explicit and the
  implicit run (the manual prints one UDEC column without saying which run it
  is). Same scheme, same nominal zone size; our AUTO zoning differs in detail.
"""
import os
import sys
sys.path.insert(0, os.path.join(os.path.dirname(__file__), ".."))
from common import check, finish, workdir, deck_with, run_deck  # noqa: E402
from thermal_common import temperatures, at  # noqa: E402

udec = sys.argv[1]
here = os.path.dirname(os.path.abspath(__file__))
X, Y = 0.166667, 0.083333
# (x, y, analytical, UDEC 1989) of Table 7-6
TABLE = [(0.0, 0.0, 458.7, 462.4), (X, 0.0, 280.5, 284.9),
         (0.0, Y, 198.2, 199.7), (X, Y, 149.4, 152.7)]

folder = workdir()
for deck, label in (("case_a.dat", "explicit"), ("case_b.dat", "implicit")):
    text = deck_with(os.path.join(here, deck), ["print temperature"])
    rc, out, secs = run_deck(udec, folder, deck, text)
    check(rc == 0, f"{deck} ({label}) runs", f"rc={rc}, {secs:.1f} s")
    check("thermal time  8.333" in out, f"{label}: the run reaches t = 8.333e-4 s")
    rows = temperatures(out)
    for x, y, t_an, t_udec in TABLE:
        t = at(rows, x, y)
        e_an = abs(t - t_an) / t_an
        e_ud = abs(t - t_udec) / t_udec
        check(e_an <= 0.025, f"{label}: T({x:g},{y:g}) = {t:.2f} within 2.5 % of the "
              f"analytical {t_an}", f"{100 * e_an:.2f} %")
        check(e_ud <= 0.01, f"{label}: T({x:g},{y:g}) = {t:.2f} within 1 % of UDEC 1989 "
              f"{t_udec}", f"{100 * e_ud:.2f} %")
finish()
