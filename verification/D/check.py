"""Verification D (manual Appendix A, Test D): Prandtl's wedge, a rough
footing on a weightless cohesive (Tresca) material, zoned Mohr-Coulomb
blocks (CONS 3, c = 1e4 Pa, phi = 0) with glued elastic joints.

Reference: Prandtl's exact limit load q = (2 + pi) c = 5.14e4 Pa; the
manual's UDEC result is within 3 % of it, and so must ours be (issue 6).
The footing is the set of top gridpoints with a prescribed y-velocity
(0 < x < 2.8); its load is the sum of their reactions FY from the deck's
own PRINT BOUNDARY (FORCES table) after 8000 and 10000 cycles, divided by
the footing's tributary width: the last loaded gridpoint's x plus half
the distance to the next top gridpoint (for the velocity-driven footing
this is the width over which the load acts in the zoning). q is the
larger of the two prints (the load has reached its plateau).
"""
import math
import os
import sys
sys.path.insert(0, os.path.join(os.path.dirname(__file__), ".."))
from common import check, finish, workdir, deck_with, run_deck  # noqa: E402

udec = sys.argv[1]
here = os.path.dirname(os.path.abspath(__file__))
q_exact = (2.0 + math.pi) * 1.0e4


def force_tables(out):
    result, rows, inside = [], None, False
    for line in out.splitlines():
        if line.startswith("BOUNDARY FORCES"):
            rows = []
            result.append(rows)
            inside = True
            continue
        if inside:
            f = line.split()
            if not f:
                inside = False
                continue
            if f[0] == "COR":
                continue
            try:
                rows.append([float(v) for v in f])
            except ValueError:
                inside = False
    return result


folder = workdir()
rc, out, sec = run_deck(udec, folder, "D.dat", deck_with(os.path.join(here, "D.dat"), []))
check(rc == 0, "D.dat runs", out[-2000:] if rc else f"{sec:.1f} s")
if rc == 0:
    qs = []
    for rows in force_tables(out):
        top = sorted((r for r in rows if r[2] > 9.5), key=lambda r: r[1])
        loaded = [r for r in top if r[4] == 4]
        if not loaded:
            continue
        xl = max(r[1] for r in loaded)
        nxt = [r[1] for r in top if r[1] > xl + 1e-6]
        width = xl + 0.5 * (min(nxt) - xl) if nxt else xl
        q = abs(sum(r[6] for r in loaded)) / width
        qs.append(q)
        print(f"footing: force {abs(sum(r[6] for r in loaded)):.4e} N/m over width {width:.3f} m -> q {q:.4e} Pa"
              f" (over 2.8 m: {abs(sum(r[6] for r in loaded))/2.8:.4e})")
    check(len(qs) == 2, "two footing-load prints found", f"{len(qs)}")
    if qs:
        q = max(qs)
        err = (q - q_exact) / q_exact
        check(abs(err) <= 0.03, "limit load within 3 % of (2 + pi) c = 5.14e4 Pa", f"{q:.4e} Pa, {100*err:+.2f} %")
finish()
