"""Application F (manual Appendix B, Problem F): load cycle of an elastic
specimen with a slipping crack (Olsson 1982; Brady et al. 1985).

Reference: Fig. F-1 and Fig. F-3 of the manual. The stress-displacement
path has three segments: loading OA (elastic deformation plus slip on the
crack), initial unloading AB (the crack does not slip: stiffer), final
unloading (slip again: softer than AB). With crack friction 50 degrees
(> the 45-degree crack inclination) the crack never slips, and the manual's
Fig. F-3 shows that the initial unloading slope for 16 degrees equals the
slope for 50 degrees.
Checks (issue 6): for friction 16 degrees the loading slope and the final
unloading slope are each at least 5 % below the initial unloading slope
(three distinct segments appear); the initial unloading slopes for 16 and
50 degrees agree within 2 %.
Measures after every load/unload step (the deck's PRINT CONT points):
sigma_a = |sum of the reactions FY of the prescribed top gridpoints| / 1 m
width (PRINT BOUNDARY FORCES), u_a = top minus bottom mean y-displacement
(PRINT BOUNDARY DISP).
"""
import math
import os
import sys
sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "..", "verification"))
from common import check, finish, workdir, deck_with, run_deck, boundary_tables  # noqa: E402

udec = sys.argv[1]
deck = os.path.join(os.path.dirname(os.path.abspath(__file__)), "F1_slipping_crack.dat")


def run(friction, folder):
    extra_prints = "PRINT CONT\nPRINT -.1,1.1 1.9,2.1 BOUNDARY FORCES\nPRINT -.1,1.1 -.1,2.1 BOUNDARY DISP\n"
    text = deck_with(deck, [], replace=[("JF=0.287", f"JF={friction:.6f}"), ("F=0.287)", f"F={friction:.6f})")])
    text = text.replace("PRINT CONT\n", extra_prints)
    rc, out, sec = run_deck(udec, folder, f"F_{friction:.3f}.dat", text)
    check(rc == 0, f"friction {friction:.3f}: deck runs", out[-2000:] if rc else f"{sec:.1f} s")
    if rc:
        return None
    forces = boundary_tables(out, "BOUNDARY FORCES")
    disps = boundary_tables(out, "BOUNDARY DISPLACEMENTS")
    sig, u = [0.0], [0.0]
    for fr, dr in zip(forces, disps):
        top = [r for r in fr if r[4] == 4 and r[2] > 1.0]
        sig.append(abs(sum(r[6] for r in top)) / 1.0)
        ut = [r[4] for r in dr if r[2] > 1.9]
        ub = [r[4] for r in dr if r[2] < 0.1]
        u.append(abs(sum(ut) / len(ut) - sum(ub) / len(ub)))
    return sig, u


def slope(sig, u, i, j):
    return (sig[j] - sig[i]) / (u[j] - u[i])


folder = workdir()
res = {}
for name, phi in [("16", 16.0), ("50", 50.0)]:
    res[name] = run(math.tan(math.radians(phi)), folder)
if res["16"] and res["50"]:
    s16, u16 = res["16"]
    s50, u50 = res["50"]
    n = len(s16) - 1
    check(n == 9, "nine load/unload steps measured", f"{n}")
    # points: 0 start, 1-4 loading, 5-9 unloading
    load16 = slope(s16, u16, 1, 4)
    init16 = slope(s16, u16, 4, 5)
    final16 = slope(s16, u16, 7, 9)
    init50 = slope(s50, u50, 4, 5)
    load50 = slope(s50, u50, 1, 4)
    print("phi 16: sigma_a", " ".join(f"{v:.4e}" for v in s16))
    print("phi 16: u_a    ", " ".join(f"{v:.4e}" for v in u16))
    print(f"slopes [Pa/m]: 16 deg loading {load16:.4e}, initial unloading {init16:.4e}, "
          f"final unloading {final16:.4e}; 50 deg loading {load50:.4e}, initial unloading {init50:.4e}")
    check(load16 < 0.95 * init16, "16 deg: loading slope (elastic + slip) below the initial unloading slope")
    check(final16 < 0.95 * init16, "16 deg: final unloading slope (slip again) below the initial unloading slope")
    check(abs(init16 - init50) <= 0.02 * init50, "initial unloading slope equal for 16 and 50 deg within 2 %",
          f"{100*(init16/init50-1):+.2f} %")
finish()
