"""Decks that more than one script test runs, each checking the same model
against a different closed form (written from the manual's Section 4.5
syntax; the closed forms are stated where they are checked)."""
import math


# One joint between two reservoirs: rigid blocks fixed, constant aperture
# 1e-4, kj = 1e8, pressures 1 and 0 at the ends of the 2 m joint (fluid_flow.py
# case 1, closed_forms_fields.py case 5). {set}: SET SFLOW or -SFLOW.
JOINT_FLOW = """round 0.01
bl 0 0 0 1 2 1 2 0
crack 0 0.5 2 0.5
prop mat=1 d=1 jkn=100 jks=100 jperm=1e8 azero=1e-4 ares=1e-4
fix -1 3 -1 2
fluid 1.0 100
{set}
bound -0.1 0.1 -1 2 pp 1.0
bound 1.9 2.1 -1 2 pp 0.0
cycle 50
print flows
print fluid
stop
"""


def spring_block(damp="", cycles=450):
    """A 10 x 1 rigid block (m = 2e4 kg) set on a horizontal joint (JKN 1e8
    over 10 m: K = 1e9 N/m) under gravity, free to swing on it; history 1 is
    the y displacement of its top corner, every cycle (probe_rigid_decks.py
    case 8, closed_forms_fields.py case 3). damp: a DAMP line (with its
    newline) or nothing."""
    return f"""round 0.02
block 0,0 0,2 10,2 10,0
split 0,1 10,1
fix 0,10 0,1
prop mat=1 dens=2000
prop jmat=1 jkn=1e8 jks=1e8 jfric=0.5
grav 0 -10
{damp}hist ncyc 1 ydis 10,2
cycle {cycles}
print hist 1
stop
"""


def salencon_tunnel(size, ring, outer_zone, steps, step_cycles, prints):
    """A circular tunnel (a = 1, 48 sides) in a Mohr-Coulomb medium (c = 1
    MPa, phi = 30 degrees, DIL = 0, K = 2e9, G = 1e9), quarter model `size`
    square with rollers on the axes, a glued ring joint at r = `ring`
    between AUTO 0.15 zones inside and AUTO `outer_zone` outside, p0 = 10
    MPa (INSITU and BOUND STRESS); the wall pressure lowered to 1 MPa in
    `steps` equal steps of `step_cycles` cycles, then 6000 more cycles and
    the `prints` lines (probe_plastic_decks.py case 2, closed_forms_fields.py
    case 9). The rollers are given again after each wall BOUND STRESS
    (manual: STRESS cancels an earlier XVEL / YVEL)."""
    hi, lo = f"{size + 0.01:g}", f"{size - 0.01:g}"
    roll = f"BOUND -.01 .01 -.01 {hi} XVEL=0\nBOUND -.01 {hi} -.01 .01 YVEL=0\n"
    step = f"{9e6 / steps:.4G}".replace("E+0", "E").replace("E+", "E")
    return f"""START
ROUND 0.01
BLOCK 0,0 0,{size:g} {size:g},{size:g} {size:g},0
TUNNEL 0,0 1,48
TUNNEL 0,0 {ring:g},48
DELETE 0,0.6 0,0.6
GEN 0,{ring - 0.3:g} 0,{ring - 0.3:g} AUTO 0.15
GEN {ring + 0.5:g},{size:g} {ring + 0.5:g},{size:g} AUTO {outer_zone:g}
CHANGE CONS=3
PROP MAT=1 DENS=2500 BULK=2E9 SHEAR=1E9 COH=1E6 FRIC=0.57735 DIL=0 JKN=1E12 JKS=1E12 JFRIC=1 JCOH=1E10 JTENS=1E10
INSITU STRESS -1E7 0 -1E7
BOUND -.01 {hi} {lo} {hi} STRESS -1E7 0 -1E7
BOUND {lo} {hi} -.01 {hi} STRESS -1E7 0 -1E7
BOUND -1.1 1.1 -1.1 1.1 STRESS -1E7 0 -1E7
""" + roll + "DAMP AUTO\nCYC 200\n" + \
        (f"BOUND -1.1 1.1 -1.1 1.1 STRESS {step} 0 {step}\n" + roll + f"CYC {step_cycles}\n") * steps + \
        "CYC 6000\n" + "".join(p + "\n" for p in prints) + "STOP\n"


def turned(a):
    """Local (xi, eta) -> global point text, slope angle a (radians)."""
    c, s = math.cos(a), math.sin(a)

    def p(xi, eta):
        return f"{xi * c - eta * s:.6f},{xi * s + eta * c:.6f}"

    def box(xi, eta, h=0.3):
        x, y = xi * c - eta * s, xi * s + eta * c
        return f"{x - h:.4f},{x + h:.4f} {y - h:.4f},{y + h:.4f}"
    return p, box
