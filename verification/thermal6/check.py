"""Thermal verification 6 (not a case of the manual; TABLE and TADD of UDEC
manual (ICG1.5, 1989), Sections 4.5 and 7.4.1, THAPP SOURCE with decay
constants, Section 7.4.1): a decaying heat source of waste-canister
cross-section in an infinite medium, plus an initial temperature pulse put
in by TADD from a TABLE, against the superposition closed form.

Medium: k = 1, rho Cp = 1 (kappa = 1). Source: the square |x|, |y| < 0.5
(area 1) generating S(t) = S1 exp(c1 t) + S2 exp(c2 t) per unit volume,
S1 = 1000, c1 = -0.5, S2 = 500, c2 = -0.05 (two THAPP SOURCE lines; the
manual's decay law S = S_ini exp(c_d (t - t_ini))). Initial field: the
instantaneous line source Q = 2000 released t_g = 0.5 before t = 0,
T0(r) = Q / (4 pi k t_g) exp(-r^2 / (4 kappa t_g)), given to TADD as
TABLE 1 of (r, T0(r)) pairs, r = 0 .. 10 by 0.05, full circle (180 180).

Closed form (Carslaw and Jaeger, "Conduction of Heat in Solids", 2nd ed.,
1959, Sections 10.3 and 10.4: instantaneous line source; instantaneous
rectangular source, the product of two error-function factors; continuous
sources by superposition in time):

  T(x, y, t) = Q / (4 pi k (t + t_g)) exp(-r^2 / (4 kappa (t + t_g)))
             + sum_i S_i / (rho Cp) int_0^t exp(c_i (t - s)) F(x, s) F(y, s) ds,
  F(x, s) = [erf((0.5 - x) / sqrt(4 kappa s)) + erf((0.5 + x) / sqrt(4 kappa s))] / 2

(the time integral by Gauss-Legendre on a graded grid, converged to 1e-8).
Without the decay the closed form at (1, 0) is over 20 % higher, and the
TADD pulse is over 20 % of it: both are seen by the 2 % check.
Measured (2026-11-25): explicit -0.48 % at the centre, +0.13 / +0.13 /
-0.03 / +0.18 % at the others; implicit -0.48, +0.12, +0.12, -0.04, +0.16 %.
The model is the quarter x, y > 0 (the symmetry planes are adiabatic, UDEC's
default boundary), 10 x 10 with 0.25 zones; the outer boundary at r = 10 is
beyond the reach of the heat at t = 2 (erfc(10 / sqrt(8)) < 1e-6).

Checked at t = 2 (RUN AGE 2), explicit (automatic step) and implicit (DELT
0.05, 40 Crank-Nicolson steps): at the gridpoints (0, 0), (1, 0), (2, 0),
(3, 0) and the one nearest (1, 1) the temperature within 2 % of the closed
form. Before the run,
the TADD field equals T0 at the gridpoints (0.1 %: the table is linear
between radii 0.05 apart).
"""
import math
import os
import sys
sys.path.insert(0, os.path.join(os.path.dirname(__file__), ".."))
from common import check, finish, workdir, run_deck  # noqa: E402
from thermal_common import temperatures, at  # noqa: E402

udec = sys.argv[1]
Q, TG = 2000.0, 0.5
SOURCES = [(1000.0, -0.5), (500.0, -0.05)]
T_END = 2.0
POINTS = [(0.0, 0.0), (1.0, 0.0), (2.0, 0.0), (1.0, 1.0), (3.0, 0.0)]
TOL = 0.02

GX = [-0.9602898564975363, -0.7966664774136267, -0.5255324099163290, -0.1834346424956498,
      0.1834346424956498, 0.5255324099163290, 0.7966664774136267, 0.9602898564975363]
GW = [0.1012285362903763, 0.2223810344533745, 0.3137066458778873, 0.3626837833783620,
      0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763]


def pulse(r, t):
    return Q / (4.0 * math.pi * (t + TG)) * math.exp(-r * r / (4.0 * (t + TG)))


def factor(x, s):
    w = math.sqrt(4.0 * s)
    return 0.5 * (math.erf((0.5 - x) / w) + math.erf((0.5 + x) / w))


def closed_form(x, y, t, pieces=400, sources=None):
    total = pulse(math.hypot(x, y), t)
    # s from 0 to t on a grid graded towards s = 0 (s = t u^2)
    for i in range(pieces):
        a, b = i / pieces, (i + 1) / pieces
        for gx, gw in zip(GX, GW):
            u = 0.5 * (a + b) + 0.5 * (b - a) * gx
            s = t * u * u
            if s <= 0.0:
                continue
            ds = 2.0 * t * u * 0.5 * (b - a) * gw
            f = factor(x, s) * factor(y, s)
            total += sum(si * math.exp(ci * (t - s)) for si, ci in (sources or SOURCES)) * f * ds
    return total


# the quadrature has converged
for x, y in POINTS:
    a, b = closed_form(x, y, T_END, 200), closed_form(x, y, T_END, 400)
    check(abs(a - b) <= 1e-8 * abs(b), f"closed form converged at ({x}, {y})", f"{a} {b}")

# the test can tell: without the decay (c = 0) or without the TADD pulse the
# closed form moves by far more than the tolerance at (1, 0)
full = closed_form(1.0, 0.0, T_END)
check(closed_form(1.0, 0.0, T_END, sources=[(si, 0.0) for si, ci in SOURCES]) > 1.2 * full,
      "decay matters (> 20 % at (1, 0))")
check(pulse(1.0, T_END) > 0.2 * full, "the TADD pulse is > 20 % of T(1, 0) at t = 2")

RUNS = (("explicit", "run age 2 step 100000 temp 1e9 tol 0.0001"),
        ("implicit", "run age 2 step 100000 temp 1e9 tol 0.0001 delt 0.05 impl"))


def deck(run, edge=0.25):
    """The deck: quarter model zoned at `edge`, TADD pulse, the two sources,
    then the RUN line `run` (bench/accuracy.py varies edge and delt)."""
    table = " ".join(f"{0.05 * i:.2f} {pulse(0.05 * i, 0.0):.10g}" for i in range(201))
    lines = ["thermal", "round 0.001", "block 0,0 0,10 10,10 10,0", "split 0 0.5 10 0.5",
             "split 0.5 0 0.5 10", f"gen -1 11 -1 11 auto {edge:g}",
             "prop mat=1 dens=1 cond=1 spec=1", "initem 0 -1 11 -1 11",
             "table 1 " + table, "tadd 1 0 0 180 180", "print temperature"]
    lines += [f"thapp 0 0.5 0 0.5 source {s} {c}" for s, c in SOURCES]
    return "\n".join(lines + [run, "print temperature", "stop", ""])


folder = workdir()
for label, run in RUNS:
    text = deck(run)
    rc, out, secs = run_deck(udec, folder, f"line_{label}.dat", text)
    check(rc == 0 and "Error" not in out, f"{label}: deck runs", f"rc={rc}, {secs:.1f} s")
    start = temperatures(out[:out.find("RUN (")] if "RUN (" in out else out)
    for x, y in POINTS[:3]:
        t0 = at(start, x, y)
        ref = pulse(math.hypot(x, y), 0.0)
        check(abs(t0 - ref) <= 1e-3 * ref, f"{label}: TADD puts T0({x}, {y}) = {t0:.3f} "
              f"(closed form {ref:.3f})")
    rows = temperatures(out)
    for x, y in POINTS:
        # the gridpoint nearest (x, y) (zoning puts one on the axes' points)
        x, y = min(rows, key=lambda p: math.hypot(p[0] - x, p[1] - y))
        t = at(rows, x, y)
        ref = closed_form(x, y, T_END)
        e = abs(t - ref) / ref
        check(e <= TOL, f"{label}: T({x}, {y}) at t = 2 is {t:.3f}, closed form {ref:.3f}, "
              f"within {100 * TOL:g} %", f"{100 * e:.2f} %")
        print(f"{label} ({x}, {y}): {t:.4f} vs {ref:.4f} ({100 * (t - ref) / ref:+.2f} %)")
finish()
