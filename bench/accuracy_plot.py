#!/usr/bin/env python3
"""Draw the cost of accuracy: one PNG per problem of bench/accuracy.py.

usage: python3 bench/accuracy.py build/bin/udec --json rows.json
       python3 bench/accuracy_plot.py rows.json docs/images [--problems E,H1]

Rows of bench/accuracy.py (each with its problem key) give one chart per
key, docs/images/accuracy_<PNG_NAMES[key]>.png (bench/accuracy.py --png
draws the same while it runs); older rows without keys, one chart per
problem name (--problems "thermal 3,appl. E").

Each picture plots |error| in % (log scale) against wall time in s (log
scale), one marker per variant of the problem, numbered in the order of the
table; a legend under the plot gives each number's knobs. A variant with no
error (exact to the printed digits) sits on the floor of the axis (1e-3 %).
Rows of a problem that measure a second quantity (marked "(closed form)" or
"not in check.py" in the table) are drawn hollow.

Standard library only: the picture, its 5 x 7 bitmap font and the PNG
encoder are bench/pngplot.py's.
"""
import argparse
import json
import math
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from pngplot import Canvas  # noqa: E402

W, H = 900, 640
LEFT, RIGHT, TOP, PLOT_BOTTOM = 90, 870, 50, 400


def decades(lo, hi):
    a, b = math.floor(math.log10(lo)), math.ceil(math.log10(hi))
    if a == b:
        b += 1
    return a, b


def label(v):
    return f"{v:g}" if 1e-3 <= v < 1e4 else f"1E{int(round(math.log10(v)))}"


TITLES = {"A": "VERIFICATION A", "E": "VERIFICATION E", "F": "APPLICATION F (SLIPPING CRACK)",
          "B": "VERIFICATION B", "D": "VERIFICATION D (PRANDTL)", "T": "TUTORIAL 2.1",
          "C": "VERIFICATION C (CRACK SLIP, BE FAR FIELD)", "VF": "VERIFICATION F (UNCONFINED FLOW)",
          "AC": "APPLICATION C (LINED TUNNELS)", "AE": "APPLICATION E (JCONS 3 SHEAR)",
          "H1": "THERMAL 1 (TAPERED FIN)", "H2": "THERMAL 2 (FURNACE WALL)",
          "H3": "THERMAL 3 (SLAB WITH SOURCE)", "H4": "THERMAL 4 (SLAB WITH FLUX)",
          "H5": "THERMAL 5 (ORTHOTROPIC BAR)", "H6": "THERMAL 6 (DECAYING SOURCE, TADD)",
          "AA": "APPLICATION A (SEISMIC ROOF)", "AD": "APPLICATION D (DAM, EARTHQUAKE)",
          "AG": "APPLICATION G (GROUTING)"}

# chart file of each problem (docs/images/accuracy_<name>.png)
PNG_NAMES = {"A": "A", "E": "E", "F": "appF", "B": "B", "D": "D", "T": "tutorial", "C": "C",
             "VF": "VF", "H1": "thermal_1", "H2": "thermal_2", "H3": "thermal_3",
             "H4": "thermal_4", "H5": "thermal_5", "H6": "thermal_6", "AA": "appA",
             "AC": "AC", "AD": "appD", "AE": "appl_e", "AG": "appG"}


def draw_key(rows, key, folder):
    """The chart of problem `key` (a bench/accuracy.py PROBLEMS key) from
    `rows`: folder/accuracy_<PNG_NAMES[key]>.png; returns its path."""
    path = os.path.join(folder, f"accuracy_{PNG_NAMES.get(key, key)}.png")
    plot(TITLES.get(key, key), [r for r in rows if r.get("key") == key], path)
    return path


def plot(problem, rows, path):
    floor = 1e-3
    pts = []
    for i, r in enumerate(rows, 1):
        err = r["err"]
        e = floor if err is not None and abs(err) < floor else (abs(err) if err is not None else None)
        secondary = "closed form" in r["quantity"] or "not in check.py" in r["quantity"]
        pts.append((i, r["wall"], e, secondary, r))
    good = [p for p in pts if p[2] is not None and p[1] > 0]
    height = max(H, PLOT_BOTTOM + 62 + 10 * len(pts))   # room for every legend line
    cases = len({r["problem"] for r in rows}) > 1       # say the case in the legend (E1 / E3)
    c = Canvas(W, height)
    c.text(LEFT, 15, f"{problem.upper()}: |ERROR| AGAINST WALL TIME", scale=2)
    if not good:
        c.text(LEFT, 100, "NO RESULT")
        c.png(path)
        return
    tx0, tx1 = decades(min(p[1] for p in good), max(p[1] for p in good))
    ey0, ey1 = decades(min(p[2] for p in good), max(p[2] for p in good))

    def X(t):
        return round(LEFT + (math.log10(t) - tx0) / (tx1 - tx0) * (RIGHT - LEFT))

    def Y(e):
        return round(PLOT_BOTTOM - (math.log10(e) - ey0) / (ey1 - ey0) * (PLOT_BOTTOM - TOP))
    grey, black = (200, 200, 200), (0, 0, 0)
    for d in range(tx0, tx1 + 1):
        x = X(10.0 ** d)
        c.line(x, TOP, x, PLOT_BOTTOM, grey)
        c.text(x - 10, PLOT_BOTTOM + 8, label(10.0 ** d))
    for d in range(ey0, ey1 + 1):
        y = Y(10.0 ** d)
        c.line(LEFT, y, RIGHT, y, grey)
        s = label(10.0 ** d)
        c.text(LEFT - 8 - 6 * len(s), y - 3, s)
    c.line(LEFT, PLOT_BOTTOM, RIGHT, PLOT_BOTTOM, black)
    c.line(LEFT, TOP, LEFT, PLOT_BOTTOM, black)
    c.text((LEFT + RIGHT) // 2 - 60, PLOT_BOTTOM + 22, "WALL TIME (S)")
    c.text(8, TOP - 14, "|ERROR| (%)")
    palette = [(31, 119, 180), (214, 39, 40), (44, 160, 44), (148, 103, 189), (255, 127, 14),
               (23, 190, 207), (140, 86, 75), (127, 127, 127)]
    # one colour per first knob (scheme, JIF, ...): the text before the first comma
    groups = []
    for p in pts:
        g = p[4]["knobs"].split(",")[0]
        if g not in groups:
            groups.append(g)
    for i, t, e, sec, r in good:
        col = palette[groups.index(r["knobs"].split(",")[0]) % len(palette)]
        x, y = X(t), Y(e)
        c.marker(x, y, col, filled=not sec)
        c.text(x + 7, y - 10, str(i), col)
    y = PLOT_BOTTOM + 42
    for i, t, e, sec, r in pts:
        col = palette[groups.index(r["knobs"].split(",")[0]) % len(palette)]
        err = "N/A" if r["err"] is None else f"{r['err']:+.2f} %"
        s = (f"{i}. " + (f"{r['problem']}: " if cases else "") + f"{r['knobs']}: {err}, {t:.2f} S"
             + (" (SECOND QUANTITY, HOLLOW)" if sec else ""))
        c.text(LEFT - 60, y, s[:135], col)
        y += 10
    quantities = []
    for r in rows:
        if r["quantity"] not in quantities:
            quantities.append(r["quantity"])
    c.text(LEFT - 60, height - 11, "QUANTITY: " + "; ".join(quantities)[:124], (80, 80, 80))
    c.png(path)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("rows", help="JSON written by bench/accuracy.py --json")
    ap.add_argument("outdir", help="folder for the PNG files (accuracy_<problem>.png)")
    ap.add_argument("--problems", help="comma-separated problem names (default: all in the file)")
    a = ap.parse_args()
    rows = json.load(open(a.rows))
    if all("key" in r for r in rows):      # rows of bench/accuracy.py: one chart per problem key
        keys = []
        for r in rows:
            if r["key"] not in keys:
                keys.append(r["key"])
        os.makedirs(a.outdir, exist_ok=True)
        for k in keys:
            if not a.problems or k in a.problems.split(","):
                print(draw_key(rows, k, a.outdir))
        return
    names = []
    for r in rows:
        if r["problem"] not in names:
            names.append(r["problem"])
    if a.problems:
        names = [n for n in names if n in a.problems.split(",")]
    os.makedirs(a.outdir, exist_ok=True)
    for n in names:
        path = os.path.join(a.outdir, "accuracy_" + re.sub(r"[^a-z0-9]+", "_", n.lower()).strip("_")
                            + ".png")
        plot(n, [r for r in rows if r["problem"] == n], path)
        print(path)


if __name__ == "__main__":
    main()
