"""GENERATE in a range, then GENERATE without one zones the rest (label `e2e`).

A rock engineer zones finely round the opening and coarsely elsewhere:
`GEN range EDGE e` then `GEN EDGE 3e`. In a jointed model some blocks
straddle any range, so the second command always meets blocks the first
one zoned. Before, that was an error ("block 3 is already zoned") and the
run stopped (random tunnels, nu-zoned: 26 of 60 decks); now those blocks are
left as they are with a note, the others are zoned, and the model runs.
GENERATE MANUAL on a zoned block stays an error naming it (its gridpoints
are explicit data that would be dropped).
"""
import re
import sys
from udec_test import check, finish, run, run_deck, workdir, write

udec = sys.argv[1]

DECK = """round 0.05
block -10,-10 -10,10 10,10 10,-10
tunnel 0 0 2 16
jset 30,0 100,0 0,0 3,0
gen -5,5 -5,5 edge 0.5
gen edge 1.5
gen edge 1.5
prop mat=1 dens=2600 k=2e10 g=1.2e10
prop jmat=1 jkn=2e10 jks=1e10 jfric=0.8
insitu stress -1e7 0 -1.5e7
bound stress -1e7 0 -1.5e7
damp auto
cycle 100
print max
stop
"""
d = workdir()
rc, out = run_deck(udec, d, "rest", DECK)
gens = re.findall(r"GENERATE: (\d+) block\(s\) zoned", out)
notes = re.findall(r"Note: GENERATE: (\d+) block\(s\) in the range already zoned", out)
check(len(gens) == 2 and len(notes) == 2, "two GENERATEs zone blocks, each later one notes the zoned ones",
      str(gens) + str(notes))
check("every block in the range is already zoned; nothing zoned" in out,
      "the third GENERATE finds nothing left to zone")
nblocks = re.findall(r"number of blocks\s+(\d+)", out)
check(bool(gens) and bool(nblocks) and sum(map(int, gens)) == int(nblocks[-1]),
      "every block zoned once", f"{gens} {nblocks}")
m = re.findall(r"max gridpoint displacement\s+(\S+)", out)
check(bool(m) and float(m[-1]) < 1e-6, "the model held by its in-situ stress stays put", str(m))

MANUAL = """block 0,0 0,1 1,1 1,0
gen edge 0.5
gen manual grid 0.5,0.5 0,1 0,0 1,0 1,1 zone 1,2,5 2,3,5 3,4,5 4,1,5
stop
"""
write(d, "manual.dat", MANUAL)
rc, out = run(udec, ["manual.dat"], cwd=d, timeout=60)
check("GENERATE MANUAL: block 1 is already zoned" in out, "MANUAL on a zoned block: an error naming it",
      out[-800:])
finish()
