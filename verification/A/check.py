"""Verification A (manual Appendix A, Test A): slip induced by a normally
incident harmonic shear wave at a joint with cohesion and no friction.

Decks: A1.dat (joint cohesion 2.5 MPa, elastic joint) and A2.dat (0.5 MPa,
slipping joint), run as printed; HIST WRITE lines are added before STOP.
Histories: 1 SXY(-160,-200), 2 SXY(-160,200), 3 XVEL(-160,-200),
4 XVEL(-160,200), every 25 cycles.

References (closed forms; the manual compares graphically, Fig. A-4):
* Incident wave: the applied shear stress 2 MPa on a viscous base sends
  half of it into the model, tau_I = 1.0 MPa (the manual's "maximum stress
  of incident wave 1.0 MPa"), particle velocity tau_I / (rho c_s) with
  c_s = (G / rho)^1/2 = 1942.6 m/s: 0.1942 m/s. Tolerance 3 %.
* A1 (cohesion 2.5 > 1.0 MPa): the wave crosses the joint unchanged; the
  velocity amplitude above the joint equals the one below within 2 %.
* A2: Miller's (1978) coefficients R = (E_R/E_I)^1/2, T = (E_T/E_I)^1/2,
  A = (1 - R^2 - T^2)^1/2 from the energy fluxes per period, computed as
  the manual describes (E_I from history 3 of A1, E_T from history 4 of A2,
  E_R from the difference of history 3 between A2 and A1). Exact values for
  a rigid-plastic interface (the joint stiffness adds a compliance
  omega rho c_s / k_s = 0.003, negligible): the interface sticks while
  |tau_I| < tau_s and slips at tau_s otherwise, so the transmitted stress
  is the incident sine clipped at tau_s and the reflected one the part cut
  off. For omega gamma U / tau_s = tau_I / tau_s = 2 (the manual's case):
  R = 0.4159, T = 0.6253, A = 0.6603 (integrals of the clipped sine,
  computed below). Tolerance: 3 % of each coefficient.
The energy integrals run over one period, t = 1.0 to 2.0 s (the transmitted
wave reaches the top at 0.21 s; steady state before 1 s), with the sampled
histories interpolated linearly.
"""
import bisect
import math
import os
import sys
sys.path.insert(0, os.path.join(os.path.dirname(__file__), ".."))
from common import check, finish, workdir, deck_with, run_deck, read_history  # noqa: E402

udec = sys.argv[1]
here = os.path.dirname(os.path.abspath(__file__))

rho, G = 0.00265, 10000.0           # deck units: 1e6 kg/m3, MPa
cs = math.sqrt(G / rho)
tau_i = 1.0                          # incident amplitude: half of STRESS 0,2,0
tau_s = 0.5                          # A2 joint cohesion
v_i = tau_i / (rho * cs)
T1, PERIOD = 1.0, 1.0


def clipped_coefficients(ratio, n=200000):
    """Exact R, T, A of a sine of amplitude `ratio` tau_s at a rigid-plastic
    interface of strength tau_s (transmitted: clipped; reflected: the rest)."""
    ei = et = er = 0.0
    for k in range(n):
        s = ratio * math.sin(2 * math.pi * (k + 0.5) / n)
        c = max(-1.0, min(1.0, s))
        ei += s * s
        et += c * c
        er += (s - c) ** 2
    r, t = math.sqrt(er / ei), math.sqrt(et / ei)
    return r, t, math.sqrt(1 - r * r - t * t)


def sampler(times, values):
    def f(t):
        i = bisect.bisect_left(times, t)
        i = min(max(i, 1), len(times) - 1)
        u = (t - times[i - 1]) / (times[i] - times[i - 1])
        return values[i - 1] * (1 - u) + values[i] * u
    return f


def flux(f, t1=T1, n=4000):
    h = PERIOD / n
    return sum(f(t1 + (k + 0.5) * h) ** 2 for k in range(n)) * h


def amplitude(times, values, t1=T1):
    return max(abs(v) for t, v in zip(times, values) if t1 <= t <= t1 + PERIOD)


folder = workdir()
runs = {}
for name in ("A1", "A2"):
    extra = [f"HIST WRITE {h} {name.lower()}_h{h}.txt" for h in (1, 2, 3, 4)]
    rc, out, sec = run_deck(udec, folder, f"{name}.dat", deck_with(os.path.join(here, f"{name}.dat"), extra))
    check(rc == 0, f"{name}.dat runs", out[-2000:] if rc else f"{sec:.2f} s")
    if rc != 0:
        finish()
    runs[name] = {h: read_history(os.path.join(folder, f"{name.lower()}_h{h}.txt")) for h in (1, 2, 3, 4)}

a1, a2 = runs["A1"], runs["A2"]
s_bot = amplitude(*a1[1])
v_bot, v_top = amplitude(*a1[3]), amplitude(*a1[4])
check(abs(s_bot / tau_i - 1) < 0.03, "A1: incident shear stress amplitude 1.0 MPa (3 %)",
      f"{s_bot:.4f} MPa")
check(abs(v_bot / v_i - 1) < 0.03, "A1: incident velocity tau_I/(rho c_s) (3 %)",
      f"{v_bot:.4f} vs {v_i:.4f} m/s")
check(abs(v_top / v_bot - 1) < 0.02, "A1: elastic joint transmits the wave unchanged (2 %)",
      f"top {v_top:.4f}, bottom {v_bot:.4f} m/s")

f_inc = sampler(*a1[3])
f_tra = sampler(*a2[4])
t_b2, v_b2 = a2[3]
f_b2 = sampler(t_b2, v_b2)
e_i = flux(f_inc)
e_t = flux(f_tra)
e_r = flux(lambda t: f_b2(t) - f_inc(t))
R, T = math.sqrt(e_r / e_i), math.sqrt(e_t / e_i)
A = math.sqrt(max(0.0, 1 - R * R - T * T))
Rx, Tx, Ax = clipped_coefficients(tau_i / tau_s)
for label, got, ref in (("R", R, Rx), ("T", T, Tx), ("A", A, Ax)):
    check(abs(got / ref - 1) < 0.03, f"A2: Miller coefficient {label} at omega gamma U / tau_s = 2 (3 %)",
          f"{got:.4f} vs exact {ref:.4f} ({100 * (got / ref - 1):+.1f} %)")
# Not asserted: the peak transmitted velocity overshoots the cap
# tau_s/(rho c_s) by 4.3 % with the deck's 60 m zones (2.7 % at EDGE 30):
# dispersion of the clipped wave's kinks (README). The fluxes above are
# what the manual compares.
v_cap = amplitude(*a2[4])
print(f"A2: peak transmitted velocity {v_cap:.4f} m/s, cap tau_s/(rho c_s) {tau_s / (rho * cs):.4f} "
      f"({100 * (v_cap * rho * cs / tau_s - 1):+.1f} %; not asserted)")
finish()
