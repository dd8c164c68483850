"""New users' decks of campaign round 7 (zoned blocks, structures, water,
heat), each written from the UDEC manual (ICG1.5, 1989) Sections 4 and 7
alone, checked against a closed form. Each case failed before its fix.

1. Steady conduction through a wall cut by a joint (Section 7.4: THERMAL,
   GEN EDGE, TFIX, THAPP CONV, RUN with the default TOL 0.1): two zoned
   blocks 1 m x 0.5 m side by side, T = 100 held on the left face, the right
   face convecting (h = 10 W/m2K) to 0. One-dimensional steady state
   (series resistances L/k + 1/h, k = 2 W/mK, L = 2 m):
     q = 100 / (L/k + 1/h) = 90.909 W/m2, T(2) = q/h = 9.0909,
     T(1) = 100 - q (1 m)/k = 54.545 at every point of the joint.
   Linear triangles hold a linear field exactly, so the check is 1e-4 C
   (the explicit run's residual transient after 6 diffusion times is below
   1e-5 C). Before: GEN EDGE 0.2 puts boundary gridpoints 0.1 m from the
   joint's ends; RUN's TOL 0.1 merged them with the other block's joint
   point and so, chained, with their own block's neighbour: the joint was
   short-circuited along the top and bottom faces, T(2) read 9.29 (+2.2 %)
   and the joint 54.3 to 56.9 (the mesh must merge only coincident points,
   never two points of one block).
2. DAMP 0 (a dynamic stage switched to no damping, as a user types it;
   the manual's form is DAMP fcrit freq, and fcrit 0 means no damping
   whatever freq): PRINT STATUS says "none". Before: refused, "expected a
   real number >= 0 (line ended)". DAMP 0.05 alone (a damping without its
   frequency) stays refused.
3. BOUNDARY XFREE after XVEL frees the points as asked: no warning that "the
   stress or load replaces a prescribed XVEL" (there was no stress or
   load); a STRESS after XVEL still warns.
4. A liner on the arch of a horseshoe (half ARC over three CRACKs, the
   manual's Fig. 3-12 way, horizontal CRACKs out from the springlines),
   STRUCT xc yc 0 rrange 12 mat thick 180 right after the excavation, zoned
   rock under a hydrostatic 5 MPa. Statics of an end node (no load on the
   node but its element and its interface): the interface force equals the
   end element's force; the arch's end nodes sit on vertical walls, so the
   end thrust goes into the interface's shear: |s-force| = thrust within
   2 % (the element's own shear and the node's inertia at the end of the
   run). Every interface intact, every element in compression, the two end
   thrusts within 15 % of each other (the ring is symmetric; the zoning is
   not). Before: an end node stepped past the arch's last edge onto the
   joint face below it (turned 90 degrees) and measured its interface
   along that face: here the first end node's interface force stopped
   balancing its element; with GEN EDGE 1.5 the other end read its drift
   along the wall as an opening of 1.2 mm, broke its interface and the end
   element carried -0.08 N.
5. A rectangle of four CRACKs inside the one block (a new user's opening):
   the fourth closes a loop of partial cracks, which is keyed as a TUNNEL
   ring is (session 41, docs/geometry.md; before, it cut nothing and DELETE
   of its inside took the whole block, and session 40's note then had to
   say that nothing remained). Now the rectangle is a block of 8 x 4 =
   32 m2 that DELETE of its range takes alone, with no note of blocks
   reaching across the model.
6. INSITU under SET -EFF (Section 4.5, INSITU: "If total pressure option
   has been selected (i.e., SET -EFF), then in-situ fluid pressures are also
   initialized"): four rigid blocks of a 10 m square, water table at the top
   (y = 0), rhow 1000, g 10, total stress syy = 26000 y. Every domain gets
   p = rhow g (0 - y) exactly (printed to six digits: 25000, 50000,
   75000), the horizontal joint at y = -5 carries the effective stress
   130000 - 50000 = 80000 (0.1 %), and with the sides on rollers and the
   boundary impermeable the model stays at rest for 200 cycles (pressures
   within 1e-4 of hydrostatic, block speed below 1e-9 m/s). Before: every
   domain read 0 (the joints carried the total stress, the water none).
7. An S-wave pulse (BOUND STRESS 0 -3E5 0 XHIS SINE 10 0.1: one period) at
   the viscous base of a zoned 40 m column, CYCLE past the pulse's end, then
   CYCLE again: the base carries no load afterwards (every FX below 1 N) and
   the top moves at most 0.01 m/s (the pulse's particle velocity is 0.2
   m/s peak). The same with XHIS LINEAR keeps the whole stress (the ramp's
   end value). Before: the whole increment stayed as a static shear load
   after the pulse (the manual's Note read literally) and the column slid
   at 0.1 m/s on its dashpots without end; a stress whose XHIS and YHIS
   differ kept half of it.
8. MSCALE PART tdel with tdel below the model's own step (Section 4.5:
   "density scaling only to those zones necessary to achieve time-step
   tdel"): the step is tdel, so CYCLE 100 covers 100 tdel. Before: the
   model's larger step was run (accur, session 40: 6.8e-4 s asked in
   Application D, more time covered than asked).
"""
import os
import re
import sys
sys.path.insert(0, os.path.dirname(__file__))
from udec_test import check, finish, run, run_clean, printed_rows  # noqa: E402

udec = sys.argv[1]

WALL = """THERMAL
ROUND 0.005
BLOCK 0,0 0,0.5 2,0.5 2,0
SPLIT 1,-1 1,2
PROP MAT=1 DENS=2500 K=6.667E9 G=4E9 COND=2 SPEC=1000 THEXP=1E-5
PROP JMAT=1 JKN=1E11 JKS=1E11 JFRIC=0.6 JCOH=1E7 JTEN=1E7
GEN EDGE 0.2
INITEM 20 -1 3 -1 1
TFIX 100 -0.01 0.01 -1 1
THAPP 1.99 2.01 -1 1 CONV 10 0
RUN AGE 3E7 TEMP 1000 STEP 100000
PRINT TEMP 1.95 2.05 -1 1
PRINT TEMP 0.95 1.05 -1 1
STOP
"""


def wall():
    out = run_clean(udec, "wall_joint", WALL)
    q = 100.0 / (2.0 / 2.0 + 1.0 / 10.0)
    rows = printed_rows(out, "PRINT TEMP 1.95 2.05 -1 1", 5)   # both tables
    face = [r for r in rows if r[2] > 1.9]
    joint = [r for r in rows if r[2] < 1.1]
    print("face", [r[4] for r in face], "joint", [r[4] for r in joint])
    check(len(face) == 4 and all(abs(r[4] - q / 10.0) < 1e-4 for r in face),
          "wall: convecting face at q/h = 9.0909", str(face))
    check(len(joint) == 8 and all(abs(r[4] - (100.0 - q / 2.0)) < 1e-4 for r in joint),
          "wall: the joint at 100 - q L/k = 54.545 on both sides", str(joint))


def damp_and_free():
    rc, out = run(udec, [], stdin_text="DAMP AUTO\nDAMP 0\nPRINT STATUS\nDAMP 0.05\n"
                  "ROUND 0.01\nBLOCK 0,0 0,1 1,1 1,0\nGEN QUAD 0.5\n"
                  "BOUND -0.1 0.1 -1 2 XVEL 0\nBOUND -0.1 0.1 -1 2 XFREE\n"
                  "BOUND 0.9 1.1 -1 2 XVEL 0\nBOUND 0.9 1.1 -1 2 STRESS -1E6 0 0\nSTOP\n")
    status = [l for l in out.splitlines() if l.strip().startswith("damping")]
    check(status and status[-1].split()[-1] == "none", "DAMP 0: no damping", "\n".join(status) or out[-2000:])
    errors = [l for l in out.splitlines() if "*** Error" in l]
    check(len(errors) == 1 and "DAMPING" in errors[0] and "fcrit freq" in errors[0],
          "DAMP 0.05: refused, naming fcrit freq (the only error)", "\n".join(errors))
    warns = [l for l in out.splitlines() if "replaces a prescribed" in l]
    check(len(warns) == 1 and "(1.0" in warns[0].replace(" ", ""),
          "XFREE: no warning; STRESS after XVEL on the right side: one", "\n".join(warns))


HORSESHOE = """ROUND 0.02
BLOCK -20,-20 -20,20 20,20 20,-20
ARC 0,0 3,0 180 12
CRACK 3,0 3,-3
CRACK 3,-3 -3,-3
CRACK -3,-3 -3,0
CRACK -20,0 -3,0
CRACK 3,0 20,0
PROP MAT=1 DENS=2600 K=16.67E9 G=10E9
PROP JMAT=1 JKN=1E11 JKS=1E11 JFRIC=1 JCOH=1E7 JTEN=1E7
GEN EDGE 2.5
INSITU STRESS -5E6 0 -5E6
BOUND STRESS -5E6 0 -5E6
DAMP AUTO
DELETE -2.9 2.9 -2.9 2.9
PROP MAT=5 DENS=2500 K=16.67E9 G=12.5E9 KN=1E12 KS=1E12 CFRIC=1 CCOH=1E9 CTENS=1E9
STRUCT 0,0 0 3.5 12 5 0.3 180
CYCLE 3000
PRINT STE
PRINT STC
STOP
"""


def horseshoe_liner():
    out = run_clean(udec, "horseshoe_liner", HORSESHOE)
    ste = out.split("PRINT STE")[-1].split("PRINT STC")[0]
    axial = [float(l.split()[6]) for l in ste.splitlines()
             if len(l.split()) == 10 and l.split()[0].isdigit()]
    stc = out.split("PRINT STC")[-1]
    iface = [l.split() for l in stc.splitlines() if len(l.split()) == 10 and l.split()[0].isdigit()]
    print("thrusts", [f"{-a:.4g}" for a in axial])
    check(len(axial) == 12 and all(a < 0.0 for a in axial), "horseshoe: 12 elements in compression", str(axial))
    check(len(iface) == 13 and all(f[9] != "broken" for f in iface), "horseshoe: no interface broken",
          "\n".join(" ".join(f) for f in iface))
    if len(axial) == 12 and len(iface) == 13:
        for e, n in ((0, 0), (11, 12)):
            fs = abs(float(iface[n][6]))
            check(abs(fs - abs(axial[e])) < 0.02 * abs(axial[e]),
                  f"horseshoe: end node {n + 1}: interface shear = end thrust",
                  f"{fs:.5g} vs {axial[e]:.5g}")
        check(abs(axial[0] - axial[11]) < 0.15 * abs(axial[0]), "horseshoe: end thrusts alike",
              f"{axial[0]:.5g} {axial[11]:.5g}")


def crack_rectangle():
    rc, out = run(udec, [], stdin_text="ROUND 0.01\nBLOCK 0,0 0,20 20,20 20,0\nCRACK 6,6 6,10\n"
                  "CRACK 6,10 14,10\nCRACK 14,10 14,6\nCRACK 14,6 6,6\nPRINT BLOCK\n"
                  "DELETE 5.9,14.1 5.9,10.1\nPRINT BLOCK\nSTOP\n")
    note = [l for l in out.splitlines() if "note: DELETE" in l]
    rows = [[l.split() for l in t.splitlines() if len(l.split()) == 9 and l.split()[0].isdigit()]
            for t in re.split(r"BLOCK +MAT", out)[1:]]
    ids = [{r[0]: float(r[5]) for r in t} for t in rows]
    gone = [a for b, a in ids[0].items() if b not in ids[1]] if len(ids) == 2 else []
    check(not note and len(gone) == 1 and abs(gone[0] - 32.0) < 1e-9,
          "crack rectangle: DELETE takes the rectangle's block (32 m2) alone",
          "\n".join(note) + out[-1500:])


def insitu_eff():
    deck = ("ROUND 0.01\nBLOCK 0,-10 0,0 10,0 10,-10\nSPLIT 0,-5 10,-5\nSPLIT 5,-11 5,1\n"
            "PROP MAT=1 DENS=2600 K=10E9 G=7E9\n"
            "PROP JMAT=1 JKN=1E10 JKS=1E10 JFRIC=0.7 AZERO=3E-4 ARES=1E-4 JPERM=83.3\n"
            "FLUID RHOW=1000 BULKW=2E8\nSET -EFF\nSET YWTAB 0\nGRAV 0 -10\n"
            "INSITU STRESS 0 0 0 YGRAD 13000 0 26000\nPRINT DOMAIN\n"
            "BOUND YVEL 0 RANGE 0,10 -10.1,-9.9\nBOUND XVEL 0 -0.1,0.1 -10,0\n"
            "BOUND XVEL 0 9.9,10.1 -10,0\nBOUND IMPERMEABLE\nDAMP AUTO\nCYCLE 200\n"
            "PRINT DOMAIN\nPRINT MAX\nPRINT CONTACT FORCE\nSTOP\n")
    rc, out = run(udec, [], stdin_text=deck)
    check(rc == 0 and "fluid pressures set in 5 domains" in out, "INSITU -EFF: 5 domains set", out[-1500:])
    tables = out.split("PRESSURE")
    for k, when in ((1, "after INSITU"), (2, "after 200 cycles")):
        rows = [l.split() for l in tables[k].splitlines()[1:6]] if len(tables) > k else []
        bad = [r for r in rows if len(r) < 5 or
               abs(float(r[1]) - 1000 * 10 * (0.0 - float(r[4]))) > 1e-4 * 75000]
        check(len(rows) == 5 and not bad, f"INSITU -EFF: hydrostatic domain pressures {when}",
              str(rows))
    vel = [l for l in out.splitlines() if "max block velocity" in l]
    check(vel and float(vel[-1].split()[3]) < 1e-9, "INSITU -EFF: the model stays at rest", str(vel))
    cf = out.split("PRINT CONTACT FORCE")[-1]
    fns = [float(l.split()[6]) for l in cf.splitlines()
           if len(l.split()) == 8 and l.split()[0].isdigit() and float(l.split()[6]) > 7e4]
    check(len(fns) == 4 and all(abs(f - 80000.0) < 80.0 for f in fns),
          "INSITU -EFF: the horizontal joint carries the effective stress 80000", str(fns) + cf[:900])


def pulse_then_rest():
    column = ("ROUND 0.01\nBLOCK 0,0 0,40 4,40 4,0\nSPLIT -1,20 5,20\n"
              "PROP MAT=1 DENS=2000 K=2E9 G=1.125E9\n"
              "PROP JMAT=1 JKN=1E12 JKS=1E12 JFRIC=1 JCOH=1E8 JTEN=1E8\nGEN QUAD 1\n"
              "BOUND -1 5 -1 0.1 XVISC YVISC MAT 1\n"
              "BOUND -1 5 -1 0.1 STRESS 0 -3E5 0 XHIS %s\n"
              "BOUND -0.1 0.1 0.1 41 YVEL 0\nBOUND 3.9 4.1 0.1 41 YVEL 0\nDAMP 0\n"
              "CYCLE 4000\nCYCLE 4000\nPRINT GRID DISP 1.9 2.1 39.9 40.1\n"
              "PRINT BOUNDARY FORCES -1 5 -1 0.1\nSTOP\n")
    for hist, want in (("SINE 10 0.1", 0.0), ("LINEAR", 3e5)):
        rc, out = run(udec, [], stdin_text=column % hist)
        rows = [l.split() for l in out.split("PRINT BOUNDARY FORCES")[-1].splitlines()
                if len(l.split()) == 9 and l.split()[0].isdigit()]
        total = sum(float(r[5]) for r in rows)
        # the base is 4 m long: 3e5 Pa gives 1.2e6 N in all
        check(rc == 0 and len(rows) == 5 and abs(abs(total) - 4.0 * want) <= 1.0 + 1e-6 * 4.0 * want,
              f"XHIS {hist}: the base keeps {4.0 * want:g} N after the CYCLE", str(rows))
        if want == 0.0:
            g = [l.split() for l in out.split("PRINT GRID DISP")[-1].splitlines()
                 if len(l.split()) == 8 and l.split()[0].isdigit()]
            check(len(g) == 1 and abs(float(g[0][6])) < 0.01, "after the pulse the top is at rest",
                  str(g))


def mscale_part_small():
    deck = ("ROUND 0.01\nBLOCK 0,0 0,4 4,4 4,0\nPROP MAT=1 DENS=2000 K=2E9 G=1.125E9\n"
            "GEN QUAD 1\nMSCALE PART 1E-5\nCYCLE 100\nSTOP\n")
    rc, out = run(udec, [], stdin_text=deck)
    line = [l for l in out.splitlines() if l.startswith("cycle 100, time")]
    check(rc == 0 and line and "timestep  1.0000E-05" in line[0] and "time  1.00000E-03" in line[0],
          "MSCALE PART 1E-5 below the model's step: the step is 1E-5", "\n".join(line) or out[-800:])


wall()
damp_and_free()
horseshoe_liner()
crack_rectangle()
insitu_eff()
pulse_then_rest()
mscale_part_small()
finish()
