"""A cut after BOUNDARY may not take away the boundary's conditions (label
e2e; UDEC manual (ICG1.5, 1989), Section 4.5, BOUNDARY: conditions are set
on the boundary corners present when the command is given; GENERATE already
refuses to zone a block that carries them).

A new user wrote BOUNDARY STRESS and INSITU right after BLOCK, then the
JSETs, the TUNNEL and GENERATE: the JSET cut the one block, its four corners
died with their loads, and the model ran two SOLVEs of 100 000 cycles each
with no load at all (largest normal force 4.5e-4 N, "force ratio 2.6"),
without a word. Checked:
1. a cut (CRACK, JSET, SPLIT) through a block that carries conditions is
   refused with an error naming the command, the block, the corner and the
   remedy, and nothing changes: PRINT BOUNDARY still lists the four corners
   with their stress increments (5e6 Pa x 20 m / 2 = 5e7 N a corner);
2. a batch deck stops at that line (exit code not 0);
3. a cut that does not reach a block with conditions (a TUNNEL inside a
   jointed model, an excavation stage after the in-situ SOLVE) is made, and
   SOLVE balances it.
"""
import re
import sys
from udec_test import check, finish, run, workdir, write

udec = sys.argv[1]
d = workdir()
session = """round 0.05
block 0,0 0,20 20,20 20,0
bound stress -5e6 0 -5e6
crack 0,10 20,10
jset 45 0 50 0 0 0 5 0 (0,0)
split 5,0 5,20
print bound
quit
"""
rc, out = run(udec, [], cwd=d, stdin_text=session)
for name in ("CRACK", "JSET", "SPLIT"):
    check(re.search(name + r": block 1 carries conditions of an earlier BOUNDARY command \(corner 1\); "
                    r"the cut replaces its corners and the conditions would be lost: give " + name +
                    r" before BOUNDARY; nothing was changed", out) is not None,
          name + " through the loaded block is refused, naming block, corner and remedy", out[-3000:])
forces = re.findall(r"^\s+\d+\s+\S+\s+\S+\s+1\s+1\s+0\.00000E\+00\s+0\.00000E\+00\s+(\S+)\s+(\S+)\s*$",
                    out, re.M)
check(len(forces) == 4, "the four corners keep their conditions (PRINT BOUNDARY FORCES)", out[-2500:])
# 5e6 Pa on two half edges of 10 m each: 5e7 N in x and in y at each corner
check(all(abs(abs(float(fx)) - 5e7) < 1.0 and abs(abs(float(fy)) - 5e7) < 1.0 for fx, fy in forces),
      "each corner's increment is still 5e7 N in x and y", str(forces))

write(d, "order.dat", """round 0.05
block 0,0 0,20 20,20 20,0
bound stress -5e6 0 -5e6
jset 45 0 50 0 0 0 2 0 (0,0)
prop mat 1 dens 2600
prop jmat 1 jkn 1e10 jks 5e9 jfric 0.7
damp auto
solve
""")
rc, out = run(udec, ["order.dat"], cwd=d)
check(rc != 0 and "JSET: block 1 carries conditions" in out and "in file order.dat, line 4" in out
      and "SOLVE" not in out.split("line 4")[-1], "a batch deck stops at the refused JSET", out[-1500:])

write(d, "stage.dat", """round 0.05
block 0,0 0,20 20,20 20,0
jset 45 0 50 0 0 0 2 0 (0,0)
jset -45 0 50 0 0 0 2 0 (1,0)
prop mat 1 dens 2600
prop jmat 1 jkn 1e10 jks 5e9 jfric 0.7
bound stress -5e6 0 -5e6
insitu stress -5e6 0 -5e6
damp auto
solve
tunnel 10 10 1.5 16
del ann 10 10 0 1.45
solve
print max
""")
rc, out = run(udec, ["stage.dat"], cwd=d, timeout=120)
check(rc == 0 and re.search(r"TUNNEL: \d+ -> \d+ blocks", out) is not None,
      "a TUNNEL inside the jointed model after BOUNDARY is cut", out[-2000:])
check(len(re.findall(r"SOLVE: balanced", out)) == 2, "both SOLVEs balance", out[-2000:])
m = re.search(r"max normal force\s+(\S+)", out)
# the field: 5e6 Pa on joints of about 1.4 m -> normal forces of the order of 1e6 N
check(m is not None and float(m.group(1)) > 1e6, "the boundary stresses still load the joints", out[-1500:])
finish()
