"""Command-language debts checked against the 1989 manual: abbreviated sub-keywords
in context (Section 4.5 PRINT tables), the sign of HISTORY NSTR against PRINT CONTACT
(Section 4.1 sign conventions), and CYCLE refusing blocks whose material has no
properties (Section 4.5 PROPERTY / CHANGE MAT)."""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(__file__))
from udec_test import check, finish, run, workdir, write  # noqa: E402

udec = sys.argv[1]

BASE = """BLOCK 0,0 0,10 10,10 10,0
SPLIT -1,5 11,5
PROP MAT 1 DENS 2000 K 1e9 G 1e9
PROP JMAT 1 JKN 1e9 JKS 1e9 JFRIC 0.5 JCOH 1e6 JTENS 1e6
"""
ZONED = BASE + """GEN EDGE 5
BOUND -1 11 -1 1 YVEL 0
BOUND -1 11 -1 1 XVEL 0
BOUND -1 11 9 11 STRESS 0 0 -1e6
"""

# --- 1. sub-keywords abbreviated as the manual's PRINT tables capitalise them
d = workdir()
write(d, "abbr.dat", ZONED + """CYC 20
PRINT ZONE ST
PRINT ZONE STR
PRINT CON D
PRINT CON F
PRINT CON S
PRINT GRID D
PRINT BOUND S
PRINT PROP B
STOP
""")
rc, out = run(udec, ["abbr.dat"], cwd=d)
check(rc == 0 and "***" not in out, "abbreviated PRINT sub-keywords run", out[-3000:])


def table_after(text, command):
    """The header line printed right after the echo of `command`."""
    lines = text.splitlines()
    for i, line in enumerate(lines):
        if line.strip() == command and i + 1 < len(lines):
            return lines[i + 1]
    return ""


# manual 4.5 PRint: Zone STate (zone state data: gridpoint addresses, mass),
# STRess (zone stresses); Contacts Disp / Force / State; Gridpoint Disp
check("GP1" in table_after(out, "PRINT ZONE ST"), "PRINT ZONE ST is ZONE STATE")
check("SXX" in table_after(out, "PRINT ZONE STR"), "PRINT ZONE STR is ZONE STRESS")
check("NORMAL-DISP" in table_after(out, "PRINT CON D"), "PRINT CON D is CONTACT DISP")
check("NORMAL-STRESS" in table_after(out, "PRINT CON F"), "PRINT CON F is CONTACT FORCE")
check("JCONS" in table_after(out, "PRINT CON S"), "PRINT CON S is CONTACT STATE")
write(d, "amb.dat", ZONED + "PRINT BOUND F\nSTOP\n")
rc, out = run(udec, ["amb.dat"], cwd=d)
# manual 4.5 PRint BOundary: Fluid and Forces both capitalise only F
check(rc == 1 and "ambiguous keyword 'F' (could be FLUID, FORCES" in out,
      "PRINT BOUND F is refused naming FLUID and FORCES", out[-1500:])
# manual 4.5 BLock: COnstitutive and CIrcular both begin with C, each needs two
# letters: a lone C is ambiguous between them, not an unknown keyword (issue 22)
write(d, "blockc.dat", "BLOCK 0,0 0,1 1,1 1,0 C 1\nSTOP\n")
rc, out = run(udec, ["blockc.dat"], cwd=d)
check(rc == 1 and "BLOCK: ambiguous keyword 'C' (could be CONSTITUTIVE, CIRCULAR" in out,
      "BLOCK C is refused as ambiguous naming CONSTITUTIVE and CIRCULAR", out[-1500:])
# a command abbreviation below every minimum that begins several commands: T
# (TAble, THERMal, TUnnel, ...) is ambiguous, not unknown
write(d, "t.dat", "T\nSTOP\n")
rc, out = run(udec, ["t.dat"], cwd=d)
check(rc == 1 and "ambiguous command abbreviation 'T'" in out and "TUNNEL" in out,
      "a lone T is refused as an ambiguous command naming TUNNEL", out[-1500:])

# --- SET WRITE / -WRITE (manual 4.5: "writes 'scratch' joint file to RJOINT"):
# the traces of CRACK and JSET given while it holds, inside the blocks, one line
# each (x1 y1 x2 y2 block); nothing after SET -WRITE (issue 22)
w = workdir()
write(w, "w.dat", """ROUND 0.02
BLOCK 0,0 0,10 10,10 10,0
CRACK 0,1 10,1
SET WRITE
CRACK -5,3 15,7
JSET 0,0 100,0 0,0 4,0 (0,2)
SET -WRITE
CRACK 0,9 10,9
STOP
""")
rc, out = run(udec, ["w.dat"], cwd=w)
rows = []
if os.path.exists(os.path.join(w, "RJOINT")):
    rows = [[float(v) for v in l.split()] for l in open(os.path.join(w, "RJOINT"))
            if not l.startswith("*")]
# CRACK -5,3 15,7 inside the square: (0,4) to (10,6); JSET at y = 2, 6 (10 is
# the top edge): each a whole trace (y = 6 meets the crack only at its end)
want = [(0, 4, 10, 6), (0, 2, 10, 2), (0, 6, 10, 6)]
ok = rc == 0 and len(rows) == 3 and all(
    any(abs(r[0] - a) < 1e-6 and abs(r[1] - b) < 1e-6 and abs(r[2] - c) < 1e-6
        and abs(r[3] - e) < 1e-6 for r in rows) for a, b, c, e in want)
check(ok and not any(abs(r[1] - 9) < 1e-6 for r in rows) and not any(abs(r[1] - 1) < 1e-6 for r in rows),
      "SET WRITE: RJOINT holds the traces of CRACK and JSET given while it holds", str(rows) + out[-800:])

# --- PRINT BOUNDARY FLUID lists the fluid conditions of the boundary joints;
# PRINT STRUCTURAL the structural element properties (as PRINT PROPERTY STRUCTURAL)
write(w, "bf.dat", """ROUND 0.02
BLOCK 0,0 0,10 10,10 10,0
SPLIT -1,5 11,5
PROP MAT 1 DENS 2000
PROP JMAT 1 JKN 1e9 JKS 1e9 AZERO 1e-4 ARES 5e-5
FLUID DEN 1000
BOUND -1 11 4 6 PP 1e5 PGRAD -1e4
BOUND -1 0.1 -1 11 IMPERM
PRINT BOUND FLUID
PROP MAT 3 DENS 2500 K 1e10 G 1e10
PRINT STRUCTURAL
STOP
""")
rc, out = run(udec, ["bf.dat"], cwd=w)
pp = [l.split() for l in out.splitlines() if re.match(r"\s+\d+\s+\S+\s+\S+\s+(PP|IMPERMEABLE)", l)]
check(rc == 0 and len(pp) == 2 and any(r[3] == "PP" and abs(float(r[4]) - (1e5 - 1e4 * 5)) < 1
                                        for r in pp) and any(r[3] == "IMPERMEABLE" for r in pp),
      "PRINT BOUNDARY FLUID: the PP contact at y = 5 (1e5 - 1e4 x 5) and the impermeable one",
      out[-1500:])
check("not yet" not in out and "STRUCTURAL properties" in out, "PRINT STRUCTURAL prints", out[-800:])

# --- 2. HISTORY NSTR and PRINT CONTACT FORCE agree: joint normal stress is
# compression positive (manual 4.1 sign conventions)
write(d, "nstr.dat", ZONED + """HIST NSTR 1
CYC 200
PRINT HIST 1
PRINT CON F
STOP
""")
rc, out = run(udec, ["nstr.dat"], cwd=d)
lines = out.splitlines()
last_hist = None
contact1 = None
for i, line in enumerate(lines):
    cols = line.split()
    if line.strip() == "PRINT HIST 1":
        j = i + 2
        while j < len(lines) and len(lines[j].split()) == 2:
            last_hist = float(lines[j].split()[1])
            j += 1
    if len(cols) == 8 and cols[0] == "1" and contact1 is None and "NORMAL-STRESS" in lines[i - 1]:
        contact1 = float(cols[6])
check(rc == 0 and last_hist is not None and contact1 is not None,
      "NSTR history and PRINT CONTACT FORCE printed", out[-2000:])
if last_hist is not None and contact1 is not None:
    # same contact, same state (the last sample is at the last cycle): equal to the
    # 6 printed digits; compression under the applied vertical stress: positive
    check(abs(last_hist - contact1) <= 1e-5 * abs(contact1),
          "HIST NSTR equals PRINT CONTACT NORMAL-STRESS", f"{last_hist} {contact1}")
    check(contact1 > 0, "joint under compression: normal stress positive (manual 4.1)",
          str(contact1))

# --- 5. CHANGE MAT to a material without properties: CYCLE refused, naming the
# block, the material and the missing properties; the model unchanged, printable and
# saveable; PROPERTY given later makes the CYCLE run (interactive, so the session
# goes on after the error)
for kind, deck, missing in (("rigid", BASE + "GRAV 0 -10\nFIX -1 11 -1 4\n", "DENSITY"),
                            ("zoned", ZONED, "DENSITY, K, G")):
    e = workdir()
    text = deck + """CYC 5
CHANGE 0 10 5 10 MAT 2
PRINT BLOCK
PRINT CON F
CYC 5
PRINT BLOCK
PRINT CON F
SAVE after.sav
PROP MAT 2 DENS 2000 K 1e9 G 1e9
CYC 5
STOP
"""
    rc, out = run(udec, [], cwd=e, stdin_text=text)
    check(f"has material 2 without {missing}" in out and "CYCLE: block 1" in out
          and "PROPERTY MAT=2" in out,
          f"{kind}: CYCLE refused naming block 1, material 2 and {missing}", out[-2500:])
    # interactive: the output of input line k follows the (k+1)-th prompt
    lines = text.splitlines()
    segments = out.split("UDEC>")
    first = lines.index("PRINT BLOCK")
    second = first + 3
    before = "".join(segments[first + 1:first + 3])
    after = "".join(segments[second + 1:second + 3])
    check(lines[second] == "PRINT BLOCK" and "BLOCK   MAT" in before and before == after,
          f"{kind}: the refused CYCLE leaves blocks and contacts unchanged", before + "\n---\n" + after)
    check(os.path.exists(os.path.join(e, "after.sav")), f"{kind}: the model is saveable after it")
    check(out.count("cycle 10,") == 1 or "cycle 10, " in out,
          f"{kind}: with PROPERTY MAT 2 given the CYCLE runs", out[-1500:])

finish()
