#!/usr/bin/env python3
"""Halo sizes of the benchmark models split along a space-filling curve
(docs/scaling.md, issue 23's "past one machine").

Models (the same as the benches build them):
  rigid  n x n unit blocks cut by two orthogonal joint sets (bench/rigid_bench,
         n = 317: 100 489 blocks; n = 1000: 1M). Contacts as udec makes them in
         that wall: two corner-edge contacts across every shared edge, one
         corner-corner contact between diagonal neighbours (the script checks
         the count against udec's: 600 400 contacts at n = 317).
  zones  a square block of n x n cells, GENERATE QUAD 1 (bench/zone_bench,
         n = 158: 99 856 zones; n = 500: 1M): four triangles around each cell's
         centre gridpoint.
Blocks (cells) are numbered along a Hilbert curve and cut into P runs of equal
length, one per rank. A rank computes every contact (zone) that touches
something it owns, so it needs the state of the blocks (gridpoints) of other
ranks those contacts (zones) touch: its halo. Per step each halo block brings
x, y, rotation, vx, vy, vr (48 bytes); each halo gridpoint x, y, vx, vy (32
bytes). Printed per model and P: cut contacts, halo items summed over ranks,
the largest halo of a rank, bytes per step summed and per rank.

    python3 bench/halo_count.py [--ranks 2,4,16,64] [--json out.json]
"""
import argparse
import json


def hilbert_d(n, x, y):
    """Index of cell (x, y) on the Hilbert curve filling a 2^k >= n square."""
    s = 1
    while s < n:
        s *= 2
    d = 0
    t = s // 2
    while t > 0:
        rx = 1 if x & t else 0
        ry = 1 if y & t else 0
        d += t * t * ((3 * rx) ^ ry)
        if ry == 0:
            if rx == 1:
                x = t - 1 - x
                y = t - 1 - y
            x, y = y, x
        t //= 2
    return d


def owners(n, ranks):
    order = sorted(range(n * n), key=lambda c: hilbert_d(n, c % n, c // n))
    own = [0] * (n * n)
    for k, c in enumerate(order):
        own[c] = k * ranks // (n * n)
    return own


def rigid(n, ranks):
    own = owners(n, ranks)
    contacts = []
    for y in range(n):
        for x in range(n):
            c = y * n + x
            if x + 1 < n:
                contacts += [(c, c + 1)] * 2
            if y + 1 < n:
                contacts += [(c, c + n)] * 2
            if x + 1 < n and y + 1 < n:
                contacts.append((c, c + n + 1))
            if x > 0 and y + 1 < n:
                contacts.append((c, c + n - 1))
    halo = [set() for _ in range(ranks)]
    cut = 0
    for a, b in contacts:
        if own[a] != own[b]:
            cut += 1
            halo[own[a]].add(b)
            halo[own[b]].add(a)
    sizes = [len(h) for h in halo]
    return {"model": "rigid", "n": n, "items": n * n, "contacts": len(contacts), "ranks": ranks,
            "cut": cut, "halo_total": sum(sizes), "halo_max": max(sizes),
            "bytes_total": 48 * sum(sizes), "bytes_max_rank": 48 * max(sizes)}


def zones(n, ranks):
    own = owners(n, ranks)
    # gridpoints: corners (n+1)^2, then centres n^2; a gridpoint belongs to the
    # rank of the lowest-numbered cell around it
    ncorner = (n + 1) * (n + 1)
    gown = [ranks] * (ncorner + n * n)
    for y in range(n):
        for x in range(n):
            c = y * n + x
            for g in (y * (n + 1) + x, y * (n + 1) + x + 1, (y + 1) * (n + 1) + x,
                      (y + 1) * (n + 1) + x + 1):
                gown[g] = min(gown[g], own[c])
            gown[ncorner + c] = own[c]
    halo = [set() for _ in range(ranks)]
    cutz = 0
    for y in range(n):
        for x in range(n):
            c = y * n + x
            cell = [y * (n + 1) + x, y * (n + 1) + x + 1, (y + 1) * (n + 1) + x + 1,
                    (y + 1) * (n + 1) + x]
            ctr = ncorner + c
            for k in range(4):
                tri = (cell[k], cell[(k + 1) % 4], ctr)
                rs = {gown[g] for g in tri}
                if len(rs) > 1:
                    cutz += 1
                for r in rs:          # every rank owning a vertex computes the zone
                    for g in tri:
                        if gown[g] != r:
                            halo[r].add(g)
    sizes = [len(h) for h in halo]
    return {"model": "zones", "n": n, "items": 4 * n * n, "gridpoints": ncorner + n * n,
            "ranks": ranks, "cut": cutz, "halo_total": sum(sizes), "halo_max": max(sizes),
            "bytes_total": 32 * sum(sizes), "bytes_max_rank": 32 * max(sizes)}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--ranks", default="2,4,16,64")
    ap.add_argument("--json", default="")
    a = ap.parse_args()
    rows = []
    print("| model | blocks / zones | ranks | cut contacts / zones | halo items (all ranks) "
          "| largest halo | bytes a step (all) | bytes a step (largest rank) |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|")
    for kind, n in (("rigid", 317), ("rigid", 1000), ("zones", 158), ("zones", 500)):
        for p in [int(x) for x in a.ranks.split(",")]:
            r = rigid(n, p) if kind == "rigid" else zones(n, p)
            if kind == "rigid" and n == 317:
                assert r["contacts"] == 600400, r["contacts"]   # udec's count of this wall
            rows.append(r)
            print("| %s | %d | %d | %d | %d | %d | %d | %d |" % (
                kind, r["items"], p, r["cut"], r["halo_total"], r["halo_max"], r["bytes_total"],
                r["bytes_max_rank"]), flush=True)
    if a.json:
        with open(a.json, "w") as f:
            json.dump(rows, f, indent=1)
            f.write("\n")


if __name__ == "__main__":
    main()
