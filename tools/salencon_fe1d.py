#!/usr/bin/env python3
"""An independent check of the dilatant Salencon closed form of
tests/scripts/closed_forms_salencon.py (docs/closed_form.md, "The Salencon tunnel's
error budget"): a 1-D axisymmetric plane-strain elasto-plastic finite-element model
(linear elements with one point each, a geometric mesh from r = a = 1 to r = b),
Mohr-Coulomb with non-associated flow (potential s1 - N_psi s3; the out-of-plane stress
carried elastically and checked to stay intermediate: "edge" counts the returns that
changed the principal order), the wall pressure lowered from p0 = 10 MPa to 1 MPa in
equal steps, each balanced by initial-stiffness iterations. Pure python (no numpy).

Usage: salencon_fe1d.py PHI PSI NEL B STEPS. Session 45 (b = 100, 9 steps): phi 30,
psi 0: -7.0627e-3 m with 200 elements (closed form -7.0679e-3, -0.07 %); psi 20:
-9.0864e-3 (closed form -9.0967e-3, -0.11 %); with 100 elements -0.26 % and -0.34 %.
"""
import math, sys
phi, psi, nel, b, nst = float(sys.argv[1]), float(sys.argv[2]), int(sys.argv[3]), float(sys.argv[4]), int(sys.argv[5])
P0, PI, C, G, K = 1e7, 1e6, 1e6, 1e9, 2e9
a1, a2 = K + 4 * G / 3, K - 2 * G / 3
sphi, spsi = math.sin(math.radians(phi)), math.sin(math.radians(psi))
Nphi, Npsi = (1 + sphi) / (1 - sphi), (1 + spsi) / (1 - spsi)
Kc = 2 * C * math.sqrt(Nphi)
q = b ** (1.0 / nel)
r = [q ** i for i in range(nel + 1)]
h = [r[i + 1] - r[i] for i in range(nel)]
rm = [0.5 * (r[i + 1] + r[i]) for i in range(nel)]
n = nel + 1
dia = [0.0] * n; off = [0.0] * nel
for e in range(nel):
    B = ((-1 / h[e], 1 / h[e]), (0.5 / rm[e], 0.5 / rm[e]))
    D = ((a1, a2), (a2, a1))
    w = rm[e] * h[e]
    for i in range(2):
        for j in range(2):
            kij = sum(B[p][i] * D[p][qq] * B[qq][j] for p in range(2) for qq in range(2)) * w
            if i == j: dia[e + i] += kij
            elif i == 0: off[e] += kij
# Thomas factorisation (symmetric tridiagonal)
cp = [0.0] * nel; dp = [0.0] * n
dp[0] = dia[0]
for i in range(1, n):
    cp[i - 1] = off[i - 1] / dp[i - 1]
    dp[i] = dia[i] - cp[i - 1] * off[i - 1]
def solve(rhs):
    y = rhs[:]
    for i in range(1, n): y[i] -= cp[i - 1] * y[i - 1]
    x = [0.0] * n
    x[-1] = y[-1] / dp[-1]
    for i in range(n - 2, -1, -1): x[i] = (y[i] - off[i] * x[i + 1]) / dp[i]
    return x
u = [0.0] * n
sig = [[P0, P0, P0] for _ in range(nel)]
eold = [[0.0, 0.0] for _ in range(nel)]
def strains(u):
    return [[(u[e + 1] - u[e]) / h[e], 0.5 * (u[e + 1] + u[e]) / rm[e]] for e in range(nel)]
edge = 0
def update(e, s0, d):
    global edge
    de0, de1 = -d[0], -d[1]
    s = [s0[0] + a1 * de0 + a2 * de1, s0[1] + a2 * de0 + a1 * de1, s0[2] + a2 * (de0 + de1)]
    i1 = max(range(3), key=lambda j: s[j]); i3 = min(range(3), key=lambda j: s[j])
    f = s[i1] - Nphi * s[i3] - Kc
    if f <= 0: return s
    m = [0.0] * 3; m[i1] = 1.0; m[i3] = -Npsi
    sm = sum(m)
    dm = [a1 * m[j] + a2 * (sm - m[j]) for j in range(3)]
    lam = f / (dm[i1] - Nphi * dm[i3])
    s2 = [s[j] - lam * dm[j] for j in range(3)]
    if max(range(3), key=lambda j: s2[j]) != i1 or min(range(3), key=lambda j: s2[j]) != i3: edge += 1
    return s2
for k in range(1, nst + 1):
    p = P0 - (P0 - PI) * k / nst
    fext = [0.0] * n; fext[0] = p * r[0]; fext[-1] = -P0 * r[-1]
    for it in range(4000):
        eps = strains(u)
        s = [update(e, sig[e], (eps[e][0] - eold[e][0], eps[e][1] - eold[e][1])) for e in range(nel)]
        fint = [0.0] * n
        for e in range(nel):
            sr, st = -s[e][0], -s[e][1]
            fint[e] += (-sr / h[e] + 0.5 * st / rm[e]) * rm[e] * h[e]
            fint[e + 1] += (sr / h[e] + 0.5 * st / rm[e]) * rm[e] * h[e]
        res = [fext[i] - fint[i] for i in range(n)]
        if max(abs(x) for x in res) < 1e-6 * P0: break
        du = solve(res)
        u = [u[i] + du[i] for i in range(n)]
    sig = s; eold = strains(u)
gap = [round(sig[e][1] - sig[e][2]) for e in range(3)]
npl = sum(1 for e in range(nel) if max(sig[e]) - Nphi * min(sig[e]) - Kc > -1e-3 * Kc)
print(f"phi {phi} psi {psi} nel {nel} b {b} steps {nst}: u(a) = {u[0]:.6e} last iters {it} edge {edge} st-sz {gap} plastic to r={r[npl]:.4f}", flush=True)
