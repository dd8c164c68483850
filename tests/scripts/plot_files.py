"""PLOT / COPY files: PostScript accepted by ghostscript (when installed),
PNG files that decode to the expected size with a white background and
drawn content, the default route in batch mode (PLT, SET PLOT, SET OUTPUT)."""
import os
import shutil
import struct
import subprocess
import sys
import zlib
sys.path.insert(0, os.path.dirname(__file__))
from udec_test import check, finish, run, workdir, write  # noqa: E402

udec = sys.argv[1]
GEOMETRY = """BLOCK      (0,0) (0,20) (20,20) (20,0)
SPLIT      (0,2) (20,8)
SPLIT      (5,3) (5,20)
SPLIT      (5,12) (20,18)
HEAD
A SIMPLE SLOPE STABILITY EXAMPLE (FRICTION COEF.=0.35)
"""


def decode_png(path, full=True):
    """(width, height, rows of RGB bytes) of an 8-bit RGB/RGBA PNG; with
    full=False the pixel data is only decompressed and its size checked."""
    data = open(path, "rb").read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError("not a PNG signature")
    pos, idat, width = 8, b"", 0
    while pos < len(data):
        (n,) = struct.unpack(">I", data[pos:pos + 4])
        kind, body = data[pos + 4:pos + 8], data[pos + 8:pos + 8 + n]
        if kind == b"IHDR":
            width, height, depth, ctype = struct.unpack(">IIBB", body[:10])
            if depth != 8 or ctype not in (2, 6):
                raise ValueError(f"unexpected PNG format depth={depth} type={ctype}")
            bpp = 3 if ctype == 2 else 4
        elif kind == b"IDAT":
            idat += body
        pos += 12 + n
    raw = zlib.decompress(idat)
    stride = width * bpp
    if len(raw) != height * (1 + stride):
        raise ValueError("pixel data size does not match the header")
    if not full:
        return width, height, None
    rows, prev, i = [], bytearray(stride), 0
    for _ in range(height):
        ftype, line = raw[i], bytearray(raw[i + 1:i + 1 + stride])
        i += 1 + stride
        for x in range(stride):
            a = line[x - bpp] if x >= bpp else 0
            b = prev[x]
            c = prev[x - bpp] if x >= bpp else 0
            if ftype == 1:
                line[x] = (line[x] + a) & 255
            elif ftype == 2:
                line[x] = (line[x] + b) & 255
            elif ftype == 3:
                line[x] = (line[x] + (a + b) // 2) & 255
            elif ftype == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[x] = (line[x] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(bytes(line) if bpp == 3 else bytes(v for k, v in enumerate(line) if k % 4 != 3))
        prev = line
    return width, height, rows


def png_ok(path, width, height, label, full=True):
    try:
        w, h, rows = decode_png(path, full)
    except Exception as exc:  # noqa: BLE001
        check(False, f"{label}: PNG decodes", str(exc))
        return
    check((w, h) == (width, height), f"{label}: PNG is {width} x {height}", f"got {w} x {h}")
    if not full:
        return
    check(rows[2][:6] == b"\xff" * 6, f"{label}: white background")
    dark = sum(1 for r in rows[::4] for k in range(0, len(r), 12) if r[k] < 100)
    samples = (h // 4) * (w // 4)
    # block outlines, legend text and frame: well above nothing, far below all
    check(0.002 * samples < dark < 0.5 * samples, f"{label}: drawn content", f"dark={dark}/{samples}")


def ps_ok(path, label):
    text = open(path, encoding="latin-1").read()
    check(text.startswith("%!PS-Adobe-3.0"), f"{label}: PostScript header")
    check("%%BoundingBox: 0 0 720 504" in text, f"{label}: bounding box 10 x 7 inches")
    check(text.rstrip().endswith("%%EOF") and "showpage" in text, f"{label}: complete")
    if shutil.which("gs"):
        p = subprocess.run(["gs", "-dNOPAUSE", "-dBATCH", "-dSAFER", "-sDEVICE=nullpage", "-q", path],
                           stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=60)
        check(p.returncode == 0 and "Error" not in p.stdout, f"{label}: ghostscript accepts it",
              p.stdout)


# Explicit COPY files: the extension chooses the format, others follow the route.
d = workdir()
write(d, "deck.dat", GEOMETRY + """PLOT BLOCKS BNUM WINDOW
COPY blocks.ps
COPY blocks.eps
COPY blocks.png
COPY BLOCKS.PLT
SET PLOT PS
COPY BLOCKS2.PLT
PLOT MAT BLOCKS NOHEADING
COPY mat.png
STOP
""")
rc, out = run(udec, ["deck.dat"], cwd=d)
check(rc == 0 and "*** Error" not in out, "COPY deck runs", out)
ps_ok(os.path.join(d, "blocks.ps"), "blocks.ps")
ps_ok(os.path.join(d, "blocks.eps"), "blocks.eps")
ps_ok(os.path.join(d, "BLOCKS2.PLT"), "BLOCKS2.PLT after SET PLOT PS")
png_ok(os.path.join(d, "blocks.png"), 1200, 840, "blocks.png")
png_ok(os.path.join(d, "BLOCKS.PLT"), 1200, 840, "BLOCKS.PLT (default PNG route)", False)
png_ok(os.path.join(d, "mat.png"), 840, 840, "NOHEADING page is square")
check("A SIMPLE SLOPE STABILITY EXAMPLE" in open(os.path.join(d, "blocks.ps"),
                                                   encoding="latin-1").read(),
      "heading is in the PostScript text")
check(not os.path.exists(os.path.join(d, "PLT")), "everything copied: no PLT written")

# Batch mode without COPY: each uncopied picture goes to PLT (the manual's default).
d = workdir()
write(d, "deck.dat", GEOMETRY + "PLOT BLOCKS\nSTOP\n")
rc, out = run(udec, ["deck.dat"], cwd=d)
check(rc == 0 and "written to PLT" in out, "uncopied batch plot reported", out)
png_ok(os.path.join(d, "PLT"), 1200, 840, "PLT at the end of the run", False)

# SET OUTPUT names the default file; SET PLOT PS its format.
d = workdir()
write(d, "deck.dat", GEOMETRY + "SET PLOT PS OUTPUT PICTURE\nPLOT BLOCKS\nPLOT BLOCKS NC\nCOPY\n")
rc, out = run(udec, ["deck.dat"], cwd=d)
check(rc == 0 and out.count("written to PICTURE (PS)") == 2,
      "replaced uncopied plot and COPY both go to the SET OUTPUT file", out)
ps_ok(os.path.join(d, "PICTURE"), "SET OUTPUT file")

# Interactive: PLOT keeps the picture; no file until COPY.
d = workdir()
rc, out = run(udec, cwd=d, stdin_text=GEOMETRY + "PLOT BLOCKS\nSTOP\n")
check("there is no screen" in out and not os.path.exists(os.path.join(d, "PLT")),
      "interactive PLOT without COPY writes nothing", out)
rc, out = run(udec, cwd=d, stdin_text="COPY\nPLOT HIST 1\nWINDOW 1 0 0 1\nSTOP\n")
check(out.count("*** Error") == 2, "COPY and WINDOW rejected, PLOT HIST only warned", out)
check("COPY: there is no plot to copy" in out, "COPY with no picture explained", out)
check("no histories are defined" in out, "history plot without histories explained", out)
check("WINDOW: expected xl < xu" in out, "bad window explained", out)
finish()
