"""New user's decks of campaign round 11: one study (a tunnel in rock cut by
crossing joint sets, held by boundary stresses) written many ways from the
UDEC manual (ICG1.5, 1989) Sections 2 and 4 (docs/closed_form.md, "Round 11",
lists every deck, its reference and our number). Units SI.

Finding (fixed):
 1. INSITU under a field that pulls joints apart named the worst slipping
    contact "a joint with no strength (no friction, no cohesion)" though its
    JFRIC was 0.5: its strength was nil because the field left it no normal
    force. The note now says "a joint in tension: no normal force for its
    friction to act on, no cohesion"; a joint of JFRIC 0 and JCOH 0 keeps
    the old words.
 2. HISTORY SXX in a model of rigid blocks recorded 0 at every sample
    without a word (HISTORY had said "taken in the nearest zone when
    cycling"). The first CYCLE or SOLVE that samples it now says the model
    has no zones and names GENERATE and HISTORY NSTR / SSTR.
 3. EDGE below twice ROUND was refused without the numbers; the error now
    gives emin, ROUND and the least EDGE allowed.
Closed forms (hold):
 4. Symmetric deck: sets at 45 and 135 degrees through the centre of a
    circular opening under a hydrostatic INSITU = BOUNDARY STRESS: the
    springline and crown / invert displacements are equal and opposite.
 5. A rigid jointed 10 x 10 m column on rollers (GRAV 0 -10): the base
    carries rho g H W = 2.5e6 N.
 6. A zoned jointed square under INSITU equal to its BOUNDARY STRESS (with a
    shear stress) stays at rest, its zone stresses as given.
 7. A top stress varying with XGRAD on a range: the base carries its
    resultant; INSITU with gravity and YGRAD (K0 0.6) on rollers: the base
    carries the weight and a side the integral of sxx.
 8. A session at the UDEC> prompt: six mistyped lines refused, nothing
    changed by them, SAVE / CYCLE / RESTART / CYCLE repeat the same cycle.
"""
import os
import sys
sys.path.insert(0, os.path.dirname(__file__))
from udec_test import check, finish, run, run_deck, tables, workdir  # noqa: E402
from shared_decks import jointed_square  # noqa: E402

udec = sys.argv[1]

# a 2 x 2 block cut by a horizontal joint, INSITU pulling the joint apart
# (syy +1e6) with a shear stress 1e5 across it
PULLED = """ROUND 0.01
BLOCK 0,0 0,2 2,2 2,0
CRACK 0,1 2,1
PROP MAT=1 DENS=2500 JKN=1E10 JKS=1E10 JFRIC={fric} JCOH=0 JTENS=0
INSITU STRESS 0 1E5 1E6
STOP
"""


def insitu_pulled():
    rc, out = run_deck(udec, workdir(), "pulled", PULLED.format(fric="0.5"))
    check("worst: contact" in out and "a joint in tension: no normal force for its friction to act on" in out
          and "no friction" not in out,
          "pulled: a joint of JFRIC 0.5 in tension is not said to have no friction", out[-1500:])
    rc, out = run_deck(udec, workdir(), "pulled0", PULLED.format(fric="0"))
    check("a joint with no strength (no friction, no cohesion)" in out and "in tension:" not in out,
          "pulled: a joint of JFRIC 0, JCOH 0 keeps 'no strength (no friction, no cohesion)'", out[-1500:])


# rigid blocks, sets at 45 / 135 degrees through the centre of a circular
# opening, INSITU = BOUNDARY STRESS (hydrostatic): the study's first deck
RING = jointed_square(20, ["45,0 40,0 0,0 4,0 (10,10)", "135,0 40,0 0,0 4,0 (10,10)"], "10,10 2,12",
                      "DENS=2500 JKN=1E10 JKS=1E10 JFRIC=0.6", "-2E6 0 -2E6")

ZONELESS = RING + """HIST SXX 10,13 UNBAL SYY 13,10
DEL ANN 10 10 0 1.9
SOLVE RATIO=1E-4
CYCLE 10
STOP
"""


def zoneless():
    rc, out = run_deck(udec, workdir(), "zoneless", ZONELESS)
    note = "note: histories 1 (SXX), 3 (SYY) read zone stresses, and the model has no zones"
    check(out.count(note) == 1 and "SOLVE: " + note in out and "HISTORY NSTR / SSTR" in out,
          "zoneless: the first SOLVE says SXX / SYY histories have no zone to read, once", out[-1500:])
    rc, out = run(udec, ["e.dat"], cwd=folder_with("e.dat", "ROUND 0.1\nEDGE 0.1\nSTOP\n"))
    check(rc != 0 and "EDGE: emin 0.1 is below twice the rounding length (ROUND 0.1): give EDGE >= 0.2" in out,
          "edge: EDGE below 2 ROUND is refused with the numbers", out[-600:])


def folder_with(name, text):
    folder = workdir()
    with open(os.path.join(folder, name), "w") as f:
        f.write(text)
    return folder


SYMMETRIC = RING + """DAMP AUTO
HIST XDIS 8,10 XDIS 12,10 YDIS 10,12 YDIS 10,8
CYCLE 100
DEL ANN 10 10 0 1.9
CYCLE 4000
PRINT HIST 1 2 3 4
STOP
"""


def symmetric():
    rc, out = run_deck(udec, workdir(), "symmetric", SYMMETRIC)
    rows = [l.split() for l in out.split("PRINT HIST 1 2 3 4")[-1].splitlines()]
    rows = [[float(v) for v in r] for r in rows if len(r) == 5 and r[0][0].isdigit()]
    if not rows:
        check(False, "symmetric: PRINT HIST table", out[-1500:])
        return
    _, w, e, n, s = rows[-1]
    print(f"symmetric: west {w:.6g} east {e:.6g} crown {n:.6g} invert {s:.6g}")
    # the deck is symmetric about x = 10, y = 10 and the diagonals: the four
    # wall points move inwards by the same amount (1e-3 relative; measured
    # 7.18542e-05 / 7.18541e-05)
    ref = abs(w)
    check(w > 0 and ref > 1e-5 and all(abs(abs(v) - ref) < 1e-3 * ref for v in (e, n, s))
          and e < 0 and n < 0 and s > 0,
          "symmetric: springlines, crown and invert move in by the same amount (1e-3)", str(rows[-1]))


# a rigid column cut by JSETs at 0 and 90 degrees, rollers base and sides
COLUMN = """ROUND 0.02
BLOCK 0,0 0,10 10,10 10,0
JSET 0,0 20,0 0,0 2.5,0 (0,0)
JSET 90,0 20,0 0,0 5,0 (0,0)
PROP MAT=1 DENS=2500 JKN=1E10 JKS=1E10 JFRIC=0.5
GRAV 0,-10
BOUND -0.1,10.1 -0.1,0.1 YVEL=0
BOUND -0.1,0.1 -0.1,10.1 XVEL=0
BOUND 9.9,10.1 -0.1,10.1 XVEL=0
DAMP AUTO
CYCLE 3000
PRINT BOUND FORCES
STOP
"""


def base_sum(out, command, y=0.0):
    t = tables(out, command)
    rows = [r for r in (t[-1] if t else []) if abs(r.get("Y", 1e9) - y) < 1e-3]
    return sum(r["FY"] for r in rows), len(rows)


def column():
    rc, out = run_deck(udec, workdir(), "column", COLUMN)
    fy, n = base_sum(out, "PRINT BOUND FORCES")
    print(f"column: base {fy:.6g} N over {n} points (-2.5e6)")
    # statics: rho g H W = 2500 x 10 x 10 x 10 (1e-4)
    check(n == 4 and abs(fy + 2.5e6) < 1e-4 * 2.5e6, "column: the base carries rho g H W = 2.5e6 N (1e-4)",
          f"{fy} {n}")


REST = """ROUND 0.02
BLOCK 0,0 0,20 20,20 20,0
JSET -30,0 40,0 0,0 3,0 (10,10)
JSET 60,0 40,0 0,0 3,0 (10,10)
GEN EDGE 3
PROP MAT=1 DENS=2700 BULK=2E10 SHEAR=1.2E10 JKN=5E10 JKS=2E10 JFRIC=0.7 JDIL=0.1 JCOH=1E5 JTENS=1E5
INSITU STRESS -5E6 1E6 -8E6
BOUND STRESS -5E6 1E6 -8E6
DAMP AUTO
CYCLE 300
PRINT MAX
STOP
"""


def at_rest():
    rc, out = run_deck(udec, workdir(), "rest", REST)
    t = {}
    for line in out.split("PRINT MAX")[-1].splitlines():
        f = line.split()
        if len(f) >= 2 and f[0] in ("max", "min"):
            name = " ".join(f[:-3]) if len(f) > 4 else " ".join(f[:-1])
            try:
                t[name] = float(f[-3] if len(f) > 4 else f[-1])
            except ValueError:
                pass
    print("rest:", {k: t.get(k) for k in ("max gridpoint displacement", "max SXX", "min SXX", "max SXY",
                                           "min SYY")})
    # no gravity, the boundary carries the INSITU field: nothing moves
    # (displacement below 1e-12 m, round-off) and the zones keep the field
    # to 1e-6 relative
    ok = t.get("max gridpoint displacement", 1.0) < 1e-12
    for key, ref in (("max SXX", -5e6), ("min SXX", -5e6), ("max SYY", -8e6), ("min SYY", -8e6),
                     ("max SXY", 1e6), ("min SXY", 1e6)):
        ok = ok and key in t and abs(t[key] - ref) < 1e-6 * abs(ref)
    check(ok, "rest: INSITU = BOUNDARY STRESS with shear: no motion, zone stresses as given (1e-6)", str(t))


TOP = """ROUND 0.02
BLOCK 0,0 0,20 20,20 20,0
JSET 0,0 40,0 0,0 4,0 (0,2)
JSET 90,0 40,0 0,0 4,0 (2,0)
GEN EDGE 2
PROP MAT=1 DENS=2500 K=1E10 G=6E9 JKN=2E10 JKS=1E10 JFRIC=0.6
BOUND -0.1 20.1 19.9 20.1 STRESS 0 0 -2E6 XGRAD 0 0 -5E4
BOUND -0.1 20.1 -0.1 0.1 YVEL 0
BOUND -0.1 0.1 -0.1 20.1 XVEL 0
BOUND 19.9 20.1 -0.1 20.1 XVEL 0
DAMP AUTO
CYCLE 3000
PRINT BOUND FORCES
STOP
"""

GRADIENT = """ROUND 0.05
BLOCK 0,0 0,50 50,50 50,0
JSET 89.9,0 100,0 0,0 5,0 (25,25)
JSET 0,0 100,0 0,0 5,0 (25,25)
TUNNEL 25,25 2,16
GEN EDGE 5
PROP MAT=1 DENS=2500 K=1E10 G=6E9 JKN=1E10 JKS=1E10 JFRIC=0.6
GRAVITY 0 -10
INSITU STRESS -0.75E6 0 -1.25E6 YGRAD 1.5E4 0 2.5E4
BOUND -0.1 0.1 -0.1 50.1 XVEL 0
BOUND 49.9 50.1 -0.1 50.1 XVEL 0
BOUND -0.1 50.1 -0.1 0.1 YVEL 0
DAMP AUTO
CYCLE 300
PRINT BOUND FORCES
STOP
"""


def loads():
    rc, out = run_deck(udec, workdir(), "top", TOP)
    fy, n = base_sum(out, "PRINT BOUND FORCES")
    # syy = -2e6 - 5e4 x on the 20 m top: resultant -(2e6 x 20 + 5e4 x 200)
    # = -5e7 N, no gravity: the base carries it (1e-4)
    print(f"top: base {fy:.6g} N over {n} points (-5e7)")
    check(abs(fy + 5e7) < 1e-4 * 5e7, "top: XGRAD top stress, the base carries its resultant 5e7 N (1e-4)",
          f"{fy} {n}")
    rc, out = run_deck(udec, workdir(), "gradient", GRADIENT)
    fy, n = base_sum(out, "PRINT BOUND FORCES")
    t = tables(out, "PRINT BOUND FORCES")
    left = sum(r["FX"] for r in (t[-1] if t else []) if abs(r["X"]) < 1e-3)
    # weight rho g H W = 2500 x 10 x 50 x 50 = 6.25e7 N (the opening is not
    # excavated); sxx = 0.6 syy: the side carries 0.6 x 1.25e6 x 50 / 2 =
    # 1.875e7 N (1e-4 both)
    print(f"gradient: base {fy:.6g} N (-6.25e7), left side {left:.6g} N (-1.875e7)")
    check(abs(fy + 6.25e7) < 1e-4 * 6.25e7 and abs(left + 1.875e7) < 1e-4 * 1.875e7,
          "gradient: base carries the weight, the side K0 x the overburden integral (1e-4)", f"{fy} {left}")


SESSION = RING.lower() + """damp auto
hist ydis 10,12 unbal
cycel 100
cycle 100
prop mat=1 jkn=2e10 jfrict=0.3
prop mat=1 jkn=2e10 jfric=-0.3
bound stress -1e6 0 -1e6 ygrad 0 0
del ann 10 10 0 1.9 area
cycle 100 200
print prop
del ann 10 10 0 1.9
save s1.sav
cycle 300
restart s1.sav
cycle 300
quit
"""


def session():
    folder = workdir()
    rc, out = run(udec, [], cwd=folder, stdin_text=SESSION)
    errors = [l for l in out.splitlines() if "*** Error" in l]
    check(rc == 0 and len(errors) == 6, "session: six mistyped lines refused, the session goes on",
          "\n".join(errors) + out[-800:])
    # the refused PROP lines changed nothing: JKN stays 1e10
    check("1  JKN           1.000000E+10" in out, "session: a refused PROP line changes nothing",
          out[-2500:])
    ends = [l for l in out.splitlines() if "cycle 400," in l]
    # the same state restarted and cycled again: the same cycle line
    same = len(ends) == 2 and ends[0].split("max unbalanced force")[1].split(",")[0] == \
        ends[1].split("max unbalanced force")[1].split(",")[0]
    check(same and os.path.exists(os.path.join(folder, "s1.sav")),
          "session: CYCLE after SAVE and after RESTART reach cycle 400 with the same unbalanced force",
          "\n".join(ends))


insitu_pulled()
zoneless()
symmetric()
column()
at_rest()
loads()
session()
finish()
