"""Blocks given INSITU and the same BOUNDARY STRESS stay at rest (rigid; cases 8-13 zoned)
(label stability; the model a rock engineer writes first: a square cut by
two crossing joint sets, a TUNNEL ring, in-situ stress, no excavation yet).

The in-situ stress is the exact answer, so each block's contact forces and
boundary loads must balance at cycle 0 and nothing may move but round-off.
Before the fix they did not (random tunnels of a new-user generator, rigid
blocks, continuous joints):
  - a contact between two rounded corners leans off its joint (its normal
    joins the corners' rounding centres), and INSITU took the traction on
    that normal, not on the joint's: the block's loads no longer closed.
    INSITU also set the forces in the frames of the contact detection, and
    the first CYCLE step turned some contacts' kinds and normals (corner
    against corner to corner against edge) with their forces;
  - the force of a contact acts at its contact point, a rounding length
    inside the end of its joint, while its stretch lies between the corner
    vertices; where the two end stretches of a joint differ (a neighbour's
    corner on the joint) the block got a moment, up to 2e5 N m at 20 MPa.
Now INSITU loads each chain of contacts of one joint (contact_joint_chains)
with the traction on its chord, shares the chord out along it, puts the
forces into the contacts' frames of the first step, and gives each chain its
moment back with a couple on its two end contacts.

Checks (PRINT MAX after 500 cycles; measured after [before] the fix):
1. 20 m square, ROUND 0.02, JSETs at 22.09 and 64.22 degrees (89 blocks,
   down to 33 kg), sxx = -27.8 MPa, syy = -17.2 MPa (random tunnel 403
   without its ring): largest block velocity below 1e-9 m/s [1.1e-12;
   2.4e-3], displacement below 1e-12 m [1.6e-15; 1.0e-5], unbalanced
   force below 1 N [2.9e-6; 1.2e4].
2. the same with its 32-sided TUNNEL ring, before excavation: the same
   bounds [1.1e-12 m/s, 1.6e-15 m, 2.9e-6 N; 2.4e-3, 1.0e-5, 1.2e4].
3. 30 m square, ROUND 0.05, JSETs at -87.61 and -5.92 degrees cutting
   through a 32-sided ring (its plug in pieces): the same bounds [8.1e-13
   m/s, 8.2e-16 m, 8.5e-6 N; 1.0e-4, 6.5e-7, 3.5e3].
4. gravity, INSITU with YGRAD (rho g), rollers on the sides and base,
   BOUNDARY STRESS on the top (random tunnel 0 of the roller generator, no
   ring): velocity below 1e-7 m/s, displacement below 1e-8 m, unbalanced
   force below 10 N, of contact forces of 2e7 N [6.3e-9 m/s, 1.7e-10 m,
   0.07 N; 7.0e-6 m/s, 2.1e-7 m]. Here the traction varies along a
   stretch; INSITU adds its moment about the stretch's centre, w^3/12
   times the traction's gradient along the joint.
5. a 3 cm strip of joint between two rounded corners (ROUND 0.02): a
   10 m square cut by a horizontal joint and two vertical joints 3 cm
   apart, one above and one below; sxx = syy = -10 MPa. The corners at
   the strip's ends lie closer than two rounding lengths, so the strip
   is one corner-corner contact whose normal joins the rounding centres
   (14 degrees off the joint) and which has no neighbour. Before the fix
   it stood for no joint (length 0): the strip's 3e5 N were missing and
   the blocks moved 3.6e-6 m. Bounds as in 1 [1.6e-23 m/s, 8.3e-24 m,
   8.9e-15 N; before 1.5e-12 m/s after settling, 3.6e-6 m].
6. random tunnel 529 (40 m square, ROUND 0.05, a 32-sided ring, its plug
   cut by the sets): a ring chord's last 10 cm (two contacts 3.4 cm
   apart) got the whole couple of its chain, which took one end's normal
   force from 7.2e5 to 3.9e4 N, below its 7.6e4 N shear at JFRIC 0.8: it
   slipped at the first step (4.5e4 N out of balance at cycle 1). Now the
   couple goes on the block pair's two contacts farthest apart. Bounds as
   in 1 [1.7e-12 m/s, 4.6e-15 m, 6.5e-6 N; before 3.8e-5 m/s, 8.5e-7 m,
   525 N].
7. gravity and rollers, three sets and a 24-sided ring (new-user tunnel
   16): a 5 cm chain whose couple left one end at |fs|/fn = 2.5 against
   JFRIC 0.8 (1.1e5 N out of balance at cycle 1). Now the two contacts of
   the couple also trade shear along the line between them (no net force
   or moment) until their ratios of shear to normal force are equal.
   Reference: the elastic joint closure under one block's weight,
   W / (JKN L) = 7.9e4 N / (2e11 Pa/m x 0.8 m) = 5e-7 m; INSITU must
   leave under 2 % of it, 1e-8 m, and an unbalanced force under 1e3 N,
   1.3 % of that weight [4.7e-10 m, 13 N, 5.7e-7 m/s: the rollers
   reactions settling, gone by cycle 7500; before 1.7e-7 m, 3.0e3 N,
   7.4e-5 m/s].
8. the strip of 5 with zoned blocks (GEN EDGE 1, K 2e10, G 1.2e10): the
   strip's contact between two gridpoint corners now takes the strip's
   load too. Reference: the missing load F = 3e5 N over the shear modulus,
   F / G = 2.4e-5 m, is the scale of the error (2.2e-5 m measured before
   the fix); bound 2e-6 m of gridpoint displacement after 500 cycles
   [4.5e-7 m: the strip's load sits on its two corner gridpoints, not
   spread along the 3 cm; the same model with the joints 0.5 m apart
   rests to 5e-18 m].
9. zoned blocks (GEN EDGE 2, K 2e10, G 1.2e10), gravity, INSITU with
   YGRAD (rho g), rollers, the top's BOUNDARY STRESS the field there, a
   joint set at 45 degrees: the traction varies along the joints. A
   gridpoint's zones take from it the traction weighted by its hat
   function; INSITU took it at the stretch's centre, and where the
   gridpoint spacing changed (1 m to 2 m) the two differ by
   w (b - a)/4 (1/3) dt/ds = 1.6e3 N. Bounds: gridpoint velocity below
   1e-12 m/s and displacement below 1e-14 m at cycles 1 and 500 [5.7e-15
   m/s, 4.4e-17 m; before 1.6e-4 m/s and 1.2e-8 m at cycle 1, 1.8e3 N].
   The same model without joints rests to 5e-16 m/s.
10. as 9 with one vertical joint (crack at x = 10): the same bounds
   [before 9.4e-5 m/s and 1.2e-8 m; 1.6e3 N at cycle 1].
11-12. random zoned tunnels with gravity (genu 221: a horseshoe, finite
   joints; genu 228: a 32-sided ring cut by two sets): at junctions of
   three or more blocks and where a ring chord meets a joint the contacts'
   gridpoints took 2.6e4 N more or less than their zones put on them.
   INSITU now corrects the zoned contacts' forces one at a time (least
   squares of the joint gridpoints' out-of-balance forces, the engine's
   pair couple included) until those forces are round-off. Bounds at cycle
   1: gridpoint velocity below 1e-12 m/s, displacement below 1e-16 m
   [221: 1.6e-14 m/s, 6.4e-20 m, 3.4e-7 N; before 5.0e-5 m/s, 1.9e-10 m,
   2.6e4 N. 228: 3.9e-14 m/s, 4.8e-19 m, 2.3e-7 N; before 2.8e-3 m/s,
   3.5e-8 m, 2.6e4 N].
13. zoned slivers (genu 127, uniform stress): two zone edges of 1 cm on
   block edges, under ROUND / 2 (GENERATE warns). The corrected contact
   forces of 11-12 give the sliver's gridpoints their loads too: 7.6 N
   left at cycle 1 [before 2.0e5 N]. The gridpoints weigh little, so the
   bound is on the velocity at cycle 1: below 1e-3 m/s [5.1e-5 m/s;
   before 1.8 m/s].
The bounds are round-off with a wide margin: a gap's round-off (1e-15 m)
times the joint stiffness (1e10-2e11 Pa/m) times a contact length (1 m)
is 1e-5 to 1e-4 N.
"""
import re
import sys
from udec_test import check, finish, run, workdir, write

udec = sys.argv[1]

SETS_403 = """round 0.02
block 0,0 0,20 20,20 20,0
jset 22.09,0 200,0 0,0 1.90,0 (13.06,17.60)
jset 64.22,0 200,0 0,0 2.17,0 (18.28,2.98)
{tunnel}
prop mat=1 d=2600
prop jmat=1 jkn=1e10 jks=5e9 jfric=1.2
insitu stress -2.77688e7 0 -1.71762e7
bound stress -2.77688e7 0 -1.71762e7
damp auto
cycle 500
print max
stop
"""

TUNNEL_184 = """round 0.05
block 0,0 0,30 30,30 30,0
jset -87.61,0 200,0 0,0 3.82,0 (2.03,18.84)
jset -5.92,0 200,0 0,0 2.31,0 (4.69,23.44)
tunnel 15.237 15.854 2.260 32
prop mat=1 d=2600
prop jmat=1 jkn=2e11 jks=1e11 jfric=0.8
insitu stress -1.09e7 0 -1.6e7
bound stress -1.09e7 0 -1.6e7
damp auto
cycle 500
print max
stop
"""

GRAVITY = """round 0.1
block 0,0 0,30 30,30 30,0
jset 45.92,0 200,0 0,0 2.15,0 (29.48,24.31)
jset -68.85,0 200,0 0,0 2.78,0 (27.06,9.30)
prop mat=1 d=2600
prop jmat=1 jkn=2e11 jks=1e11 jfric=1
grav 0 -9.81
insitu stress -4.58783e6 0 -6.69715e6 ygrad 12753 0 25506
bound -1,31 29.9,30.1 stress -4.20524e6 0 -5.93197e6
bound -0.1,0.1 -1,31 xvel 0
bound 29.9,30.1 -1,31 xvel 0
bound -1,31 -0.1,0.1 yvel 0
damp auto
cycle 500
print max
stop
"""

STRIP = """round 0.02
block 0,0 0,10 10,10 10,0
crack 0,5 10,5
crack 5,5 5,10
crack 5.03,0 5.03,5
prop mat=1 d=2600
prop jmat=1 jkn=1e10 jks=5e9 jfric=0.6
insitu stress -1e7 0 -1e7
bound stress -1e7 0 -1e7
damp auto
cycle 500
print max
stop
"""

TUNNEL_529 = """round 0.05
block 0,0 0,40 40,40 40,0
jset 76.61,0 200,0 0,0 3.57,0 (16.35,21.75)
jset -18.74,0 200,0 0,0 3.93,0 (33.69,12.91)
tunnel 19.408 19.450 3.847 32
prop mat=1 d=2600
prop jmat=1 jkn=1e10 jks=5e9 jfric=0.8
insitu stress -5.95561e6 0 -8.89294e6
bound stress -5.95561e6 0 -8.89294e6
damp auto
cycle 500
print max
stop
"""

GRAVITY_16 = """round 0.05
block 0,0 0,30 30,30 30,0
jset -16.80,0 200,0 0,0 3.43,0 (19.36,7.85)
jset 51.30,0 200,0 0,0 1.63,0 (23.92,4.59)
jset -72.35,0 200,0 0,0 2.23,0 (5.50,21.76)
tunnel 15.737 14.707 2.497 24
prop mat=1 d=2600
prop jmat=1 jkn=2e11 jks=1e11 jfric=0.8
grav 0 -9.81
insitu stress -2.557e7 0 -1.42799e7 ygrad 12753 0 25506
bound -1,31 29.9,30.1 stress -2.51874e7 0 -1.35147e7
bound -0.1,0.1 -1,31 xvel 0
bound 29.9,30.1 -1,31 xvel 0
bound -1,31 -0.1,0.1 yvel 0
damp auto
cycle 500
print max
stop
"""

STRIP_ZONED = STRIP.replace("prop mat=1 d=2600", "gen edge 1.0\nprop mat=1 d=2600 k=2e10 g=1.2e10")

# 9-10: zoned, gravity, INSITU with YGRAD, the top's BOUNDARY STRESS the
# field's value there (syy = -1e7 + 25506 x 20 = -9.48988e6 Pa)
ZONED_GRAVITY = """round 0.05
block 0,0 0,20 20,20 20,0
{joints}
gen edge 2.0
prop mat=1 d=2600 k=2e10 g=1.2e10
prop jmat=1 jkn=5e10 jks=2.5e10 jfric=0.8
grav 0 -9.81
insitu stress -5e6 0 -1e7 ygrad 12753 0 25506
bound -1,21 19.9,20.1 stress -4744940 0 -9489880
bound -0.1,0.1 -1,21 xvel 0
bound 19.9,20.1 -1,21 xvel 0
bound -1,21 -0.1,0.1 yvel 0
damp auto
cycle 1
print max
cycle 499
print max
stop
"""

# 11-12: random zoned tunnels with gravity (new-user generator genu, seeds
# 221 and 228), the top's BOUNDARY STRESS the field's value there
TUNNEL_221 = """round 0.05
block 0,0 0,30 30,30 30,0
jset -59.88,0 200.00,0 0.00,0 1.55,0 (19.89,11.27)
jset 26.05,0 5.09,0 0.79,0 3.39,0 (26.60,14.60)
crack 12.392,12.142 18.851,12.142
crack 12.392,12.142 12.392,15.372
crack 18.851,12.142 18.851,15.372
arc 15.621 15.372 18.851 15.372 180 12
gen edge 2.00
prop mat=1 d=2600 k=2e10 g=1.2e10
prop jmat=1 jkn=5e+10 jks=2.5e+10 jfric=0.6
grav 0 -9.81
insitu stress -2.55801e+07 0 -1.38781e+07 ygrad 12753 0 25506
bound -1,31 29.9,30.1 stress -25197510 0 -13112920
bound -0.1,0.1 -1,31 xvel 0
bound 29.9,30.1 -1,31 xvel 0
bound -1,31 -0.1,0.1 yvel 0
damp auto
cycle 1
print max
stop
"""

TUNNEL_228 = """round 0.05
block 0,0 0,20 20,20 20,0
jset 86.77,0 200.00,0 0.00,0 3.41,0 (14.72,15.73)
jset -3.70,0 200.00,0 0.00,0 3.64,0 (12.67,1.66)
tunnel 10.880 9.920 2.216 32
gen edge 3.00
prop mat=1 d=2600 k=2e10 g=1.2e10
prop jmat=1 jkn=1e+10 jks=5e+09 jfric=0.6
grav 0 -9.81
insitu stress -1.15436e+07 0 -1.75126e+07 ygrad 12753 0 25506
bound -1,21 19.9,20.1 stress -11288540 0 -17002480
bound -0.1,0.1 -1,21 xvel 0
bound 19.9,20.1 -1,21 xvel 0
bound -1,21 -0.1,0.1 yvel 0
damp auto
cycle 1
print max
stop
"""

# 13: zoned slivers (genu 127): zone edges of 1 cm on block edges, under
# ROUND / 2, where a neighbour's rounded corner spans several gridpoints
SLIVER_127 = """round 0.02
block 0,0 0,20 20,20 20,0
jset -89.01,0 200.00,0 0.00,0 3.56,0 (15.79,8.62)
jset -32.41,0 200.00,0 0.00,0 2.42,0 (0.68,14.91)
jset 38.43,0 200.00,0 0.00,0 2.57,0 (12.78,6.78)
crack 8.572,8.894 12.116,8.894
crack 8.572,8.894 8.572,10.666
crack 12.116,8.894 12.116,10.666
arc 10.344 10.666 12.116 10.666 180 12
gen edge 1.50
prop mat=1 d=2600 k=2e10 g=1.2e10
prop jmat=1 jkn=1e+10 jks=5e+09 jfric=1
insitu stress -2.10949e+07 -162950 -1.41122e+07
bound stress -2.10949e+07 -162950 -1.41122e+07
damp auto
cycle 1
print max
stop
"""

BV, BU, UF = "max block velocity", "max block displacement", "max unbalanced force"
GV, GU = "max gridpoint velocity", "max gridpoint displacement"
RIGID_REST = {BV: 1e-9, BU: 1e-12, UF: 1.0}

# (name, deck, {PRINT MAX line: bound}); the largest value over the deck's
# PRINT MAXes must lie below the bound
CASES = [
    ("1 crossing sets", SETS_403.format(tunnel=""), RIGID_REST),
    ("2 crossing sets and ring", SETS_403.format(tunnel="tunnel 9.955 10.977 2.302 32"), RIGID_REST),
    ("3 tunnel 184", TUNNEL_184, RIGID_REST),
    ("4 gravity and rollers", GRAVITY, {BV: 1e-7, BU: 1e-8, UF: 10.0}),
    ("5 strip between two rounded corners", STRIP, RIGID_REST),
    ("6 tunnel 529", TUNNEL_529, RIGID_REST),
    ("7 gravity, rollers, tunnel 16", GRAVITY_16, {BV: 1e-5, BU: 1e-8, UF: 1e3}),
    ("8 zoned strip", STRIP_ZONED, {GU: 2e-6}),
    ("9 zoned, gravity, a 45-degree set", ZONED_GRAVITY.format(joints="jset 45,0 200,0 0,0 3,0 (10,10)"),
     {GV: 1e-12, GU: 1e-14}),
    ("10 zoned, gravity, one vertical joint", ZONED_GRAVITY.format(joints="crack 10,0 10,20"),
     {GV: 1e-12, GU: 1e-14}),
    ("11 zoned tunnel 221, gravity", TUNNEL_221, {GV: 1e-12, GU: 1e-16}),
    ("12 zoned tunnel 228, gravity", TUNNEL_228, {GV: 1e-12, GU: 1e-16}),
    ("13 zoned slivers, genu 127", SLIVER_127, {GV: 1e-3}),
]


def largest(out, key):
    """The largest value of PRINT MAX's line `key` in the output."""
    m = re.findall(r"^\s*" + key + r"\s+(\S+)", out, re.M)
    return max(float(x) for x in m) if m else None


for name, text, bounds in CASES:
    folder = workdir()
    write(folder, "t.dat", text)
    rc, out = run(udec, ["t.dat"], cwd=folder, timeout=120)
    check(rc == 0 and "*** Error" not in out, f"{name}: runs", out[-2000:])
    for key, bound in bounds.items():
        v = largest(out, key)
        print(name, key, v)
        check(v is not None and v < bound, f"{name}: {key} {v} < {bound}")
finish()
