"""Salencon's tunnel for another friction angle and with dilation (label
`verification`): the wall displacement of closed_forms_fields.py case 9
(there phi = 30 degrees, DIL = 0) for phi = 40 degrees, DIL = 0 and for
phi = 30 degrees with a dilation angle psi = 20 degrees (DIL = tan psi =
0.36397, manual Section 4.5, PROPERTY: "block dilation coefficient, tangent
of dilation angle"). Decks written from the manual's syntax (the tunnel of
shared_decks.salencon_tunnel: a = 1, p0 = 10 MPa, c = 1 MPa, K = 2e9,
G = 1e9, nu = 0.2857, 16 a quarter square, the wall pressure lowered to
pi = 1 MPa in STEPS equal steps).

Reference (Salencon 1969; the plastic zone's stresses and radius do not
depend on psi): Kp = (1 + sin phi) / (1 - sin phi), sc = 2 c cos phi /
(1 - sin phi), R = a [2 (p0 (Kp - 1) + sc) / ((Kp + 1) ((Kp - 1) pi +
sc))]^(1 / (Kp - 1)): 1.4653 a (phi 30), 1.1818 a (phi 40); in the plastic
zone s_r = (pi + sc / (Kp - 1)) (r / a)^(Kp - 1) - sc / (Kp - 1), s_t =
Kp s_r + sc (compression positive). The plastic strains obey the flow
rule e_r^p + Kpsi e_t^p = 0, Kpsi = (1 + sin psi) / (1 - sin psi), so
with e_r = du/dr, e_t = u / r:
    d(r^Kpsi u) / dr = r^Kpsi (e_r^e + Kpsi e_t^e),
the elastic strains those of the stress change (plane strain), integrated
inwards from the elastic ring's u(R) = -(p0 - s_re) R / (2 G), s_re =
(2 p0 - sc) / (Kp + 1). psi = 0 gives case 9's -7.068 mm; phi 40: -5.248
mm; phi 30, psi 20: -9.097 mm (29 % more than without dilation).

Tolerance: the mean radial displacement of the wall's gridpoints within 2 %,
as in case 9. Measured with STEPS = 18 (case 9's unloading): -0.77 % (phi 40),
-0.73 % (psi 20); with the 9 steps used here: -0.43 % and +0.28 %.
The error budget of the psi 20 case (docs/closed_form.md, "The Salencon
tunnel's error budget", session 45): the closed form is confirmed to 0.1 % by
an independent 1-D finite-element solution (tools/salencon_fe1d.py); the
stress boundary at 16 a adds +1.4 %, the 48-sided wall -0.3 %, the zones of
0.15 a -0.3 %, large strain (the engine moves its gridpoints, the closed form
is small-strain) -1.5 %, and each of the 9 stages, given at once, overshoots
and adds about +1.8 % of plastic flow (36 stages: -1.56 %); what remains is a
dilatant-flow deficit of the engine of about 2 % in the quasi-static limit
(psi 0 agrees there), open. So the +0.28 % passes by that luck: a deck
without it (small strain, 32 a, converged staging) reads -2 % or below. The
tolerance is not loosened and the deck not changed until the deficit is found.
"""
import math
import sys
from shared_decks import salencon_tunnel
from udec_test import check, finish, run_clean, tables

udec = sys.argv[1]
P0, PI, COH, GS, KB = 1.0e7, 1.0e6, 1.0e6, 1.0e9, 2.0e9
NU = (3 * KB - 2 * GS) / (2 * (3 * KB + GS))
STEPS = 9


def salencon_wall(phi_deg, psi_deg, n=4000):
    """u(a) (a = 1, outward positive) and R for friction and dilation
    angles phi and psi (degrees)."""
    s = math.sin(math.radians(phi_deg))
    kp = (1 + s) / (1 - s)
    sc = 2 * COH * math.cos(math.radians(phi_deg)) / (1 - s)
    r_pl = (2 * (P0 * (kp - 1) + sc) / ((kp + 1) * ((kp - 1) * PI + sc))) ** (1 / (kp - 1))
    sre = (2 * P0 - sc) / (kp + 1)
    sp = math.sin(math.radians(psi_deg))
    kpsi = (1 + sp) / (1 - sp)
    val = r_pl ** kpsi * (-(P0 - sre) * r_pl / (2 * GS))
    h = (r_pl - 1.0) / n
    for k in range(n):
        rho = 1.0 + (k + 0.5) * h
        sr = (PI + sc / (kp - 1)) * rho ** (kp - 1) - sc / (kp - 1)
        st = kp * sr + sc
        er = -((1 - NU) * (sr - P0) - NU * (st - P0)) / (2 * GS)
        et = -((1 - NU) * (st - P0) - NU * (sr - P0)) / (2 * GS)
        val -= rho ** kpsi * (er + kpsi * et) * h
    return val, r_pl


for name, phi, psi in (("phi40", 40.0, 0.0), ("psi20", 30.0, 20.0)):
    deck = salencon_tunnel(16, 3, 1.0, STEPS, 1500, ["PRINT GRID DISP"])
    props = f"FRIC={math.tan(math.radians(phi)):.5f} DIL={math.tan(math.radians(psi)):.5f}"
    check("FRIC=0.57735 DIL=0 " in deck, f"{name}: the shared deck's properties found")
    out = run_clean(udec, "salencon_" + name, deck.replace("FRIC=0.57735 DIL=0 ", props + " "))
    gd = tables(out, "PRINT GRID DISP")
    if not gd:
        check(False, f"salencon {name}: gridpoints printed")
        continue
    us = [(g["X-DISP"] * g["X"] + g["Y-DISP"] * g["Y"]) / math.hypot(g["X"], g["Y"])
          for g in gd[-1] if abs(math.hypot(g["X"], g["Y"]) - 1.0) < 0.02]
    ref, r_pl = salencon_wall(phi, psi)
    mean = sum(us) / len(us) if us else float("nan")
    print(f"salencon {name}: R = {r_pl:.4f} a, {len(us)} wall gridpoints, mean {mean:.5g} m "
          f"(closed form {ref:.5g}, {100 * (mean / ref - 1):+.2f} %)")
    check(len(us) >= 13 and abs(mean - ref) < 0.02 * abs(ref),
          f"salencon {name}: mean wall displacement of the closed form with dilation within 2 %",
          f"{mean:.5g} against {ref:.5g}")
finish()
