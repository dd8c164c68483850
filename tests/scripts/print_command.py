"""PRINT in batch runs (docs/print.md): FILE redirection writes the file and
nothing on the screen or in OUT; the three range forms; keywords for data not
yet available and undefined histories do not stop a batch run; JPLOT and LINK
(docs/geometry.md)."""
import os
import re
import sys
sys.path.insert(0, os.path.dirname(__file__))
from udec_test import check, finish, run, workdir, write  # noqa: E402

udec = sys.argv[1]
MODEL = "ROUND 0.01\nBLOCK 0,0 0,10 10,10 10,0\nSPLIT 5,-1 5,11\nSPLIT -1,5 11,5\n"
HEADER = "   BLOCK   MAT  CONS"


def block_rows(text):
    """Block ids of the rows following each BLOCK table header."""
    tables = []
    for part in text.split(HEADER)[1:]:
        rows = []
        for line in part.splitlines()[1:]:
            m = re.match(r"^\s+(\d+)\s+\d+\s+\d+\s+\d+\s+\d+\s+\S+E[+-]\d+", line)
            if not m:
                break
            rows.append(int(m.group(1)))
        tables.append(sorted(rows))
    return tables


d = workdir()
# FILE: the table goes to the file only (not the screen, not OUT).
write(d, "file.dat", MODEL + "PRINT FILE blocks.txt BLOCK\nSTOP\n")
rc, out = run(udec, ["file.dat"], cwd=d)
check(rc == 0, "PRINT FILE run ends with status 0", out)
check(HEADER not in out, "PRINT FILE: nothing on the screen", out)
check(HEADER not in open(os.path.join(d, "OUT")).read(), "PRINT FILE: nothing in OUT")
text = open(os.path.join(d, "blocks.txt")).read()
check(block_rows(text) == [[1, 2, 3, 4]], "PRINT FILE: the file holds the 4 blocks", text)
check(not os.path.exists(os.path.join(d, "blocks.txt.udec-tmp")), "no temporary left")

# Ranges: box, REG, ANN select blocks by centroid (1 at 2.5,7.5; 2 at 7.5,7.5;
# 3 at 7.5,2.5; 4 at 2.5,2.5 - the order the cutting engine numbers them).
write(d, "ranges.dat", MODEL + "PRINT BLOCK\nPRINT 0,5 0,5 BLOCK\n"
      "PRINT REG 0,0 0,10 5,10 5,0 BLOCK\nPRINT ANN 10 10 0 4 BLOCK\nSTOP\n")
rc, out = run(udec, ["ranges.dat"], cwd=d)
tables = block_rows(out)
check(rc == 0 and len(tables) == 4, "four BLOCK tables", out)
if len(tables) == 4:
    check(tables[0] == [1, 2, 3, 4], "no range: all blocks", out)
    check(tables[1] == [4], "box 0,5 0,5: block 4", out)
    check(tables[2] == [1, 4], "REG left half: blocks 1 and 4", out)
    check(tables[3] == [2], "ANN around (10,10), r <= 4: block 2", out)

# Data that does not exist yet, undefined histories: reported, the run goes on
# (the manual's decks use these lines).
write(d, "na.dat", MODEL + "PRINT HIST 1 2\nPR HMAX 5\nPRINT MAX FF\nPRI STE STC\n"
      "PR CON BOUND\nHEAD\nreached\nSTOP\n")
rc, out = run(udec, ["na.dat"], cwd=d)
check(rc == 0 and "reached" in out, "unavailable PRINT data does not stop a batch run", out)
check("PRINT FF: there is no free field" in out and "not yet available" not in out,
      "FF without FFIELD GEN: there is no free field", out)
check(out.count("there are no structural elements") == 2, "STE, STC: no structures yet", out)
check("history 1 is not defined" in out and "history 5 is not defined" in out,
      "undefined histories are noted", out)
check("no boundary conditions" in out, "PRINT BOUND without boundary conditions", out)

# A misplaced sub-keyword is an input error: the batch run stops.
write(d, "bad.dat", MODEL + "PRINT DISP\nHEAD\nnot reached\nSTOP\n")
rc, out = run(udec, ["bad.dat"], cwd=d)
check(rc != 0 and "PRINT DISPLACEMENTS: give it after CONTACT" in out
      and "not reached" not in out, "PRINT DISP alone is an input error", out)

# JPLOT: CRACK between START and STOP does not split blocks; after STOP it does.
write(d, "jplot.dat", MODEL + "JPLOT START\nCRACK -1,7 11,7\nJPLOT STOP\nPRINT BLOCK\n"
      "CRACK -1,7 11,7\nPRINT BLOCK\nSTOP\n")
rc, out = run(udec, ["jplot.dat"], cwd=d)
tables = block_rows(out)
check(rc == 0 and "JPLOT STOP: 2 joint segment(s) recorded" in out, "JPLOT records 2 pieces", out)
check(len(tables) == 2 and len(tables[0]) == 4 and len(tables[1]) == 6,
      "JPLOT: no split while recording, split after STOP", out)

# LINK: validated, nothing stored.
write(d, "link.dat", MODEL + "LINK 2,8 8,8\nLINK 2,8 20,8\nSTOP\n")
rc, out = run(udec, ["link.dat"], cwd=d)
check("LINK: blocks 1 and 2 need no link" in out, "LINK accepted with a note", out)
check(rc != 0 and "LINK: the second point (20, 8) is not inside any block" in out,
      "LINK with a point outside the blocks is an input error", out)
# PRINT MAX with every block FIXed: no unbalanced force (before: -1.00000E+00,
# the search's start value, printed as the largest)
write(d, "fixed.dat", MODEL + "PROP MAT 1 DENS 2600\nPROP JMAT 1 JKN 1e9 JKS 1e9\nGRAV 0 -9.81\n"
      "FIX -1 11 -1 11\nCYCLE 5\nPRINT MAX\nFREE 0 5 0 5\nCYCLE 1\nPRINT MAX\nSTOP\n")
rc, out = run(udec, ["fixed.dat"], cwd=d)
lines = [l for l in out.splitlines() if l.startswith("  max unbalanced force")]
check(rc == 0 and len(lines) == 2 and "none  (every block is FIXed)" in lines[0]
      and re.search(r"\s6\.3\d+E\+05\s+block\s+\d+$", lines[1]) is not None,
      "PRINT MAX: no unbalanced force while every block is FIXed, "
      "the free block's weight (6.38e5 N) after FREE",
      "\n".join(lines) + out[-600:])
finish()
