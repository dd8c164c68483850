"""Mohr-Coulomb (CONS 3) zones on AUTO zoning (the paired mixed
discretization, src/zones/zones_mixed.f90) against closed forms, with decks
written from the manual's Section 4 syntax alone (BLOCK, TUNNEL, GEN AUTO,
CHANGE CONS=3, PROP DENS BULK SHEAR COH FRIC DIL TENS, INSITU, BOUNDARY,
DAMP AUTO, PRINT ZONE STRESS / PRINT BOUNDARY FORCES).

1. Prandtl footing on a weightless c-phi material (phi = 10 deg, associated).
2. Circular tunnel (quarter model) in a Mohr-Coulomb medium: Salencon 1969.
3. Plane-strain compression, DIL = 0, 0.2 and = FRIC: peak and post-peak.
4. Simple shear of a cohesive (phi = 0) block: shear stress saturates at c.
Tolerances are stated per check together with the values measured when the
script was written (Release, 2026-11-21).
"""
import collections
import math
import os
import sys
import udec_test
from udec_test import check, finish, workdir, tables, zone_rows

udec = sys.argv[1]
src = sys.argv[2]
sys.path.insert(0, os.path.join(src, "verification"))
from common import boundary_tables, footing_loads  # noqa: E402
from shared_decks import salencon_tunnel  # noqa: E402

FOLDER = workdir()


def run_deck(name, text):
    return udec_test.run_deck(udec, FOLDER, name, text, 600, forbidden=("***",))[1]


# ---------------------------------------------------------------------------
# 1. Footing: verification D's geometry and deck (25 glued blocks, rough
#    footing 0 <= x <= 2.8 pushed at 2e-3 m/s, rollers), the material given
#    friction: c = 1e4 Pa, phi = 10 deg, associated flow (DIL = FRIC).
#    Prandtl: q = c Nc, Nc = (Nq - 1) cot(phi), Nq = exp(pi tan phi)
#    tan^2(45 + phi/2) = 2.471, Nc = 8.345, q = 8.345e4 Pa. (Associated flow:
#    the limit load is unique; DIL = 0 gave 1.5 % less on AUTO 1.5.) The
#    Prandtl mechanism for the loaded width reaches x = 10.7 < 11.5.
#    Load = sum of the footing gridpoints' reactions over the tributary width
#    (last loaded gridpoint + half the next top zone edge), as verification/D.
#    Measured (Release): AUTO 1.5 -0.6 % at 24000 cycles; AUTO 0.75 -4.2 %
#    at 32000 (levelled off by 24000). Refining further goes lower (AUTO 0.5 -7.8 %, without
#    the joints -4.7 %; crossed quads, unpaired, QUAD 1.0 / 0.5 / 0.25 without
#    joints: -2.4 / -5.0 / -6.4 %): both discretizations settle some 5-7 %
#    under Prandtl for phi = 10 while phi = 0 (verification D) converges to
#    within 1-2 %; not resolved here (see the report of probe-plastic).
#    Tolerance: 3 % at AUTO 1.5, 6 % at AUTO 0.75; levelled off: the last
#    8000 cycles change the load by under 1 %.
phi = math.radians(10.0)
tphi = math.tan(phi)
nq = math.exp(math.pi * tphi) * math.tan(math.pi / 4 + phi / 2) ** 2
q_prandtl = (nq - 1) / tphi * 1.0e4
d_deck = open(os.path.join(src, "verification", "D", "D.dat")).read()


for size, tol, nblock in (("1.5", 0.03, 3), ("0.75", 0.06, 4)):
    text = d_deck.replace("COH=1E4", f"COH=1E4 FRIC={tphi:.6f} DIL={tphi:.6f}").replace(
        "GEN 0,12 0,10 AUTO 1.5", f"GEN 0,12 0,10 AUTO {size}")
    text = text[:text.index("CYC 8000")] + "CYC 8000\nPR BOU FORCES\n" * nblock + "STOP\n"
    out = run_deck(f"footing_auto{size}", text)
    loads = [q for q, _, _ in footing_loads(out)]
    check(len(loads) == nblock, f"footing AUTO {size}: {nblock} load prints", str(loads))
    if len(loads) == nblock:
        err = loads[-1] / q_prandtl - 1
        print(f"footing AUTO {size}: q = {loads[-1]:.4e} Pa vs Prandtl {q_prandtl:.4e}: {100 * err:+.2f} %")
        check(abs(err) <= tol, f"footing AUTO {size}: limit load within {100 * tol:.0f} % of c Nc",
              f"{loads} vs {q_prandtl:.4e}: {100 * err:+.2f} %")
        check(abs(loads[-1] / loads[-2] - 1) < 0.01, f"footing AUTO {size}: load levelled off (1 %)",
              str(loads))

# ---------------------------------------------------------------------------
# 2. Circular tunnel, Salencon (1969): quarter model 8 x 8, hole radius a = 1
#    (TUNNEL 48 sides, inner block deleted), a glued ring joint at r = 2.5
#    separating AUTO 0.15 zoning inside from AUTO 0.8 outside. p0 = 10 MPa
#    hydrostatic (INSITU and BOUND STRESS on the outer sides), the wall
#    pressure lowered from p0 to pi = 1 MPa in three steps; c = 1 MPa,
#    phi = 30 deg, DIL = 0. Rollers on the axes are given again after each
#    wall BOUND STRESS (manual: STRESS cancels an earlier XVEL / YVEL).
#    Kp = 3, sigma_c = 2 c cos(phi)/(1 - sin(phi)) = 3.464 MPa,
#    R = a [2 (p0 (Kp - 1) + sigma_c)/((Kp + 1)((Kp - 1) pi + sigma_c))]^(1/(Kp-1))
#      = 1.465 a;
#    plastic: sr = (pi + sc/(Kp-1)) (r/a)^(Kp-1) - sc/(Kp-1), st = Kp sr + sc;
#    elastic: sr, st = p0 -/+ (p0 - sre)(R/r)^2, sre = (2 p0 - sc)/(Kp + 1).
#    The plane-strain solution needs szz intermediate: INSITU gives
#    szz = nu (sxx + syy) = -5.7 MPa, which stays between sr and st.
#    Checks: ring averages (width 0.2 a, zone centroids) of sr and st within
#    3 % of p0 for a < r < 2.2 a (measured at most 2.5 % -- st just outside R
#    -- and 0.7 % at the wall); the plastic/elastic transition: no zone with
#    a plastic state (at failure or failed in the past) beyond 1.05 R and no
#    elastic zone inside 0.95 R (measured 1.009 R and 0.979 R; zones 0.1 a).
P0, PI, COH = 1.0e7, 1.0e6, 1.0e6
sphi = math.sin(math.radians(30.0))
KP = (1 + sphi) / (1 - sphi)
SC = 2 * COH * math.cos(math.radians(30.0)) / (1 - sphi)
R_PL = (2 * (P0 * (KP - 1) + SC) / ((KP + 1) * ((KP - 1) * PI + SC))) ** (1 / (KP - 1))
SRE = (2 * P0 - SC) / (KP + 1)


def salencon(r):
    if r >= R_PL:
        return P0 - (P0 - SRE) * (R_PL / r) ** 2, P0 + (P0 - SRE) * (R_PL / r) ** 2
    sr = (PI + SC / (KP - 1)) * r ** (KP - 1) - SC / (KP - 1)
    return sr, KP * sr + SC


TUNNEL = salencon_tunnel(8, 2.5, 0.8, 3, 6000, ["PRINT ZONE STRESS", "PRINT ZONE STATE", "PRINT GRID"])
out = run_deck("tunnel", TUNNEL)
if tables(out, "PRINT GRID"):
    rings = collections.defaultdict(list)
    plastic_r, elastic_r = [], []
    for z, x, y, _ in zone_rows(out):
        r, t = math.hypot(x, y), math.atan2(y, x)
        c2, s2 = math.cos(2 * t), math.sin(2 * t)
        sm, dd = 0.5 * (z["SXX"] + z["SYY"]), 0.5 * (z["SXX"] - z["SYY"])
        sr, st = -(sm + dd * c2 + z["SXY"] * s2), -(sm - dd * c2 - z["SXY"] * s2)
        (plastic_r if z["PLASTICITY"] in (1.0, 2.0) else elastic_r).append(r)
        if r < 2.2:
            rings[int((r - 1.0) / 0.2)].append((r, sr, st))
    worst = (0.0, "")
    for k in sorted(rings):
        v = rings[k]
        rm = sum(a[0] for a in v) / len(v)
        e = [sum(salencon(a[0])[j] for a in v) / len(v) for j in (0, 1)]
        m = [sum(a[1 + j] for a in v) / len(v) for j in (0, 1)]
        d = max(abs(m[0] - e[0]), abs(m[1] - e[1])) / P0
        print(f"tunnel ring r = {rm:.2f}: sr {m[0]:.4e} ({e[0]:.4e}), st {m[1]:.4e} ({e[1]:.4e}), "
              f"{100 * d:.2f} % of p0")
        if d > worst[0]:
            worst = (d, f"r = {rm:.2f}")
    check(worst[0] <= 0.03, "tunnel: ring-averaged sr, st within 3 % of p0 of Salencon's",
          f"worst {100 * worst[0]:.2f} % at {worst[1]}")
    pmax, emin = max(plastic_r), min(elastic_r)
    print(f"tunnel: R = {R_PL:.4f}; outermost plastic zone {pmax:.4f} ({pmax / R_PL:.3f} R), "
          f"innermost elastic zone {emin:.4f} ({emin / R_PL:.3f} R)")
    check(pmax <= 1.05 * R_PL and emin >= 0.95 * R_PL, "tunnel: plastic radius within 5 % of Salencon's R",
          f"plastic up to {pmax:.4f}, elastic from {emin:.4f}, R {R_PL:.4f}")

# ---------------------------------------------------------------------------
# 3. Plane-strain compression of a 1 x 2 sample, AUTO 0.25, confined by
#    sxx = -1e6 (INSITU + BOUND STRESS), top pushed at 0.05 m/s to an axial
#    strain of 0.83 % (8000 cycles; peak reached at about 0.2 %).
#    c = 1e6, phi = 30 deg, TENS 5e5: s1 = N s3 + 2 c sqrt(N) = 6.464e6.
#    szz starts at nu (sxx + syy) = -5e5 and stays intermediate.
#    Checks at 0.83 %: the mean syy at the peak within 1.5 % (the dead side
#    load grows as the side shortens: measured -0.25, +0.37, +0.39 %), the zone
#    spread of syy within the stated band, and no checkerboard: under 5 % of
#    the zones differ from the mean of sxx with the opposite sign to all of
#    their edge neighbours (measured 3 % for DIL = 0, 1 % or less otherwise).
#    Band: DIL = FRIC 1 % (measured 0.2 %), DIL = 0.2 4 % (2.0 %), DIL = 0
#    15 % (11 %: non-associated flow does not stay homogeneous -- a smooth
#    non-uniform pattern, not a checkerboard; crossed quads give 8 %).
MC = """start
round 0.01
block 0 0 0 2 1 2 1 0
gen auto 0.25
change cons=3
prop mat=1 dens=2000 bulk=1.6667e9 shear=1e9 coh=1e6 fric=0.57735 tens=5e5 dil={dil}
insitu stress -1e6 0 -1e6
bound stress -1e6,0,-1e6
bound -.1 1.1 -.01 .01 yvel=0
bound -.01 .01 -.01 .01 xvel=0
bound -.1 1.1 1.99 2.01 yvel=-0.05
damp auto
cycle 8000
print zone stress
print zone state
print grid
stop
"""
PEAK = 3e6 + 2e6 * math.sqrt(3)
for dil, band in (("0", 0.15), ("0.2", 0.04), ("0.57735", 0.01)):
    out = run_deck(f"compression_dil{dil}", MC.format(dil=dil))
    if not tables(out, "print grid"):
        continue
    rows = zone_rows(out, "print zone stress", "print zone state", "print grid")
    syy = [-z["SYY"] / PEAK for z, *_ in rows]
    mean = sum(syy) / len(syy)
    spread = max(abs(s - mean) for s in syy)
    sxx = {int(z["ZONE"]): z["SXX"] for z, *_ in rows}
    edges = collections.defaultdict(list)
    for z, _, _, ids in rows:
        for a, b in ((ids[0], ids[1]), (ids[1], ids[2]), (ids[2], ids[0])):
            edges[frozenset((a, b))].append(int(z["ZONE"]))
    nb = collections.defaultdict(list)
    for zz in edges.values():
        if len(zz) == 2:
            nb[zz[0]].append(zz[1])
            nb[zz[1]].append(zz[0])
    m = sum(sxx.values()) / len(sxx)
    checker = sum(1 for z in sxx if nb[z] and all((sxx[z] - m) * (sxx[y] - m) < 0 for y in nb[z]))
    print(f"compression DIL={dil}: mean syy / peak {mean:.4f}, spread {100 * spread:.1f} %, "
          f"checkerboard zones {checker} of {len(sxx)}")
    check(abs(mean - 1) <= 0.015, f"compression DIL={dil}: mean syy at the peak N s3 + 2c sqrt(N) (1.5 %)",
          f"{mean:.4f}")
    check(spread <= band, f"compression DIL={dil}: zone spread of syy within {100 * band:.0f} %",
          f"{100 * spread:.2f} %")
    check(checker <= 0.05 * len(sxx), f"compression DIL={dil}: no checkerboard (5 % of zones)",
          f"{checker} of {len(sxx)}")

# ---------------------------------------------------------------------------
# 4. Simple shear of a 2 x 1 cohesive block (c = 1e5, phi = 0, G = 1e8),
#    AUTO 0.2, no initial stress: every boundary gridpoint YVEL = 0, base
#    XVEL = 0, top XVEL = 1e-3 m/s, sides free in x (vx = v y / H with
#    sxx = syy = szz = 0 is then the exact solution). Elastic sxy = G gamma
#    reaches c at gamma = 1e-3; at 20000 cycles gamma = 1.8e-3, at 40000
#    3.7e-3. Checks: every zone's sxy within 0.1 % of c (measured 0.007 %),
#    every zone plastic, and the top reaction / width within 0.5 % of c
#    (measured 0.01 %). Reference: Tresca, (s1 - s3)/2 = c with szz
#    intermediate (szz = 0).
SHEAR = """START
ROUND 0.01
BLOCK 0,0 0,1 2,1 2,0
GEN 0,2 0,1 AUTO 0.2
CHANGE CONS=3
PROP MAT=1 DENS=2000 BULK=2E8 SHEAR=1E8 COH=1E5 FRIC=0 DIL=0 TENS=1E6
BOUND -.1 2.1 -.1 1.1 YVEL=0
BOUND -.1 2.1 -.01 .01 XVEL=0
BOUND -.1 2.1 .99 1.01 XVEL=1E-3
DAMP AUTO
CYC 20000
PRINT ZONE STRESS
PRINT BOUNDARY FORCES
CYC 20000
PRINT ZONE STRESS
PRINT BOUNDARY FORCES
STOP
"""
out = run_deck("simple_shear", SHEAR)
zs = tables(out, "PRINT ZONE STRESS")
bt = boundary_tables(out, "BOUNDARY FORCES")
check(len(zs) == 2 and len(bt) == 2, "simple_shear: two stress and two force prints", f"{len(zs)} {len(bt)}")
for k, (t, rows) in enumerate(zip(zs, bt)):
    worst = max(abs(r["SXY"] / 1e5 - 1) for r in t)
    plastic = all(r["PLASTICITY"] in (1.0, 2.0) for r in t)
    tau = -sum(r[5] for r in rows if r[2] > 0.99) / 2.0
    print(f"simple_shear print {k + 1}: worst zone sxy {100 * worst:.3f} % off c, top reaction/width {tau:.5e}")
    check(worst <= 1e-3 and plastic, f"simple_shear print {k + 1}: every zone plastic with sxy = c (0.1 %)",
          f"worst {100 * worst:.3f} %, all plastic {plastic}")
    check(abs(tau / 1e5 - 1) <= 5e-3, f"simple_shear print {k + 1}: top shear force / width = c (0.5 %)",
          f"{tau:.5e}")

finish()
