"""Results are the same to the last bit at any thread count (issue 23).

Each deck runs at OMP_NUM_THREADS=1 and 2 (and once more at 2); EXPORT HISTORY
(17 significant digits), EXPORT .vtu and the saved model (SAVE, HDF5 written
without object times) must be equal byte for byte. Decks: an elastic zoned
block (threaded zone stress pass: a thread adds the terms of the gridpoints
only its chunk of zones touches, those shared by two chunks are gathered in the
one-thread order), two jointed elastic blocks of two materials (two zone groups,
each cut into chunks; contacts between the blocks), a Mohr-Coulomb block zoned by GENERATE AUTO (mixed
discretization: one-thread zone pass, threaded gridpoint motion), an FDEF
block cut by a joint (zones and contacts), and two jointed rigid walls. Tolerance:
none. The two zoned blocks have more than 4000 zones (zones_mechanics runs
smaller models on one thread); the larger wall (1 024 blocks, 5 890 contacts)
more than 4000 contacts and 1000 blocks, so its contact passes and block motion
run threaded (contact_mechanics: each contact's force terms gathered per block
in the one-thread order, the test fails if a block adds them in another order;
engine_rigid: the motion's sums taken in block order). Checks that each deck really cycled keep the comparison from passing on
empty output."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from udec_test import check, finish, run, workdir, write  # noqa: E402

udec = sys.argv[1]

OUT = """EXPORT {n}.vtu
EXPORT HISTORY {n}.csv
SAVE {n}.sav
"""

DECKS = {
    "elastic": """ROUND 0.01
BLOCK 0,0 0,32 32,32 32,0
GEN QUAD 1
PROP MAT=1 DENS=2500 K=1E10 G=6E9 JKN=1E10 JKS=1E10
GRAV 0 -10
BOUNDARY -1,33 -0.1,0.1 YVEL=0
DAMP AUTO
HIST YVEL 16,32 UNBAL
HIST SXX 16,16
CYCLE 200
""",
    "elastic_two_groups": """ROUND 0.01
BLOCK 0,0 0,40 40,40 40,0
CRACK 0,20.5 40,20.5
CHANGE FDEF
GEN QUAD 1
PROP MAT=1 DENS=2500 K=1E10 G=6E9 JKN=1E10 JKS=1E10
PROP MAT=2 DENS=2000 K=5E9 G=3E9 JKN=1E10 JKS=1E10
CHANGE 0,40 20.5,40 MAT=2
GRAV 0 -10
BOUNDARY -1,41 -0.1,0.1 YVEL=0
DAMP AUTO
HIST YVEL 20,40 UNBAL
HIST SXX 20,10
CYCLE 200
""",
    "mohr": """ROUND 0.01
BLOCK 0,0 0,26 26,26 26,0
GEN AUTO 0.75
PROP MAT=1 DENS=2500 K=1E9 G=6E8 JKN=1E10 JKS=1E10
CHANGE CONS=3
PROP MAT=1 COH=1E4 FRIC=0.577 TENS=1E3
GRAV 0 -10
BOUNDARY -1,27 -0.1,0.1 YVEL=0
BOUNDARY -1,27 25.9,26.1 YVEL=-1e-3
DAMP AUTO
HIST YVEL 13,26 UNBAL
HIST SXX 13,13
CYCLE 200
""",
    "fdef_joint": """ROUND 0.01
BLOCK 0,0 0,4 4,4 4,0
CRACK 0,1 4,3
CHANGE FDEF
GEN EDGE 0.4
PROP MAT=1 DENS=2000 K=1e9 G=0.6e9 JKN=1e9 JKS=1e9 JFRIC=30
GRAV 0 -10
FIX 0 4 0 0.5
DAMP AUTO
HIST YVEL 2,4 UNBAL
HIST SXX 2,2
CYCLE 500
""",
    "rigid_wall_large": """ROUND 0.01
BLOCK 0,0 0,32 32,32 32,0
JSET 0,0 320,0 0,0 1,0 0,0
JSET 90,0 320,0 0,0 1,0 0,0
PROP MAT=1 DENS=2500 JKN=1E10 JKS=1E10 JFRIC=0.5 JCOH=1E3 JTEN=1E2
GRAV 0 -10
FIX -1,33 -1,1
DAMP AUTO
HIST YVEL 16.5,31.5 UNBAL
HIST XDIS 0.5,31.5
CYCLE 150
""",
    "rigid_wall": """ROUND 0.01
BLOCK 0,0 0,8 8,8 8,0
JSET 0,0 80,0 0,0 1,0 0,0
JSET 90,0 80,0 0,0 1,0 0,0
PROP MAT=1 DENS=2500 JKN=1E10 JKS=1E10 JFRIC=0.5
GRAV 0 -10
FIX -1,9 -1,1
DAMP AUTO
HIST YVEL 4.5,7.5 UNBAL
CYCLE 300
""",
}


def files(folder, name):
    got = {}
    for ext in ("csv", "vtu", "sav"):
        path = os.path.join(folder, f"{name}.{ext}")
        got[ext] = open(path, "rb").read() if os.path.exists(path) else None
    return got


for name, deck in DECKS.items():
    runs = []
    for label, threads in (("1 thread", "1"), ("2 threads", "2"), ("2 threads again", "2")):
        folder = workdir()
        write(folder, "deck.dat", deck + OUT.format(n=name))
        os.environ["OMP_NUM_THREADS"] = threads
        rc, out = run(udec, ["deck.dat"], cwd=folder, timeout=300)
        check(rc == 0, f"{name}, {label}: the deck runs", out[-1500:])
        runs.append((label, files(folder, name)))
    first = runs[0][1]
    rows = (first["csv"] or b"").decode(errors="replace").splitlines()
    # the deck cycled: history rows, and a non-zero velocity in the last one
    check(len(rows) > 10, f"{name}: the history has rows ({len(rows)})")
    if len(rows) > 10:
        last = rows[-1].split(",")
        check(len(last) > 2 and float(last[2]) != 0.0, f"{name}: the history moved", rows[-1])
    for ext in ("csv", "vtu", "sav"):
        check(first[ext] is not None and len(first[ext]) > 0, f"{name}: {ext} written at 1 thread")
        for label, got in runs[1:]:
            check(got[ext] == first[ext], f"{name}: {ext} at {label} is the 1-thread file byte for byte")

finish()
