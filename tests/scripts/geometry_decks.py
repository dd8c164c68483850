"""The geometry of every manual deck builds without error (issue 3): the set-up
of each deck that does not start from a RESTART (up to its first CYCLE) runs in
batch mode with exit status 0, and
the block counts the manual states hold (tutorial: 4 blocks, Section 2.1;
verification D: 25 blocks, Appendix A)."""
import glob
import os
import re
import shutil
import sys
sys.path.insert(0, os.path.dirname(__file__))
from udec_test import check, finish, run, workdir  # noqa: E402

udec, root = sys.argv[1], sys.argv[2]
EXPECTED_BLOCKS = {"examples/tutorial/slope1.dat": 4, "verification/D/D.dat": 25}

decks = sorted(glob.glob(os.path.join(root, "examples", "**", "*.dat"), recursive=True)
               + glob.glob(os.path.join(root, "verification", "**", "*.dat"), recursive=True))
ran = 0
for deck in decks:
    rel = os.path.relpath(deck, root)
    with open(deck, encoding="latin-1") as f:
        text = f.read()
    first = next((ln for ln in text.splitlines() if ln.strip() and not ln.strip().startswith("*")), "")
    if re.match(r"\s*(REST|RES\b|R\b)", first, re.I):
        continue                       # needs a save file from another deck
    # Print the blocks of the set-up: just before the first CYCLE or BOUNDARY
    # XVEL/YVEL (whose physics may need deformable blocks that have not
    # landed), else before
    # the final STOP.
    lines = text.rstrip().splitlines()
    cyc = [i for i, ln in enumerate(lines) if re.match(r"\s*(C|CY|CYC|CYCL|CYCLE)\b", ln, re.I)
           # BOUNDARY XVEL / YVEL needs zoned FDEF blocks (GENERATE): an error on rigid ones
           or (re.match(r"\s*BO\w*\b", ln, re.I) and re.search(r"\b[XY]VEL\b", ln, re.I))]
    if cyc:
        lines = lines[:cyc[0]] + ["PRINT BLOCK", "STOP"]
    else:
        stop = max(i for i, ln in enumerate(lines) if re.match(r"\s*(STO|STOP|QUIT|END)\b", ln, re.I))
        lines.insert(stop, "PRINT BLOCK")
    d = workdir()
    with open(os.path.join(d, "deck.dat"), "w", encoding="latin-1") as f:
        f.write("\n".join(lines) + "\n")
    rc, out = run(udec, ["deck.dat"], cwd=d, timeout=300)
    ran += 1
    check(rc == 0 and "*** Error" not in out, f"geometry builds: {rel}", out[-1500:])
    table = out.split("   BLOCK   MAT  CONS")[-1]
    nblocks = len(re.findall(r"^\s+\d+\s+\d+\s+\d+\s+\d+\s+\d+\s+\S+E[+-]\d+", table, re.M))
    check(nblocks > 0, f"blocks printed for {rel}", out[-800:])
    if rel in EXPECTED_BLOCKS:
        check(nblocks == EXPECTED_BLOCKS[rel],
              f"{rel}: {EXPECTED_BLOCKS[rel]} blocks as the manual says (got {nblocks})")
    shutil.rmtree(d, ignore_errors=True)
print(f"{ran} decks built")
check(ran >= 25, "most manual decks build their geometry")
finish()
