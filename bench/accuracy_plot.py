#!/usr/bin/env python3
"""Draw the cost of accuracy: one PNG per problem of bench/accuracy.py.

usage: python3 bench/accuracy.py build/bin/udec --json rows.json
       python3 bench/accuracy_plot.py rows.json docs/images [--problems "thermal 3,appl. E"]

Each picture plots |error| in % (log scale) against wall time in s (log
scale), one marker per variant of the problem, numbered in the order of the
table; a legend under the plot gives each number's knobs. A variant with no
error (exact to the printed digits) sits on the floor of the axis (1e-3 %).
Rows of a problem that measure a second quantity (marked "(closed form)" or
"not in check.py" in the table) are drawn hollow.

Standard library only: the PNG is written with zlib, text with the 5 x 7
bitmap font below.
"""
import argparse
import json
import math
import os
import re
import struct
import zlib

FONT = {  # 5 x 7 glyphs, one string of 7 rows of 5 bits per character
    "0": "01110100011001110101110011000101110", "1": "00100011000010000100001000010001110",
    "2": "01110100010000100010001000100011111", "3": "11111000100010000010000011000101110",
    "4": "00010001100101010010111110001000010", "5": "11111100001111000001000011000101110",
    "6": "00110010001000011110100011000101110", "7": "11111000010001000100010000100001000",
    "8": "01110100011000101110100011000101110", "9": "01110100011000101111000010001001100",
    "A": "01110100011000111111100011000110001", "B": "11110100011000111110100011000111110",
    "C": "01110100011000010000100001000101110", "D": "11100100101000110001100011001011100",
    "E": "11111100001000011110100001000011111", "F": "11111100001000011110100001000010000",
    "G": "01110100011000010111100011000101111", "H": "10001100011000111111100011000110001",
    "I": "01110001000010000100001000010001110", "J": "00111000100001000010000101001001100",
    "K": "10001100101010011000101001001010001", "L": "10000100001000010000100001000011111",
    "M": "10001110111010110101100011000110001", "N": "10001100011100110101100111000110001",
    "O": "01110100011000110001100011000101110", "P": "11110100011000111110100001000010000",
    "Q": "01110100011000110001101011001001101", "R": "11110100011000111110101001001010001",
    "S": "01111100001000001110000010000111110", "T": "11111001000010000100001000010000100",
    "U": "10001100011000110001100011000101110", "V": "10001100011000110001100010101000100",
    "W": "10001100011000110101101011010101010", "X": "10001100010101000100010101000110001",
    "Y": "10001100011000101010001000010000100", "Z": "11111000010001000100010001000011111",
    " ": "0" * 35, ".": "00000000000000000000000000110001100",
    ",": "00000000000000000000001100010001000", "-": "00000000000000011111000000000000000",
    "+": "00000001000010011111001000010000000", "%": "11000110010001000100010001001100011",
    "(": "00010001000100001000010000010000010", ")": "01000001000001000010000100010001000",
    "=": "00000000001111100000111110000000000", "/": "00000000010001000100010001000000000",
    ":": "00000011000110000000011000110000000",
    "|": "00100001000010000100001000010000100", "_": "00000000000000000000000000000011111",
    "'": "00100001000100000000000000000000000", "*": "00000001001010101110101010010000000",
    "<": "00010001000100010000010000010000010", "[": "01110010000100001000010000100001110",
    "]": "01110000100001000010000100001001110", ">": "01000001000001000001000100010001000",
}
W, H = 900, 640
LEFT, RIGHT, TOP, PLOT_BOTTOM = 90, 870, 50, 400


class Canvas:
    def __init__(self, w, h):
        self.w, self.h = w, h
        self.px = bytearray(b"\xff" * (w * h * 3))

    def dot(self, x, y, c):
        if 0 <= x < self.w and 0 <= y < self.h:
            i = 3 * (y * self.w + x)
            self.px[i:i + 3] = bytes(c)

    def line(self, x0, y0, x1, y1, c, width=1):
        n = max(abs(x1 - x0), abs(y1 - y0), 1)
        for k in range(int(n) + 1):
            x = round(x0 + (x1 - x0) * k / n)
            y = round(y0 + (y1 - y0) * k / n)
            for dx in range(width):
                for dy in range(width):
                    self.dot(x + dx, y + dy, c)

    def text(self, x, y, s, c=(0, 0, 0), scale=1):
        for ch in s:
            g = FONT.get(ch.upper() if ch.upper() in FONT and ch not in FONT else ch, FONT[" "])
            for r in range(7):
                for col in range(5):
                    if g[r * 5 + col] == "1":
                        for a in range(scale):
                            for b in range(scale):
                                self.dot(x + col * scale + a, y + r * scale + b, c)
            x += 6 * scale

    def marker(self, x, y, c, filled=True, r=5):
        for dx in range(-r, r + 1):
            for dy in range(-r, r + 1):
                d = dx * dx + dy * dy
                if d <= r * r and (filled or d >= (r - 1.5) ** 2):
                    self.dot(x + dx, y + dy, c)

    def png(self, path):
        raw = b"".join(b"\x00" + bytes(self.px[3 * y * self.w:3 * (y + 1) * self.w])
                       for y in range(self.h))

        def chunk(tag, data):
            return (struct.pack(">I", len(data)) + tag + data
                    + struct.pack(">I", zlib.crc32(tag + data) & 0xffffffff))
        tmp = path + ".tmp"
        with open(tmp, "wb") as f:
            f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", self.w, self.h,
                                                                         8, 2, 0, 0, 0))
                    + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))
        os.replace(tmp, path)


def decades(lo, hi):
    a, b = math.floor(math.log10(lo)), math.ceil(math.log10(hi))
    if a == b:
        b += 1
    return a, b


def label(v):
    return f"{v:g}" if 1e-3 <= v < 1e4 else f"1E{int(round(math.log10(v)))}"


def plot(problem, rows, path):
    floor = 1e-3
    pts = []
    for i, r in enumerate(rows, 1):
        err = r["err"]
        e = floor if err is not None and abs(err) < floor else (abs(err) if err is not None else None)
        secondary = "closed form" in r["quantity"] or "not in check.py" in r["quantity"]
        pts.append((i, r["wall"], e, secondary, r))
    good = [p for p in pts if p[2] is not None and p[1] > 0]
    c = Canvas(W, H)
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
        s = f"{i}. {r['knobs']}: {err}, {t:.2f} S" + (" (SECOND QUANTITY, HOLLOW)" if sec else "")
        c.text(LEFT - 60, y, s[:135], col)
        y += 10
        if y > H - 12:
            break
    c.text(LEFT - 60, H - 11, "QUANTITY: " + rows[0]["quantity"][:120], (80, 80, 80))
    c.png(path)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("rows", help="JSON written by bench/accuracy.py --json")
    ap.add_argument("outdir", help="folder for the PNG files (accuracy_<problem>.png)")
    ap.add_argument("--problems", help="comma-separated problem names (default: all in the file)")
    a = ap.parse_args()
    rows = json.load(open(a.rows))
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
