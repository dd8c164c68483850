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
  goes in after 5000 cycles of the excavated main tunnel, which by then is
  at rest in our run (max gridpoint velocity 2.2e-4 m/s, history 15 moving
  3e-9 m per cycle), so the main liner carries its own weight and almost
  no ground load (README.md). Independent checks instead of the manual's
  number:
  - statics of the upper half ring: its interfaces carry no force (the
    crown separated, state "slip", n-force 0), so the two springline
    elements hold the weight of the four upper lumped masses between them:
    thrust = 4 m g / 2 exactly (m from PR STE LM); asserted within 1 %;
  - the main-liner thrust is its self-weight: the same deck with the main
    liner's density divided by 100 (material 6, D = 24) gives thrusts 100
    times smaller, within 2 % of the largest thrust at every element
    (measured 0.5 %: the ground load taken after installation).
"""
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


folder = workdir()
printed = open(deck).read()
elem, mass = run(printed, "C1_tunnel_support.dat", folder)
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
light = printed.replace(MAIN, "PROP MAT=6 D=24 G=10E9 K=13E9 KN=1E8 KS=1E7 CFRIC=10.0\n"
                        + MAIN.replace(" 8 5 ", " 8 6 "))
elem2, _ = run(light, "C1_light_main_liner.dat", folder)
for e in sorted(main):
    t1, t2 = -main[e][5], -elem2[e][5]
    check(abs(100 * t2 - t1) <= 0.02 * m_max, f"main element {e}: thrust {t1:.4g} N with D = 2400, "
          f"100 x {t2:.4g} N with D = 24: proportional to the liner's weight within 2 % of the "
          "largest thrust", f"{100 * (100 * t2 - t1) / m_max:+.2f} % of it")
finish()
