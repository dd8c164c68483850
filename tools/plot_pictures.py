#!/usr/bin/env python3
"""Pictures of docs/plot.md: one small model (two zoned blocks on a sloping
joint, loaded from above) plotted the ways a user plots it.

    python3 tools/plot_pictures.py <udec binary> <output folder> <prefix> [--before]

writes <prefix>_<kind>.png for each kind of plot. `--before` leaves out the
plots udec could not draw before issue 22/24 (JOINT / JLINE profiles, ROTATE,
GPFORCES, DSH), so that the same script makes the "before" pictures from an
older binary."""
import os
import subprocess
import sys
import tempfile

DECK = """HEADING
Two zoned blocks on a sloping joint, loaded from above
ROUND 0.02
BLOCK 0,0 0,10 10,10 10,0
CRACK 0,3 10,7
PROP MAT 1 DENS 2000 K 1e9 G 6e8
PROP JMAT 1 JKN 2e9 JKS 1e9 JFRIC 0.3
GEN EDGE 1
BOUND -1 11 -0.1 0.1 YVEL 0
BOUND -1 11 -0.1 0.1 XVEL 0
BOUND -1 11 9.9 10.1 STRESS 0 0 -1e6
HIST YDIS 5 10
HIST XDIS 10 10
DAMP AUTO
CYC 1500
"""

PLOTS = [
    ("contour", "PLOT SYY BLOCKS"),
    ("vectors", "PLOT BLOCKS DISP SHEAR"),
    ("history", "PLOT HIST 1 2"),
]
NEW_PLOTS = [
    ("joint_profile", "PLOT BLOCKS JOINT 0,3 10,7 NSTR"),
    ("jline", "PLOT BLOCKS JLINE 2,0 2,10 SSTR"),
    ("rotate", "PLOT ROTATE ZONE BLOCKS"),
    ("gpforces", "PLOT BLOCKS GPFORCES DSH"),
]


def main():
    udec, out, prefix = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2]), sys.argv[3]
    plots = PLOTS if "--before" in sys.argv[4:] else PLOTS + NEW_PLOTS
    os.makedirs(out, exist_ok=True)
    deck = DECK
    for kind, command in plots:
        deck += f"{command}\nCOPY {os.path.join(out, prefix + '_' + kind + '.png')}\n"
    deck += "STOP\n"
    with tempfile.TemporaryDirectory() as d:
        with open(os.path.join(d, "pictures.dat"), "w") as f:
            f.write(deck)
        run = subprocess.run([udec, "pictures.dat"], cwd=d, capture_output=True, text=True)
        if run.returncode != 0 or "***" in run.stdout:
            sys.stdout.write(run.stdout[-3000:])
            sys.exit(1)


if __name__ == "__main__":
    main()
