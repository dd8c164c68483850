"""A new user's slips in ranges and cut lines (UDEC manual (ICG1.5, 1989),
Section 4.1, "Geometric locations ... xl,xu yl,yu": the range is
xl < x < xu, yl < y < yu, so a reversed pair selects nothing).

1. Reversed limits (xl > xu or yl > yu) are refused by every command that takes
   a range, naming the pair and the order meant; the model is left as before
   (earlier rounds swapped them silently: FIX 10 0 0 10 fixed 0 < x < 10).
   Equal limits stay accepted (an inclusive line, docs/commands-walk.md).
2. SPLIT and CRACK with two coincident points are refused naming the points
   (SPLIT 0 0 0 0 was accepted and cut nothing)."""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(__file__))
from udec_test import check, finish, run, workdir  # noqa: E402

udec = sys.argv[1]
d = workdir()

MODEL = """BLOCK 0,0 0,10 10,10 10,0
SPLIT -1,5 11,5
SPLIT 5,-1 5,11
PROP MAT 1 DENS 2000 K 1e9 G 1e9
PROP JMAT 1 JKN 1e9 JKS 1e9 JFRIC 0.5
"""

# every range-taking command of Sections 4.5 and 7.4, each with x and with y
# reversed; the message names the command and the reversed pair
REVERSED = [
    ("FIX 10 0 0 10", "FIX: range 10 0 0 10: xl > xu (a range is xl xu yl yu, lower limit first: give 0 10)"),
    ("FREE 0 10 10 0", "FREE: range 0 10 10 0: yl > yu"),
    ("CHANGE 10 0 0 10 MAT 1", "CHANGE: range 10 0 0 10: xl > xu"),
    ("DELETE 6 4 -1 11", "DELETE: range 6 4 -1 11: xl > xu"),
    ("BOUND 0 10 1 -1 YVEL 0", "BOUNDARY: range 0 10 1 -1: yl > yu"),
    ("INSITU 10 0 0 10 STRESS -1e6 0 -1e6", "INSITU: range 10 0 0 10: xl > xu"),
    ("LOAD 10 0 0 10 0 -1e3", "LOAD: range 10 0 0 10: xl > xu"),
    ("PRINT 10 0 0 10 BLOCK", "PRINT: range 10 0 0 10: xl > xu"),
    ("GEN 0 10 10 0 EDGE 2", "GENERATE: range 0 10 10 0: yl > yu"),
    ("PFIX 10 0 0 10 PRESSURE 1e5", "PFIX: range 10 0 0 10: xl > xu"),
    ("TFIX 50 10 0 0 10", "TFIX: range 10 0 0 10: xl > xu"),
    ("INITEM 50 0 10 10 0", "INITEM: range 0 10 10 0: yl > yu"),
    ("THAPP 10 0 0 10 SOURCE 1", "THAPP: range 10 0 0 10: xl > xu"),
    ("TFREE 10 0 0 10", "TFREE: range 10 0 0 10: xl > xu"),
    # the positional ranges of these were refused already; they stay so
    ("STRESS 10 0 0 10 2 2", "STRESS: expected xl < xu and yl < yu"),
    ("WINDOW 10 0 0 10", "WINDOW: expected xl < xu"),
]
deck = MODEL + "".join(c + "\n" for c, _ in REVERSED) + \
    "PRINT BLOCK\nSPLIT 0 0 0 0\nCRACK 2.5,2.5 2.5,2.5\nSPLIT 2.5,-1 2.5,-1.0\n" + \
    "PRINT BLOCK\nFIX 0 10 0 10\nFIX 0 10 5 5\nSTOP\n"
rc, out = run(udec, cwd=d, stdin_text=deck)
for command, message in REVERSED:
    # the parser names an optional range's command as "CHANGE (range)"
    name, _, rest = message.partition(":")
    found = re.search(re.escape(name) + r"( \(range\))?:" + re.escape(rest), out)
    check(found is not None, "reversed limits refused: " + command, out[-3000:])
# the error count: one per reversed command and one per coincident cut
check(out.count("*** Error") == len(REVERSED) + 3,
      "every reversed range and coincident cut refused, nothing else", out[-4000:])
check("SPLIT: x1,y1 = 0,0 and x2,y2 = 0,0 are the same point; the line needs two distinct points"
      in out, "SPLIT 0 0 0 0 refused naming the points", out[-3000:])
check("CRACK: x1,y1 = 2.5,2.5 and x2,y2 = 2.5,2.5 are the same point; the crack needs two "
      "distinct points" in out, "a zero-length CRACK refused naming the points", out[-3000:])
check("SPLIT: x1,y1 = 2.5,-1 and x2,y2 = 2.5,-1 are the same point" in out,
      "SPLIT with the same point typed two ways refused", out[-3000:])

# the model after the refused commands is the model before them: 4 blocks,
# none deleted or cut (the two PRINT BLOCK tables are identical)
tables = []
for line in out.splitlines():
    if "BLOCK   MAT  CONS" in line:
        tables.append([])
    elif tables and re.match(r"\s+\d+\s+\d+\s+\d+\s+\d+\s+\d+\s+\S+E", line):
        tables[-1].append(line)
check(len(tables) == 2 and len(tables[0]) == 4, "both PRINT BLOCK tables of 4 blocks printed",
      out[-2000:])
check(len(tables) == 2 and tables[0] == tables[1],
      "refused cuts and ranges left the blocks as they were", str(tables))
# in order, the same commands act (FIX fixes the 4 blocks; a line range
# with equal limits is accepted and selects no centroid)
check("FIX 4 block(s)" in out and "FIX: no block centroid lies in the range" in out,
      "ranges in order are taken", out[-1500:])

# FFIELD's y range (Section 4.5 FFIELD <y1 y2> MAT n) follows the same rule
deck = """BLOCK 0,0 0,10 10,10 10,0
PROP MAT 1 DENS 2000 K 1e9 G 1e9
GEN EDGE 5
FFIELD GEN 0 10 6
FFIELD 8 2 MAT 1
FFIELD 2 8 MAT 1
STOP
"""
rc, out = run(udec, cwd=d, stdin_text=deck)
check("FFIELD y1 y2: expected y1 <= y2, got 8 2" in out and out.count("*** Error") == 1,
      "FFIELD y1 y2 reversed refused, in order accepted", out[-2000:])
finish()
