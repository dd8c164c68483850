"""Application C (manual Appendix B, Problem C): liner thrusts of the two
tunnels, from the deck as printed (PR STE at the end of the run).

References and tolerances:
* Service tunnel: "the greatest axial loads for the service tunnel occurs at
  the horizontal midplane. At this position, the thrust is 1.7 x 10^5 N"
  (Appendix B, Problem C text; Table C-1 element 1, 1.656e5). Asserted: the
  largest thrust of the 16 service elements within 5 % of 1.7e5 and its
  element's midpoint on the horizontal midplane (|y + 70| < 0.5 m).
* Main tunnel: the manual gives 1.2e5 N (Table C-1: 1.223e5 / 1.206e5 on the
  lower diagonals, 2.8e4 at the crown); ours is 8.06e4 (-33 %). The liner
  goes in after 5000 cycles of the excavated main tunnel; by then the
  tunnel's convergence is done (history 15, XDIS(35,-70), 2.0e-6 m from
  its value at rest, of 24.0 mm; the model's 1.58 Hz fundamental still
  rings, a surface gridpoint at 6.0e-3 m/s, README.md), so the main liner
  carries its own weight and almost no ground load. Independent checks instead of the manual's number:
  - statics of the upper half ring: its interfaces carry no force (the
    crown separated, state "slip", n-force 0), so the two springline
    elements hold the weight of the four upper lumped masses between them:
    thrust = 4 m g / 2 exactly (m from PR STE LM); asserted within 1 %;
  - a liner put in a rock at rest carries its weight only: the deck with
    SOLVE RATIO 1E-7 before the main liner goes in, run with the printed
    liner and with its density divided by 100 (material 6, D = 24), gives
    thrusts 100 times smaller, within 2 % of the largest thrust at every
    element (measured 0.14 %); and the printed deck's thrusts are those of
    the rock at rest within 2 % of the largest (measured 0.14 %). (Before
    2026-11-26 the printed deck itself was compared with its light-liner
    copy: the rock seemed at rest after 5000 cycles only because a
    one-way mixed-discretization zone made DAMP AUTO overdamp it, and the
    light liner's smaller timestep then leaves its last 5000 cycles 0.46 s
    of motion instead of 1.27 s, so that copy ends mid-swing; README.md);
  - the closed form of the lined tunnel (convergence-confinement), below:
    a main liner put in at the moment of excavation takes the thrust
    p R of that solution within 5 % (measured -1.4 %, session 41), so the liner, its
    interface and the rock have the stiffnesses the deck gives, and the
    1989 table's excess over ours is 1.7 % of that thrust (README.md);
  - not asserted: Table C-1 as a liner put in before the convergence was
    done. Until 2026-11-27 the printed deck with the main liner in after a
    fitted 700 cycles of the main tunnel was asserted (every element within
    5 % of the table's largest). That thrust is set by where the whole
    model's 1.58 Hz fundamental swing is when the liner goes in, not by the
    tunnel: with the consistent boundary load on gridpoints (session 41) the
    main wall's mean convergence at cycle 700 is the same to 0.04 % (29.889
    against 29.877 mm) and the thrusts moved by 8 to 16 % of the table's
    largest. A check of a transient's phase is not a check of the liner;
    the run is printed for information (README.md).
"""
import math
import os
import re
import sys
sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "..", "verification"))
from common import check, finish, workdir, run_deck  # noqa: E402

udec = sys.argv[1]
deck = os.path.join(os.path.dirname(os.path.abspath(__file__)), "C1_tunnel_support.dat")
MAIN = "STRUC 30 -70 22.5 4.3 8 5 0.46"


def tables(out):
    """(elements, masses) of the last PR STE STC LM: {id: row}."""
    last = out.rsplit("PR STE STC LM", 1)[1]
    elem, mass, part = {}, {}, None
    for line in last.splitlines():
        if line.startswith("Structural elements"):
            part = elem
        elif line.startswith("Structural element interfaces"):
            part = None
        elif line.startswith("Structural element lumped masses"):
            part = mass
        elif part is not None and re.match(r"^\s+\d+\s", line):
            f = line.split()
            part[int(f[0])] = [float(v) for v in f[1:]]
    return elem, mass


def run(text, name, folder):
    rc, out, secs = run_deck(udec, folder, name, text)
    check(rc == 0, f"{name} runs", f"rc={rc}, {secs:.1f} s")
    return tables(out)


def after(save, text):
    """A deck that RESTARTs the printed run's `save` and goes on with what
    `text` (the printed deck, changed) does after its SAVE `save`; its own
    SAVEs renamed, so the printed run's files stay as they are."""
    tail = text.split(f"SAVE {save}\n", 1)[1]
    return f"RESTART {save}\n" + tail.replace("SAVE CHAN", "SAVE V_CHAN")


# Cost: the six runs below share the deck's first stages, so the printed run
# goes first and the others RESTART from its SAVE CHAN2 (service tunnel
# excavated, no liner yet: 610 cycles) or SAVE CHAN3 (5000 cycles after the
# service liner and the main tunnel's excavation)
# instead of cycling them again (SAVE / RESTART continues a run bit for bit:
# the thrusts are those of the whole decks to every printed digit). The
# light liner of the printed deck, printed for information only, restarts
# too. Cycles: 41 310 plus one SOLVE, before 59 360 plus two SOLVEs; wall
# time 33 s instead of 54.5 s on the shared 2-core machine at a load average
# of 20-22 (2026-11-27), every printed number unchanged.
folder = workdir()
printed = open(deck).read()
rc, out_gp, secs = run_deck(udec, folder, "C1_tunnel_support.dat",
                             printed.replace("SAVE CHAN3\n", "SAVE CHAN3\nPRINT GRIDPOINT\n"))
check(rc == 0, "C1_tunnel_support.dat runs (PRINT GRIDPOINT added after SAVE CHAN3)", f"rc={rc}, {secs:.1f} s")
elem, mass = tables(out_gp)
# elements 1-16: service tunnel (nodes 1-16); 17-24: main tunnel (nodes 17-24)
service = {e: r for e, r in elem.items() if e <= 16}
main = {e: r for e, r in elem.items() if e >= 17}
check(len(service) == 16 and len(main) == 8, "16 service and 8 main liner elements")


def midpoint(e):
    n1, n2 = int(elem[e][0]), int(elem[e][1])
    return ((mass[n1][0] + mass[n2][0]) / 2, (mass[n1][1] + mass[n2][1]) / 2)


e_max = max(service, key=lambda e: -service[e][5])
t_max = -service[e_max][5]
check(abs(t_max / 1.7e5 - 1) <= 0.05, f"service tunnel: largest thrust {t_max:.4g} N within 5 % of "
      "the manual's 1.7e5 N", f"{100 * (t_max / 1.7e5 - 1):+.1f} %")
check(abs(midpoint(e_max)[1] + 70) < 0.5, "service tunnel: the largest thrust is at the horizontal "
      "midplane", f"element {e_max} at {midpoint(e_max)}")

m_max = max(-r[5] for r in main.values())
print(f"info: main tunnel largest thrust {m_max:.4g} N (manual 1.2e5 N, "
      f"{100 * (m_max / 1.2e5 - 1):+.1f} %)")
# upper half: nodes with y > -70
upper = [n for n in range(17, 25) if mass[n][1] > -70]
weight = sum(mass[n][5] for n in upper) * 10.0  # GRAVITY 0 -10
spring = [e for e in main if abs(midpoint(e)[1] + 70) < 0.1]
check(len(upper) == 4 and len(spring) == 2, "four upper nodes and two springline elements",
      f"{upper} {spring}")
for e in spring:
    t = -main[e][5]
    check(abs(t - weight / 2) <= 0.01 * weight / 2, f"main tunnel springline element {e}: thrust "
          f"{t:.4g} N = half the upper half-ring's weight {weight / 2:.4g} N within 1 %",
          f"{100 * (t / (weight / 2) - 1):+.2f} %")

# Closed form of the lined tunnel (convergence-confinement; the same form as
# verification E, manual Appendix A, Problem E, Eq. (E-2)): a liner put in at
# the moment of excavation (u0 = 0) carries p = Ks u_inf / (1 + Ks u_inf / p0),
# thrust T = p R, where
#   p0    = 8.36e5 Pa, the in-situ stress at the tunnel's centre (y = -70:
#           1.02e5 - 70 x 1.34e4, the deck's INSITU line);
#   u_inf = the unlined wall's mean radial convergence, measured in the printed
#           run after its 5000 cycles (PRINT GRIDPOINT after SAVE CHAN3; the
#           deck's RESET DISP makes it the excavation's own), so that the rock's
#           stiffness p0 / u_inf includes the box, the service tunnel and gravity;
#   Ks    = the support's radial stiffness per unit wall area: the interface
#           spring KN = 1e8 N/m of each node over its element length L, in series
#           with the ring's E A / R^2 (E = 9 K G / (3 K + G), A = 0.46 m^2, R the
#           nodes' radius; the manual's KN is a force / displacement per node,
#           Section 4.5 PROPERTY, structural element properties).
# Asserted: the mean thrust of the 8 main elements of that run (main liner
# density 24, so its weight adds 1 %, PROPERTY as the printed MAT=5 otherwise)
# within 5 % of p R (measured -1.4 %, 2026-11-27, session 41). It shows the liner, its interface and
# the rock interact with the stiffnesses the deck gives: a liner that goes in
# with the whole convergence ahead of it takes 1.8e6 N, the 1989 table's
# ground part (about 3e4 N over ours at every element) is 1.7 % of that, and a
# liner that goes in after the tunnel is at rest takes its weight only.
x0, y0, P0 = 30.0, -70.0, 1.02e5 - 70 * 1.34e4
p0 = -P0
gp = out_gp.split("SAVE CHAN3", 1)[1].split("PRINT GRIDPOINT", 1)[1]
ur = []
for line in gp.split("GRIDPT", 1)[1].splitlines()[1:]:
    f = line.split()
    if len(f) != 8 or not f[0].isdigit():
        break
    x, y, dx, dy = (float(v) for v in f[2:6])
    r = math.hypot(x - x0, y - y0)
    if 3.8 < r < 4.3:  # the main tunnel's wall (TUN 30 -70 4.11 12, rounded)
        ur.append(-((x - x0) * dx + (y - y0) * dy) / r)
check(len(ur) >= 12, "main tunnel wall gridpoints found", str(len(ur)))
u_inf = sum(ur) / len(ur)
K, G, A = 13e9, 10e9, 0.46
E = 9 * K * G / (3 * K + G)
R = sum(math.hypot(mass[n][0] - x0, mass[n][1] - y0) for n in range(17, 25)) / 8
L = sum(main[e][4] for e in main) / 8  # element length
ks = 1.0 / (L / 1e8 + R * R / (E * A))
p = ks * u_inf / (1 + ks * u_inf / p0)
imm = after("CHAN2", printed).replace(MAIN + "\n", "").replace(
    "DEL 28 32 -72 -68\n", "DEL 28 32 -72 -68\nPROP MAT=6 D=24 G=10E9 K=13E9 KN=1E8 KS=1E7 "
    "CFRIC=10.0\n" + MAIN.replace(" 8 5 ", " 8 6 ") + "\n")
elem3, _ = run(imm, "C1_main_liner_at_excavation.dat", folder)
t_mean = sum(-elem3[e][5] for e in range(17, 25)) / 8
check(abs(t_mean / (p * R) - 1) <= 0.05, f"main liner put in at excavation: mean thrust {t_mean:.4g} N "
      f"within 5 % of the closed form p R = {p * R:.4g} N (u_inf {u_inf:.4g} m, Ks {ks:.4g} Pa/m, "
      f"rock p0/u_inf {p0 / u_inf:.4g} Pa/m, R {R:.4g} m)", f"{100 * (t_mean / (p * R) - 1):+.2f} %")
print(f"info: the 1989 table's largest thrust 1.2e5 N is {100 * 1.2e5 / t_mean:.1f} % of it")

LIGHT = "PROP MAT=6 D=24 G=10E9 K=13E9 KN=1E8 KS=1E7 CFRIC=10.0\n" + MAIN.replace(" 8 5 ", " 8 6 ")
# the rock at rest when the main liner goes in: SOLVE to a force ratio of
# 1e-7 (a ratio of 1e-5 can stop while the 1.58 Hz fundamental swings
# through zero force, a surface gridpoint still at 1.8e-3 m/s; README.md)
rest = after("CHAN3", printed)
elem_r, _ = run(rest.replace("RESTART CHAN3\n", "RESTART CHAN3\nSOLVE RATIO 1E-7\nSAVE RESTED\n"),
                "C1_main_liner_at_rest.dat", folder)
elem_rl, _ = run(rest.replace("RESTART CHAN3\n", "RESTART RESTED\n").replace(MAIN, LIGHT),
                 "C1_light_main_liner_at_rest.dat", folder)
for e in sorted(main):
    t0, t1, t2 = -main[e][5], -elem_r[e][5], -elem_rl[e][5]
    check(abs(100 * t2 - t1) <= 0.02 * m_max, f"main element {e}, rock at rest: thrust {t1:.4g} N with "
          f"D = 2400, 100 x {t2:.4g} N with D = 24: proportional to the liner's weight within 2 % of "
          "the largest thrust", f"{100 * (100 * t2 - t1) / m_max:+.2f} % of it")
    check(abs(t0 - t1) <= 0.02 * m_max, f"main element {e}: printed deck's thrust {t0:.4g} N = that "
          f"of the rock at rest {t1:.4g} N within 2 % of the largest thrust",
          f"{100 * (t0 - t1) / m_max:+.2f} % of it")
# Not asserted: the 1989 table as a liner put in before the convergence was
# done, the printed deck with the main liner in after 700 cycles of the
# excavated main tunnel instead of 5000 (module docstring, README.md: the
# thrust of a liner put in mid-transient follows the phase of the model's
# fundamental swing, which the boundary load's discretisation moves while
# the tunnel's convergence stays the same). Printed against Table C-1
# (Appendix B, Problem C), the element at the same midpoint.
TABLE_C1 = [((33.68, -70.01), 9.901e4), ((32.60, -72.61), 1.223e5), ((30.00, -73.68), 1.045e5),
            ((27.40, -72.60), 1.206e5), ((26.33, -70.00), 9.610e4), ((27.40, -67.41), 4.832e4),
            ((30.00, -66.33), 2.800e4), ((32.60, -67.40), 4.810e4)]
early = after("CHAN2", printed).replace("RESET DISP\nCYC 5000\nSAVE V_CHAN3\n",
                                       "RESET DISP\nCYC 700\nSAVE V_CHAN3\n")
check(early.count("CYC 700") == 1, "the 700-cycle deck is edited")
elem_e, mass_e = run(early, "C1_main_liner_after_700.dat", folder)
errors = []
for (xm, ym), t_1989 in TABLE_C1:
    e = min(range(17, 25), key=lambda k: math.dist(
        ((mass_e[int(elem_e[k][0])][0] + mass_e[int(elem_e[k][1])][0]) / 2,
         (mass_e[int(elem_e[k][0])][1] + mass_e[int(elem_e[k][1])][1]) / 2), (xm, ym)))
    errors.append(100 * (-elem_e[e][5] - t_1989) / 1.223e5)
print("info: main liner in after 700 cycles, thrust minus Table C-1 in Table C-1's order, % of "
      "its largest 1.223e5 N:", " ".join(f"{v:+.1f}" for v in errors))

# not asserted: the printed deck with the light liner (README.md)
elem2, _ = run(after("CHAN3", printed).replace(MAIN, LIGHT), "C1_light_main_liner.dat", folder)
print("info: printed deck, 100 x thrust with D = 24 minus thrust with D = 2400, % of the largest:",
      " ".join(f"{100 * (100 * -elem2[e][5] + main[e][5]) / m_max:+.1f}" for e in sorted(main)))
finish()
