#!/usr/bin/env python3
"""Random tunnels in zoned (FDEF) rock, written from the manual's Sections 2
and 4 syntax the way a new user writes them, run and classified.

    tools/zoned_campaign.py UDEC OUTDIR [N [FIRST]]

Each deck (seed i): a square of rock held by its in-situ stress (INSITU and
BOUNDARY STRESS alike, or gravity with gradients and a fixed base, or
viscous sides), a TUNNEL, 0-3 joint sets (continuous or not, weak or
strong), GENERATE EDGE / AUTO (with and without ranges, coarse to fine;
QUAD on a jointed box without tunnel), elastic or Mohr-Coulomb zones, the
rest rigid in some decks, MSCALE in some, then CYCLE before excavation
(the model must stay still), DELETE or CHANGE CONS 0 of the plug, a liner
(STRUCTURE) or CABLE bolts in some, CYCLE, PRINT MAX / GRID / ZONE, PLOT.
Decks above 100 are of later families (NEW_KINDS): staged excavation,
yielding Mohr-Coulomb rock, very fine and very coarse zoning, near-parallel
joint sets; decks 1-100 are the same as before they were added.

Classes per deck: exit status (timeout = hang), errors and warnings, the
largest gridpoint displacement and velocity before excavation ("still":
below 1e-5 m and 1e-4 m/s, a thousandth of the excavation's), after excavation the unbalanced force against
the in-situ stress times the zone size ("balanced": below 1e-3), a lone
vibrating gridpoint (its speed above 20 times the 99th percentile of all
gridpoints' speeds, and above 1e-4 m/s), and for elastic unjointed decks the crown and
sidewall displacements against Kirsch's closed form (plane strain, Brady
and Brown, Rock Mechanics for Underground Mining, Section 7.4:
u_r(a, theta) = -a/(4G) [(ph + pv) - (pv - ph)(3 - 4 nu) cos 2 theta]),
asserted within 5 % (boundary at 8 radii, a polygon of 12-24 sides and
zones of a third of the radius; TUNNEL's horizontal cuts glued by stiff,
strong joints).

Writes OUTDIR/deck_i.dat, deck_i.out and a summary table to stdout.
"""
import math
import os
import random
import re
import subprocess
import sys
import time

NUM = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"
# families of the decks above 100: staged excavation (top heading, then the
# bench, a liner in half of them), Mohr-Coulomb rock weak enough to yield
# round the tunnel, very fine (a tenth of the radius) and very coarse (one
# to two radii) zoning, two near-parallel joint sets (acute wedges)
NEW_KINDS = ["staged", "yield", "fine", "coarse", "acute"]


def make_deck(seed):
    rnd = random.Random(seed)
    d = {"seed": seed}
    kind = rnd.choice(["kirsch", "jointed", "jointed", "plastic", "mixed", "gravity",
                       "viscous", "liner", "cable", "quad"])
    if seed % 10 == 0:
        kind = "kirsch"
    if seed > 100:
        # later families (decks 1-100 stay as they were)
        kind = rnd.choice(NEW_KINDS)
    d["kind"] = kind
    r = round(rnd.uniform(1.0, 4.0), 2)
    nside = rnd.choice([12, 16, 20, 24])
    if kind == "kirsch":
        L = 8 * r
        xc = yc = 0.0
    else:
        L = round(r * rnd.uniform(4.0, 8.0), 1)
        if kind == "fine":
            L = round(r * rnd.uniform(3.0, 4.0), 1)
        xc = round(rnd.uniform(-0.2, 0.2) * L, 2)
        yc = round(rnd.uniform(-0.2, 0.2) * L, 2)
    d.update(r=r, L=L, xc=xc, yc=yc, n=nside)
    rounding = rnd.choice([None, 0.05, 0.1, 0.02])
    if kind == "kirsch":
        # the manual's advice (Section 4.5, ROUND): about 1 % of the block
        # edges; the default 0.5 straightens a small tunnel's ring
        rounding = round(r / 50, 3)
    k0 = round(rnd.uniform(0.5, 2.0), 2)
    pv = round(rnd.uniform(5e6, 30e6), -5)
    ph = round(k0 * pv, -5)
    if kind == "kirsch" and seed % 20 == 0:
        ph = pv
    d.update(pv=pv, ph=ph)
    G = rnd.choice([5e9, 1.2e10, 2e10])
    nu = rnd.choice([0.2, 0.25, 0.3])
    K = round(2 * G * (1 + nu) / (3 * (1 - 2 * nu)), -6)
    d.update(G=G, K=K, nu=(3 * K - 2 * G) / (2 * (3 * K + G)))
    lines = ["heading", f"random tunnel {seed} ({kind})"]
    if rounding:
        lines.append(f"round {rounding}")
    lines.append(f"block -{L},-{L} -{L},{L} {L},{L} {L},-{L}")
    if kind != "quad":
        lines.append(f"tunnel {xc} {yc} {r} {nside}")
    nsets = 0 if kind == "kirsch" else rnd.choice([1, 2, 2, 3])
    if kind in ("quad", "acute"):
        nsets = 2
    if kind == "yield":
        nsets = rnd.choice([0, 1])
    sets = []
    for s in range(nsets):
        ang = round(rnd.uniform(-90, 90), 1)
        if kind == "quad":
            ang = [0.0, 90.0][s]
        if kind == "acute" and s == 1:
            # near-parallel to the first set: acute wedges between them
            ang = round(sets[0][0] + rnd.choice([-1, 1]) * rnd.uniform(3.0, 10.0), 1)
        sp = round(rnd.uniform(0.6, 1.5) * r, 2)
        if rnd.random() < 0.3 and kind != "quad":
            trace, gap = round(rnd.uniform(2, 4) * sp, 1), round(rnd.uniform(0.3, 1) * sp, 1)
        else:
            trace, gap = 100, 0
        x0 = round(rnd.uniform(-1, 1) * sp, 2)
        lines.append(f"jset {ang},0 {trace},0 {gap},0 {sp},0 {x0},0")
        sets.append((ang, sp, trace, gap))
    d["sets"] = sets
    # zoning
    e = round(r * rnd.uniform(0.25, 0.8), 2)
    if kind == "kirsch":
        e = round(r * rnd.uniform(0.2, 0.35), 2)
    if kind == "fine":
        e = round(r * rnd.uniform(0.08, 0.15), 3)
    if kind == "coarse":
        e = round(r * rnd.uniform(1.0, 2.0), 2)
    word = rnd.choice(["edge", "auto"])
    if kind == "quad":
        lines.append(f"gen quad {round(r * 0.5, 2)}")
    elif kind == "mixed":
        h = round(3 * r, 1)
        lines.append(f"gen {xc - h},{xc + h} {yc - h},{yc + h} {word} {e}")
    elif kind == "kirsch":
        e = round(r / 3, 2)
        lines.append(f"gen edge {e}")
    elif rnd.random() < 0.5:
        h = round(2.5 * r, 1)
        lines.append(f"gen {xc - h},{xc + h} {yc - h},{yc + h} {word} {e}")
        lines.append(f"gen {word} {round(min(3 * e, L / 3), 2)}")
    else:
        lines.append(f"gen {word} {e}")
    d["e"] = e
    dens = 2600
    lines.append(f"prop mat=1 dens={dens} k={K:.4g} g={G:.4g}")
    plastic = kind in ("plastic", "yield") or (kind not in ("kirsch",) and rnd.random() < 0.3)
    if plastic:
        coh = round(rnd.uniform(0.05, 0.3) * pv, -4)
        if kind == "yield":
            # weak rock: the wall's tangential stress (up to 3 pv) exceeds its
            # strength 2 c cos(phi) / (1 - sin(phi)): a plastic ring forms
            coh = round(rnd.uniform(0.03, 0.1) * pv, -4)
        lines.append(f"prop mat=1 coh={coh:.4g} fric={round(rnd.uniform(0.5, 1.0), 2)} "
                     f"tens={coh / 2:.4g}")
        lines.append("change cons=3")
    d["plastic"] = plastic
    weak = rnd.random() < 0.5 and kind != "kirsch"
    jkn = round(G * rnd.choice([0.2, 1.0, 5.0, 50.0]) / max(e, 0.1), -8)
    if kind == "kirsch":
        # TUNNEL's two horizontal cuts, glued: stiff and strong joints
        jkn = round(100 * G / e, -8)
        lines.append(f"prop jmat=1 jkn={jkn:.4g} jks={jkn:.4g} jfric=1 jcoh={10 * pv:.4g} "
                     f"jtens={10 * pv:.4g}")
    else:
        lines.append(f"prop jmat=1 jkn={jkn:.4g} jks={jkn / 2:.4g} jfric={0.4 if weak else 0.8}"
                     + ("" if weak else f" jcoh={pv / 10:.4g} jtens={pv / 20:.4g}"))
    d["weak"] = weak
    # loading
    grav = kind == "gravity"
    if grav:
        g = 9.81
        ytop = L
        lines.append(f"grav 0 -{g}")
        # syy(y) = -pv + rho g (y - yc) at the tunnel, sxx = k0 syy
        rg = dens * g
        lines.append(f"insitu stress -{ph:.4g} 0 -{pv:.4g} ygrad {rg * k0:.4g} 0 {rg:.4g}")
        lines.append(f"bound -{L + 0.1},-{L - 0.1} -{L},{L} stress -{ph:.4g} 0 -{pv:.4g} "
                     f"ygrad {rg * k0:.4g} 0 {rg:.4g}")
        lines.append(f"bound {L - 0.1},{L + 0.1} -{L},{L} stress -{ph:.4g} 0 -{pv:.4g} "
                     f"ygrad {rg * k0:.4g} 0 {rg:.4g}")
        lines.append(f"bound -{L + 1},{L + 1} {L - 0.1},{L + 0.1} stress -{ph:.4g} 0 -{pv:.4g} "
                     f"ygrad {rg * k0:.4g} 0 {rg:.4g}")
        # last: STRESS on the sides removes a velocity given before on their
        # ends (manual Section 4.5, BOUNDARY, Caution)
        lines.append(f"bound -{L + 1},{L + 1} -{L + 0.1},-{L - 0.1} yvel 0")
    else:
        lines.append(f"insitu stress -{ph:.4g} 0 -{pv:.4g}")
        lines.append(f"bound stress -{ph:.4g} 0 -{pv:.4g}")
        if kind == "viscous":
            lines.append(f"bound -{L + 0.1},-{L - 0.1} -{L},{L} xvisc yvisc mat 1")
            lines.append(f"bound {L - 0.1},{L + 0.1} -{L},{L} xvisc yvisc mat 1")
    mscale = rnd.random() < 0.2
    if mscale:
        lines.append("mscale part 1e-3")
    lines.append("damp auto")
    lines.append(f"hist unbal ydis {xc},{yc + r} xdis {xc + r},{yc} yvel {xc},{yc + r}")
    lines.append("cycle 500")
    lines.append("print max")
    # excavation
    q = 0.8 * r
    if kind == "quad":
        lines.append(f"change {-0.5 * r},{0.5 * r} {-0.5 * r},{0.5 * r} cons=0")
    elif kind == "staged":
        # top heading, cycles, then the bench
        lines.append(f"delete {xc - q},{xc + q} {yc},{yc + q}")
        lines.append(f"cycle {rnd.choice([1000, 2000])}")
        lines.append("print max")
        lines.append(f"change {xc - q},{xc + q} {yc - q},{yc} cons=0")
    elif rnd.random() < 0.5:
        lines.append(f"delete {xc - q},{xc + q} {yc - q},{yc + q}")
    else:
        lines.append(f"change {xc - q},{xc + q} {yc - q},{yc + q} cons=0")
    if kind in ("liner", "staged") and (kind == "liner" or rnd.random() < 0.5):
        lines.append(f"prop mat=2 dens=2500 k=1.4e10 g=1e10 kn={jkn * 0.1:.4g} ks={jkn * 0.05:.4g}")
        lines.append(f"structure {xc} {yc} 0 {r * 1.1:.3g} {nside} 2 0.3")
    if kind == "cable":
        lines.append("prop mat=3 dens=7800 k=1.7e11 g=8e10 yield=2.5e5")
        lines.append("prop mat=4 jks=2e9 jcoh=2e5")
        for a in (45, 90, 135):
            c, s_ = math.cos(math.radians(a)), math.sin(math.radians(a))
            lines.append(f"cable {xc + 0.9 * r * c:.3f},{yc + 0.9 * r * s_:.3f} "
                         f"{xc + 2.2 * r * c:.3f},{yc + 2.2 * r * s_:.3f} 6 3 5e-4 4")
    ncyc = rnd.choice([2000, 3000, 4000]) if kind != "kirsch" else 8000
    lines.append(f"cycle {ncyc}")
    lines.append("print max")
    lines.append(f"cycle 1000")
    lines.append("print max")
    lines.append("print grid")
    lines.append(f"print {xc - 1.05 * r},{xc + 1.05 * r} {yc - 1.05 * r},{yc + 1.05 * r} grid")
    lines.append("plot block smin")
    lines.append(f"copy deck_{seed}.png")
    lines.append("stop")
    text = "\n".join(lines) + "\n"
    d["text"] = re.sub(r"-?\d+\.\d{5,}", lambda m: f"{float(m.group()):.5g}", text)
    return d


def maxes(out):
    """The PRINT MAX tables: list of dicts quantity -> (value, id)."""
    res = []
    cur = None
    for ln in out.splitlines():
        if ln.strip().startswith("QUANTITY") and "VALUE" in ln:
            cur = {}
            res.append(cur)
            continue
        if cur is not None:
            m = re.match(r"\s+([a-zA-Z|() ,]+?)\s{2,}(" + NUM + r")(?:\s+(\w+)\s+(\d+))?\s*$", ln)
            if m:
                cur[m.group(1).strip()] = (float(m.group(2)), m.group(4))
            else:
                cur = None
    return res


def grid_rows(out, last_only=True):
    rows = []
    blocks = []
    cur = None
    for ln in out.splitlines():
        if ln.strip().startswith("GRIDPT") and "X-VEL" in ln:
            cur = []
            blocks.append(cur)
            continue
        if cur is not None:
            p = ln.split()
            if len(p) == 8 and p[0].isdigit():
                cur.append([int(p[0]), int(p[1])] + [float(v) for v in p[2:]])
            else:
                cur = None
    return blocks


def classify(d, rc, out, wall):
    c = {"seed": d["seed"], "kind": d["kind"], "rc": rc, "wall": wall}
    c["errors"] = [l for l in out.splitlines() if "***" in l or l.startswith("Error")
                   or "failure" in l.lower()]
    c["warnings"] = [l for l in out.splitlines() if l.startswith("Warning")]
    mx = maxes(out)
    c["nmax"] = len(mx)
    if mx:
        pre = mx[0]
        c["pre_disp"] = pre.get("max gridpoint displacement", (float("nan"), None))[0]
        c["pre_vel"] = pre.get("max gridpoint velocity", (float("nan"), None))[0]
    if len(mx) >= 3:
        a, b = mx[1], mx[2]
        c["vel_a"] = a.get("max gridpoint velocity", (float("nan"), None))[0]
        c["vel_b"] = b.get("max gridpoint velocity", (float("nan"), None))
    m = re.findall(r"max unbalanced force\s+(" + NUM + ")", out)
    if m:
        c["unbal"] = float(m[-1])
        c["unbal_rel"] = float(m[-1]) / (max(d["pv"], d["ph"]) * d["e"])
    g = grid_rows(out)
    if g:
        sp = sorted(math.hypot(r[6], r[7]) for r in g[0])
        p99 = sp[int(0.99 * (len(sp) - 1))]
        c["lone"] = sp[-1] / max(p99, 1e-300)
        c["vmax"] = sp[-1]
    if d["kind"] == "kirsch" and len(g) >= 2:
        G, nu, a = d["G"], d["nu"], d["r"]
        ph, pv = d["ph"], d["pv"]
        def kir(th):
            return -a / (4 * G) * ((ph + pv) - (pv - ph) * (3 - 4 * nu) * math.cos(2 * th))
        errs = []
        for r in g[1]:
            x, y = r[2] - r[4] - d["xc"], r[3] - r[5] - d["yc"]     # where it was
            rr = math.hypot(x, y)
            if abs(rr - a) > 1e-3 * a or math.hypot(r[4], r[5]) < 1e-12:
                continue        # off the wall, or the plug's (CHANGE CONS 0) gridpoints
            th = math.atan2(y, x)
            ur = (r[4] * x + r[5] * y) / rr
            errs.append((ur - kir(th)) / abs(kir(0) if abs(kir(0)) > abs(kir(math.pi / 2)) else kir(math.pi / 2)))
        if errs:
            c["kirsch"] = max(errs, key=abs)
    # verdict
    bad = []
    if rc is None:
        bad.append("hang")
    elif rc != 0:
        bad.append(f"exit{rc}")
    if c["errors"]:
        bad.append("error")
    if c.get("pre_disp", 0) > 1e-5 or c.get("pre_vel", 0) > 1e-4:
        bad.append("drift")
    if c.get("unbal_rel", 0) > 1e-3:
        bad.append("unbalanced")
    # (a lone gridpoint among gridpoints at round-off, 1e-12 m/s, is no vibration)
    if c.get("lone", 0) > 20 and c.get("vmax", 0) > 1e-4:
        bad.append("lone-vibration")
    if abs(c.get("kirsch", 0)) > 0.05:
        bad.append("kirsch")
    c["verdict"] = ",".join(bad) or "clean"
    return c


def report(c, results):
    results.append(c)
    print(f"{c['seed']:4d} {c['kind']:8s} {c['verdict']:28s} pre {c.get('pre_disp', -1):.1e} "
          f"{c.get('pre_vel', -1):.1e} unbal {c.get('unbal_rel', -1):.1e} "
          f"lone {c.get('lone', -1):7.1f} vmax {c.get('vmax', -1):.1e} "
          f"kirsch {c.get('kirsch', 0):+.3f} wall {c['wall']:.0f}s", flush=True)


def main():
    udec, outdir = sys.argv[1], sys.argv[2]
    n = int(sys.argv[3]) if len(sys.argv) > 3 else 60
    first = int(sys.argv[4]) if len(sys.argv) > 4 else 1
    jobs = int(os.environ.get("JOBS", "2"))
    os.makedirs(outdir, exist_ok=True)
    decks = [make_deck(s) for s in range(first, first + n)]
    running, results = [], []
    queue = list(decks)
    if os.environ.get("RECLASSIFY"):
        # classify the outputs of an earlier run (no udec run)
        queue = []
        for d in decks:
            out = open(os.path.join(outdir, f"deck_{d['seed']}.out"), errors="replace").read()
            rc = 0 if "*** Run stopped" not in out else 1
            report(classify(d, rc, out, 0.0), results)
    while queue or running:
        while queue and len(running) < jobs:
            d = queue.pop(0)
            name = f"deck_{d['seed']}"
            open(os.path.join(outdir, name + ".dat"), "w").write(d["text"])
            f = open(os.path.join(outdir, name + ".out"), "w")
            p = subprocess.Popen(["timeout", "600", udec, name + ".dat"], cwd=outdir, stdout=f,
                                 stderr=subprocess.STDOUT)
            running.append((d, p, f, time.time()))
        time.sleep(0.2)
        for item in list(running):
            d, p, f, t0 = item
            if p.poll() is None:
                continue
            f.close()
            running.remove(item)
            rc = p.returncode
            out = open(f.name, errors="replace").read()
            report(classify(d, None if rc == 124 else rc, out, time.time() - t0), results)
    clean = sum(1 for c in results if c["verdict"] == "clean")
    print(f"decks {len(results)}, clean {clean}")


if __name__ == "__main__":
    main()
