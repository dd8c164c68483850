"""Units that do not agree announce themselves (label e2e; UDEC manual
(ICG1.5, 1989), Section 4.1, Table 4-1: any consistent set of units, no
conversions; with stresses in MPa the density is in 10^6 kg/m3).

A new user wrote moduli in MPa (K 16667, G 12500, JKN 2e4) with a density
of 2700 (kg/m3) and GRAVITY 0 -9.81: the weight at the foot of the 20 m
model, rho g H = 5.3e5 "MPa", stopped the second step on Contact Overlap
Too Great with no word of units. Checked: the first CYCLE says the material
would strain by rho g H / E (17.7 here, E = 9 K G / (3 K + G) = 30 000) and
names Table 4-1; the overlap headroom note counts the weight (JKN x ROUND =
400 against 5.3e5). The same deck with the density in 10^6 kg/m3 (2.7e-3)
gets neither note and SOLVE balances (ratio 1e-5); strain 1.8e-5 there.
"""
import re
import sys
from udec_test import check, finish, run, workdir, write

udec = sys.argv[1]
d = workdir()
DECK = """round 0.02
block 0,0 0,20 20,20 20,0
jset 45,0 40,0 0,0 4,0 (0,0)
jset -45,0 40,0 0,0 4,0 (0,0)
gen edge 2
prop mat 1 d {dens} k 16667 g 12500
prop jmat 1 jkn 2e4 jks 2e4 jfric 0.7
grav 0 -9.81
bound 0,20 -.1,.1 yvel 0
bound -.1,.1 0,20 xvel 0
bound 19.9,20.1 0,20 xvel 0
damp auto
{run}
stop
"""
write(d, "bad.dat", DECK.format(dens="2700", run="cycle 1"))
rc, out = run(udec, ["bad.dat"], cwd=d)
note = re.search(r"CYCLE: note: under its own weight material 1 would strain by rho g H / E = (\S+) "
                 r"over the model's height H: are the units consistent\? \(manual Table 4-1", out)
check(note is not None, "kg/m3 density with MPa moduli: the units note", out[-2000:])
if note:
    # 2700 x 9.81 x 20 / 30000 = 17.66 (E = 9 K G / (3 K + G) = 30 000 exactly)
    check(abs(float(note.group(1)) - 17.658) < 0.01, "the strain is rho g H / E = 17.66", note.group(0))
check(re.search(r"CYCLE: note: the joints of material 1 take a normal stress change of JKN x ROUND "
                r"= 4\.000E\+02 .*largest stress in the model \(5\.29\dE\+05\)", out) is not None,
      "the headroom note counts the weight's stress rho g H", out[-2000:])
write(d, "good.dat", DECK.format(dens="2.7e-3", run="solve"))
rc, out = run(udec, ["good.dat"], cwd=d)
check(rc == 0 and "SOLVE: balanced" in out, "density in 10^6 kg/m3: SOLVE balances", out[-1500:])
check("units consistent" not in out and "before Contact Overlap Too Great" not in out,
      "consistent units: no units note, no headroom note", out[-1500:])
finish()
