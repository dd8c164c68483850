"""Verification B (manual Appendix A, Test B): elastic jointed medium.

Reference: Singh's (1973) transversely isotropic moduli, Eqs. B-1 to B-6,
with the manual's joint stiffnesses and the boundary-adjusted spacings
s_n = 2/9.5 m, s_s = 2/9 m, stagger s = 0.1 m (computed here: E_n = 53.4,
E_s = 44.2 GPa, nu_ns = 0.156; the manual prints 53.3, 44.0, 0.16), used in
plane-strain transversely isotropic relations (Lekhnitskii) as the manual
says:
   s-direction (x) cycling, sigma_n fixed:  slope = E_s / (1 - nu^2)
   n-direction (y) cycling, sigma_s fixed:  slope = E_n / (1 - nu_ns^2 E_s / E_n)
Acceptance (manual text and issue 6): the stress-strain slopes of loading
(2 -> 10 MPa) and unloading (10 -> 2 MPa) are within 4 % of these, in
both directions. B.dat is the manual's deck (x cycling); B_n.dat is ours
(y cycling, not printed in the manual, see README).
Strains: x from XDIS at (0,1) and (2,1), y from YDIS at (1,0) and (1,2),
over the 2 m sample; one value at the end of every 1500-cycle load step.
Slope of a branch: least-squares slope of stress change against strain
over its five points (the slope of the curves of Figs. B2 and B-3).
"""
import os
import sys
sys.path.insert(0, os.path.join(os.path.dirname(__file__), ".."))
from common import check, finish, workdir, deck_with, run_deck, read_history  # noqa: E402

udec = sys.argv[1]
here = os.path.dirname(os.path.abspath(__file__))

Ei, nui = 89e9, 0.26
knv, ksv, knh, ksh = 395.9e9, 438.8e9, 531.9e9, 438.8e9
sn, ss, s = 2 / 9.5, 2 / 9, 0.1
bnn = 1 / (1 + ksv * s / (knh * ss) * (1 - s / sn))
En = Ei / (1 + bnn * Ei / (knh * sn))
Es = Ei / (1 + Ei / (knv * ss))
nuns = nui * knh * sn / (knh * sn + bnn * Ei)
slope_s = Es / (1 - nui ** 2)
slope_n = En / (1 - nuns ** 2 * Es / En)
check(abs(En - 53.3e9) < 0.2e9 and abs(Es - 44.0e9) < 0.3e9 and abs(nuns - 0.16) < 0.005,
      "Singh constants reproduce the manual's E_n 53.3, E_s 44.0 GPa, nu_ns 0.16",
      f"E_n {En/1e9:.2f} E_s {Es/1e9:.2f} nu_ns {nuns:.3f}")

folder = workdir()
samples_per_step = 1500 // 50


def step_values(h):
    """History value at the end of each load step (0 = before loading)."""
    return [0.0] + [h[samples_per_step * k - 1] for k in range(1, 9)]


for deck, hists, ref, label in [("B.dat", (3, 4), slope_s, "x (s-direction)"),
                                ("B_n.dat", (1, 2), slope_n, "y (n-direction)")]:
    extra = [f"HIST WRITE {hists[0]} h{hists[0]}.txt", f"HIST WRITE {hists[1]} h{hists[1]}.txt"]
    rc, out, sec = run_deck(udec, folder, deck, deck_with(os.path.join(here, deck), extra))
    check(rc == 0, f"{deck} runs", out[-2000:] if rc else f"{sec:.1f} s")
    if rc:
        continue
    _, a = read_history(os.path.join(folder, f"h{hists[0]}.txt"))
    _, b = read_history(os.path.join(folder, f"h{hists[1]}.txt"))
    eps = [(vb - va) / 2.0 for va, vb in zip(step_values(a), step_values(b))]
    # least-squares slope of |stress change| against |strain change| over
    # the five points of each branch (the slope of the plotted curve)
    def fit(idx, sig):
        xs = [eps[i] for i in idx]
        mx, my = sum(xs) / 5, sum(sig) / 5
        return sum((x - mx) * (y - my) for x, y in zip(xs, sig)) / sum((x - mx) ** 2 for x in xs)
    load = fit(range(0, 5), [-2e6 * k for k in range(5)])
    unload = fit(range(4, 9), [-8e6 + 2e6 * k for k in range(5)])
    for name, val in [("loading", load), ("unloading", unload)]:
        err = (val - ref) / ref
        check(abs(err) <= 0.04, f"{label} {name} slope within 4 % of {ref/1e9:.2f} GPa",
              f"{val/1e9:.2f} GPa, {100*err:+.2f} %")
    print(f"{deck}: wall time {sec:.1f} s; strains at step ends: " + " ".join(f"{e:.3e}" for e in eps))
finish()
