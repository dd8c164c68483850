"""Rigid blocks given INSITU and the same BOUNDARY STRESS stay at rest
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


def maxima(out):
    """PRINT MAX's block velocity, displacement and unbalanced force."""
    get = {}
    for key in ("max block velocity", "max block displacement", "max unbalanced force"):
        m = re.findall(r"^\s*" + key + r"\s+(\S+)", out, re.M)
        get[key] = float(m[-1]) if m else None
    return get


def case(name, text, vmax, umax, fmax):
    folder = workdir()
    write(folder, "t.dat", text)
    rc, out = run(udec, ["t.dat"], cwd=folder, timeout=120)
    check(rc == 0 and "*** Error" not in out, f"{name}: runs", out[-2000:])
    m = maxima(out)
    print(name, m)
    v, u, f = (m["max block velocity"], m["max block displacement"], m["max unbalanced force"])
    check(v is not None and v < vmax, f"{name}: max block velocity {v} < {vmax} m/s")
    if umax is not None:
        check(u is not None and u < umax, f"{name}: max block displacement {u} < {umax} m")
    check(f is not None and f < fmax, f"{name}: max unbalanced force {f} < {fmax} N")


case("1 crossing sets", SETS_403.format(tunnel=""), 1e-9, 1e-12, 1.0)
case("2 crossing sets and ring", SETS_403.format(tunnel="tunnel 9.955 10.977 2.302 32"),
     1e-9, 1e-12, 1.0)
case("3 tunnel 184", TUNNEL_184, 1e-9, 1e-12, 1.0)
case("4 gravity and rollers", GRAVITY, 1e-7, 1e-8, 10.0)
finish()
