"""PRINT BOUNDARY FORCES at velocity-held corners of rigid blocks (UDEC manual
(ICG1.5, 1989), Section 4.5 BOUNDARY XVEL / YVEL and PRINT BOUNDARY): the row
of a held direction gives the force the body puts on the support, as it does
at a held gridpoint (boundary_held_loads.py). A rigid block's corners carry no
force of their own: the cycle holds the block's motion (engine_rigid_velocity),
and the reaction of each corner is its share of the part of the block's force
the constraints hold, the smallest set of corner forces with that resultant
and moment (exact statics for up to three independent held directions). Before
session 41 these rows printed 0 (docs/robustness.md, round 2).

1. A trapezoid (0,0) (0,1) (3,1) (1,0), density 2000, g = 10 (weight W =
   40 000 N, centroid x = 13/12), held in y at its two base corners and in x at
   (0,0), 10 cycles (no contact: the held block does not move). Statics about
   the base corners: the corner at x = 1 pushes down 13 W / 12, the one at x = 0
   pulls up W / 12 (the centroid lies beyond the base), x 0. Tolerance 1e-6 W
   (rounding of a 3 x 3 solve).
2. Two 2 x 1 m rigid blocks stacked (a CRACK at y = 1, JKN = JKS = 1e9), the
   lower held in y at both base corners and in x at (0,0), SOLVE (ratio 1e-5):
   each base corner pushes down half the weight of both (40 000 N of 80 000),
   x 0; tolerance 1e-4 of the weight (the ratio 1e-5 of the forces in the
   model, and the printed 6 digits).
"""
import sys
from udec_test import check, finish, run_clean, printed_rows

udec = sys.argv[1]

HEAD = "ROUND 0.01\n"
HOLD = """GRAV 0 -10
BOUND YVEL 0 RANGE -0.01,2.01 -0.01,0.01
BOUND XVEL 0 RANGE -0.01,0.01 -0.01,0.01
DAMP AUTO
"""
CASES = {
    "trapezoid": (HEAD + "BLOCK 0,0 0,1 3,1 1,0\nPROP MAT 1 DENS 2000\n" + HOLD + "CYCLE 10\n",
                  40000.0, {0.0: (0.0, 40000.0 / 12), 1.0: (None, -40000.0 * 13 / 12)}, 1e-6),
    "stack": (HEAD + "BLOCK 0,0 0,2 2,2 2,0\nCRACK -1,1 3,1\n"
              "PROP MAT 1 DENS 2000 JKN 1E9 JKS 1E9 JFRIC 1\n" + HOLD + "SOLVE\n",
              80000.0, {0.0: (0.0, -40000.0), 2.0: (None, -40000.0)}, 1e-4),
}
for name, (deck, weight, want, tol) in CASES.items():
    out = run_clean(udec, name, deck + "PRINT BOUNDARY FORCES\nSTOP\n")
    # COR X Y IX IY FX FY DFX DFY
    rows = printed_rows(out, "PRINT BOUNDARY FORCES", 9)
    held = {round(r[1], 6): r for r in rows if abs(r[2]) < 1e-6}
    print(name, {x: (r[5], r[6]) for x, r in held.items()})
    check(sorted(held) == sorted(want), f"{name}: the held base corners are printed", out[-2000:])
    for x, (fx, fy) in want.items():
        r = held.get(x)
        if r is None:
            continue
        check(abs(r[6] - fy) <= tol * weight,
              f"{name}: corner at x = {x} gives its reaction in y, {fy:.6g} (tolerance {tol:g} W)",
              f"printed {r[6]:.6g}")
        if fx is not None:
            check(abs(r[5] - fx) <= tol * weight,
                  f"{name}: corner at x = {x} gives its reaction in x, {fx:g}", f"printed {r[5]:.6g}")
    total = sum(r[6] for r in held.values())
    check(abs(total + weight) <= tol * weight,
          f"{name}: the reactions add up to the weight ({-weight:g})", f"sum {total:.6g}")
finish()
