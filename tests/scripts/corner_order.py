"""BLOCK and JREGION corners given anticlockwise. The manual asks for them in
clockwise order (UDEC manual (ICG1.5), Section 4.5, BLOCK and JREGION); a
new user's slope deck listed them the other way round and was refused at
its second line. The same corners in either order describe the same
polygon, so udec takes anticlockwise corners in reverse order with a note.
Reference: the deck with the corners given clockwise; the anticlockwise
deck must print the same corners (PRINT CORNERS, byte for byte, their
1989 addresses too: the first corner stays first) after JSET
cuts the block and the same JREGION-limited joints. A self-intersecting
outline is still refused whichever way round it is given."""
import os
import sys
sys.path.insert(0, os.path.dirname(__file__))
from udec_test import check, finish, run, run_deck, workdir, write  # noqa: E402

udec = sys.argv[1]

SLOPE_CW = "0,0 0,35 15,35 30,20 60,20 60,0"
SLOPE_ACW = "0,0 60,0 60,20 30,20 15,35 0,35"
REGION_CW = "5,5 5,30 40,18 40,5"
REGION_ACW = "5,5 40,5 40,18 5,30"


def deck(block, region):
    return f"""ROUND 0.05
BLOCK {block}
JREGION {region}
JSET 35,0 100,0 0,0 3,0
JSET -60,0 100,0 0,0 4,0
PRINT CORNERS
"""


def corners(out):
    """The PRINT CORNERS table and what the cuts printed."""
    keep = [line for line in out.splitlines()
            if not line.startswith(("BLOCK", "JREGION", "Note: BLOCK", "Note: JREGION"))]
    return "\n".join(keep)


folder = workdir()
_, ref = run_deck(udec, folder, "cw", deck(SLOPE_CW, REGION_CW))
_, out = run_deck(udec, folder, "acw", deck(SLOPE_ACW, REGION_ACW))
check("Note: BLOCK: the corners were given anticlockwise" in out,
      "anticlockwise BLOCK: a note says the corners were taken in reverse", out[:1500])
check("Note: JREGION: the corners were given anticlockwise" in out,
      "anticlockwise JREGION: a note says the corners were taken in reverse", out[:1500])
check("anticlockwise" not in ref, "clockwise corners: no note", ref[:1500])
check(corners(out) == corners(ref),
      "anticlockwise corners cut into the same blocks as clockwise ones (PRINT CORNERS)",
      "\n".join(a + "  |  " + b for a, b in zip(corners(ref).splitlines(), corners(out).splitlines())
                if a != b)[:2000])
check(len([line for line in out.splitlines() if line.strip()[:1].isdigit()]) > 100,
      "the corner table is printed", out[-500:])

# a bow tie is refused in either order, and the refusal names the command
for name, text in (("bow", "0,0 10,10 10,0 0,10"), ("bow_rev", "0,10 10,0 10,10 0,0")):
    write(folder, name + ".dat", f"BLOCK {text}\n")
    rc, out = run(udec, [name + ".dat"], cwd=folder)
    check(rc != 0 and "*** Error: BLOCK: the boundary intersects itself" in out,
          f"{name}: a self-intersecting BLOCK is refused", out[-800:])
finish()
