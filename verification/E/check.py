"""Verification E (manual Appendix A, Test E): radial
displacement of a circular tunnel wall (r = 1) in an elastic medium
(G = 1e3, P0 = 10 in the deck's units) after excavation.

References (manual Table E-1): analytic u = r P0 / 2G = 5.0e-3 (Eq. E-1);
UDEC 1989 with a constant-stress far-field boundary (E1): 5.2e-3, with a
zero-displacement boundary (E3): 4.7e-3. Acceptance (issue 6): each of
ours within 5 % of the manual's own number for the same boundary.
u is the mean inward displacement of the four wall points of histories
1-4 (XDIS at (1,0) and (-1,0), YDIS at (0,1) and (0,-1)) after the deck's
400 cycles.

Supported cases (E2 constant stress, E4 fixed boundary; 24 beam elements,
STRUCTURE 0 0 7.5 1.1 24 1 .1, KN = 1e3): Table E-1 gives
  wall displacement with support: 4.6e-3 (E2), 4.2e-3 (E4)  -> asserted, 5 %
  support stiffness 243 MPa/m (both)                          -> asserted, 5 %
  support pressure 1.117 (E2), 1.021 (E4) MPa                 -> reported only
  support pressure vs the ground-reaction closed form built on this
  model's own unsupported wall displacement at the support angles
  (K u0 / (1 + K u0 / P0), Fig. E-3)                          -> asserted, 5 %
The support pressure P_i is the mean thrust (-axial force of PRINT STE)
divided by the support radius 1 m (manual text). The support stiffness is
P_i over the wall's inward displacement where the support touches it (node
displacement of PRINT LM plus the interface closure -un of PRINT STC): this
is what Table E-1's 243 = 1.117 / 4.6e-3 = 1.021 / 4.2e-3 measures.

With the deck's joints our P_i is the manual's to 0.2 % (E2 1.1150 MPa,
E4 1.0200 MPa; reported, not asserted). Until 2026-11-26 it was 5 % and
9 % above: at every vertex of the TUNNEL rings the inner ring's corner
fills a re-entrant corner of the outer ring and had a contact with only one
of the two chords, so the "transparent" ring joints were not, the wall
moved 5.2 mm at the joints but up to 6.06 mm between them, and the support
(which touches the wall between the joints) met more ground movement
(README, "Ring vertices"). Not asserted against the manual's P_i; instead
against the ground-reaction closed form with this model's own wall, and,
with JKN = JKS = 1e5, P_i = 1.048 MPa (analytic 1.075) and P_i / u = 240.1
MPa/m, asserted below (5 %) as the check of the structure against the
closed form with a uniform ground.
"""
import math
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


def wall_at_supports(out):
    """Inward radial displacement of the unsupported wall (gridpoints at
    r = 1 m before excavation, PRINT GRID DISP), interpolated in angle at the
    24 support nodes (7.5 + 15 k degrees): the mean, min and max."""
    lines = out.splitlines()
    start = [i for i, l in enumerate(lines) if l.startswith("  GRIDPT   BLOCK")][-1]
    pts = []
    for line in lines[start + 1:]:
        v = line.split()
        if len(v) < 8 or not v[0].isdigit():
            break
        x, y, ux, uy = (float(t) for t in v[2:6])
        x0, y0 = x - ux, y - uy
        r = math.hypot(x0, y0)
        if abs(r - 1.0) < 1e-3:
            pts.append((math.degrees(math.atan2(y0, x0)) % 360.0, -(ux * x0 + uy * y0) / r))
    pts.sort()
    ext = [(t - 360.0, u) for t, u in pts] + pts + [(t + 360.0, u) for t, u in pts]
    us = []
    for k in range(24):
        a = 7.5 + 15.0 * k
        for (t1, u1), (t2, u2) in zip(ext, ext[1:]):
            if t1 <= a <= t2 and t2 > t1:
                us.append(u1 + (u2 - u1) * (a - t1) / (t2 - t1))
                break
    return sum(us) / max(len(us), 1), min(us), max(us), len(pts), len(us)


ground = {}
for deck, ref, label in [("E1_stress_bc_no_support.dat", 5.2e-3, "constant-stress boundary"),
                         ("E3_zero_disp_no_support.dat", 4.7e-3, "zero-displacement boundary")]:
    rc, out, sec = run_deck(udec, folder, deck, deck_with(os.path.join(here, deck),
                                                          extra + ["PRINT GRID DISP"]))
    check(rc == 0, f"{deck} runs", out[-2000:] if rc else f"{sec:.1f} s")
    if rc:
        continue
    ground[label] = wall_at_supports(out)
    print(f"info: {label}: unsupported wall at the 24 support angles: mean "
          f"{ground[label][0]*1e3:.3f} mm (min {ground[label][1]*1e3:.3f}, max "
          f"{ground[label][2]*1e3:.3f}; {ground[label][3]} wall gridpoints)")
    u, h = wall_displacement()
    err = (u - ref) / ref
    check(abs(err) <= 0.05, f"{label}: wall displacement within 5 % of the manual's {ref*1e3:.1f} mm",
          f"{u*1e3:.3f} mm ({100*err:+.1f} %), analytic 5.0 mm; points " + " ".join(f"{v:.3e}" for v in h))


def table(out, title, ncol):
    """Rows (lists of floats) of the PRINT table whose first line starts with title."""
    lines = out.splitlines()
    start = [i for i, l in enumerate(lines) if l.startswith(title)][-1]
    rows = []
    for line in lines[start + 2:]:
        v = line.split()
        if len(v) < ncol or not v[0].isdigit():
            break
        rows.append([float(x) for x in v[:ncol]])
    return rows


for deck, u_ref, p_ref, label in [
        ("E2_stress_bc_support.dat", 4.6e-3, 1.117, "constant-stress boundary, support"),
        ("E4_zero_disp_support.dat", 4.2e-3, 1.021, "zero-displacement boundary, support")]:
    rc, out, sec = run_deck(udec, folder, deck,
                            deck_with(os.path.join(here, deck), extra + ["PRI LM STC"]))
    check(rc == 0, f"{deck} runs", out[-2000:] if rc else f"{sec:.1f} s")
    if rc:
        continue
    u, h = wall_displacement()
    err = (u - u_ref) / u_ref
    check(abs(err) <= 0.05, f"{label}: wall displacement within 5 % of the manual's "
          f"{u_ref*1e3:.1f} mm", f"{u*1e3:.3f} mm ({100*err:+.1f} %)")
    ste = table(out, "Structural elements", 7)
    check(len(ste) == 24, f"{label}: 24 structural elements printed", f"{len(ste)}")
    thrust = -sum(r[6] for r in ste) / len(ste)
    p_i = thrust / 1.0          # support radius 1 m (manual text)
    lm = table(out, "Structural element lumped masses", 5)
    stc = table(out, "Structural element interfaces", 9)
    wall = []
    for node, it in zip(lm, stc):
        x, y, ux, uy = node[1:5]
        x0, y0 = x - ux, y - uy
        r = (x0 * x0 + y0 * y0) ** 0.5
        wall.append(-(ux * x0 + uy * y0) / r - it[7])
    u_wall = sum(wall) / len(wall)
    k_ss = p_i / u_wall
    err = (k_ss - 243.0) / 243.0
    check(abs(err) <= 0.05, f"{label}: support stiffness within 5 % of the manual's 243 MPa/m",
          f"{k_ss:.1f} MPa/m ({100*err:+.1f} %): P_i {p_i:.4f} MPa over the wall's "
          f"{u_wall*1e3:.3f} mm at the support")
    err = (p_i - p_ref) / p_ref
    print(f"info: {label}: support pressure {p_i:.4f} MPa, manual {p_ref} ({100*err:+.1f} %), "
          f"analytic 1.075; not asserted (see the docstring)")
    # Independent check of P_i (closed form, Fig. E-3: the ground-reaction
    # line meets the support line). The elastic ground of this model gives
    # u = u0 (1 - P_i / P0) at the support (superposition), u0 the
    # unsupported wall displacement there (E1 / E3 of this check); the support
    # gives P_i = K_ss u. So P_i = K_ss u0 / (1 + K_ss u0 / P0), P0 = 10 MPa,
    # K_ss as measured above. Tolerance 5 % (the manual's for E).
    u_bound = "constant-stress boundary" if "constant" in label else "zero-displacement boundary"
    if u_bound in ground:
        u0 = ground[u_bound][0]
        p_pred = k_ss * u0 / (1.0 + k_ss * u0 / 10.0)
        err = (p_i - p_pred) / p_pred
        check(abs(err) <= 0.05, f"{label}: support pressure within 5 % of the ground-reaction "
              f"closed form K u0 / (1 + K u0 / P0) with this model's unsupported wall",
              f"P_i {p_i:.4f} vs {p_pred:.4f} MPa ({100*err:+.2f} %), u0 {u0*1e3:.3f} mm, "
              f"K {k_ss:.1f} MPa/m; the manual's {p_ref} gives back u0 = "
              f"{p_ref / (k_ss * (1 - p_ref / 10.0)) * 1e3:.2f} mm")

# E2 with stiff ("transparent") joints: a uniform ground. References: the
# analytic support pressure of Table E-1 (Eqs. E-1, E-2), 1.075 MPa, and the
# support stiffness 243 MPa/m (Table E-1); 5 %. 1200 cycles: the support
# pressure changes by < 0.01 % from 1200 to 2400 cycles (measured).
deck = "E2_stress_bc_support.dat"
text = deck_with(os.path.join(here, deck), extra + ["PRI LM STC"],
                 replace=[("JKN=1E4 JKS=1E4", "JKN=1E5 JKS=1E5"), ("CYC 400", "CYC 1200")])
rc, out, sec = run_deck(udec, folder, "E2_stiff_joints.dat", text)
check(rc == 0, "E2 with JKN = JKS = 1e5 runs", out[-2000:] if rc else f"{sec:.1f} s")
if not rc:
    u, h = wall_displacement()
    ste = table(out, "Structural elements", 7)
    p_i = -sum(r[6] for r in ste) / len(ste)
    err = (p_i - 1.075) / 1.075
    check(abs(err) <= 0.05, "E2, stiff joints: support pressure within 5 % of the analytic 1.075 MPa",
          f"{p_i:.4f} MPa ({100*err:+.1f} %), manual 1.117 with the deck's joints")
    err = (p_i / u - 243.0) / 243.0
    check(abs(err) <= 0.05, "E2, stiff joints: P_i / wall displacement (histories) within 5 % of 243 MPa/m",
          f"{p_i / u:.1f} MPa/m ({100*err:+.1f} %), u = {u*1e3:.3f} mm")
finish()
