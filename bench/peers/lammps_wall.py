#!/usr/bin/env python3
"""The brick wall of bench/rigid_bench in LAMMPS (issue 23's peer benchmark).

An n x n square of 1 m square blocks (n = 32, 100, 317 for about 1k, 10k, 100k
blocks), side by side without gaps, rounding 0.01 m, bottom row held, gravity
10 m/s^2 down, density 2500 kg/m^3, contact stiffness 1e10: in LAMMPS each
block is a body particle of style rounded/polygon (four vertices inset by the
rounding radius, so the rounded outlines touch as the blocks do in udec), pair
style body/rounded/polygon, fix nve/body and enforce2d. The same number of steps
runs in both programs, one thread each, the order alternating between repeats.

Printed per size: udec's figure (rigid_bench: M contact-cycles/s, and block-steps
per second), LAMMPS's (block-steps per second from its "Loop time", and the same
contact count as udec's times the steps over that time: the walls have the same
corner-edge contacts), and the ratio udec / LAMMPS. Medians of the repeats.

LAMMPS is not a build or test dependency: Debian's package `lammps` (which has the
BODY package) is installed on demand with --install (apt-get, as root), as
tools/install-deps.sh installs the build dependencies.

    python3 bench/peers/lammps_wall.py [--build build] [--sizes 1000,10000]
        [--steps 100] [--repeats 3] [--install] [--json out.json]
"""
import argparse
import json
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

SIDES = {1000: 32, 10000: 100, 100000: 317}


def lammps_exe():
    for name in ("lmp", "lmp_serial", "lammps"):
        path = shutil.which(name)
        if path:
            return path
    return None


def install():
    env = dict(os.environ, DEBIAN_FRONTEND="noninteractive")
    subprocess.run(["apt-get", "install", "-y", "--no-install-recommends", "lammps"], env=env,
                   check=True)


def has_body(lmp):
    out = subprocess.run([lmp, "-h"], stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                         text=True).stdout
    return "body/rounded/polygon" in out


def write_wall(folder, n, rounding=0.01, rho=2500.0, kn=1.0e10, steps=100, dt=1.0e-4):
    """Data file and input script of the n x n wall; returns the input's path."""
    h = 0.5 - rounding              # vertex inset: outline = polygon + rounding circle
    mass = rho * 1.0
    inertia = mass * (1.0 + 1.0) / 12.0     # square of side 1 about its centre
    lines = ["udec brick wall %d x %d" % (n, n), "",
             "%d atoms" % (n * n), "1 atom types", "%d bodies" % (n * n), "",
             "%.1f %.1f xlo xhi" % (-2.0, n + 2.0), "%.1f %.1f ylo yhi" % (-2.0, 2.0 * n + 2.0),
             "-0.5 0.5 zlo zhi", "", "Atoms", ""]
    k = 0
    for j in range(n):
        for i in range(n):
            k += 1
            lines.append("%d 1 1 %.6g %.6f %.6f 0" % (k, mass, i + 0.5, j + 0.5))
    lines += ["", "Bodies", ""]
    for k in range(1, n * n + 1):
        lines.append("%d 1 19" % k)
        lines.append("4")
        lines.append("%.9g %.9g %.9g 0 0 0" % (inertia / 2, inertia / 2, inertia))
        lines.append("%.6f %.6f 0 %.6f %.6f 0 %.6f %.6f 0 %.6f %.6f 0"
                     % (-h, -h, h, -h, h, h, -h, h))
        lines.append("%.6f" % (2.0 * rounding))
    with open(os.path.join(folder, "wall.data"), "w") as f:
        f.write("\n".join(lines) + "\n")
    script = """units si
dimension 2
boundary f f p
atom_style body rounded/polygon 1 6
atom_modify map array
read_data wall.data
pair_style body/rounded/polygon 0.1 0.1 0.5 1.0 0.01
pair_coeff * * {kn} 0.0
comm_modify vel yes
neighbor 0.05 bin
neigh_modify every 1 delay 0 check yes
timestep {dt}
region base block INF INF INF 1.0 INF INF
group base region base
fix 1 all nve/body
fix 2 all enforce2d
fix 3 all gravity 10.0 vector 0 -1 0
fix 4 base setforce 0.0 0.0 0.0
velocity base set 0.0 0.0 0.0
thermo {steps}
run {steps}
""".format(kn=kn, dt=dt, steps=steps)
    path = os.path.join(folder, "in.wall")
    with open(path, "w") as f:
        f.write(script)
    return path


def run_lammps(lmp, folder, steps):
    env = dict(os.environ, OMP_NUM_THREADS="1")
    out = subprocess.run([lmp, "-in", "in.wall", "-log", "log.wall"], cwd=folder, env=env,
                         stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True).stdout
    m = re.search(r"Loop time of ([0-9.eE+-]+) on 1 procs for (\d+) steps with (\d+) atoms", out)
    if not m:
        sys.exit("lammps_wall.py: no 'Loop time' in LAMMPS's output:\n" + out[-3000:])
    return float(m.group(1)), int(m.group(2)), int(m.group(3))


def run_udec(build, size, steps):
    env = dict(os.environ, OMP_NUM_THREADS="1")
    exe = os.path.join(build, "bin", "rigid_bench")
    out = subprocess.run([exe, str(size), str(steps), "1", str(size)], env=env,
                         stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True).stdout
    m = re.search(r"rigid_bench: blocks=(\d+) contacts=(\d+) s_per_cycle=\s*([0-9.eE+-]+)", out)
    if not m:
        sys.exit("lammps_wall.py: no 'rigid_bench:' line in:\n" + out[-3000:])
    return int(m.group(1)), int(m.group(2)), float(m.group(3))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--build", default="build")
    ap.add_argument("--sizes", default="1000,10000")
    ap.add_argument("--steps", type=int, default=100)
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--install", action="store_true", help="apt-get install lammps if missing")
    ap.add_argument("--json", default="")
    a = ap.parse_args()
    lmp = lammps_exe()
    if lmp is None and a.install:
        install()
        lmp = lammps_exe()
    if lmp is None:
        sys.exit("lammps_wall.py: no LAMMPS (lmp) found; run with --install (Debian package lammps)")
    if not has_body(lmp):
        sys.exit("lammps_wall.py: %s has no pair style body/rounded/polygon (BODY package)" % lmp)
    rows = []
    print("| blocks | contacts (udec) | udec M contact-cycles/s | LAMMPS M contact-cycles/s "
          "| udec / LAMMPS | udec block-steps/s | LAMMPS block-steps/s |")
    print("|---:|---:|---:|---:|---:|---:|---:|")
    for size in [int(x) for x in a.sizes.split(",") if x]:
        n = SIDES[size]
        u_rates, l_rates, ratios = [], [], []
        contacts = blocks = 0
        for r in range(a.repeats):
            folder = tempfile.mkdtemp(prefix="udec-lammps-")
            try:
                write_wall(folder, n, steps=a.steps)

                def lam():
                    t, steps, atoms = run_lammps(lmp, folder, a.steps)
                    return t / steps, atoms

                def ude():
                    return run_udec(a.build, size, a.steps)
                if r % 2 == 0:
                    tl, atoms = lam()
                    blocks, contacts, tu = ude()
                else:
                    blocks, contacts, tu = ude()
                    tl, atoms = lam()
            finally:
                shutil.rmtree(folder, ignore_errors=True)
            u_rates.append(contacts / tu / 1e6)
            l_rates.append(contacts / tl / 1e6)
            ratios.append(tl / tu)
        row = {"blocks": blocks, "lammps_bodies": n * n, "contacts": contacts, "steps": a.steps,
               "udec_mcc_per_s": statistics.median(u_rates),
               "lammps_mcc_per_s": statistics.median(l_rates),
               "ratio_median": statistics.median(ratios), "ratio_min": min(ratios),
               "ratio_max": max(ratios)}
        rows.append(row)
        print("| %d | %d | %.2f | %.2f | %.2f (%.2f..%.2f) | %.3g | %.3g |" % (
            blocks, contacts, row["udec_mcc_per_s"], row["lammps_mcc_per_s"], row["ratio_median"],
            row["ratio_min"], row["ratio_max"], row["udec_mcc_per_s"] * 1e6 * blocks / contacts,
            row["lammps_mcc_per_s"] * 1e6 * n * n / contacts), flush=True)
    load = os.getloadavg()[0]
    print("load average (1 min) at the end: %.2f; LAMMPS: %s" % (load, lmp))
    if a.json:
        with open(a.json, "w") as f:
            json.dump({"date_utc": time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime()),
                       "loadavg_end": load, "repeats": a.repeats, "rows": rows}, f, indent=1)
            f.write("\n")


if __name__ == "__main__":
    main()
