"""Verification E (manual Appendix A, Test E), unsupported cases: radial
displacement of a circular tunnel wall (r = 1) in an elastic medium
(G = 1e3, P0 = 10 in the deck's units) after excavation.

References (manual Table E-1): analytic u = r P0 / 2G = 5.0e-3 (Eq. E-1);
UDEC 1989 with a constant-stress far-field boundary (E1): 5.2e-3, with a
zero-displacement boundary (E3): 4.7e-3. Acceptance (issue 6): each of
ours within 5 % of the manual's own number for the same boundary.
u is the mean inward displacement of the four wall points of histories
1-4 (XDIS at (1,0) and (-1,0), YDIS at (0,1) and (0,-1)) after the deck's
400 cycles.
"""
import os
import sys
sys.path.insert(0, os.path.join(os.path.dirname(__file__), ".."))
from common import check, finish, workdir, deck_with, run_deck, read_history  # noqa: E402

udec = sys.argv[1]
here = os.path.dirname(os.path.abspath(__file__))
folder = workdir()
extra = [f"HIST WRITE {k} h{k}.txt" for k in (1, 2, 3, 4)]


def wall_displacement():
    h = [read_history(os.path.join(folder, f"h{k}.txt"))[1][-1] for k in (1, 2, 3, 4)]
    return (-h[0] + h[1] - h[2] + h[3]) / 4.0, h


for deck, ref, label in [("E1_stress_bc_no_support.dat", 5.2e-3, "constant-stress boundary"),
                         ("E3_zero_disp_no_support.dat", 4.7e-3, "zero-displacement boundary")]:
    rc, out, sec = run_deck(udec, folder, deck, deck_with(os.path.join(here, deck), extra))
    check(rc == 0, f"{deck} runs", out[-2000:] if rc else f"{sec:.1f} s")
    if rc:
        continue
    u, h = wall_displacement()
    err = (u - ref) / ref
    check(abs(err) <= 0.05, f"{label}: wall displacement within 5 % of the manual's {ref*1e3:.1f} mm",
          f"{u*1e3:.3f} mm ({100*err:+.1f} %), analytic 5.0 mm; points " + " ".join(f"{v:.3e}" for v in h))
finish()
