"""The zones' stiffness is symmetric (label stability; reference: Maxwell-
Betti reciprocity of linear elasticity, the force at gridpoint B per unit
displacement of A equals the force at A per unit displacement of B).

CONS 3 zones use the mixed discretization: a triangle takes the mean
volumetric strain of itself and a partner across an edge (the 1989 zone word
KZLL). The pairing leaves a few zones without a partner of their own; each
such leftover pointed one way at a paired neighbour and took its strain,
while the neighbour's pair ignored the leftover. The stiffness was then not
symmetric (up to 22 % of the largest term on these blocks), and that part
does work over a cycle of motion: at the acute corner of a block where four
blocks meet at a joint crossing (the guide's tunnel, docs/guide/tunnel.md)
the corner gridpoint's oscillation grew at 415 1/s at 1460 Hz without
damping, DAMP AUTO held it at a steady rattle, and SOLVE never reached its
default ratio (2.9e-4 after 100,000 cycles). Now a leftover joins its
neighbour's pair and the three share one mean: symmetric.

Checked on three single zoned blocks of CONS 3 zones (gravity off, no
stress): each boundary gridpoint in turn is given a velocity of 1e-3 m/s in
x, then y, for one cycle (BOUNDARY XVEL / YVEL on a range around it, from
the same saved state), and the forces at all boundary gridpoints are read:
column j of the stiffness times v dt. Every pair of entries K(i, j) and
K(j, i) agrees within 1e-5 of the largest entry (PRINT's six digits).
"""
import os
import sys
from udec_test import check, finish, run, workdir, write

udec = sys.argv[1]
SHAPES = [("0,0 0,1 1.3,0", 0.9), ("0,0 0,1 1,1.2 1.3,0", 0.5),
          ("0,0 0,1 0.6,1.4 1.3,1 1.1,0", 0.7)]
PROPS = """CHANGE CONS=3
PROP MAT=1 D=2600 K=2e10 G=1.2e10 COH=1e9 FRIC=0.8 TEN=1e9
"""


def rows(text, ncol):
    for line in text.splitlines():
        f = line.split()
        if len(f) == ncol and f[0].isdigit():
            yield f


for shape, edge in SHAPES:
    label = f"BLOCK {shape}, GEN EDGE {edge}"
    d = workdir()
    head = f"BLOCK {shape}\nGEN EDGE {edge}\n" + PROPS
    write(d, "setup.dat", head + "PRINT GRID DISP\nSAVE s.sav\nSTOP\n")
    rc, out = run(udec, ["setup.dat"], cwd=d)
    check(rc == 0 and "Error" not in out, label + ": setup runs", out[-1500:])
    part = out.split("PRINT GRID DISP", 1)[-1]
    gps = [(int(f[0]), float(f[2]), float(f[3])) for f in rows(part, 8)]
    deck = ""
    for g, x, y in gps:
        for comp in ("XVEL", "YVEL"):
            deck += (f"RESTART s.sav\nBOUND {x - 1e-4:.6f} {x + 1e-4:.6f} {y - 1e-4:.6f} "
                     f"{y + 1e-4:.6f} {comp} 1e-3\nCYCLE 1\nPRINT GRID FORCES\n")
    write(d, "kicks.dat", deck + "STOP\n")
    rc, out = run(udec, ["kicks.dat"], cwd=d, timeout=120)
    check(rc == 0 and "Error" not in out, label + ": the kicks run", out[-1500:])
    tabs = out.split("PRINT GRID FORCES")[1:]
    n = len(gps)
    index = {g: i for i, (g, _, _) in enumerate(gps)}
    k = [[0.0] * (2 * n) for _ in range(2 * n)]
    for col, tab in enumerate(tabs[:2 * n]):
        for f in rows(tab, 6):
            if int(f[0]) in index:
                r = index[int(f[0])]
                k[2 * r][col] = float(f[4])
                k[2 * r + 1][col] = float(f[5])
    # a gridpoint BOUNDARY cannot hold (inside the block) has an empty column
    kicked = [any(abs(k[r][2 * c]) > 0 for r in range(2 * n)) for c in range(n)]
    kmax = max(abs(v) for row in k for v in row)
    worst, where = 0.0, None
    for i in range(2 * n):
        for j in range(i + 1, 2 * n):
            if not (kicked[i // 2] and kicked[j // 2]):
                continue
            s = abs(k[i][j] - k[j][i])
            if s > worst:
                worst, where = s, (gps[i // 2][0], "xy"[i % 2], gps[j // 2][0], "xy"[j % 2],
                                   k[i][j], k[j][i])
    print(f"{label}: {sum(kicked)} gridpoints kicked, largest |K - K^T| / max |K| = "
          f"{worst / kmax if kmax else 0:.2e} at {where}")
    check(sum(kicked) >= 6 and kmax > 0, label + ": the kicks move the block", str(kicked))
    check(kmax > 0 and worst <= 1e-5 * kmax,
          f"{label}: stiffness symmetric within 1e-5 (largest skew {worst:.4g} of {kmax:.4g} at {where})")
finish()
