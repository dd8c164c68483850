#!/usr/bin/env python3
"""Random jointed tunnels of rigid and SDEF blocks, written the way seven kinds of
new users write them from the manual's Sections 2 and 4 (UDEC manual (ICG1.5, 1989)):

  grad      BOUNDARY STRESS with XGRAD / YGRAD gradients on all four sides, gravity, no INSITU
  stages    INSITU + BOUNDARY STRESS, the opening excavated in 3 DELETE stages
  change    CHANGE JMAT to a softer joint after the excavation has settled
  bolts     REINFORCE bolts across the roof
  sdef      CHANGE SDEF (CONS 1) for the whole model
  fracdamp  FRACTION 0.5 and Rayleigh mass damping (DAMP fcrit freq MASS) instead of AUTO
  deep      a 50 MPa field with its gravity gradient, gravity on

Each deck: a 30 m square, TUNNEL of radius 3 m at its centre, two JSETs (random angles,
spacing 2-4 m), JKN 20 GPa, friction 0.7, no cohesion. The script runs them and classifies
each: exit status, error lines, every SOLVE balanced (force ratio 1e-4), the final largest
block velocity, and the largest block displacement against a Kirsch-scale estimate
p a (1 + k0) / (4 G_eq) (G_eq from the joints' stiffness times spacing, in series with the
rock for SDEF): a ratio beyond 10 is flagged (a key block sliding or falling in, or a
defect). Usage: tunnel_campaign.py UDEC OUTDIR [N_PER_KIND [FIRST_SEED]]."""
import math
import os
import random
import re
import subprocess
import sys
import time

L, XC, YC, A = 30.0, 15.0, 15.0, 3.0
KINDS = ["grad", "stages", "change", "bolts", "sdef", "fracdamp", "deep"]
RHOG = 2600 * 9.81


def deck(kind, seed):
    r = random.Random(f"{kind}-{seed}")
    a1 = r.uniform(10, 80)
    a2 = a1 - r.uniform(60, 120)
    s1, s2 = r.uniform(2.0, 4.0), r.uniform(2.0, 4.0)
    p = r.choice([5e6, 10e6, 20e6])
    k0 = r.choice([0.5, 1.0, 1.5])
    d = f"""HEAD tunnel campaign {kind} {seed}
ROUND 0.05
BLOCK 0,0 0,{L:g} {L:g},{L:g} {L:g},0
TUNNEL {XC:g} {YC:g} {A:g} 16
JSET {a1:.1f},0 100,0 0,0 {s1:.2f},0 {r.uniform(0, 3):.2f},{r.uniform(0, 3):.2f}
JSET {a2:.1f},0 100,0 0,0 {s2:.2f},0 {r.uniform(0, 3):.2f},{r.uniform(0, 3):.2f}
PROP MAT 1 DENS 2600 K 30e9 G 18e9
PROP JMAT 1 JKN 20e9 JKS 2e9 JFRIC 0.7 JCOH 0 JTENS 0
"""
    field = f"{-k0 * p:g} 0 {-p:g}"
    excavate = f"DELETE ANN {XC:g} {YC:g} 0 {A - 0.01:g}\n"
    solve = "SOLVE RATIO 1e-4 CYCLES {}\n"
    if kind == "grad":
        d += f"GRAV 0 -9.81\nBOUND STRESS {field} XGRAD 0 0 0 YGRAD {k0 * RHOG:g} 0 {RHOG:g}\n"
        d += "DAMP AUTO\n" + solve.format(20000) + excavate + solve.format(20000)
    elif kind == "stages":
        d += f"INSITU STRESS {field}\nBOUND STRESS {field}\nDAMP AUTO\n" + solve.format(5000)
        for lo, hi in ((YC + 1, YC + A), (YC - 1, YC + 1), (YC - A, YC - 1)):
            d += f"DELETE {XC - A:g} {XC + A:g} {lo:g} {hi:g}\n" + solve.format(15000)
    elif kind == "change":
        d += "PROP JMAT 2 JKN 5e9 JKS 0.5e9 JFRIC 0.35 JCOH 0 JTENS 0\n"
        d += f"INSITU STRESS {field}\nBOUND STRESS {field}\nDAMP AUTO\n" + excavate
        d += solve.format(15000) + "CHANGE JMAT 2\n" + solve.format(20000)
    elif kind == "bolts":
        d += ("PROP MAT 2 RASTIFF 1e9 RSSTIFF 1e8 RLENGTH 0.5 RUAXIAL 3e5 RUSHEAR 1e5 "
              "RSEXP 1 RAEXP 1 RRFAC 1\n")
        d += f"INSITU STRESS {field}\nBOUND STRESS {field}\nDAMP AUTO\n" + excavate
        for ang in range(30, 151, 20):
            c, s = math.cos(math.radians(ang)), math.sin(math.radians(ang))
            d += (f"REINFORCE 2 {XC + (A + 0.05) * c:.3f},{YC + (A + 0.05) * s:.3f} "
                  f"{XC + (A + 4) * c:.3f},{YC + (A + 4) * s:.3f}\n")
        d += solve.format(20000) + "PRINT REINF\n"
    elif kind == "sdef":
        d += f"CHANGE SDEF\nCHANGE CONS 1\nINSITU STRESS {field}\nBOUND STRESS {field}\n"
        d += "DAMP AUTO\n" + excavate + solve.format(20000)
    elif kind == "fracdamp":
        d += f"INSITU STRESS {field}\nBOUND STRESS {field}\nFRACTION 0.5\n"
        d += f"DAMP 0.5 {r.choice([2, 5, 20])} MASS\n" + excavate + "CYCLE 15000\n"
    elif kind == "deep":
        p = 50e6
        field = f"{-k0 * p:g} 0 {-p:g}"
        grad = f"YGRAD {k0 * RHOG:g} 0 {RHOG:g}"
        d += f"GRAV 0 -9.81\nINSITU STRESS {field} {grad}\nBOUND STRESS {field} {grad}\n"
        d += "DAMP AUTO\n" + solve.format(5000) + excavate + solve.format(20000)
    d += "PRINT MAX\nSTOP\n"
    return d, p, k0, (s1 + s2) / 2


def classify(kind, out, p, k0, spacing):
    errors = [ln for ln in out.splitlines() if ln.startswith("***")]
    solves = re.findall(r"SOLVE: (balanced|not balanced)[^\n]*ratio ([0-9.E+-]+)", out)
    balanced = all(s[0] == "balanced" for s in solves) if solves else None
    u = re.findall(r"max block displacement\s+(\S+)", out)
    v = re.findall(r"max block velocity\s+(\S+)", out)
    e_rock, nu = 45e9, 0.25
    e_eq = 20e9 * spacing
    if kind == "sdef":
        e_eq = 1 / (1 / e_rock + 1 / e_eq)
    g_eq = e_eq / (2 * (1 + nu))
    u_k = p * A * (1 + k0) / (4 * g_eq)
    ratio = float(u[-1]) / u_k if u else None
    return errors, balanced, (solves[-1][1] if solves else None), \
        (float(v[-1]) if v else None), ratio


def main():
    udec, outdir = sys.argv[1], sys.argv[2]
    n = int(sys.argv[3]) if len(sys.argv) > 3 else 9
    first = int(sys.argv[4]) if len(sys.argv) > 4 else 1
    os.makedirs(outdir, exist_ok=True)
    totals = {}
    for kind in KINDS:
        for seed in range(first, first + n):
            name = f"{kind}{seed}"
            text, p, k0, spacing = deck(kind, seed)
            with open(os.path.join(outdir, name + ".dat"), "w") as f:
                f.write(text)
            t0 = time.time()
            try:
                res = subprocess.run([udec, name + ".dat"], cwd=outdir, capture_output=True,
                                     text=True, timeout=600)
                rc, out = res.returncode, res.stdout + res.stderr
            except subprocess.TimeoutExpired:
                rc, out = -1, "*** timeout (600 s)"
            with open(os.path.join(outdir, name + ".out"), "w") as f:
                f.write(out)
            errors, balanced, last, vmax, ratio = classify(kind, out, p, k0, spacing)
            balanced = balanced and rc == 0   # a run that failed did not balance
            flag = "" if ratio is not None and ratio <= 10 else "  u/u_Kirsch > 10 or none"
            print(f"{name:10s} rc={rc} {time.time() - t0:5.1f} s errors={len(errors)} "
                  f"balanced={balanced} ratio={last} vmax={vmax} u/u_Kirsch="
                  f"{None if ratio is None else round(ratio, 2)}{flag}", flush=True)
            t = totals.setdefault(kind, [0, 0, 0, 0])
            t[0] += 1
            t[1] += rc == 0
            t[2] += bool(balanced)
            t[3] += ratio is not None and ratio <= 10
    print("kind      decks exit-0 balanced u/u_Kirsch<=10")
    for kind, t in totals.items():
        print(f"{kind:9s} {t[0]:5d} {t[1]:6d} {t[2]:8d} {t[3]:6d}")


if __name__ == "__main__":
    main()
