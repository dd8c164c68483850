"""Thermal verification Case 4 (manual Section 7.8.5, Table 7-5): unit heat
flux into a semi-infinite slab; temperatures at t = 0.2 s and 1.0 s, and the
thermal yy-stress after mechanical equilibrium (rollers on y = 0 and 0.2).

The decks run as printed. `bou -1 6 ... yvel 0` takes two corners of the
rigid block x > 5 as well: there the velocity constrains the block's motion
(engine_rigid_velocity; a note says so), and that block is FIXed, which
wins. The rigid block carries temperatures (Fig. 7-4 triangles). `print temperature`
after each thermal SAVE, and `print hist 4 5 6 7 8 9`, `print zone`,
`print gridpoint` after each `c 2000` are added.

References: T = (2 q sqrt(a t) / k) ierfc(x / (2 sqrt(a t))) (Carslaw and
Jaeger p. 75) and syy = -E alpha T / (1 - nu) (Timoshenko and Goodier p.
435; E = 1, nu = 0.25 from K = 0.667, G = 0.4; alpha = 1e-3).

Tolerances:
* Temperatures at the table's x (interpolated linearly between the
  gridpoints on y = 0, spacing 0.1 m): within 1.5 % for both runs (manual:
  up to 1.39 % explicit, 2.40 % implicit) where T > 0.05; below that (the
  row x = 1.094 at t = 0.2, T = 0.0215) within 1e-3 absolute, 0.2 % of the
  surface temperature: linear interpolation over 0.1 m of the convex ierfc
  profile alone overestimates by about 3e-4 there (measured +5.1e-4).
* syy in the history zones (constant-stress triangles; the history names
  the zone whose centroid is nearest to the requested point) against the
  closed form at the zone's centroid: within 5 % at all six (manual: up to
  5.4 % at its points). The centroids lie up to 0.06 m from the table's x
  (0.411 -> 0.350), where the closed form differs by 3 to 19 % from its
  value at the table's x: that is the "syy off by up to 19 %" seen when a
  history is compared with the table's row (README.md).
* syy at the table's x itself, the whole table (six x, both times): a
  quadratic least-squares fit (area-weighted) of the zone stresses whose
  centroids lie within 0.3 m of x, evaluated at x, against the closed form:
  within 3 % at t = 0.2 s and 1 % at t = 1.0 s (manual's own largest
  errors 5.43 % and 2.17 %; measured 2.2 % and 0.2 %).
* SET NTHER 2000 NMECH 50 before the first RUN (explicit deck, a third run):
  the automatic hand-over to mechanical cycles (Section 7.5.1) must give the
  same equilibrium syy after `c 2000` at t = 0.2 s within 0.5 % (the
  thermal stress is linear in the temperature change, so applying it in two
  parts changes only the path).
"""
import math
import os
import re
import sys
sys.path.insert(0, os.path.join(os.path.dirname(__file__), ".."))
from common import check, finish, workdir, deck_with, run_deck  # noqa: E402
from thermal_common import temperatures, along  # noqa: E402

udec = sys.argv[1]
here = os.path.dirname(os.path.abspath(__file__))
XS = [0, 0.1563, 0.3125, 0.4688, 0.625, 0.7813, 1.094]
# Table 7-5, analytical Syy (in units of 1e-3 of the deck's stress unit)
SXS = [0.1098, 0.214, 0.411, 0.5385, 0.839, 1.036]
STABLE = {0.2: [-0.5369, -0.4259, -0.2624, -0.185, -0.0727, -0.0363],
          1.0: [-1.3629, -1.2368, -1.02, -0.8951, -0.6439, -0.5104]}


def _rows(lines, start):
    rows = []
    for line in lines[start + 1:]:
        try:
            rows.append([float(v) for v in line.split()[:6]])
        except ValueError:
            break
        if not rows[-1]:
            break
    return rows


def zone_field(text):
    """[(xc, area, syy)] of every zone, from PRINT ZONE and PRINT GRIDPOINT."""
    lines = text.splitlines()
    geo = st = gp = None
    for i, line in enumerate(lines):
        if line.startswith("    ZONE   BLOCK     GP1"):
            geo = _rows(lines, i)
        elif line.startswith("    ZONE   BLOCK           SXX"):
            st = _rows(lines, i)
        elif line.startswith("  GRIDPT   BLOCK             X             Y        X-DISP"):
            gp = _rows(lines, i)
    xy = {int(r[0]): r[2] for r in gp}
    return [(sum(xy[int(g[k])] for k in (2, 3, 4)) / 3, g[5], z[4]) for g, z in zip(geo, st)]


def fit_at(zones, x, h=0.3):
    """Area-weighted quadratic least-squares fit of syy(xc) over |xc - x| <= h, at x."""
    m = [[0.0] * 3 for _ in range(3)]
    b = [0.0] * 3
    for xc, a, s in zones:
        if abs(xc - x) <= h:
            r = [1.0, xc - x, (xc - x) ** 2]
            for i in range(3):
                b[i] += a * r[i] * s
                for j in range(3):
                    m[i][j] += a * r[i] * r[j]
    for i in range(3):  # Gaussian elimination (3 x 3, positive definite)
        for k in range(i + 1, 3):
            f = m[k][i] / m[i][i]
            for j in range(i, 3):
                m[k][j] -= f * m[i][j]
            b[k] -= f * b[i]
    c = [0.0] * 3
    for i in (2, 1, 0):
        c[i] = (b[i] - sum(m[i][j] * c[j] for j in range(i + 1, 3))) / m[i][i]
    return c[0]


def ierfc(u):
    return math.exp(-u * u) / math.sqrt(math.pi) - u * math.erfc(u)


def temp(x, t):
    return 2 * math.sqrt(t) * ierfc(x / (2 * math.sqrt(t)))


def syy(x, t):
    return -1.0 * 1e-3 * temp(x, t) / 0.75


# the closed forms reproduce the table's analytical columns
# (the table rounds; 0.8436 at x = 0.3125, t = 1 is 0.8433 by the formula: 4e-4)
check(abs(temp(0, 0.2) - 0.5046) < 1e-4 and abs(temp(0.3125, 1.0) - 0.8436) < 5e-4,
      "closed-form temperature matches Table 7-5")
check(abs(1e3 * syy(0.1098, 0.2) + 0.5369) < 1e-3, "closed-form stress matches Table 7-5 "
      "(in units of 1e-3)")

folder = workdir()
reference_nther = {}
for deck, label, ttol in (("case_a.dat", "explicit", 0.015), ("case_b.dat", "implicit", 0.015)):
    save1, save2 = ("case4_1e.sav", "case4_2e.sav") if label == "explicit" else \
        ("case4_1i.sav", "case4_2i.sav")
    prt = "print -1 2 -0.001 0.001 temperature"
    replace = [(f"save {save1}\n", f"save {save1}\n{prt}\n"),
               (f"save {save2}\n", f"save {save2}\n{prt}\n"),
               ("c 2000\n", "c 2000\nprint hist 4 5 6 7 8 9\nprint zone\nprint gridpoint\n")]
    text = deck_with(os.path.join(here, deck), [], replace)
    rc, out, secs = run_deck(udec, folder, deck, text)
    check(rc == 0, f"{deck} ({label}) runs as printed", f"rc={rc}, {secs:.1f} s")
    check(out.count("corner(s) of rigid or SDEF blocks") == 2,
          f"{label}: the two BOUNDARY YVEL lines note the rigid corners they constrain")
    # temperature tables: split the output at each print
    parts = out.split(prt)
    check(len(parts) >= 3, f"{label}: two temperature tables printed")
    for part, t in zip(parts[1:3], (0.2, 1.0)):
        rows = temperatures(part)
        line = [(x, y) for (x, y) in rows if abs(y) < 1e-9 and x <= 5]
        for x in XS:
            v = along(rows, line, x)
            ref = temp(x, t)
            ok = abs(v - ref) <= (ttol * ref if ref > 0.05 else 1e-3)
            check(ok, f"{label} t={t}: T({x}) = {v:.5f} vs {ref:.5f}",
                  f"{100 * (v / ref - 1):+.2f} %")
    # history zone centroids
    cent = {int(m.group(1)): float(m.group(2)) for m in
            re.finditer(r"history (\d): SYY \(\S+\) taken at zone \d+ \(([-\d.E]+),", out)}
    check(len(cent) == 6, f"{label}: six SYY histories", f"{cent}")
    tables = out.split("print hist 4 5 6 7 8 9")[1:]
    check(len(tables) == 2, f"{label}: two history prints")
    for tab, t in zip(tables, (0.2, 1.0)):
        rows = [l.split() for l in tab.splitlines()
                if re.match(r"^\s+\d\.\d+E[-+]\d+\s+-?\d", l)]
        last = [float(v) for v in rows[-1][1:7]]
        if label == "explicit" and t == 0.2:
            reference_nther = dict(zip(range(4, 10), last))
        for h, v in zip(range(4, 10), last):
            x = cent.get(h, float("nan"))
            ref = syy(x, t)
            check(abs(v - ref) <= 0.05 * abs(ref),
                  f"{label} t={t}: history syy at the centroid x={x:.4f} = {v:.4e} vs {ref:.4e}",
                  f"{100 * (v / ref - 1):+.2f} %")
        zones = zone_field(tab)
        for x, tabled in zip(SXS, STABLE[t]):
            v = fit_at(zones, x)
            ref = syy(x, t)
            # the table's analytical figures are the closed form to 1e-3 (largest
            # differences: 5e-4 at x = 1.036, t = 0.2; 8e-4 at x = 0.839, t = 1.0)
            check(abs(1e3 * ref - tabled) <= 1e-3, f"closed form {1e3 * ref:.4f} is the table's "
                  f"{tabled} at x = {x}, t = {t} (units of 1e-3)")
            tol = 0.03 if t == 0.2 else 0.01
            check(abs(v - ref) <= tol * abs(ref),
                  f"{label} t={t}: syy at the table's x={x} = {v:.4e} vs {ref:.4e} within "
                  f"{100 * tol:g} %", f"{100 * (v / ref - 1):+.2f} %")
# NTHER / NMECH: the same t = 0.2 s stresses through the automatic hand-over
replace = [("run clo 1e10", "set nther 2000 nmech 50\nrun clo 1e10"),
           ("c 2000\n", "c 2000\nprint hist 4 5 6 7 8 9\n")]
text = deck_with(os.path.join(here, "case_a.dat"), [], replace)
rc, out, secs = run_deck(udec, folder, "case_a.dat", text)
check(rc == 0, "case_a.dat with SET NTHER 2000 NMECH 50 runs", f"rc={rc}, {secs:.1f} s")
check(len(re.findall(r"^cycle \d+, time", out.split("save case4_1e.sav")[0], re.M)) == 2,
      "NTHER hands over to mechanical cycles twice during the 4000 thermal steps")
tab = out.split("print hist 4 5 6 7 8 9")[1]
rows = [l.split() for l in tab.splitlines() if re.match(r"^\s+\d\.\d+E[-+]\d+\s+-?\d", l)]
last = [float(v) for v in rows[-1][1:7]]
for h, v in zip(range(4, 10), last):
    ref = reference_nther[h]
    check(abs(v - ref) <= 0.005 * abs(ref), f"NTHER: syy history {h} = {v:.4e} vs {ref:.4e} "
          "without NTHER", f"{100 * (v / ref - 1):+.2f} %")
finish()
