"""Thermal verification Case 1 (manual Section 7.8.2, Table 7-2): steady
temperature along a tapered fin (wall at 1100 degC, convection h = 15 to air
at 100 degC on both sloping faces).

Both decks run as printed; `print temperature` is added before STOP. The
surface temperature at the table's x positions is interpolated linearly
between the gridpoints on the lower fin face (y = 0.041667 x / 0.3333).

Tolerances:
* Against the analytical solution (Carslaw and Jaeger p. 142): within 1 %.
  The manual's UDEC errors are up to 0.45 %; our AUTO zoning puts 11 zone
  edges along the face (the 2-D model, the linear interpolation between them
  and the few zones across the thin tip account for the rest; measured up
  to 0.55 %, at the tip).
* Against the manual's UDEC columns: within 1 % likewise (same scheme).
* Steady state: the explicit (80000 steps) and implicit (100 steps of 10 s)
  runs agree within 0.05 %.
"""
import os
import sys
sys.path.insert(0, os.path.join(os.path.dirname(__file__), ".."))
from common import check, finish, workdir, deck_with, run_deck  # noqa: E402
from thermal_common import temperatures, along  # noqa: E402

udec = sys.argv[1]
here = os.path.dirname(os.path.abspath(__file__))
# x, analytical, explicit, implicit (Table 7-2)
TABLE = [(0.0, 1100, 1100, 1100), (0.04166, 940.5, 936.5, 936.7),
         (0.08332, 801, 797.4, 797.7), (0.125, 677.5, 675, 675.4),
         (0.1666, 569.8, 567.8, 568.2), (0.2083, 475.8, 474.3, 474.7),
         (0.25, 394.5, 393.4, 393.7), (0.2916, 324.7, 323.6, 323.8),
         (0.3333, 264.8, 265, 265.2)]
SLOPE = 0.041667 / 0.3333

folder = workdir()
profiles = {}
for deck, label, col in (("case_a.dat", "explicit", 2), ("case_b.dat", "implicit", 3)):
    text = deck_with(os.path.join(here, deck), ["print temperature"])
    rc, out, secs = run_deck(udec, folder, deck, text)
    check(rc == 0, f"{deck} ({label}) runs", f"rc={rc}, {secs:.1f} s")
    rows = temperatures(out)
    face = [(x, y) for (x, y) in rows if x >= -1e-9 and abs(y - SLOPE * x) < 1e-5]
    check(len(face) >= 9, f"{label}: gridpoints on the lower fin face", f"{len(face)}")
    profiles[label] = []
    for row in TABLE:
        x, t_an, t_udec = row[0], row[1], row[col]
        t = along(rows, face, x)
        profiles[label].append(t)
        e_an = abs(t - t_an) / t_an
        e_ud = abs(t - t_udec) / t_udec
        check(e_an <= 0.01, f"{label}: T(x={x}) = {t:.1f} within 1 % of the analytical "
              f"{t_an}", f"{100 * e_an:.2f} %")
        check(e_ud <= 0.01, f"{label}: T(x={x}) = {t:.1f} within 1 % of UDEC 1989 {t_udec}",
              f"{100 * e_ud:.2f} %")
diff = max(abs(a - b) / a for a, b in zip(profiles["explicit"], profiles["implicit"]))
check(diff <= 5e-4, "explicit and implicit steady states agree within 0.05 %",
      f"{100 * diff:.4f} %")
finish()
