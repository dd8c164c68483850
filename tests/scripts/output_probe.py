"""Output and session commands on a zoned, jointed model as a user who
knows only the manual writes them (manual 4.5 HISTORY / PRINT, 4.6 PLOT):

- HISTORY TYPE n given before history n is defined (the Appendix E deck:
  `HIST N=5 XDIS(2,2) YDIS(2,2) TYPE=5` then a second HIST line) types
  history n while cycling once it exists;
- PLOT ... ABC=n HIST m (the Appendix E decks' history plots) is AB n;
- the legend of a history plot names the contact / block of a contact or
  block history and no place for UNBAL (no "at (0, 0)");
- a history with a single sample is marked on its plot;
- PRINT ... FILE name with no keyword after FILE is refused (the manual:
  FILE must precede the keywords) and writes no file;
- RESET DISP zeroes gridpoint displacements, RESET STRESS zone stresses,
  RESET MAT n STRESS only the zones of material n (joints kept), and MAT
  given after STRESS is refused with nothing reset;
- PRINT STRESS with a mistyped huge grid (nx ny = 100000 100000, 1e10
  lines) is refused instead of printing for hours;
- CHANGE SDEF on zoned blocks says they stay zoned, and does not claim they stay rigid.
"""
import os
import re
import sys
sys.path.insert(0, os.path.dirname(__file__))
from udec_test import check, finish, workdir, write  # noqa: E402
from udec_test import run as run_udec  # noqa: E402

udec = sys.argv[1]


def run(*args, **kwargs):
    """udec_test.run without the runtime warnings of a Debug build."""
    rc, out = run_udec(*args, **kwargs)
    out = re.sub(r"(?m)^(At line \d+ of file .*|Fortran runtime warning: .*)\n", "", out)
    return rc, out


BASE = """HEAD
output probe
ROUND 0.01
BLOCK 0,0 0,2 1,2 1,0
CRACK -0.1,0.9 1.1,1.1
CHANGE FDEF MAT=1 CONS=3
GEN AUTO 0.4
PROP MAT=1 D=2.6E-3 K=4000 G=3000 COH=1 FRIC=30 TENS=0.5
PROP JMAT=1 JKN=1e4 JKS=1e4 JFRIC=0.3
CHANGE JMAT=1 JCONS=2
BOUND -0.1,1.1 -0.1,0.01 YVEL=0
BOUND -0.1,0.01 -0.1,0.01 XVEL=0
BOUND -0.1 1.1 1.99 2.1 YVEL=-0.01
DAMP AUTO
"""


def typed_values(out):
    """(cycle, typed value) rows of the CYCLE table."""
    rows = []
    for line in out.splitlines():
        m = re.match(r"^\s+(\d+)\s+(\S+E[-+]\d+)\s+(\S+E[-+]\d+)\s*$", line)
        if m:
            rows.append((int(m.group(1)), float(m.group(3))))
    return rows


def last_written(path):
    with open(path) as f:
        rows = [line.split() for line in f if not line.startswith("#")]
    return float(rows[-1][1])


# --- TYPE n before history n exists
d = workdir()
write(d, "t.dat", BASE + """HIST N=10 YDIS 0.5,2 TYPE=3
HIST SYY 0.5,0.5 NSTR 1
CYC 100
HIST WRITE 3 h3.txt
STOP
""")
rc, out = run(udec, ["t.dat"], cwd=d)
check(rc == 0, "TYPE before definition: deck runs", out[-2000:])
check("history 3" in out and "nothing is typed" not in out,
      "TYPE=3 given before history 3 exists: history 3 is typed while cycling", out[-3000:])
rows = typed_values(out)
check(len(rows) > 0 and rows[-1][0] == 100, "TYPE: a typed row at cycle 100", out[-3000:])
if rows and os.path.exists(os.path.join(d, "h3.txt")):
    # the typed value at cycle 100 is history 3's sample at cycle 100 (NCYC 10);
    # typed with 7 significant digits: relative tolerance 1e-6
    ref = last_written(os.path.join(d, "h3.txt"))
    check(abs(rows[-1][1] - ref) <= 1e-6*abs(ref), "TYPE: typed value is history 3",
          f"typed {rows[-1][1]} written {ref}")

# TYPE n never defined: CYCLE says so and types nothing
write(d, "t2.dat", BASE + """HIST N=10 YDIS 0.5,2 TYPE=4
CYC 20
STOP
""")
rc, out = run(udec, ["t2.dat"], cwd=d)
check(rc == 0 and "TYPE 4 names no history (1 defined)" in out and not typed_values(out),
      "TYPE of a history never defined: CYCLE note, nothing typed", out[-2000:])

# --- PLOT ABC=n, legends, a single-sample history
write(d, "p.dat", BASE + """HIST N=10 YDIS 0.5,2 SYY 0.5,0.5 UNBAL NSTR 1
CYC 100
HIST N=20 XDIS 1 2
CYC 20
PLOT XREV AB=1 HIST 2
COPY ab.png
PLOT XREV ABC=1 HIST 2
COPY abc.png
PLOT HIST 3 4
COPY legend.ps
PLOT HIST 5
COPY single.ps
STOP
""")
rc, out = run(udec, ["p.dat"], cwd=d)
check(rc == 0, "plot deck runs", out[-2000:])


def read_bytes(name):
    path = os.path.join(d, name)
    return open(path, "rb").read() if os.path.exists(path) else b""


ab, abc = read_bytes("ab.png"), read_bytes("abc.png")
check(len(ab) > 0 and ab == abc, "PLOT ABC=1 draws what AB=1 draws (identical PNG)")
legend = read_bytes("legend.ps").decode("latin-1")
check("( 3 UNBAL \\(N\\))" in legend, "legend: UNBAL without a place, with its unit", legend[-1500:])
check("NSTR contact 1" in legend, "legend: NSTR names its contact", legend[-1500:])
check("at \\(0, 0\\)" not in legend, "legend: no 'at (0, 0)' for placeless histories")
single = read_bytes("single.ps").decode("latin-1")
# history 5 was defined after 100 cycles with NCYC 20: one sample (cycle
# 120); its curve width is 1.80 page units -> the marker is two strokes
check(len(re.findall(r"^1\.80 W$", single, re.M)) == 2,
      "single-sample history: a cross marks the sample", single[-1500:])

# --- PRINT ... FILE at the end of the line
write(d, "f.dat", BASE + """HIST N=10 YDIS 0.5,2
CYC 10
PRINT HIST 1 FILE late.txt
""")
rc, out = run(udec, ["f.dat"], cwd=d)
check(rc != 0 and "FILE must precede" in out and "late.txt" in out,
      "PRINT HIST 1 FILE name: refused with the manual's rule", out[-1500:])
check(not os.path.exists(os.path.join(d, "late.txt")), "PRINT ... FILE at the end writes no file")
write(d, "f2.dat", BASE + """HIST N=10 YDIS 0.5,2
CYC 10
PRINT FILE early.txt HIST 1
STOP
""")
rc, out = run(udec, ["f2.dat"], cwd=d)
text = open(os.path.join(d, "early.txt")).read() if os.path.exists(os.path.join(d, "early.txt")) else ""
check(rc == 0 and "1 YDIS" in text, "PRINT FILE name HIST 1 writes the table to the file", out[-1500:])
# headers use the manual's HISTORY keyword (Section 4.5: YDis x y), not the internal
# gridpoint kind name, and say where the value is taken
check("GYDIS" not in text and "column 1 YDIS at (" in text and "gridpoint" in text,
      "PRINT HIST header: manual keyword YDIS with its location", text[:800])


# --- RESET on zoned blocks
def table(out, header, first_col):
    """Rows (lists of floats, first column int) of the table under `header`."""
    rows, on = {}, False
    for line in out.splitlines():
        if header in line:
            on = True
            continue
        if on:
            parts = line.split()
            if len(parts) < 3 or not parts[0].isdigit():
                on = False
                continue
            rows[int(parts[0])] = parts[1:]
    return rows


write(d, "r.dat", BASE + """CHANGE -0.1 1.1 -0.1 0.9 MAT=2
PROP MAT=2 D=2.6E-3 K=4000 G=3000 COH=1 FRIC=30 TENS=0.5
HIST N=10 YDIS 0.5,2
CYC 100
RESET STRESS MAT 2
PRINT HEAD
RESET DISP
PRINT GRID DISP
RESET MAT 2 STRESS
PRINT ZONE STRESS
PRINT CONT FORCE
RESET STRESS
PRINT ZONE STRESS
CYC 10
HIST WRITE 1 y.txt
STOP
""")
rc, out = run(udec, ["r.dat"], cwd=d)
check(rc != 0 and "must precede STRESS" in out, "RESET STRESS MAT 2: refused", out[-1500:])
write(d, "r.dat", open(os.path.join(d, "r.dat")).read().replace("RESET STRESS MAT 2\nPRINT HEAD\n", ""))
rc, out = run(udec, ["r.dat"], cwd=d)
check(rc == 0, "RESET deck runs", out[-2000:])
parts = out.split("RESET MAT 2 STRESS")
grid = table(parts[0], "X-DISP", 0)
# exact zeros: the values are set, not computed
check(len(grid) > 0 and all(float(r[3]) == 0.0 and float(r[4]) == 0.0 for r in grid.values()),
      "RESET DISP: every gridpoint displacement printed as 0", parts[0][-2000:])
if len(parts) > 1:
    after_mat = parts[1].split("PRINT CONT FORCE")
    zones = table(after_mat[0], "SXX", 0)
    blocks = {b: [z for z, r in zones.items() if r[0] == b] for b in ("1", "2")}
    zero = lambda r: all(float(v) == 0.0 for v in r[1:5])  # noqa: E731
    # block 2 (below the joint) is material 2: its zones exactly 0; block 1 keeps
    # its (compressive, about -0.1 after 100 cycles) stresses
    check(blocks["2"] and all(zero(zones[z]) for z in blocks["2"]),
          "RESET MAT 2 STRESS: zones of material 2 zeroed", after_mat[0][-3000:])
    check(blocks["1"] and not any(zero(zones[z]) for z in blocks["1"]),
          "RESET MAT 2 STRESS: zones of material 1 kept", after_mat[0][-3000:])
    forces = table(after_mat[1].split("RESET STRESS")[0], "NORMAL-FORCE", 0)
    check(forces and all(float(r[3]) > 0.0 for r in forces.values()),
          "RESET MAT 2 STRESS: joint forces kept", after_mat[1][:2000])
    final = table(out.split("RESET STRESS\n")[-1].split("CYC 10")[0], "SXX", 0)
    check(final and all(zero(r) for r in final.values()), "RESET STRESS: all zone stresses 0")
if os.path.exists(os.path.join(d, "y.txt")):
    # YDIS after RESET DISP starts from 0: after 10 more cycles at the top
    # velocity 0.01 the top moved by about 10 dt * 0.01, far below the
    # 100-cycle displacement before the reset (factor 5 margin)
    with open(os.path.join(d, "y.txt")) as f:
        ys = [float(line.split()[1]) for line in f if not line.startswith("#")]
    check(len(ys) >= 2 and abs(ys[-1]) < abs(ys[-2])/5.0,
          "RESET DISP: YDIS history continues from 0", str(ys[-3:]))


# --- PRINT STRESS grid guard
write(d, "s.dat", BASE + """PRINT STRESS 0 1 0 2 100000 100000
""")
rc, out = run(udec, ["s.dat"], cwd=d, timeout=60)
check(rc != 0 and "PRINT STRESS: nx ny = 100000 100000" in out,
      "PRINT STRESS 100000 x 100000: refused", out[-1500:])
# just above the limit of 1e6 points: refused; a normal grid: printed
write(d, "s.dat", BASE + """PRINT STRESS 0 1 0 2 1001 1000
""")
rc, out = run(udec, ["s.dat"], cwd=d, timeout=60)
check(rc != 0 and "more than 1 000 000 points" in out, "PRINT STRESS 1001 x 1000: refused",
      out[-1500:])
write(d, "s.dat", BASE + """PRINT STRESS 0 1 0 2 4 5
STOP
""")
rc, out = run(udec, ["s.dat"], cwd=d, timeout=60)
check(rc == 0 and "principal stresses on 4 x 5 points" in out,
      "PRINT STRESS 4 x 5 is printed", out[-1500:])


# --- CHANGE SDEF message on a zoned model
write(d, "c.dat", BASE + """CHANGE SDEF
STOP
""")
rc, out = run(udec, ["c.dat"], cwd=d)
check(rc == 0 and "zoned (FDEF) block(s) in the range stay zoned" in out and "stay rigid" not in out,
      "CHANGE SDEF on zoned blocks: they stay zoned, no claim that blocks are rigid", out[-800:])

finish()
