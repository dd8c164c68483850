"""Error-against-wall-time charts as PNG, standard library only (zlib,
struct): a log-log scatter with one colour per series, axes with decade
ticks, a title and a legend in a 5 x 7 bitmap font (upper case). Used by
bench/accuracy.py --png DIR; no matplotlib on the build machines.

    chart(path, title, series, xlabel, ylabel)
    series: [(label, [(x, y, tag), ...]), ...], x > 0 and y > 0 (log axes);
    tag: a short text drawn beside the point (or ""). Points are not joined
    (the rows of one series differ in several knobs; the tags say which).
"""
import math
import os
import struct
import zlib

# 5 x 7 glyphs, one string of 7 rows of 5 bits ('#' = ink) per character.
_GLYPHS = {
    "0": ".###.#...##..###.#.###..##...#.###.", "1": "..#...##....#....#....#....#...###.",
    "2": ".###.#...#....#...#...#...#...#####", "3": "#####...#...#.....#.....##...#.###.",
    "4": "...#...##..#.#.#..#.#####...#....#.", "5": "######....####.....#....##...#.###.",
    "6": "..##..#...#....####.#...##...#.###.", "7": "#####....#...#...#...#....#....#...",
    "8": ".###.#...##...#.###.#...##...#.###.", "9": ".###.#...##...#.####....#...#..##..",
    "A": ".###.#...##...#######...##...##...#", "B": "####.#...##...#####.#...##...#####.",
    "C": ".###.#...##....#....#....#...#.###.", "D": "###..#..#.#...##...##...##..#.###..",
    "E": "######....#....####.#....#....#####", "F": "######....#....####.#....#....#....",
    "G": ".###.#...##....#.####...##...#.####", "H": "#...##...##...#######...##...##...#",
    "I": ".###...#....#....#....#....#...###.", "J": "..###...#....#....#....##..#..##...",
    "K": "#...##..#.#.#..##...#.#..#..#.#...#", "L": "#....#....#....#....#....#....#####",
    "M": "#...###.###.#.##.#.##...##...##...#", "N": "#...##...###..##.#.##..###...##...#",
    "O": ".###.#...##...##...##...##...#.###.", "P": "####.#...##...#####.#....#....#....",
    "Q": ".###.#...##...##...##.#.##..#..##.#", "R": "####.#...##...#####.#.#..#..#.#...#",
    "S": ".####.....#.....###.....#....#####.", "T": "#####..#....#....#....#....#....#..",
    "U": "#...##...##...##...##...##...#.###.", "V": "#...##...##...##...##...#.#.#...#..",
    "W": "#...##...##...##.#.##.#.##.#.#.#.#.", "X": "#...##...#.#.#...#...#.#.#...##...#",
    "Y": "#...##...#.#.#...#....#....#....#..", "Z": "#####....#...#...#...#...#....#####",
    " ": "." * 35, ".": "." * 30 + "..#..", ",": "......................#....#...#...",
    "-": "." * 15 + "#####" + "." * 15, "+": "....." + "..#....#..#####..#....#.." + ".....",
    "%": "##...##..#...#...#...#...#..##...##", "/": "....#....#...#...#...#....#....#...",
    "(": "...#...#...#....#....#.....#.....#.", ")": ".#.....#.....#....#....#...#...#...",
    "=": "." * 10 + "#####.....#####" + "." * 10, ":": ".......#....#.........#....#.......",
    "|": "..#.." * 7, "[": ".###." + ".#..." * 5 + ".###.", "]": ".###." + "...#." * 5 + ".###.",
    "<": "...#...#...#...#.....#.....#.....#.", ">": ".#.....#.....#.....#...#...#...#...",
    "*": "." * 5 + "..#..#.#.#.###.#.#.#..#.." + "." * 5, "'": "..#....#....#......" + "." * 16,
}


def _glyph(ch):
    g = _GLYPHS.get(ch.upper(), _GLYPHS.get(ch, "." * 35))
    return g if len(g) == 35 else "." * 35


class Canvas:
    def __init__(self, w, h):
        self.w, self.h = w, h
        self.px = bytearray([255] * (w * h * 3))

    def dot(self, x, y, c):
        x, y = int(round(x)), int(round(y))
        if 0 <= x < self.w and 0 <= y < self.h:
            i = 3 * (y * self.w + x)
            self.px[i:i + 3] = bytes(c)

    def line(self, x0, y0, x1, y1, c, width=1):
        n = int(max(abs(x1 - x0), abs(y1 - y0))) + 1
        for k in range(n + 1):
            t = k / n
            x, y = x0 + t * (x1 - x0), y0 + t * (y1 - y0)
            for dx in range(-(width // 2), width - width // 2):
                for dy in range(-(width // 2), width - width // 2):
                    self.dot(x + dx, y + dy, c)

    def box(self, x0, y0, x1, y1, c):
        for y in range(int(y0), int(y1) + 1):
            for x in range(int(x0), int(x1) + 1):
                self.dot(x, y, c)

    def text(self, x, y, s, c=(0, 0, 0), scale=1):
        for ch in s:
            g = _glyph(ch)
            for r in range(7):
                for q in range(5):
                    if g[5 * r + q] == "#":
                        self.box(x + q * scale, y + r * scale, x + q * scale + scale - 1,
                                 y + r * scale + scale - 1, c)
            x += 6 * scale
        return x

    def marker(self, x, y, c, filled=True, r=5):
        """A disc of radius r (a ring when not filled)."""
        for dx in range(-r, r + 1):
            for dy in range(-r, r + 1):
                d = dx * dx + dy * dy
                if d <= r * r and (filled or d >= (r - 1.5) ** 2):
                    self.dot(x + dx, y + dy, c)

    def png(self, path):
        """Write the picture through a temporary beside `path` and a rename."""
        raw = b"".join(b"\x00" + bytes(self.px[3 * self.w * y:3 * self.w * (y + 1)])
                       for y in range(self.h))

        def chunk(kind, data):
            return (struct.pack(">I", len(data)) + kind + data
                    + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF))
        tmp = path + ".tmp"
        with open(tmp, "wb") as f:
            f.write(b"\x89PNG\r\n\x1a\n")
            f.write(chunk(b"IHDR", struct.pack(">IIBBBBB", self.w, self.h, 8, 2, 0, 0, 0)))
            f.write(chunk(b"IDAT", zlib.compress(raw, 9)))
            f.write(chunk(b"IEND", b""))
        os.replace(tmp, path)


COLOURS = [(0, 90, 200), (210, 60, 30), (20, 150, 60), (150, 60, 170), (200, 150, 0), (0, 160, 170)]


def _decades(lo, hi):
    a, b = math.floor(math.log10(lo)), math.ceil(math.log10(hi))
    if b <= a:
        b = a + 1
    return a, b


def _tick(e):
    v = 10.0 ** e
    return f"{v:g}" if -3 <= e <= 4 else f"1E{e}"


def chart(path, title, series, xlabel="WALL TIME [S]", ylabel="|ERROR| [%]"):
    W, H, L, R, T, B = 760, 520, 80, 20, 40, 150
    cv = Canvas(W, H)
    pts = [(x, y) for _, ps in series for x, y, _ in ps if x > 0 and y > 0]
    if not pts:
        pts = [(1.0, 1.0)]
    xa, xb = _decades(min(p[0] for p in pts), max(p[0] for p in pts))
    ya, yb = _decades(min(p[1] for p in pts), max(p[1] for p in pts))

    def X(x):
        return L + (math.log10(x) - xa) / (xb - xa) * (W - L - R)

    def Y(y):
        return H - B - (math.log10(y) - ya) / (yb - ya) * (H - T - B)
    grey, black = (215, 215, 215), (0, 0, 0)
    for e in range(xa, xb + 1):
        cv.line(X(10.0 ** e), T, X(10.0 ** e), H - B, grey)
        cv.text(X(10.0 ** e) - 3 * len(_tick(e)), H - B + 6, _tick(e))
    for e in range(ya, yb + 1):
        cv.line(L, Y(10.0 ** e), W - R, Y(10.0 ** e), grey)
        cv.text(L - 6 * len(_tick(e)) - 6, Y(10.0 ** e) - 3, _tick(e))
    cv.line(L, T, L, H - B, black)
    cv.line(L, H - B, W - R, H - B, black)
    cv.text(L, 12, title[:110], black, 1)
    cv.text((W - 6 * len(xlabel)) // 2, H - B + 20, xlabel)
    cv.text(6, T - 14, ylabel)
    for k, (label, ps) in enumerate(series):
        c = COLOURS[k % len(COLOURS)]
        good = [(x, y, t) for x, y, t in ps if x > 0 and y > 0]
        for x, y, t in good:
            cv.box(X(x) - 3, Y(y) - 3, X(x) + 3, Y(y) + 3, c)
            if t:
                cv.text(X(x) + 6, Y(y) - 10 + 9 * k, t, c)
        ly = H - B + 40 + 14 * k
        cv.box(L, ly, L + 8, ly + 6, c)
        cv.text(L + 14, ly, label[:100], c)
    cv.png(path)
