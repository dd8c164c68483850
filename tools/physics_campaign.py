#!/usr/bin/env python3
"""Tunnels in crossing joint sets, written as different new users write them
from the UDEC manual (ICG1.5, 1989), Sections 2 and 4, checked against physics
(campaign round 4; rounds 1-3: tunnel_campaign.py, zoned_campaign.py).

Each seed draws one deck: SI (Pa, kg/m3) or MPa units (MPa, Mg/m3 scaled to
MN), a 30-60 m square, a TUNNEL (radius 2-4 m) at the centre, off-centre or
within two diameters of a side, or a horseshoe (half ARC over three CRACKs,
manual Section 3, Fig. 3-12), three JSETs of which one non-persistent
(trace/gap), optionally dense (spacing ~1 m: ~2000 blocks), rigid, or zoned
(GEN AUTO / EDGE; QUAD refuses the JSETs' triangles) elastic or Mohr-Coulomb (CONS 3), with INSITU and the
same BOUNDARY STRESS. Then:

  still    1000 cycles before any excavation: the largest displacement must
           stay below 1e-6 x the model's size (the initial state is exact);
  excav    the opening is deleted and SOLVEd to half the cycles, SAVEd, the
           save RESTARTed in a second run and SOLVEd on: both runs exit 0,
           no error line, the final largest displacement against the
           Kirsch scale p a (1 + k0) / (4 G_eq) (ratio > 10 flagged: a key
           block falling in or a defect; the rock engineer then looks).

The continuum check (glued joints give Kirsch/Lame's u = p a / (2 G)) and the
frictional roof wedge's closed form are tests/scripts/tunnel_physics.py.
Usage: physics_campaign.py UDEC OUTDIR [N [FIRST_SEED]]"""
import math
import os
import random
import re
import subprocess
import sys


def deck(seed):
    r = random.Random(f"camp4-{seed}")
    mpa = r.random() < 0.5
    f = 1e-6 if mpa else 1.0            # stress unit
    dense = r.random() < 0.2
    L = 30.0 if dense else r.choice([30.0, 40.0, 60.0])
    a = r.uniform(2.0, 4.0)
    where = r.choice(["centre", "offcentre", "nearside"])
    xc = yc = L / 2
    if where == "offcentre":
        xc, yc = L * r.uniform(0.35, 0.65), L * r.uniform(0.35, 0.65)
    elif where == "nearside":
        xc, yc = L * r.uniform(0.4, 0.6), r.uniform(3.0, 4.0) * a
    shape = r.choice(["tunnel", "tunnel", "horseshoe"])
    zoning = r.choice(["rigid", "rigid", "auto", "edge"])
    cons3 = zoning != "rigid" and r.random() < 0.5
    p = r.choice([5e6, 10e6, 20e6]) * f
    k0 = r.choice([0.5, 1.0, 1.5, 2.0])
    a1 = r.uniform(-90, 90)
    sets = [a1, a1 + r.uniform(40, 80), a1 + r.uniform(100, 140)]
    sp = [r.uniform(0.8, 1.2) if dense else r.uniform(2.0, 5.0) for _ in sets]
    d = [f"HEAD physics campaign {seed}: {where} {shape}{' dense' if dense else ''} {zoning}"
         f"{' cons3' if cons3 else ''} {'MPa' if mpa else 'SI'}",
         f"ROUND {0.01 * L / 30:.4g}", f"BLOCK 0,0 0,{L:g} {L:g},{L:g} {L:g},0"]
    if shape == "tunnel":
        d.append(f"TUNNEL {xc:.3f},{yc:.3f} {a:.3f} {r.choice([16, 20, 24])}")
    else:
        h = 0.8 * a
        d += [f"ARC {xc:.3f} {yc:.3f} {xc + a:.3f} {yc:.3f} 180 12",
              f"CRACK {xc + a:.3f},{yc:.3f} {xc + a:.3f},{yc - h:.3f}",
              f"CRACK {xc - a:.3f},{yc - h:.3f} {xc + a:.3f},{yc - h:.3f}",
              f"CRACK {xc - a:.3f},{yc:.3f} {xc - a:.3f},{yc - h:.3f}"]
    for i, (ang, s) in enumerate(zip(sets, sp)):
        ang = (ang + 90) % 180 - 90
        if i == 2:   # non-persistent: trace and gap
            tr, gp = r.uniform(3, 8), r.uniform(1, 3)
            d.append(f"JSET {ang:.1f},0 {tr:.2f},1 {gp:.2f},0.5 {s:.2f},0 "
                     f"({r.uniform(0, s):.2f},{r.uniform(0, s):.2f})")
        else:
            d.append(f"JSET {ang:.1f},0 {2 * L:g},0 0,0 {s:.2f},0 ({r.uniform(0, s):.2f},{r.uniform(0, s):.2f})")
    if zoning == "auto":
        d.append(f"GEN 0,{L:g} 0,{L:g} AUTO {L / 20:.3g}")
    elif zoning == "edge":
        d.append(f"GEN EDGE {L / 20:.3g}")
    dens = 2600 * (1e-6 if mpa else 1.0)
    E_K, E_G = 20e9 * f, 12e9 * f
    mat = f"PROP MAT=1 DENS={dens:g} K={E_K:g} G={E_G:g}"
    if cons3:
        mat += f" COH={r.choice([2e6, 5e6]) * f:g} FRIC=0.8 TENS={1e6 * f:g}"
        d += [mat, "CHANGE CONS=3"]
    else:
        d.append(mat)
    jkn = r.choice([10e9, 20e9, 50e9]) * f
    d.append(f"PROP JMAT=1 JKN={jkn:g} JKS={jkn / 10:g} JFRIC={r.uniform(0.6, 0.9):.2f} "
             f"JCOH={r.choice([0, 0, 0.1e6, 1e6]) * f:g} JTENS=0")
    field = f"{-k0 * p:g} 0 {-p:g}"
    d += [f"INSITU STRESS {field}", f"BOUND STRESS {field}", "DAMP AUTO",
          "CYCLE 1000", "PRINT MAX"]
    if shape == "tunnel":
        d.append(f"DELETE ANN {xc:.3f} {yc:.3f} 0 {a - 0.01:.3f}")
    else:
        d += [f"DELETE ANN {xc:.3f} {yc:.3f} 0 {a - 0.01:.3f}",
              f"DELETE {xc - a + 0.01:.3f},{xc + a - 0.01:.3f} {yc - 0.8 * a + 0.01:.3f},{yc:.3f}"]
    d += ["SOLVE RATIO 1e-4 CYCLES 8000", f"SAVE c4_{seed}.sav", "STOP"]
    G_eq = 1.0 / (1.0 / E_G + 1.0 / (0.1 * jkn * min(sp)))
    est = p * a * (1 + k0) / (4 * G_eq)
    rest = [f"RESTART c4_{seed}.sav", "SOLVE RATIO 1e-4 CYCLES 12000", "PRINT MAX", "STOP"]
    return "\n".join(d) + "\n", "\n".join(rest) + "\n", L, est


def maxdisp(text):
    vals = [float(m.group(1)) for m in
            re.finditer(r"max (?:block|gridpoint) displacement\s+(\S+)", text)]
    return max(vals) if vals else float("nan")


def run(udec, folder, name, text, timeout=600):
    path = os.path.join(folder, name + ".dat")
    with open(path, "w") as fh:
        fh.write(text)
    try:
        p = subprocess.run([udec, name + ".dat"], cwd=folder, capture_output=True,
                           text=True, timeout=timeout)
        out, rc = p.stdout + p.stderr, p.returncode
    except subprocess.TimeoutExpired:
        out, rc = "TIMEOUT", -9
    with open(os.path.join(folder, name + ".out"), "w") as fh:
        fh.write(out)
    return rc, out


def one(udec, folder, seed):
    first, second, L, est = deck(seed)
    rc1, out1 = run(udec, folder, f"c4_{seed}", first)
    parts = re.split(r"(?im)^PRINT MAX\s*$", out1)
    pre = maxdisp(parts[1]) if len(parts) > 1 else float("nan")
    rc2, out2 = run(udec, folder, f"c4_{seed}r", second) if rc1 == 0 else (-1, "")
    post = maxdisp(out2)
    errs = [ln.strip() for ln in (out1 + out2).splitlines() if "***" in ln or "Error" in ln]
    bal = [("balanced" in ln and "not" not in ln) for ln in (out1 + out2).splitlines() if "SOLVE:" in ln]
    flags = []
    if rc1 or rc2:
        flags.append(f"rc {rc1}/{rc2}")
    if not pre < 1e-6 * L:
        flags.append("MOVED-BEFORE-EXCAVATION")
    if errs:
        flags.append("errors")
    if not post <= 10 * est:
        flags.append("LARGE")
    head = first.splitlines()[0].split(": ", 1)[1]
    print(f"{seed:4d} {head:45s} pre/L {pre / L:9.2e} post/kirsch {post / est:8.2f} "
          f"solves {sum(bal)}/{len(bal)} {' '.join(flags)} {'|'.join(errs)[:160]}", flush=True)
    return flags


def main(one_deck=one):
    """UDEC OUTDIR [N [FIRST_SEED]]: one_deck(udec, folder, seed) for each seed
    (support_campaign.py draws its own decks through this loop)."""
    udec, folder = os.path.abspath(sys.argv[1]), sys.argv[2]
    n = int(sys.argv[3]) if len(sys.argv) > 3 else 20
    first = int(sys.argv[4]) if len(sys.argv) > 4 else 1
    os.makedirs(folder, exist_ok=True)
    bad = 0
    for seed in range(first, first + n):
        bad += bool(one_deck(udec, folder, seed))
    print(f"{n} decks, {bad} flagged")


if __name__ == "__main__":
    main()
