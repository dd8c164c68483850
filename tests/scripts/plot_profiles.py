"""PLOT JOINT, JLINE, ROTATE, GPFORCES, DSH and the STRESS command (UDEC manual
(ICG1.5, 1989), Sections 4.5 and 4.6), each checked against what PRINT lists for
the same model; the title line of every picture (issue 24).

A zoned 10 m square cut by three horizontal joints (y = 2.5, 5, 7.5) is loaded
from above with a shear component; after 300 cycles the legends of the plots
(read from the PostScript, four digits) must equal the PRINT tables:
- JOINT 0,5 10,5 SSTR / NSTR: the contacts of PRINT JOINT 0,5 10,5, and the
  range of SHEAR-FORCE / LENGTH, NORMAL-FORCE / LENGTH (relative 1e-3: the
  legend's four digits). `PLOT JOINT 0,5 10,5 SSTR` once read x1 = 0 as a
  scale and refused it ("expected a scale > 0, got 0").
- JOINT ... 18: contact offset 18 (KCFN, the normal force, Section 6.1).
- JLINE 3,0 3,10 NSTR: one point per joint, the contact whose stretch of joint
  (ALONG +/- LENGTH/2) holds x = 3.
- GPFORCES: the largest |(X-FORCE, Y-FORCE)| of PRINT GRIDPOINT FORCE.
- DSH: one arrow per contact with a shear displacement in PRINT CONTACT DISP.
- STRESS xl xu yl yu nx ny prints what PRINT STRESS prints.
"""
import math
import os
import re
import sys

sys.path.insert(0, os.path.dirname(__file__))
from udec_test import check, finish, run, tables, workdir, write  # noqa: E402

udec = sys.argv[1]

DECK = """HEADING
profile test
ROUND 0.02
BLOCK 0,0 0,10 10,10 10,0
SPLIT -1,2.5 11,2.5
SPLIT -1,5 11,5
SPLIT -1,7.5 11,7.5
PROP MAT 1 DENS 2000 K 1e9 G 6e8
PROP JMAT 1 JKN 2e9 JKS 1e9 JFRIC 0.3
GEN EDGE 1.5
BOUND -1 11 -0.1 0.1 YVEL 0
BOUND -1 11 -0.1 0.1 XVEL 0
BOUND -1 11 9.9 10.1 STRESS -2e5 1e5 -1e6
DAMP AUTO
CYC 300
PRINT JOINT 0,2.5 10,2.5
PRINT JOINT 0,5 10,5
PRINT JOINT 0,7.5 10,7.5
PRINT GRID FORCE
PRINT CON DISP
PLOT JOINT 0,5 10,5 SSTR
COPY sstr.ps
PLOT JOINT 0 5 10 5 NSTR
COPY nstr.ps
PLOT JOINT 0,5 10,5 18
COPY koff.ps
PLOT JLINE 3,0 3,10 NSTR
COPY jline.ps
PLOT BLOCKS GPFORCES
COPY gpf.ps
PLOT BLOCKS DSH
COPY dsh.ps
PLOT ROTATE ZONE
COPY rz.ps
PLOT ROTATE BLOCK BLOCKS
COPY rb.ps
STRESS 1 9 1 9 3 2
PRINT STRESS 1 9 1 9 3 2
STOP
"""

d = workdir()
write(d, "p.dat", DECK)
rc, out = run(udec, ["p.dat"], cwd=d, timeout=120)
check(rc == 0 and "***" not in out, "the deck runs without an error or a 'not yet' note",
      out[-2500:])


def ps(name):
    path = os.path.join(d, name)
    return open(path).read() if os.path.exists(path) else ""


def legend_range(text):
    """(n, minimum, maximum) of a profile legend 'n point(s): minimum a, maximum b'."""
    m = re.search(r"\((\d+) point\\\(s\\\): minimum (\S+), maximum (\S+)\)", text)
    return (int(m.group(1)), float(m.group(2)), float(m.group(3))) if m else None


def close(a, b, tol=1e-3):
    return abs(a - b) <= tol * max(abs(a), abs(b), 1e-30)


joints = tables(out, "PRINT JOINT 0,5 10,5")
check(len(joints) == 1 and len(joints[0]) >= 5, "PRINT JOINT lists the middle joint's contacts")
mid = joints[0] if joints else []
if mid:
    sstr = [r["SHEAR-FORCE"] / r["LENGTH"] for r in mid]
    nstr = [r["NORMAL-FORCE"] / r["LENGTH"] for r in mid]
    for name, vals in (("sstr.ps", sstr), ("nstr.ps", nstr)):
        got = legend_range(ps(name))
        check(got is not None and got[0] == len(mid) and close(got[1], min(vals))
              and close(got[2], max(vals)),
              f"PLOT JOINT ({name}): count, minimum, maximum = PRINT JOINT's "
              f"({len(mid)}, {min(vals):.4e}, {max(vals):.4e})", str(got))
    fn = [r["NORMAL-FORCE"] for r in mid]
    got = legend_range(ps("koff.ps"))
    check(got is not None and got[0] == len(mid) and close(got[1], min(fn))
          and close(got[2], max(fn)),
          "PLOT JOINT .. 18 (offset KCFN): the range of NORMAL-FORCE", str(got))

# JLINE x = 3: per joint, the contact whose stretch holds x = 3
expect = []
for y in ("2.5", "5", "7.5"):
    t = tables(out, f"PRINT JOINT 0,{y} 10,{y}")
    rows = [r for r in (t[0] if t else []) if abs(r["ALONG"] - 3.0) <= 0.5 * r["LENGTH"]]
    if rows:
        expect.append(rows[0]["NORMAL-FORCE"] / rows[0]["LENGTH"])
got = legend_range(ps("jline.ps"))
check(len(expect) == 3 and got is not None and got[0] == 3 and close(got[1], min(expect))
      and close(got[2], max(expect)),
      "PLOT JLINE 3,0 3,10 NSTR: one point per joint, the contact holding x = 3",
      f"{got} vs {expect}")

grid = tables(out, "PRINT GRID FORCE")
if grid:
    fmax = max(math.hypot(r["X-FORCE"], r["Y-FORCE"]) for r in grid[0])
    m = re.search(r"\(maximum = (\S+)\)", ps("gpf.ps"))
    check(m is not None and close(float(m.group(1)), fmax),
          f"PLOT GPFORCES: the largest gridpoint force of PRINT GRID FORCE ({fmax:.4e})",
          m.group(0) if m else ps("gpf.ps")[-500:])
else:
    check(False, "PRINT GRID FORCE printed a table")

cdisp = tables(out, "PRINT CON DISP")
if cdisp:
    umax = max(abs(r["SHEAR-DISP"]) for r in cdisp[0])
    nsh = sum(1 for r in cdisp[0] if abs(r["SHEAR-DISP"]) > 1e-6 * umax)
    m = re.search(r"\((\d+) contact\\\(s\\\) with shear displacement\)", ps("dsh.ps"))
    check(m is not None and int(m.group(1)) == nsh,
          f"PLOT DSH: one arrow per contact with a shear displacement ({nsh})",
          m.group(0) if m else "")
else:
    check(False, "PRINT CON DISP printed a table")

for name in ("rz.ps", "rb.ps"):
    text = ps(name)
    check("rotation \\(degrees, ccw +\\)" in text and re.search(r"\(minimum \S+, maximum \S+\)", text),
          f"PLOT ROTATE ({name}): titled with its unit, with the range")

# STRESS prints what PRINT STRESS prints
parts = out.split("\nSTRESS 1 9 1 9 3 2\n")
if len(parts) == 2:
    a, b = parts[1].split("\nPRINT STRESS 1 9 1 9 3 2\n")
    check(a.strip() == b.split("\nSTOP")[0].strip() and "SMIN" in a,
          "STRESS xl xu yl yu nx ny prints the same table as PRINT STRESS", a + "\n--\n" + b)
else:
    check(False, "STRESS echoed once", out[-800:])

# issue 24: the title line names the heading, the cycle and the time
m = re.search(r"\(profile test   cycle 300   time (\S+) s\)", ps("sstr.ps"))
check(m is not None, "title line: heading, cycle and time", ps("sstr.ps")[:0])

# bad input: the command and the token named, nothing drawn
for line, text in (("PLOT JOINT 0,5 10,5 XYZ", "expected APE, FLOW, NSTR, PP, SSTR, VEL"),
                   ("PLOT ROTATE Q", "PLOT ROTATE: expected BLOCK or ZONE, got 'Q'"),
                   ("PLOT JLINE 1,1 1,1 NSTR", "expected two different points"),
                   ("PLOT JOINT 0,5 10,5 5", "contact offset 5 names no field")):
    write(d, "bad.dat", DECK.replace("PRINT JOINT 0,2.5", line + "\nPRINT JOINT 0,2.5"))
    rc, bad = run(udec, ["bad.dat"], cwd=d, timeout=120)
    check(rc == 1 and text in bad, f"{line}: refused ({text})", bad[-800:])

finish()
