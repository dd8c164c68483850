#!/usr/bin/env python3
"""What a new user writes after a first tunnel, from the UDEC manual (ICG1.5,
1989), Sections 2 and 4 alone (campaign round 5; rounds 1-4:
tunnel_campaign.py, zoned_campaign.py, physics_campaign.py).

Each seed draws one deck of a family:

  tunnel   a jointed box under GRAVITY, the in-situ stress of its depth
           (INSITU STRESS ... YGRAD ..., top free or loaded by the
           overburden of 100-500 m), rollers on the sides and base (BOUNDARY
           XVEL / YVEL, or FIX of the outer blocks of a rigid model);
           rigid or zoned (GEN AUTO, elastic or CONS 3); staged: two drifts,
           or a heading then its bench, DELETEd in two steps; support after
           part of the convergence: REINFORCE bolts, CABLEs or a STRUCTURE
           liner; optionally water (FLUID, SET YWTAB, joint permeability,
           PFIX of the opening's domains to atmospheric pressure: a tunnel
           draining into the opening);
  slope    a bench under gravity: one joint dipping alpha out of the face, a
           back crack (SPLIT), friction drawn 4-10 degrees above or below
           alpha; optional steep crossing joints in the block behind;
  wedge    a roof wedge cut by two SPLITs above a TUNNEL, everything else
           FIXed, the wedge FREEd, held only by n vertical REINFORCE bolts
           installed just after the excavation.

Checks (every family):
  rc       exit 0 and no error line ("***", "Error") in any run;
  still    1000 cycles before any excavation: largest displacement below
           1e-6 x the model's size (tunnel only: the other two start from no
           stress);
  restart  the last stage is cycled N/2, SAVEd, cycled N/2 and PRINT MAX'd;
           a second run RESTARTs the save and cycles N/2: PRINT MAX
           identical;
Physics where a closed form exists:
  slope    a frictional block on a plane of dip alpha stays iff
           tan(phi) >= tan(alpha) (no cohesion): stays = largest
           displacement below 2 mm (10 x the joint's elastic shear), slides =
           above 1/4 of the undamped g (sin a - cos a tan phi) t^2 / 2 at
           the run's time t, or still moving (faster than 1 mm/s) at the end
           (DAMP AUTO slows the sliding, of zoned wedges far more);
  wedge    statics of the hanging wedge: the sum of the bolt forces equals
           its weight W, each bolt F = k d with d the wedge's drop, while
           W < n RUAXIAL (1 %); beyond, the wedge falls;
  tunnel   the largest displacement after excavation below 10 x the Kirsch
           scale of the depth's stress (flag only).

Usage: support_campaign.py UDEC OUTDIR [N [FIRST_SEED]]"""
import math
import os
import random
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from physics_campaign import main as campaign_main, maxdisp, run  # noqa: E402  (one runner)

G = 10.0


def tunnel_deck(r, seed, tag):
    mpa = r.random() < 0.4
    f = 1e-6 if mpa else 1.0
    dens = 2600.0 * (1e-6 if mpa else 1.0)
    W = r.choice([30.0, 40.0])
    H = W
    depth = r.choice([0.0, 100.0, 200.0, 500.0])       # overburden above the top
    zoning = r.choice(["rigid", "rigid", "auto"])
    cons3 = zoning == "auto" and r.random() < 0.4
    water = r.random() < 0.3
    support = r.choice(["none", "bolts", "cables", "liner"])
    stage = r.choice(["bench", "two"])
    k0 = r.choice([0.5, 1.0, 1.5])
    a = r.uniform(2.0, 3.0)
    xc, yc = W / 2, H * r.uniform(0.4, 0.55)
    if stage == "two":
        xs = [W / 2 - 2.2 * a, W / 2 + 2.2 * a]
    else:
        xs = [xc]
    bound = "fix" if zoning == "rigid" and r.random() < 0.5 else "rollers"
    head = (f"{tag} {zoning}{' cons3' if cons3 else ''} {stage} {support}"
            f"{' water' if water else ''} depth {depth:g} {'MPa' if mpa else 'SI'} {bound}")
    d = [f"HEAD support campaign {seed}: {head}", "ROUND 0.02",
         f"BLOCK 0,0 0,{H:g} {W:g},{H:g} {W:g},0"]
    for x in xs:
        d.append(f"TUNNEL {x:.3f},{yc:.3f} {a:.3f} {r.choice([16, 20])}")
    if stage == "bench":   # the heading is the upper half: SPLIT at the springline
        # (the manual's TUNNEL: later CRACKs do not penetrate the periphery, SPLIT does)
        d.append(f"SPLIT {xc - a - 0.5:.3f},{yc:.3f} {xc + a + 0.5:.3f},{yc:.3f}")
    a1 = r.uniform(-80, 80)
    for ang in (a1, a1 + r.uniform(60, 120)):
        ang = (ang + 90) % 180 - 90
        s = r.uniform(2.5, 5.0)
        d.append(f"JSET {ang:.1f},0 {2 * W:g},0 0,0 {s:.2f},0 ({r.uniform(0, s):.2f},{r.uniform(0, s):.2f})")
    if zoning == "auto":
        d.append(f"GEN 0,{W:g} 0,{H:g} AUTO {W / 15:.3g}")
    E_K, E_G = 15e9 * f, 9e9 * f
    mat = f"PROP MAT=1 DENS={dens:g} K={E_K:g} G={E_G:g}"
    if cons3:
        d += [mat + f" COH={3e6 * f:g} FRIC=0.9 TENS={0.5e6 * f:g}", "CHANGE CONS=3"]
    else:
        d.append(mat)
    jkn = 10e9 * f
    jp = f"PROP JMAT=1 JKN={jkn:g} JKS={jkn / 10:g} JFRIC={r.uniform(0.6, 0.9):.2f} JCOH=0 JTENS=0"
    if water:
        # k_j = 1 / (12 mu): 300 /(Pa s) in SI, 3e8 /(MPa s) (manual Section 3.12.2, Eq. 61)
        jp += " JPERM=300 AZERO=0.0005 ARES=0.0002" if not mpa else " JPERM=3e8 AZERO=0.0005 ARES=0.0002"
    d.append(jp)
    g = G
    rhow = 1000.0 * (1e-6 if mpa else 1.0)
    # effective stress at height y: syy = -(rho g depth + rho' g (H - y))
    # (compression negative; dry overburden, water table at the top, rho' =
    # rho - rho_w under it: the manual's SET EFF logic puts buoyancy on blocks)
    reff = dens - rhow if water else dens
    syy0 = -(dens * g * depth + reff * g * H)
    d.append(f"GRAVITY 0 -{g:g}")
    if water:
        d += [f"FLUID RHOW={rhow:g} BULKW={2e9 * f / 100:g}", f"SET YWTAB {H:g}"]
    d.append(f"INSITU STRESS {k0 * syy0:.6g} 0 {syy0:.6g} YGRAD {k0 * reff * g:.6g} 0 {reff * g:.6g}")
    e = 0.05
    top = []
    if depth > 0:
        top = [f"BOUND {-e:g},{W + e:g} {H - e:g},{H + e:g} STRESS 0 0 {-dens * g * depth:.6g}"]
    top_first = r.random() < 0.5    # the manual's caution: STRESS after XVEL frees the corners
    if top_first:
        d += top
    if bound == "rollers":
        d += [f"BOUND {-e:g},{W + e:g} {-e:g},{e:g} YVEL 0",
              f"BOUND {-e:g},{e:g} {-e:g},{H + e:g} XVEL 0",
              f"BOUND {W - e:g},{W + e:g} {-e:g},{H + e:g} XVEL 0"]
    else:   # the tutorial's way: the outer blocks fixed (every block touching a
        # side: centroids within 6 m, the largest joint spacing plus a margin)
        d += [f"FIX 0,{W:g} 0,6", f"FIX 0,6 0,{H:g}", f"FIX {W - 6:g},{W:g} 0,{H:g}"]
    if not top_first:
        d += top
    d += ["DAMP AUTO", "HIST UNBAL", f"HIST YDIS {xs[0]:.3f},{yc + a:.3f}", "CYCLE 1000", "PRINT MAX"]
    # stage 1: first drift or heading
    if stage == "bench":   # the ring's upper half: a range above the springline
        d.append(f"DELETE {xc - a + 0.01:.3f},{xc + a - 0.01:.3f} {yc + 0.01:.3f},{yc + a - 0.01:.3f}")
    else:
        d.append(f"DELETE ANN {xs[0]:.3f} {yc:.3f} 0 {a - 0.01:.3f}")
    def pfix(x):
        # the opening at atmospheric pressure: in the manual's SET EFF logic the
        # domain pressure is the excess over hydrostatic, -rho_w g (ywt - y)
        return (f"PFIX {x - a:.3f},{x + a:.3f} {yc - a:.3f},{yc + a:.3f} PRESSURE "
                f"{-rhow * g * H:.6g} YGRAD {rhow * g:.6g}")
    if water:
        d.append(pfix(xs[0]))
    d += ["CYCLE 600", "PLOT BLOCK DISP", f"COPY s5_{seed}_1.png", "PRINT MAX"]
    # support
    for x in xs:
        if support == "bolts":
            d.append(f"PROP MAT=5 RASTIFF={2e8 * f:g} RSSTIFF={2e7 * f:g} RUAXIAL={2e5 * f:g} "
                     f"RUSHEAR={1e5 * f:g} RLENGTH=0.5 RRFAC=1 RSEXP=1 RAEXP=1")
            for ang in (45, 90, 135):
                t = math.radians(ang)
                d.append(f"REINFORCE 5 {x + (a - 0.2) * math.cos(t):.3f} {yc + (a - 0.2) * math.sin(t):.3f} "
                         f"{x + (a + 4) * math.cos(t):.3f} {yc + (a + 4) * math.sin(t):.3f}")
        elif support == "cables":
            d += [f"PROP MAT=6 DENS={7800 * (1e-6 if mpa else 1):g} K={170e9 * f:g} G={80e9 * f:g} "
                  f"YIELD={2.5e5 * f:g} YCOMP={2.5e5 * f:g}",
                  f"PROP MAT=7 JKS={1e9 * f:g} JCOH={2e5 * f:g}"]
            for ang in (45, 90, 135):
                t = math.radians(ang)
                d.append(f"CABLE {x + (a - 0.3) * math.cos(t):.3f} {yc + (a - 0.3) * math.sin(t):.3f} "
                         f"{x + (a + 4) * math.cos(t):.3f} {yc + (a + 4) * math.sin(t):.3f} 6 6 5e-4 7")
        elif support == "liner":
            d.append(f"PROP MAT=8 DENS={2500 * (1e-6 if mpa else 1):g} K={16e9 * f:g} G={10e9 * f:g} "
                     f"KN={5e9 * f:g} KS={5e8 * f:g} CFRIC=0.5 CCOH=0 CTENS=0")
            if stage == "bench":
                d.append(f"STRUCT {x:.3f} {yc:.3f} 0 {a + 0.2:.3f} 12 8 0.2 180")
            else:
                d.append(f"STRUCT {x:.3f} {yc:.3f} 0 {a + 0.2:.3f} 16 8 0.2")
        if stage == "two":
            break          # the second drift is supported after its excavation
    d += ["CYCLE 600", "PRINT MAX"]
    # stage 2: the bench or the second drift
    if stage == "bench":
        d.append(f"DELETE {xc - a + 0.01:.3f},{xc + a - 0.01:.3f} {yc - a + 0.01:.3f},{yc - 0.01:.3f}")
    else:
        d.append(f"DELETE ANN {xs[1]:.3f} {yc:.3f} 0 {a - 0.01:.3f}")
    if water:     # the bench's domains are new: PFIX again (manual, PFIX)
        d.append(pfix(xs[-1]))
    d += ["CYCLE 500", f"SAVE s5_{seed}.sav", "CYCLE 500", "PRINT MAX", "PLOT BLOCK STRESS",
          f"COPY s5_{seed}_2.ps", "PRINT HIST 2"]
    d += [p for p in [dict(bolts="PRINT REINFORCE", cables="PRINT CABLE", liner="PRINT STE").get(support)]
          if p] + ["STOP"]
    rest = [f"RESTART s5_{seed}.sav", "CYCLE 500", "PRINT MAX", "STOP"]
    sv = dens * g * (depth + H - yc)
    G_eq = 1.0 / (1.0 / E_G + 1.0 / (0.1 * jkn * 2.5))
    est = sv * a * (1 + k0) / (4 * G_eq)
    return d, rest, W, dict(est=est)


def slope_deck(r, seed, tag):
    """A bench of height H, face at beta, a joint dipping alpha daylighting at
    the toe; a back crack from the joint to the crest."""
    H = r.choice([10.0, 20.0])
    beta = r.uniform(60, 80)
    alpha = r.uniform(25, 45)
    above = r.random() < 0.5
    phi = alpha + (r.uniform(4, 10) if above else -r.uniform(4, 10))
    zoning = r.choice(["rigid", "rigid", "auto"])
    cross = r.random() < 0.4
    W = 3 * H
    xt = H                                  # toe of the face at (xt, 0.3 H) above the base block
    y0 = 0.3 * H
    ytop = y0 + H
    xcrest = xt + H / math.tan(math.radians(beta))
    # the joint daylights on the face h1 above the toe (a wedge daylighting
    # at the floor is blocked by it) and rises at alpha to the top surface
    h1 = 0.25 * H
    xd, yd = xt + h1 / math.tan(math.radians(beta)), y0 + h1
    ta = math.tan(math.radians(alpha))
    xj = xd + (ytop - yd) / ta
    xback = xcrest + 0.6 * (xj - xcrest)   # back crack between crest and the joint's outcrop
    yback = yd + (xback - xd) * ta
    head = f"{tag} {zoning} alpha {alpha:.1f} phi {phi:.1f} {'stays' if above else 'slides'}{' cross' if cross else ''}"
    d = [f"HEAD support campaign {seed}: {head}", "ROUND 0.02",
         f"BLOCK 0,0 0,{y0:g} {xt:.3f},{y0:g} {xcrest:.3f},{ytop:g} {W:g},{ytop:g} {W:g},0",
         f"SPLIT 0,{y0:g} {W:g},{y0:g}",
         f"CRACK {xd - 0.5:.3f},{yd - 0.5 * ta:.4f} {xj + 0.5:.3f},{ytop + 0.5 * ta:.4f}",
         f"CRACK {xback:.3f},{yback - 0.3:.3f} {xback:.3f},{ytop + 0.5:g}"]
    if cross:   # steep joints in the rock behind the back crack
        d += [f"JREGION {xback + 0.5:.3f},{y0:g} {xback + 0.5:.3f},{ytop:g} {W:g},{ytop:g} {W:g},{y0:g}",
              f"JSET {r.uniform(70, 110):.1f},0 {2 * W:g},0 0,0 {r.uniform(2, 4):.2f},0"]
    if zoning == "auto":
        d.append(f"GEN 0,{W:g} 0,{ytop:g} AUTO {H / 6:.3g}")
    d += ["PROP MAT=1 DENS=2500 K=10e9 G=6e9",
          f"PROP JMAT=1 JKN=5e9 JKS=5e8 JFRIC={math.tan(math.radians(phi)):.5f} JCOH=0 JTENS=0",
          "GRAVITY 0 -10", "DAMP AUTO"]
    if zoning == "rigid":
        d.append(f"FIX 0,{W:g} 0,{y0:g}")
    else:
        d += [f"BOUND -0.05,{W + 0.05:g} -0.05,0.05 XVEL 0 YVEL 0",
              f"BOUND -0.05,0.05 -0.05,{y0:g} XVEL 0", f"BOUND {W - 0.05:g},{W + 0.05:g} -0.05,{ytop:g} XVEL 0"]
    xw = (xd + xcrest + xback) / 3
    d += [f"HIST XDIS {xcrest:.3f},{ytop:g}", "CYCLE 3000", "PRINT MAX", "PLOT BLOCK DISP",
          f"COPY s5_{seed}_1.png",
          f"CYCLE 2000", f"SAVE s5_{seed}.sav", "CYCLE 2000", "PRINT MAX", "PRINT CONTACT",
          "PLOT BLOCK VELOCITY", f"COPY s5_{seed}_2.ps", "STOP"]
    rest = [f"RESTART s5_{seed}.sav", "CYCLE 2000", "PRINT MAX", "STOP"]
    return d, rest, W, dict(above=above, xw=xw, alpha=alpha, phi=phi, zoning=zoning)


def wedge_deck(r, seed, tag):
    """Roof wedge of half-angle th above a tunnel, hanging on n vertical bolts."""
    a = r.uniform(2.0, 3.0)
    L = 20.0
    xc, yc = L / 2, L / 2
    th = r.uniform(20, 35)
    n = r.choice([2, 4])
    k = r.choice([1e7, 5e7, 2e8])
    dens = 2600.0
    zoning = r.choice(["rigid", "rigid", "auto"])
    t = math.tan(math.radians(th))
    # apex above the crown, lines cutting the circle (hap sin(th) <= 0.92 a)
    hap = a * r.uniform(1.25, 1.6)
    # SPLIT lines through the apex (xc, yc + hap) at th from the vertical
    ya = yc + hap

    def xl(y):      # the left line: x = xc - t (ya - y)
        return xc - t * (ya - y)

    def xr(y):
        return xc + t * (ya - y)
    d = ["ROUND 0.01", f"BLOCK 0,0 0,{L:g} {L:g},{L:g} {L:g},0",
         f"TUNNEL {xc:g},{yc:g} {a:.3f} 24",
         f"SPLIT {xl(-1):.4f},-1 {xl(L + 1):.4f},{L + 1:g}",
         f"SPLIT {xr(-1):.4f},-1 {xr(L + 1):.4f},{L + 1:g}"]
    # the wedge's base: where the lines meet the circle above its centre,
    # u = y - yc the larger root of (1 + t^2) u^2 - 2 t^2 h u + t^2 h^2 - a^2 = 0
    qa, qb, qc = 1 + t * t, -2 * t * t * hap, t * t * hap * hap - a * a
    ylo = yc + (-qb + math.sqrt(qb * qb - 4 * qa * qc)) / (2 * qa)
    half = xr(ylo) - xc
    fr = {2: [-0.5, 0.5], 4: [-0.75, -0.3, 0.3, 0.75]}[n]
    xs = [xc + q * half for q in fr]
    # the wedge's weight from its polygon (apex, base chord, minus the
    # circular segment above the chord): for choosing the bolts' capacity only
    u0 = ylo - yc
    wtri = half * (ya - ylo)
    wseg = a * a * math.acos(u0 / a) - u0 * math.sqrt(a * a - u0 * u0)
    West = dens * G * max(wtri - wseg, 0.05 * wtri)
    hold = r.random() < 0.7
    Fy = (3.0 if hold else 0.5) * West / n
    ex = r.choice([0, 1])
    head = f"{tag} {zoning} th {th:.1f} n {n} k {k:g} exp {ex} {'holds' if hold else 'falls'}"
    d.insert(0, f"HEAD support campaign {seed}: {head}")
    if zoning == "auto":
        d.append(f"GEN 0,{L:g} 0,{L:g} AUTO 1.0")
    d += [f"PROP MAT=1 DENS={dens:g} K=10e9 G=6e9",
          "PROP JMAT=1 JKN=1e10 JKS=1e9 JFRIC=0.5 JCOH=0 JTENS=0",
          f"PROP MAT=5 RASTIFF={k:g} RSSTIFF={k:g} RUAXIAL={Fy:.6g} RUSHEAR={Fy:.6g} RLENGTH=0.2 "
          f"RRFAC=1 RSEXP={ex} RAEXP={ex}",
          "GRAVITY 0 -10", "DAMP AUTO"]
    if zoning == "rigid":
        d += [f"FIX 0,{L:g} 0,{L:g}", f"FREE {xc - 0.5:g},{xc + 0.5:g} {ylo:.3f},{ya:.3f}"]
    else:
        d += [f"BOUND -0.05,{L + 0.05:g} -0.05,{L + 0.05:g} XVEL 0 YVEL 0"]
    d += [f"DELETE ANN {xc:g} {yc:g} 0 {a - 0.01:.3f}"]
    for x in xs:
        d.append(f"REINFORCE 5 {x:.4f} {ylo - 0.6:.4f} {x:.4f} {ya + 2:.4f}")
    d += ["PRINT BLOCK", f"HIST YDIS {xc:g},{ylo + 0.02:.3f}", "CYCLE 20000", "PRINT MAX",
          "PLOT BLOCK REINFORCE", f"COPY s5_{seed}_1.png",
          f"SAVE s5_{seed}.sav", "CYCLE 20000", "PRINT MAX", "PRINT REINFORCE", "STOP"]
    rest = [f"RESTART s5_{seed}.sav", "CYCLE 20000", "PRINT MAX", "STOP"]
    return d, rest, L, dict(n=n, k=k, Fy=Fy, dens=dens, zoning=zoning, hold=hold, ex=ex,
                            xc=xc, ylo=ylo, ya=ya)


def deck(seed):
    r = random.Random(f"camp5-{seed}")
    fam = r.choice(["tunnel", "tunnel", "slope", "wedge"])
    fn = dict(tunnel=tunnel_deck, slope=slope_deck, wedge=wedge_deck)[fam]
    d, rest, L, info = fn(r, seed, fam)
    info["fam"] = fam
    return "\n".join(d) + "\n", "\n".join(rest) + "\n", L, info


def print_max_blocks(out):
    """The text after each echoed PRINT MAX, in order."""
    return re.split(r"(?im)^\s*PRINT MAX\s*$", out)[1:]


def wedge_check(out, u, info):
    """Statics of the wedge hanging on its bolts (reference: equilibrium, and
    the law of the bolt's axial spring under monotonic loading,
    dF = k du (1 - F / Fu)^e of the manual's Section 3.10.1, Eqs. 43-44:
    e = 0: F = min(k d, Fu); e = 1: F = Fu (1 - exp(-k d / Fu))); 1 %."""
    wedge, area = None, None
    sec = out.split("PRINT BLOCK", 1)[-1]
    for m in re.finditer(r"(?m)^\s+(\d+)\s+\d+\s+\d+\s+\d+\s+\d+\s+(\S+)\s+(\S+)\s+(\S+)\s+\d+\s*$", sec):
        x, y = float(m.group(3)), float(m.group(4))
        if abs(x - info["xc"]) < 0.05 and info["ylo"] < y < info["ya"]:
            wedge, area = int(m.group(1)), float(m.group(2))
            break
    if wedge is None:
        return ["NO-WEDGE"]
    W = info["dens"] * G * area
    rows = re.findall(r"(?m)^\s+\d+\s+(\d+)\s+(\d+)\s+\d+\s+\S+\s+\S+\s+\S+\s+\S+\s+(\S+)\s+\S+\s+\S+\s+\S+\s*$",
                      out.split("PRINT REINFORCE")[-1])
    fa = [float(f) for b1, b2, f in rows if wedge in (int(b1), int(b2))]
    if len(fa) != info["n"]:
        return [f"BOLTS {len(fa)}/{info['n']}"]
    k, Fu, n = info["k"], info["Fy"], info["n"]
    if info["hold"]:
        flags = []
        if abs(sum(fa) - W) > 0.01 * W:
            flags.append(f"SUM-F {sum(fa):.4e} W {W:.4e}")
        if info["zoning"] == "rigid" and info["ex"] == 0:   # path-independent below Fu
            ref = min(k * u, Fu) if info["ex"] == 0 else Fu * (1 - math.exp(-k * u / Fu))
            if max(abs(f - ref) for f in fa) > 0.01 * ref:
                flags.append(f"F-NOT-KD {fa[0]:.4e} ref {ref:.4e}")
        return flags
    # n Fu = W / 2: the bolts yield, the wedge falls
    flags = []
    if not u > 100 * W / (n * k) and not u > 0.5:
        flags.append("WEDGE-HELD-BEYOND-CAPACITY")
    if max(fa) > Fu * (1 + 1e-4):        # the printed digits
        flags.append("F-ABOVE-RUAXIAL")
    return flags


def one(udec, folder, seed):
    first, second, L, info = deck(seed)
    rc1, out1 = run(udec, folder, f"s5_{seed}", first)
    rc2, out2 = run(udec, folder, f"s5_{seed}r", second) if rc1 == 0 else (-1, "")
    pm1, pm2 = print_max_blocks(out1), print_max_blocks(out2)
    errs = [ln.strip() for ln in (out1 + out2).splitlines() if "***" in ln or "Error" in ln]
    flags, note = [], ""
    if rc1 or rc2:
        flags.append(f"rc {rc1}/{rc2}")
    if "lie outside the TUNNEL ring" in out1:
        flags.append("rock-outside-ring-deleted(noted)")
    if errs:
        flags.append("errors")
    if info["fam"] == "tunnel" and pm1:
        pre = maxdisp(pm1[0])
        note += f"pre/L {pre / L:8.1e} "
        if not pre < 1e-6 * L:
            warned = "replaces a prescribed XVEL" in out1
            flags.append("moved-corners-freed(warned)" if warned else "MOVED-BEFORE-EXCAVATION")
    if pm1 and pm2:
        a_, b_ = maxdisp(pm1[-1]), maxdisp(pm2[-1])
        if not a_ == b_:
            flags.append(f"RESTART-DIFFERS {a_:.6e} {b_:.6e}")
    if info["fam"] == "tunnel" and pm1:
        post = maxdisp(pm1[-1])
        note += f"post/kirsch {post / info['est']:7.2f} "
        if not post <= 10 * info["est"]:
            flags.append("LARGE")
    if info["fam"] == "slope" and pm1:
        u = maxdisp(pm1[-1])
        times = [float(t) for t in re.findall(r"(?m)^cycle \d+, time\s+(\S+),", out1)]
        t = times[-1] if times else float("nan")
        al, ph = math.radians(info["alpha"]), math.radians(info["phi"])
        # frictional sliding from rest: u = g (sin a - cos a tan phi) t^2 / 2
        ufree = 0.5 * G * max(math.sin(al) - math.cos(al) * math.tan(ph), 0.0) * t * t
        note += f"u {u:9.3e} t {t:7.3g} "
        if info["above"] and not u < 2e-3:
            flags.append("SLID-ABOVE-LIMIT")
        if not info["above"]:
            note += f"u/free {u / ufree:5.2f} "
            # DAMP AUTO slows a sliding zoned wedge far more than a rigid one
            # (seed 50: 0.14 of free sliding, 1.15 with DAMP 0; rigid 0.5-0.9):
            # then it must still be moving at the end
            v = [float(x) for x in re.findall(r"max (?:block|gridpoint) velocity\s+(\S+)", pm1[-1])]
            note += f"v {max(v, default=0):8.2e} "
            if not (u > 0.25 * ufree or max(v, default=0) > 1e-3):
                flags.append("STAYED-BELOW-LIMIT")
    if info["fam"] == "wedge" and pm1:
        u = maxdisp(pm1[-1])
        note += f"u {u:9.3e} "
        flags += wedge_check(out1, u, info)
    head = first.splitlines()[0].split(": ", 1)[1]
    print(f"{seed:4d} {head:62s} {note}{' '.join(flags)} {'|'.join(errs)[:200]}", flush=True)
    return flags


if __name__ == "__main__":
    campaign_main(one)
