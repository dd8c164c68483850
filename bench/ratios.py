#!/usr/bin/env python3
"""udec's rigid-block and zone cycles as ratios to lean reference kernels (issue 23).

Machines differ, so the speed targets are ratios to two small stand-alone
programs that do the minimum work of the same hot loops (a rigid-block
contact kernel and a constant-strain-triangle zone kernel), compiled and run
on the same machine in the same run, alternating with udec's own benchmarks
(build/bin/rigid_bench, build/bin/zone_bench) on the same number of blocks or
zones. The kernels are not part of udec: give the folder that holds their
sources (contacts.f90, zones.f90) with --ref DIR or the environment variable
UDEC_PERF_REF; they are compiled into a temporary folder at run time.

    python3 bench/ratios.py [--build build] [--ref DIR] [--repeats 3]
                            [--rigid 10000,100000] [--zones 100000,1000000]
                            [--json docs/performance.json]

For each size and repeat the two sides run one after the other, the order
alternating between repeats; the figure is the median over the repeats of
the per-repeat ratio udec / kernel (rates per contact-cycle or per
zone-update), printed with the spread (min..max) of the ratios, the medians
of both rates, and the load average at start and end (the machine may be
shared). Both sides run on one thread (OMP_NUM_THREADS=1).
"""
import argparse
import json
import os
import platform
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

# udec sizes (bench/rigid_bench.f90, bench/zone_bench.f90) and the kernel
# lattice that has the same number of blocks (bx = by) or zones (2 (n-1)^2)
RIGID_SIDES = {1000: 32, 10000: 100, 100000: 317, 1000000: 1000}
ZONE_SIDES = {10000: 50, 100000: 158, 1000000: 500}


def kernel_zone_side(nzones):
    """Grid side n of the zone kernel with 2 (n-1)^2 ~ nzones."""
    return int(round((nzones / 2.0) ** 0.5)) + 1


def run(cmd, env):
    t0 = time.time()
    out = subprocess.run(cmd, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                         text=True, check=False)
    if out.returncode != 0:
        sys.exit("ratios.py: %s failed (%d):\n%s" % (" ".join(cmd), out.returncode, out.stdout))
    return out.stdout, time.time() - t0


def grab(pattern, text, what):
    m = re.search(pattern, text)
    if not m:
        sys.exit("ratios.py: no %s in output:\n%s" % (what, text))
    return float(m.group(1))


def loadavg():
    try:
        return os.getloadavg()[0]
    except OSError:
        return float("nan")


def machine():
    model = platform.processor() or platform.machine()
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    model = line.split(":", 1)[1].strip()
                    break
    except OSError:
        pass
    return "%s, %d cores" % (model, os.cpu_count() or 0)


def compile_kernels(ref, tmp, fc):
    exe = {}
    for name in ("contacts", "zones"):
        src = os.path.join(ref, name + ".f90")
        if not os.path.isfile(src):
            sys.exit("ratios.py: %s not found (give --ref DIR or UDEC_PERF_REF)" % src)
        exe[name] = os.path.join(tmp, name)
        subprocess.run([fc, "-O3", "-march=native", "-fopenmp", src, "-o", exe[name]],
                       cwd=tmp, check=True)
    return exe


def series(label, size, pairs):
    """Medians and spread of one size: pairs = [(udec_rate, kernel_rate), ...]."""
    ratios = [u / k for u, k in pairs]
    return {
        "work": label, "size": size, "repeats": len(pairs),
        "udec_rate_median": statistics.median(u for u, _ in pairs),
        "kernel_rate_median": statistics.median(k for _, k in pairs),
        "ratio_median": statistics.median(ratios),
        "ratio_min": min(ratios), "ratio_max": max(ratios),
        "ratios": ratios,
    }


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--build", default="build", help="udec build folder (bin/rigid_bench ...)")
    ap.add_argument("--ref", default=os.environ.get("UDEC_PERF_REF", ""),
                    help="folder of the reference kernels' sources (or UDEC_PERF_REF)")
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--rigid", default="10000,100000", help="block counts ('' for none)")
    ap.add_argument("--zones", default="100000,1000000", help="zone counts ('' for none)")
    ap.add_argument("--mc", action="store_true", help="zone bench with Mohr-Coulomb (no kernel "
                    "ratio target; the kernel runs plastic too)")
    ap.add_argument("--rigid-cycles", type=int, default=100)
    ap.add_argument("--zone-cycles", type=int, default=50)
    ap.add_argument("--json", default="", help="write the figures here as JSON")
    ap.add_argument("--fc", default="gfortran")
    a = ap.parse_args()
    if not a.ref:
        sys.exit("ratios.py: give the reference kernels' folder with --ref DIR or UDEC_PERF_REF")
    rigid_bench = os.path.join(a.build, "bin", "rigid_bench")
    zone_bench = os.path.join(a.build, "bin", "zone_bench")
    env = dict(os.environ, OMP_NUM_THREADS="1")
    tmp = tempfile.mkdtemp(prefix="udec-ratios-")
    results = []
    load0 = loadavg()
    try:
        exe = compile_kernels(a.ref, tmp, a.fc)
        for size in [int(x) for x in a.rigid.split(",") if x]:
            side = RIGID_SIDES[size]
            steps = max(20, int(4.0e7 / (4 * side * side)))
            pairs = []
            for r in range(a.repeats):
                def udec():
                    out, _ = run([rigid_bench, str(size), str(a.rigid_cycles), "1", str(size)], env)
                    return grab(r"Mcontact_cycles_per_s=([0-9.eE+-]+)", out, "rigid rate")

                def kern():
                    out, _ = run([exe["contacts"], str(side), str(side), str(steps), "0", "0"], env)
                    return grab(r"full-cycle Mcont/s=\s*([0-9.eE+-]+)", out, "kernel rate")
                if r % 2 == 0:
                    k = kern(); u = udec()
                else:
                    u = udec(); k = kern()
                pairs.append((u, k))
                print("rigid %7d  repeat %d: udec %.2f  kernel %.2f  M contact-cycles/s  ratio %.3f"
                      % (size, r + 1, u, k, u / k), flush=True)
            results.append(series("rigid", size, pairs))
        for size in [int(x) for x in a.zones.split(",") if x]:
            n = kernel_zone_side(size)
            steps = max(10, int(2.0e7 / size))
            pairs = []
            for r in range(a.repeats):
                def udec():
                    # zone_bench's sizes are 4 n^2 zones (99 856 for 100k)
                    out, _ = run([zone_bench, str(int(size * 1.1)), str(a.zone_cycles), "1",
                                  "MC" if a.mc else "EL", str(int(size * 0.9))], env)
                    return grab(r"Mzone_updates_per_s=([0-9.eE+-]+)", out, "zone rate")

                def kern():
                    out, _ = run([exe["zones"], str(n), str(n), str(steps), "0", "0",
                                  "1" if a.mc else "0"], env)
                    return grab(r"full-cycle Mzone/s=\s*([0-9.eE+-]+)", out, "kernel rate")
                if r % 2 == 0:
                    k = kern(); u = udec()
                else:
                    u = udec(); k = kern()
                pairs.append((u, k))
                print("zones %7d  repeat %d: udec %.2f  kernel %.2f  M zone-updates/s  ratio %.3f"
                      % (size, r + 1, u, k, u / k), flush=True)
            results.append(series("zones-mc" if a.mc else "zones", size, pairs))
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    load1 = loadavg()
    print()
    print("| work | size | udec (median) | kernel (median) | ratio median | ratio min..max |")
    print("|---|---:|---:|---:|---:|---|")
    for s in results:
        unit = "M contact-cycles/s" if s["work"] == "rigid" else "M zone-updates/s"
        print("| %s | %d | %.2f %s | %.2f | %.3f | %.3f..%.3f |" % (
            s["work"], s["size"], s["udec_rate_median"], unit, s["kernel_rate_median"],
            s["ratio_median"], s["ratio_min"], s["ratio_max"]))
    print("load average (1 min): %.2f at start, %.2f at end; %s" % (load0, load1, machine()))
    if a.json:
        doc = {"machine": machine(), "date_utc": time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime()),
               "loadavg_start": load0, "loadavg_end": load1, "repeats": a.repeats,
               "rigid_cycles": a.rigid_cycles, "zone_cycles": a.zone_cycles, "results": results}
        with open(a.json, "w") as f:
            json.dump(doc, f, indent=1)
            f.write("\n")


if __name__ == "__main__":
    main()
