#!/usr/bin/env python3
"""Random TUNNEL rings in two crossing joint sets: how many leave a block
straddling the ring (TUNNEL's warning "the ring still crosses N block(s)")
and how the area DELETE takes compares with the ring.

Each draw (seeded, reproducible): a square box of side 24 m, ROUND 0.02, two
persistent JSETs at random angles (the second 60 to 120 degrees from the
first) with random spacings 0.8 to 1.5 m and random origins, then TUNNEL xc
yc r n with the centre drawn within 1 m of the box centre (off the joint
grid), r one of 2, 3.7, 5 and n 12 to 48 sides, then PRINT BLOCK, DELETE ANN
xc yc 0 (r - 0.01), PRINT BLOCK. Printed per draw: the deck's parameters,
the blocks the ring still crosses, and the deleted area over the ring
polygon's area (0.5 n r^2 sin(360/n)). Used by e2e.tunnel_ring_tips (a few
draws) and by hand (docs/geometry.md, "A ring side across a block's tip").

usage: ring_straddle_sweep.py UDEC [--seed S] [--count N] [--keep DIR]
"""
import argparse
import math
import os
import random
import re
import subprocess
import sys
import tempfile


def draw(rng):
    a1 = rng.uniform(-90.0, 90.0)
    a2 = a1 + rng.uniform(60.0, 120.0)
    s1 = rng.uniform(0.8, 1.5)
    s2 = rng.uniform(0.8, 1.5)
    o1 = (rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0))
    o2 = (rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0))
    xc = rng.uniform(-1.0, 1.0)
    yc = rng.uniform(-1.0, 1.0)
    r = rng.choice([2.0, 3.7, 5.0])
    n = rng.randint(12, 48)
    return dict(a1=a1, a2=a2, s1=s1, s2=s2, o1=o1, o2=o2, xc=xc, yc=yc, r=r, n=n)


def deck(p):
    return f"""round 0.02
block -12,-12 -12,12 12,12 12,-12
jset {p['a1']:.4f},0 100,0 0,0 {p['s1']:.4f},0 ({p['o1'][0]:.4f},{p['o1'][1]:.4f})
jset {p['a2']:.4f},0 100,0 0,0 {p['s2']:.4f},0 ({p['o2'][0]:.4f},{p['o2'][1]:.4f})
tunnel {p['xc']:.4f} {p['yc']:.4f} {p['r']} {p['n']}
print block
del ann {p['xc']:.4f} {p['yc']:.4f} 0 {p['r'] - 0.01:.4f}
print block
"""


def block_area_total(text):
    """Sum of AREA over the rows of one PRINT BLOCK table."""
    total = 0.0
    for line in text.splitlines():
        f = line.split()
        if len(f) == 9 and f[0].isdigit() and f[1].isdigit():
            total += float(f[5])
    return total


def run_one(udec, p, folder):
    path = os.path.join(folder, "ring.dat")
    with open(path, "w") as fh:
        fh.write(deck(p))
    out = subprocess.run([udec, "ring.dat"], cwd=folder, stdout=subprocess.PIPE,
                         stderr=subprocess.STDOUT, text=True, timeout=300).stdout
    m = re.search(r"ring still crosses (\d+) block", out)
    straddle = int(m.group(1)) if m else 0
    m = re.search(r"departs from the ring drawn by (\S+) m2", out)
    p["misfit"] = float(m.group(1)) if m else 0.0
    parts = out.split("del ann")
    before = block_area_total(parts[0])
    after = block_area_total(parts[1]) if len(parts) > 1 else before
    ring = 0.5 * p["n"] * p["r"] ** 2 * math.sin(2.0 * math.pi / p["n"])
    return straddle, (before - after) / ring, out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("udec")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--count", type=int, default=20)
    ap.add_argument("--keep", help="folder for the decks that leave a straddle")
    args = ap.parse_args()
    args.udec = os.path.abspath(args.udec)
    rng = random.Random(args.seed)
    folder = tempfile.mkdtemp(prefix="ring-sweep-")
    total = 0
    worst = 0.0
    departs = 0
    for k in range(args.count):
        p = draw(rng)
        straddle, ratio, out = run_one(args.udec, p, folder)
        total += straddle
        departs += p["misfit"] > 0.0
        worst = max(worst, abs(ratio - 1.0))
        print(f"draw {k}: sets {p['a1']:.1f}/{p['s1']:.2f} {p['a2']:.1f}/{p['s2']:.2f} "
              f"ring ({p['xc']:.3f},{p['yc']:.3f}) r {p['r']} n {p['n']}: "
              f"straddles {straddle}, deleted/ring {ratio:.6f}"
              + (f", departs from the ring by {p['misfit']} m2" if p["misfit"] else ""))
        if straddle and args.keep:
            os.makedirs(args.keep, exist_ok=True)
            with open(os.path.join(args.keep, f"draw{k}.dat"), "w") as fh:
                fh.write(deck(p))
    print(f"total straddles {total} in {args.count} draws; "
          f"largest |deleted/ring - 1| {worst:.3e}; "
          f"{departs} draw(s) warned that the opening departs from the ring")
    return 0


if __name__ == "__main__":
    sys.exit(main())
