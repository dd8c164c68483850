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


# A 20 m joint between two fixed zoned blocks (QUAD 0.5: contacts 0.5 m
# apart), aperture 1e-4, kj = 1e8, p = 1 at x = 0 and 0 at x = 20; {fluid}:
# the FLUID line (and SET), {cycles}: the cycles before PRINT FLUID
# (closed_forms_fields.py case 4, closed_forms_hm.py case 3).
JOINT_20 = """round 0.01
bl 0 0 0 1 20 1 20 0
crack 0 0.5 20 0.5
gen quad 0.5
prop mat=1 d=1 k=1e8 g=1e8
prop jmat=1 jkn=1e8 jks=1e8 jperm=1e8 azero=1e-4 ares=1e-4
bound -1 21 -1 2 xvel 0 yvel 0
{fluid}
bound -0.1 0.1 -1 2 pp 1.0
bound 19.9 20.1 -1 2 pp 0.0
cycle {cycles}
print fluid
stop
"""

# Kirsch's hole (a = 1, TUNNEL of 48 sides) in a 16 a quarter square, rollers
# on the axes, INSITU and BOUNDARY STRESS sxx = -5 MPa, syy = -10 MPa, zones
# of 0.15 a inside a glued ring at 3 a and of a outside it; the plug deleted
# after 100 cycles, DAMP AUTO, 12000 cycles (closed_forms_fields.py case 1;
# closed_forms_hm.py case 1 leaves the INSITU out).
KIRSCH_QUARTER = """START
ROUND 0.01
BLOCK 0,0 0,16 16,16 16,0
TUNNEL 0,0 1,48
TUNNEL 0,0 3,48
GEN 0,2.8 0,2.8 AUTO 0.15
GEN 3.5,16 3.5,16 AUTO 1.0
PROP MAT=1 DENS=2500 BULK=1.66667E9 SHEAR=1E9 JKN=1E12 JKS=1E12 JFRIC=1 JCOH=1E10 JTENS=1E10
INSITU STRESS -5E6 0 -1E7
BOUND -.01 16.01 15.99 16.01 STRESS -5E6 0 -1E7
BOUND 15.99 16.01 -.01 16.01 STRESS -5E6 0 -1E7
BOUND -.01 .01 -.01 16.01 XVEL=0
BOUND -.01 16.01 -.01 .01 YVEL=0
DAMP AUTO
CYC 100
DELETE 0,0.6 0,0.6
HIST NCYC 100 XDIS 1,0 YDIS 0,1
CYC 12000
PRINT HIST 1 2
PRINT ZONE STRESS
PRINT ZONE STATE
PRINT GRID
STOP
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


def heated_block(bounds, tail):
    """A 1 x 1 zoned block (QUAD 0.25, K 5e9, G 3e9, THEXP 1e-5) at 0 C,
    the BOUND lines `bounds`, then heated by TFIX 50 throughout; `tail`:
    the lines that run and print it (closed_forms_fields.py case 7,
    closed_forms_hm.py case 4)."""
    return ("THERMAL\nROUND 0.01\nBLOCK 0,0 0,1 1,1 1,0\nGEN QUAD 0.25\n"
            "PROP MAT 1 D 2000 K 5E9 G 3E9 SPEC 1000 COND 2 THEXP 1E-5\n"
            "INITEM 0 -1 2 -1 2\n" + bounds + "TFIX 50 -1 2 -1 2\n" + tail + "STOP\n")


def turned(a):
    """Local (xi, eta) -> global point text, slope angle a (radians)."""
    c, s = math.cos(a), math.sin(a)

    def p(xi, eta):
        return f"{xi * c - eta * s:.6f},{xi * s + eta * c:.6f}"

    def box(xi, eta, h=0.3):
        x, y = xi * c - eta * s, xi * s + eta * c
        return f"{x - h:.4f},{x + h:.4f} {y - h:.4f},{y + h:.4f}"
    return p, box


# campaign round 8, deck 6: a 2 x 1 m rigid block (weight 4e4 N) on a horizontal joint of
# two 1 m contacts, JTEN 5e4 Pa, on a FIXed base, 1000 cycles at rest under DAMP AUTO
# (camp8_decks' ramped pull, sudden_load's pulls given at once)
TENSILE_BLOCK = """ROUND 0.01
BLOCK 0,-1 0,1 4,1 4,-1
CRACK 0,0 4,0
CRACK 1,0 1,1
CRACK 3,0 3,1
DELETE 0 1 0 1
DELETE 3 4 0 1
PROP MAT=1 DENS=2000 K=1E10 G=1E10
PROP JMAT=1 JKN=1E10 JKS=1E10 JFRIC=0.5 JCOH=1E5 JTEN=5E4
FIX 0 4 -1 0
GRAV 0 -10
DAMP AUTO
CYCLE 1000
"""

# A 2 x 1 rigid block on a 6 x 1 base (to be FIXed), horizontal joint at
# y = 1 from x = 2 to 4; the deck's HEAD line goes before it, its PROP,
# FIX and the rest after (closed_forms_r3.py case 6, closed_forms_r4.py
# cases 1 and 6).
BLOCK_ON_BASE = """ROUND 0.01
BLOCK 0,0 0,2 6,2 6,0
CRACK -1,1 7,1
CRACK 2,0.5 2,2.5
CRACK 4,0.5 4,2.5
DELETE 0,2 1,2
DELETE 4,6 1,2
"""


# A column of five 1 x 1 m rigid blocks (density 2000) over a base block, horizontal
# joints JKN = JKS = 1e9 with a tensile strength (closed_forms_r3.py case 1,
# local_damping.py case 1); what follows (FIX of the base, GRAV, DAMP, cycles) is the
# test's.
COLUMN_FIVE = """HEAD a column of five rigid blocks on a fixed base
ROUND 0.01
BLOCK 0,0 0,6 1,6 1,0
CRACK -1,1 2,1
CRACK -1,2 2,2
CRACK -1,3 2,3
CRACK -1,4 2,4
CRACK -1,5 2,5
PROP MAT=1 DENS=2000 JKN=1E9 JKS=1E9 JFRIC=1 JCOH=1E9 JTENS=1E9
"""


def kirsch_boundary_stress(damp, cycles):
    """KIRSCH_QUARTER loaded by BOUNDARY STRESS alone (its INSITU line left out) under
    the DAMP line `damp`, `cycles` cycles after the excavation, then PRINT HIST 1 2
    (closed_forms_hm.py case 1, local_damping.py case 2)."""
    deck = (KIRSCH_QUARTER.replace("INSITU STRESS -5E6 0 -1E7\n", "")
            .replace("DAMP AUTO", damp)
            .replace("CYC 12000\nPRINT HIST 1 2\nPRINT ZONE STRESS\nPRINT ZONE STATE\nPRINT GRID\n",
                     f"CYC {cycles}\nPRINT HIST 1 2\n"))
    assert "INSITU" not in deck and damp in deck and f"CYC {cycles}\n" in deck and "PRINT GRID" not in deck
    return deck


# Kirsch's wall displacements for that deck (a = 1, sxx = -5, syy = -10 MPa, G = 1e9,
# kappa = 2; Jaeger, Cook and Zimmerman, Section 8.4, the far field's displacement
# added): u_r(a) = a (kappa + 1) (P + 2 Q cos 2 theta) / (4 G) at the springline and
# the crown.
KIRSCH_BS_P, KIRSCH_BS_Q = 0.5 * (-5.0e6 - 1.0e7), 0.5 * (-5.0e6 + 1.0e7)
KIRSCH_BS_SPRING = 3.0 * (KIRSCH_BS_P + 2 * KIRSCH_BS_Q) / 4.0e9
KIRSCH_BS_CROWN = 3.0 * (KIRSCH_BS_P - 2 * KIRSCH_BS_Q) / 4.0e9


def check_kirsch_bs(name, out, rows, window, settled):
    """The walls of kirsch_boundary_stress's run (`out`, history every 100 cycles, at
    least `rows` samples) within 1 % of the crown's of Kirsch's, and moving by less
    than `settled` x the crown's over the last `window` samples."""
    from udec_test import check, check_walls, printed_rows
    hist = printed_rows(out, "PRINT HIST 1 2", 3)
    if len(hist) < rows:
        check(False, f"{name}: history printed", out[-2000:])
        return
    ux, uy = hist[-1][1], hist[-1][2]
    moved = max(max(abs(r[1] - ux), abs(r[2] - uy)) for r in hist[-window - 1:])
    check_walls(f"{name}: wall displacements a (kappa + 1) (P + 2 Q cos 2 theta) / (4 G) within 1 % of the crown's",
                ux, uy, KIRSCH_BS_SPRING, KIRSCH_BS_CROWN, 0.01)
    print(f"{name}: moved {100 * moved / abs(KIRSCH_BS_CROWN):.4f} % of the crown's over the last "
          f"{100 * window} cycles")
    check(moved < settled * abs(KIRSCH_BS_CROWN),
          f"{name}: settled (the walls move by < {100 * settled:g} % over {100 * window} cycles)", f"{moved:.3g} m")


# A 2 x 1 rigid block on a joint, cut out of one BLOCK by CRACKs with the
# pieces beside it DELETEd (the lower block spans x -1 .. 3, y -1 .. 0; FIX it
# with FIX -2 4 -1 0). Shared by e2e.camp8_decks (the direct shear test) and
# e2e.camp9_decks (a bolt across the joint).
SHEAR_BOX = """ROUND 0.01
BLOCK -1,-1 -1,1 3,1 3,-1
CRACK -1,0 3,0
CRACK 0,-0.5 0,1.5
CRACK 2,-0.5 2,1.5
DELETE -1 0 0 1
DELETE 2 3 0 1
"""


def jointed_square(size, sets, tunnel, props, stress, bound=True, rounding="0.05"):
    """A square model of side `size` from the origin cut by JSETs (each the
    command's arguments) around TUNNEL `tunnel`, PROP MAT=1 `props`, INSITU
    STRESS `stress` and, with `bound`, BOUNDARY STRESS equal to it: the new
    user's first tunnel deck (campaign rounds 11 and 12)."""
    lines = [f"ROUND {rounding}", f"BLOCK 0,0 0,{size} {size},{size} {size},0"]
    lines += [f"JSET {s}" for s in sets]
    lines += [f"TUNNEL {tunnel}", f"PROP MAT=1 {props}", f"INSITU STRESS {stress}"]
    if bound:
        lines.append(f"BOUND STRESS {stress}")
    return "\n".join(lines) + "\n"
