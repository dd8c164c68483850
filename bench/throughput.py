#!/usr/bin/env python3
"""Throughput against model size (issue 23): runs bench/rigid_bench and
bench/zone_bench (elastic) over their sizes on one thread, writes the figures
as JSON beside docs/performance.md (docs/throughput.json) and draws them
against N as a PNG (docs/throughput.png, bench/pngplot.py: standard library).

    python3 bench/throughput.py [--build build] [--rigid 100000] [--zones 1000000]
        [--repeats 3] [--out docs]
"""
import argparse
import json
import os
import re
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import pngplot  # noqa: E402


def run(cmd):
    env = dict(os.environ, OMP_NUM_THREADS="1")
    return subprocess.run(cmd, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                          text=True, check=True).stdout


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--build", default="build")
    ap.add_argument("--rigid", type=int, default=100000, help="largest block count")
    ap.add_argument("--zones", type=int, default=1000000, help="largest zone count")
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--out", default="docs")
    a = ap.parse_args()
    load0 = os.getloadavg()[0]
    out = run([os.path.join(a.build, "bin", "rigid_bench"), str(a.rigid), "100", str(a.repeats)])
    rigid = [{"blocks": int(m.group(1)), "contacts": int(m.group(2)),
              "s_per_cycle": float(m.group(3)), "mcc_per_s": float(m.group(4))}
             for m in re.finditer(r"rigid_bench: blocks=(\d+) contacts=(\d+) s_per_cycle=\s*(\S+)"
                                  r" Mcontact_cycles_per_s=\s*(\S+)", out)]
    out = run([os.path.join(a.build, "bin", "zone_bench"), str(a.zones), "50", str(a.repeats)])
    zones = [{"zones": int(m.group(1)), "s_per_cycle": float(m.group(2)),
              "mzu_per_s": float(m.group(3))}
             for m in re.finditer(r"zone_bench: zones=(\d+) s_per_cycle=\s*(\S+)"
                                  r" Mzone_updates_per_s=\s*(\S+)", out)]
    load1 = os.getloadavg()[0]
    doc = {"date_utc": time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime()),
           "loadavg_start": load0, "loadavg_end": load1, "repeats": a.repeats,
           "threads": 1, "rigid": rigid, "zones_elastic": zones}
    os.makedirs(a.out, exist_ok=True)
    with open(os.path.join(a.out, "throughput.json"), "w") as f:
        json.dump(doc, f, indent=1)
        f.write("\n")
    series = [("RIGID M CONTACT-CYCLES/S", [(r["blocks"], r["mcc_per_s"], "") for r in rigid]),
              ("ZONES M ZONE-UPDATES/S", [(z["zones"], z["mzu_per_s"], "") for z in zones])]
    pngplot.chart(os.path.join(a.out, "throughput.png"), "THROUGHPUT, ONE THREAD (LOAD %.0f)" % load1,
                  series, xlabel="BLOCKS OR ZONES", ylabel="M UPDATES / S")
    for r in rigid:
        print("rigid %7d blocks: %.2f M contact-cycles/s" % (r["blocks"], r["mcc_per_s"]))
    for z in zones:
        print("zones %7d zones: %.2f M zone-updates/s" % (z["zones"], z["mzu_per_s"]))
    print("load average (1 min): %.1f at start, %.1f at end" % (load0, load1))


if __name__ == "__main__":
    main()
