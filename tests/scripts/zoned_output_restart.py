"""Output of a zoned, plastic, boundary-loaded model (manual 4.5 PRINT,
HISTORY, SAVE, RESTART):

- a HISTORY given after cycling has no samples before it: PRINT HIST shows
  '-' there, PRINT HMAX and HIST WRITE use only its own samples (they read
  0 from the start of the run before);
- SAVE / RESTART continuity: CYCLE N, SAVE, RESTART, CYCLE M prints bit for
  bit what CYCLE N, CYCLE M prints, with DAMP AUTO, MSCALE, boundary histories
  (SINE, LINEAR, an HREAD table), a ZPRESS source, XMUL/YMUL, and increments
  and history types pending when the file was saved;
- absolute file names (SAVE /path, RESTART /path) keep their leading /;
- the same commands typed at the interactive prompt print the same tables;
- the save file names its integer codes (issue 24): an attribute on each coded
  dataset says what its values mean, for h5dump or h5py readers.
"""
import os
import re
import sys
sys.path.insert(0, os.path.dirname(__file__))
from udec_test import check, finish, workdir, write  # noqa: E402
from udec_test import run as run_udec  # noqa: E402

udec = sys.argv[1]


def run(*args, **kwargs):
    """udec_test.run without the runtime warnings of a Debug build (stderr,
    interleaved with the tables)."""
    rc, out = run_udec(*args, **kwargs)
    out = re.sub(r"(?m)^(At line \d+ of file .*|Fortran runtime warning: .*)\n", "", out)
    return rc, out

TABLE = "table heading\n5 0.02\n0.0 0.5 1.0 0.5 0.2\n"
BASE = """START
ROUND 0.01
BLOCK 0,0 0,10 10,10 10,0
SPLIT -1,5 11,5
GEN QUAD 2.5
CHANGE CONS=3 MAT=1 JCONS=2 JMAT=2
PROP MAT=1 D=2000 K=1E9 G=6E8 COH=1E6 FRIC=0.5 TENS=1E5
PROP MAT=2 JKN=1E10 JKS=1E10 JFRIC=0.6 JCOH=1E5
SET GRAV 0 -10
BOUND -.1 .1 -1 11 XVEL=0
BOUND -1 11 -.1 .1 YVEL=0
BOUND -1 11 9.9 10.1 STRESS 0 0 -5E6
BOUND 9.9 10.1 6 9 HREAD 1 tab.txt
BOUND 9.9 10.1 6 9 XLOAD -1E5 XHIST 1
BOUND 9.9 10.1 1 4 XLOAD -1E5 XHIST SINE 20 0.05
SET ZPRESS 5 2.5 1.5 1E5
MSCALE ON
DAMP AUTO
HIST NCYC=3 SXX 3 3 SYY 3 3 SXY 3 3 XDIS 10 10 YDIS 10 10 XVEL 10 10 YVEL 10 10 DAMP UNBAL
CYCLE 60
"""
# given after the first CYCLE: pending increments and histories, a new
# source and two histories defined late
MIDDLE = """BOUND 9.9 10.1 1 4 XLOAD 2E5 XHIST LINEAR
BOUND 9.9 10.1 6 9 YLOAD 1E5 YHIST 1
BOUND -1 11 9.9 10.1 HIST SINE 10 0.03
SET ZPRESS 5 7.5 1.5 -2E5
BOUND 2 8 9.9 10.1 XMUL 0.5 YMUL 2
HIST SXX 7 7 YVEL 5 5
"""
TAIL = """PRINT GRID
PRINT ZONE STRESS
PRINT BOUND
PRINT CONTACT
PRINT HIST 1 2 3 4 5 6 7 8 9 10 11
PRINT HMAX
PRINT MAX
PRINT STATUS
"""


def after(text, marker):
    """The output from the first line starting with `marker` on."""
    i = text.find("\n" + marker)
    return text[i + 1:] if i >= 0 else ""


def hist_rows(text):
    """Rows of the first PRINT HIST table: lists of the 12 columns."""
    rows = []
    for line in after(text, "PRINT HIST").splitlines()[2:]:
        cols = line.split()
        if len(cols) != 12:
            break
        rows.append(cols)
    return rows


d = workdir()
write(d, "tab.txt", TABLE)

# --- straight run and the late histories
write(d, "straight.dat", BASE + MIDDLE + "CYCLE 40\n" + TAIL + "HIST WRITE 10 h10.txt\nSTOP\n")
rc, straight = run(udec, ["straight.dat"], cwd=d)
check(rc == 0 and "***" not in straight, "straight run without errors", straight[-3000:])
rows = hist_rows(straight)
# samples every 3 cycles: 20 in the first CYCLE 60, 13 in CYCLE 40 (63 .. 99)
check(len(rows) == 33, "PRINT HIST: 33 samples", str(len(rows)))
if len(rows) == 33:
    check(all(r[10] == "-" and r[11] == "-" for r in rows[:20]),
          "histories 10, 11 (given at cycle 60) show '-' before their first sample", str(rows[:3]))
    check(all(r[10] != "-" and r[11] != "-" for r in rows[20:]),
          "histories 10, 11 have values from cycle 63 on", str(rows[20:23]))
    check(all(r[1] != "-" for r in rows), "history 1 has every sample")
    # HMAX of history 10 over its own 13 samples: read the table back
    own = [float(r[10]) for r in rows[20:]]
    times = [float(r[0]) for r in rows[20:]]
    m = re.search(r"^\s+10\s+SXX\s+(\S+)\s+(\S+)\s+(\S+)\s+(\S+)", after(straight, "PRINT HMAX"),
                  re.M)
    check(m is not None, "PRINT HMAX lists history 10")
    if m:
        vmax, tmax, vmin, tmin = (float(x) for x in m.groups())
        # the table and HMAX print the same es14.5 numbers: equal to 6 digits
        check(vmax == max(own) and vmin == min(own),
              "PRINT HMAX 10: extremes of its own samples (not 0 from before it existed)",
              m.group(0) + " " + str((max(own), min(own))))
        check(tmax >= times[0] and tmin >= times[0], "PRINT HMAX 10: times after its definition",
              m.group(0))
text = open(os.path.join(d, "h10.txt")).read() if os.path.exists(os.path.join(d, "h10.txt")) else ""
data = [ln for ln in text.splitlines() if not ln.startswith("#")]
check(len(data) == 13, "HIST WRITE 10: the 13 samples history 10 has", text[:500])

# --- SAVE after CYCLE 60 and the pending commands, RESTART, CYCLE 40
write(d, "part1.dat", BASE + MIDDLE + "SAVE {0}/r.sav\nSAVE {0}/r.sav\nSTOP\n".format(d))
rc, part1 = run(udec, ["part1.dat"], cwd=d)
check(rc == 0 and "Model saved to '{}/r.sav'".format(d) in part1,
      "SAVE with an absolute name (twice)", part1[-2000:])
# the attributes are null-terminated strings in the file; HDF5 keeps small
# metadata uncompressed, so their text is in its bytes
with open(os.path.join(d, "r.sav"), "rb") as f:
    raw = f.read()
for path_text in [b"0 elastic, 1 at failure now, 2 failed in the past, 3 tension failure",
                  b"1 corner-corner, 2 corner of block1 on an edge of block2",
                  b"JCONS of the manual (Section 4.5 CHANGE): 1 point contact Mohr-Coulomb",
                  b"bits: 1 at slip, 2 open (tension failure)",
                  b"CONS of the manual (Section 4.5 CHANGE): 0 null (excavated)",
                  b"x per direction, as PRINT BOUNDARY STATE: 0 free, 1 stress or load",
                  b"damping: 0 none, 1 automatic",
                  b"stress (Pa in SI); compression negative",
                  b"force per unit thickness (N/m in SI); fn compression positive"]:
    check(path_text in raw, "the save file explains its codes: " + path_text.decode()[:40])
write(d, "part2.dat", "RESTART {}/r.sav\nCYCLE 40\n".format(d) + TAIL + "STOP\n")
rc, part2 = run(udec, ["part2.dat"], cwd=d)
check(rc == 0 and "Model restored from '{}/r.sav'".format(d) in part2,
      "RESTART with an absolute name", part2[:2000])
a = after(straight, "PRINT GRID")
b = after(part2, "PRINT GRID")
a = a[:a.find("\nHIST WRITE")]
b = b[:b.find("\nSTOP")]
check(len(a) > 10000 and a == b, "CYCLE 60 + SAVE + RESTART + CYCLE 40 prints what CYCLE 60 + "
      "CYCLE 40 prints, bit for bit",
      "\n".join(x for x in __import__("difflib").unified_diff(a.splitlines(), b.splitlines(),
                                                                  lineterm=""))[:3000])

# --- a file that does not exist or is damaged: the model stays, the saved file too
with open(os.path.join(d, "r.sav"), "rb") as f:
    saved = f.read()
with open(os.path.join(d, "bad.sav"), "wb") as f:
    f.write(saved[:3000])
session = ("RESTART r.sav\nRESTART nothere.sav\nRESTART bad.sav\nCYCLE 40\n" + TAIL + "STOP\n")
rc, inter = run(udec, [], cwd=d, stdin_text=session)
check("RESTART: cannot read save file 'nothere.sav'" in inter and
      "RESTART: cannot read save file 'bad.sav'" in inter, "bad RESTARTs are refused", inter[:2000])

def table_lines(text):
    """Output lines from the first gridpoint table on that belong to tables
    (they start with a blank; echoed commands and prompts do not)."""
    text = text.replace("UDEC> ", "\n")
    i = text.find("  GRIDPT")
    return [ln for ln in text[i:].splitlines() if ln.startswith(" ")] if i >= 0 else []


ti, tb = table_lines(inter), table_lines(part2)
check(len(tb) > 200 and ti == tb,
      "interactive: after refused RESTARTs the model continues as restored, same tables",
      str(len(ti)) + " " + str(len(tb)))
with open(os.path.join(d, "r.sav"), "rb") as f:
    check(f.read() == saved, "the saved file is unchanged")
finish()
