"""A fractured JCONS 5 joint stays fractured when its blocks separate and
touch again (label e2e).

UDEC manual (ICG1.5, 1989), Section 4.5, CHANGE, the JCONS table: JCONS 5
is JCONS 2 "except that internal fracture flag is set for each joint
segment when joint shear or tensile strength is exceeded. If fracture flag
is set, then cohesion and tension are ignored in all subsequent
calculations."

Before the fix, contact detection re-created the contacts of a pair of
blocks that had separated with the defaults: JCONS 2 (the CHANGE JCONS 5
was lost) and no fracture flag, so the broken joint had its JCOH and JTEN
back. (JCONS 2 itself keeps its strength by the manual's table: only
JCONS 5 records a fracture.)

The deck: a 2 m x 2 m square cut at y = 1, the lower block fixed; joint
JKN = JKS = 1e9 Pa/m, JCOH 1e6 Pa, JTEN 1e5 Pa, CHANGE JCONS 5.
1. GRAV 0 50 pulls the upper block (5200 kg) off: 2.6e5 N on 2 m is
   1.3e5 Pa of tension > JTEN, the joint fractures and the block flies
   (its contacts are broken once the gap exceeds twice ROUND).
2. GRAV 0 -50 brings it back; it lands and settles; GRAV 0 0 unloads it.
3. GRAV 0 10: 5.2e4 N of tension, 2.6e4 Pa on the joint, twice that at
   the dynamic peak: below JTEN, so an intact joint holds the block at
   the elastic stretch W / (2 JKN L) = 5.2e4 / (2 x 1e9 x 1) = 2.6e-5 m
   (measured before the fix: 2.6e-5 m, contacts JCONS 2). The fractured
   joint has no tension: the block leaves, 0.5 g t^2 = 2.9 m in the
   0.77 s of 2000 steps without damping losses (2.08 m measured with DAMP
   AUTO on). Checks: the re-made contacts are JCONS 5 with the fracture
   flag (state F) and the block rises more than 0.5 m.
"""
import re
import sys
from udec_test import check, finish, run, workdir, write

udec = sys.argv[1]

DECK = """round 0.02
block 0,0 0,2 2,2 2,0
crack 0,1 2,1
prop mat=1 d=2600
prop jmat=1 jkn=1e9 jks=1e9 jfric=0.5 jcoh=1e6 jten=1e5
change jcons=5
fix 0,2 0,1
grav 0 50
cycle 300
print max
grav 0 -50
damp auto
cycle 3000
grav 0 0
cycle 3000
print contacts
reset disp
grav 0 10
cycle 2000
print max
stop
"""

folder = workdir()
write(folder, "t.dat", DECK)
rc, out = run(udec, ["t.dat"], cwd=folder, timeout=120)
check(rc == 0 and "*** Error" not in out, "deck runs", out[-2000:])
ncont = [int(x) for x in re.findall(r"number of contacts\s+(\d+)", out)]
check(len(ncont) == 2 and ncont[0] == 0, f"1: the joint broke and its contacts went ({ncont})")
rows = re.findall(r"^\s*\d+\s+1\s+2\s+\d\s+(\d+)\s+(\d+)\s+\S+\s+\S+\s+\S+\s+\S+\s+\d+\s+\d+\s+(\S+)",
                  out, re.M)
print("re-made contacts (JMAT, JCONS, STATE):", rows)
check(len(rows) >= 2, "2: the block landed and has contacts again", out[-3000:])
check(all(r[1] == "5" for r in rows), f"2: the re-made contacts keep JCONS 5 ({rows})")
check(all(r[2].endswith("F") for r in rows), f"2: the re-made contacts are fractured ({rows})")
disp = re.findall(r"max block displacement\s+(\S+)", out)
u = float(disp[-1]) if disp else None
print("displacement under GRAV 0 10:", u)
check(u is not None and u > 0.5, f"3: the fractured joint lets the block go: {u} > 0.5 m "
      "(held at 2.6e-5 m before the fix)")
finish()
