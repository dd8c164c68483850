"""New users' decks of campaign round 9: dynamic, thermal, joint water flow and
structures, written from the UDEC manual (ICG1.5, 1989) Sections 2, 3, 4, 7 and
Appendix B alone (docs/closed_form.md, "Round 9", lists every deck, its
reference and our number). Units SI; K = 6.667e9, G = 4e9 (E = 1e10, nu =
0.25), density 2500 unless said: c_s = sqrt(G / rho) = 1264.9 m/s, thermal
diffusivity kappa = COND / (rho SPEC) = 8e-7 m^2/s.

Dynamic (Section 3.8, Section 4.5 BOUNDARY, DAMP, FFIELD):
 1. S wave up a 1 x 100 m column (sides YVEL 0), base XVEL 1E-2 XHIS SINE 50
    0.01, free top: arrival h / c_s (0.5 % of the travel time at the 5 %
    threshold, histories every 2 steps), peak v0 mid-height (1 %), 2 v0 at
    the free top (2 %).
 2. The same column driven by BOUND STRESS 0 1E5 0 XHIS SINE 50 0.01 at an
    XVISC base (MAT 1): v = tau / (2 rho c_s) = 0.01581 m/s (1 %), doubled at
    the top (2 %); what comes back after the reflection below 2 % of the
    peak. Before: a pure shear stress got "the stress pulls on the boundary
    ... wants negative (compressive) values", a note for far-field loads.
 3. A rigid 2 x 1 block on a joint (JKN 1E8: k = 2e8 N/m, m = 5000 kg, f =
    31.83 Hz) ringing under DAMP 0.05 31.83 MASS: peaks fall by exp(-2 pi
    xi / sqrt(1 - xi^2)) = 0.7301 a period (1 % over 8 periods).
 4. A 20 x 20 m site, sides XVISC YVISC FF on a free field (FFIELD GEN, MAT,
    SXY 2E5 XVISC YVISC), base XVISC YVISC with STRESS 0 2E5 0 and BOUND
    HIST=SIN(20.0,0.025) as Application D prints it: the surface at the
    centre and at both sides moves 2 tau / (2 rho c_s) = 0.06325 m/s (1 %).
    With Application D's `FFIELD SXY=1` the sides were tied to a column driven
    by 1 Pa and the surface moved 0.0085 m/s without a word; now a note
    names both stresses.
Thermal (Section 7, RUN, TFIX, THAPP):
 5. Steady conduction in a 4 m bar, TFIX 100 and 0 at the ends: linear
    (0.01 degree).
 6. TFIX 100 at x = 0, THAPP CONV 5 0 at x = 2 (k = 2): T(L) = 100 / (1 +
    h L / k) = 16.667, the profile linear (0.01 degree).
 7. THAPP SOURCE 100 in a 2 m bar with both ends at 0: T = S x (L - x) /
    (2 k), 25 at the middle (0.2 % of it: the centre gridpoints of QUAD).
 8. THAPP FLUX 100 on the end of a long bar for 2.5e5 s: T = (2 q / k)
    [sqrt(kappa t / pi) exp(-x^2 / 4 kappa t) - x / 2 erfc(x / 2 sqrt(kappa
    t))], 25.23 at the surface (0.5 % of it).
 9. Free thermal expansion (plane strain) by TFIX 70 over a block at INITEM
    20, THEXP 1e-5: u = alpha dT (1 + nu) x (0.1 %), szz = -E alpha dT = -5e6
    Pa (0.1 %), in-plane stresses below 1e-3 of it. The new user first gave
    RUN STEP 1 after TFIX over every gridpoint: "nothing conducts" (now: every
    gridpoint is held by TFIX, CYCLE takes the steps).
Joint flow (Section 3.13):
10. Bingham grout (FLUID 1000 2E9 0.25) in a 10 m joint, aperture 1e-4,
    JPERM 83.3, 1e5 Pa across: q = kj a^3 (dp - 2 COHW L / a) / L = 4.165e-7
    m^2/s, half the Newtonian (0.1 %); COHW 0.6 is above the threshold
    gradient (Eq. 64): no flow.
Structures (Section 3.10):
11. A bolt (REINFORCE, RSEXP 1) across a smooth joint of a rigid block
    sheared by BOUND XVEL 1E-3: F = F_b (1 - exp(-RSSTIFF ds / F_b)), F_b =
    RUSHEAR / 2 for a bolt normal to the joint (Eq. 41) (0.1 %).
12. A grouted cable (31 nodes, 0.1 m apart, EA / L = 1e9, grout JKS 1e10 x
    0.1 m = 1e9 a node) across a joint that opens by delta: the crossing
    element's N = k delta / sqrt(5) (the infinite chain: rho = (3 - sqrt 5)
    / 2) (0.5 %), YIELD 2e5 after it (0.1 %).
13. A roof wedge (2.25 m^2, 56 250 N) over a rectangular opening, frictionless
    joints, held by two vertical CABLEs: each crossing element carries half
    the weight plus the cable's own below the joint (0.1 %).
14. Mistakes, typed at the prompt: each error names the command, the token
    and what was expected, and the refused line changes nothing; RUN AGE
    stopped by the TEMP limit says which limit to raise.
"""
import math
import os
import sys
sys.path.insert(0, os.path.dirname(__file__))
from udec_test import cable_elements, check, finish, histories, printed_number, run, run_deck, tables, workdir  # noqa: E402
from shared_decks import SHEAR_BOX  # noqa: E402

udec = sys.argv[1]
RHO, G = 2500.0, 4e9
CS = math.sqrt(G / RHO)
ELASTIC = "PROP MAT=1 DENS=2500 K=6.667E9 G=4E9"
STIFF = "PROP MAT=1 DENS=2500 K=1E10 G=1E10"  # rigid blocks: the rock's moduli do not enter


def arrival(h, level=0.05):
    peak = max(abs(v) for _, v in h)
    return next(t for t, v in h if abs(v) > level * peak)


def peak(h, t_end=1e30):
    return max((abs(v) for t, v in h if t <= t_end), default=0.0)


def deck_histories(name, deck, n):
    """Run `deck` with PRINT HIS 1 .. n and STOP after it: (the n tables or None
    with a failed check, the output)."""
    rc, out = run_deck(udec, workdir(), name, deck + "".join(f"PRINT HIS {i}\n" for i in range(1, n + 1))
                       + "STOP\n")
    h = histories(out)
    if len(h) != n:
        check(False, f"{name}: {n} histories printed", out[-1500:])
        return None, out
    return h, out


COLUMN = """HEAD S wave up a column
ROUND 0.01
BLOCK 0,0 0,100 1,100 1,0
GEN QUAD 1
""" + ELASTIC + """
BOUND -0.1 1.1 -0.1 100.1 YVEL 0
{base}
DAMP 0 0
HIST NCYC 2 XVEL 0.5 0 XVEL 0.5 50 XVEL 0.5 100
CYCLE 3000
"""


def s_wave_velocity():
    h, out = deck_histories("s_velocity", COLUMN.format(
        base="BOUND -0.1 1.1 -0.1 0.1 XVEL 1E-2 XHIS SINE 50 0.01"), 3)
    if h is None:
        return
    t0, t1, t2 = (arrival(x) for x in h)
    p1, p2 = peak(h[1], t1 + 0.012), peak(h[2], t2 + 0.012)
    print(f"S wave (velocity): travel {t1 - t0:.5f} / {t2 - t0:.5f} s ({50 / CS:.5f} / {100 / CS:.5f}), "
          f"peaks {p1:.5g} / {p2:.5g} (1e-2 / 2e-2)")
    check(abs(t1 - t0 - 50 / CS) < 0.005 * 50 / CS and abs(t2 - t0 - 100 / CS) < 0.005 * 100 / CS,
          "S wave (velocity): arrives at h / c_s (0.5 %)", f"{t1 - t0} {t2 - t0}")
    check(abs(p1 - 1e-2) < 1e-4 and abs(p2 - 2e-2) < 4e-4,
          "S wave (velocity): v0 inside, 2 v0 at the free top (1 %, 2 %)", f"{p1} {p2}")


def s_wave_stress():
    base = ("BOUND -0.1 1.1 -0.1 0.1 XVISC MAT=1\n"
            "BOUND -0.1 1.1 -0.1 0.1 STRESS 0 1E5 0 XHIS SINE 50 0.01\n"
            "BOUND -0.1 1.1 -0.1 0.1 YVEL 0")
    h, out = deck_histories("s_stress", COLUMN.format(base=base), 3)
    check("pulls on the boundary" not in out, "S wave (stress): no tension note for a pure shear input",
          "\n".join(l for l in out.splitlines() if "note" in l))
    check("replaces a prescribed XVEL / YVEL at 2 points" in out,
          "S wave (stress): STRESS on the held base corners warns they are free", out[-1500:])
    if h is None:
        return
    v = 1e5 / (2 * RHO * CS)
    t1, t2 = arrival(h[1]), arrival(h[2])
    p1, p2 = peak(h[1], t1 + 0.012), peak(h[2], t2 + 0.012)
    late = max(peak([q for q in x if q[0] > 0.3]) for x in h)
    print(f"S wave (stress): peaks {p1:.5g} / {p2:.5g} ({v:.5g} / {2 * v:.5g}), after 0.3 s {late:.3g}")
    check(abs(p1 - v) < 0.01 * v and abs(p2 - 2 * v) < 0.02 * 2 * v,
          "S wave (stress): tau / (2 rho c_s) inside, doubled at the top (1 %, 2 %)", f"{p1} {p2}")
    check(late < 0.02 * v, "S wave (stress): the viscous base takes the reflection out (2 %)", f"{late}")


def ringing_block():
    deck = """ROUND 0.01
BLOCK 0,-1 0,1 2,1 2,-1
CRACK -1,0 3,0
""" + STIFF + """
PROP JMAT=1 JKN=1E8 JKS=1E8 JFRIC=1
FIX -1 3 -2 0
DAMP 0.05 31.83 MASS
LOAD -1 3 0.5 1.5 0 -1E5
HIST NCYC 1 YVEL 1 1
CYCLE 400
"""
    h, out = deck_histories("ringing", deck, 1)
    if h is None:
        return
    h = h[0]
    peaks = [h[i] for i in range(1, len(h) - 1) if h[i][1] > h[i - 1][1] and h[i][1] >= h[i + 1][1]
             and h[i][1] > 0]
    ref = math.exp(-2 * math.pi * 0.05 / math.sqrt(1 - 0.05 ** 2))
    got = (peaks[8][1] / peaks[0][1]) ** (1 / 8) if len(peaks) > 8 else float("nan")
    print(f"ringing block: decay a period {got:.5f} ({ref:.5f})")
    check(abs(got - ref) < 0.01 * ref, "ringing block: DAMP 0.05 at its frequency, decay a period (1 %)",
          f"{got} {[p[1] for p in peaks[:9]]}")


SITE = """HEAD vertical S wave through a site with free-field sides
ROUND 0.01
BLOCK -10,-20 -10,0 10,0 10,-20
GEN QUAD 1
""" + ELASTIC + """
BOUND MAT=1
BOUND -10.1,-9.9 -20.1,0.1 XVISC YVISC FF
BOUND 9.9,10.1 -20.1,0.1 XVISC YVISC FF
BOUND -10.1,10.1 -20.1,-19.9 XVISC YVISC
FFIELD GEN (-20,0) 21
FFIELD MAT=1
BOUND -10.1,10.1 -20.1,-19.9 STRESS 0, 2E5, 0
BOUND HIST=SIN(20.0,0.025)
FFIELD SXY={sxy} XVISC YVISC
BOUND -10.1,10.1 -20.1,-19.9 YVEL=0
DAMP 0 0
HIST NCYC 2 XVEL 0,0 XVEL -10,0 XVEL 10,0
CYCLE 600
PRINT HIS 1
PRINT HIS 2
PRINT HIS 3
STOP
"""


def free_field():
    rc, out = run_deck(udec, workdir(), "site", SITE.format(sxy="2E5"))
    check("note: FFIELD" not in out and "pulls on the boundary" not in out,
          "free field: no note when the column's base has the model's stress",
          "\n".join(l for l in out.splitlines() if "note" in l))
    h = histories(out)
    ref = 2 * 2e5 / (2 * RHO * CS)
    got = [peak(x) for x in h]
    print(f"free field: surface peaks centre / sides {got} ({ref:.5g})")
    check(len(got) == 3 and all(abs(p - ref) < 0.01 * ref for p in got),
          "free field: the surface moves 2 tau / (2 rho c_s) at the centre and both sides (1 %)", str(got))
    rc, out = run(udec, [], stdin_text=SITE.format(sxy="1").split("DAMP")[0] + "STOP\n")
    notes = [l for l in out.splitlines() if "note: FFIELD SXY" in l]
    check(len(notes) == 1 and "sxy 200000" in notes[0] and "FFIELD SXY 200000" in notes[0],
          "free field: Application D's SXY=1 under STRESS 0 2E5 0 gets a note naming both", out[-1500:])


BAR = """ROUND 0.01
BLOCK 0,0 0,0.2 {L},0.2 {L},0
GEN QUAD 0.1
PROP MAT=1 DENS=2500 K=6.667E9 G=4E9 COND=2 SPEC=1000
THERMAL
{bc}
RUN AGE {age} TEMP 1E9 STEP 10000000
PRINT TEMP
STOP
"""


def bar(name, length, bc, age, law, tol):
    rc, out = run_deck(udec, workdir(), name, BAR.format(L=length, bc=bc, age=age))
    rows = tables(out, "PRINT TEMP")
    rows = rows[-1] if rows else []
    worst = max(((abs(r["TEMPERATURE"] - law(r["X"])), r["X"], r["TEMPERATURE"]) for r in rows),
                default=(float("inf"), 0, 0))
    print(f"{name}: {len(rows)} gridpoints, worst at x = {worst[1]:g}: {worst[2]:.6g} ({law(worst[1]):.6g})")
    check(len(rows) > 100 and worst[0] < tol, f"{name}: temperatures within {tol:g} of the closed form",
          str(worst))


def thermal_bars():
    bar("steady", 4, "TFIX 100 -0.01 0.01 -1 1\nTFIX 0 3.99 4.01 -1 1", "2E7",
        lambda x: 100 * (1 - x / 4), 0.01)
    bar("convection", 2, "TFIX 100 -0.01 0.01 -1 1\nTHAPP 1.99 2.01 -1 1 CONV 5 0", "1E7",
        lambda x: 100 - (100 - 100 / (1 + 5 * 2 / 2)) * x / 2, 0.01)
    bar("source", 2, "TFIX 0 -0.01 0.01 -1 1\nTFIX 0 1.99 2.01 -1 1\nTHAPP -1 3 -1 1 SOURCE 100 0", "5E6",
        lambda x: 100 * x * (2 - x) / (2 * 2), 0.05)
    kap, t, q, k = 8e-7, 2.5e5, 100.0, 2.0
    s = math.sqrt(kap * t)
    bar("flux", 6, "INITEM 0 -1 7 -1 1\nTHAPP -0.01 0.01 -1 1 FLUX 100 0", "2.5E5",
        lambda x: 2 * q / k * (s / math.sqrt(math.pi) * math.exp(-x * x / (4 * s * s))
                               - x / 2 * math.erfc(x / (2 * s))), 0.005 * 25.23)


def free_expansion():
    head = """ROUND 0.01
BLOCK 0,0 0,1 2,1 2,0
GEN QUAD 0.25
PROP MAT=1 DENS=2500 K=6.667E9 G=4E9 COND=2 SPEC=1000 THEXP=1E-5
THERMAL
INITEM 20 -1 3 -1 2
BOUND -0.01 0.01 -0.01 1.01 XVEL 0
BOUND -0.01 2.01 -0.01 0.01 YVEL 0
TFIX 70 -1 3 -1 2
DAMP AUTO
"""
    rc, out = run(udec, [], stdin_text=head + "RUN STEP 1\nSTOP\n")
    err = [l for l in out.splitlines() if "*** Error" in l]
    check(len(err) == 1 and "every gridpoint's temperature is held by TFIX" in err[0] and "CYCLE" in err[0],
          "free expansion: RUN with every gridpoint TFIXed says so and names CYCLE", "\n".join(err))
    rc, out = run_deck(udec, workdir(), "expansion", head + "CYCLE 3000\nPRINT GRID DISP\nPRINT ZONE STRESS\nSTOP\n")
    eps = 1e-5 * 50 * 1.25
    grid = tables(out, "PRINT GRID DISP")
    grid = grid[-1] if grid else []
    worst = max((max(abs(r["X-DISP"] - eps * (r["X"] - r["X-DISP"])), abs(r["Y-DISP"] - eps * (r["Y"] - r["Y-DISP"])))
                 for r in grid), default=float("inf"))
    zones = tables(out, "PRINT ZONE STRESS")
    zones = zones[-1] if zones else []
    szz = [z["SZZ"] for z in zones]
    inplane = max((max(abs(z["SXX"]), abs(z["SXY"]), abs(z["SYY"])) for z in zones), default=float("inf"))
    print(f"free expansion: worst displacement error {worst:.3g} m (u at x = 2: {2 * eps:.4g}), "
          f"szz {min(szz, default=0):.6g} .. {max(szz, default=0):.6g} (-5e6), in-plane {inplane:.3g}")
    check(len(grid) > 50 and worst < 1e-3 * 2 * eps, "free expansion: u = alpha dT (1 + nu) x (0.1 %)", str(worst))
    check(szz and all(abs(v + 5e6) < 5e3 for v in szz) and inplane < 5e3,
          "free expansion: szz = -E alpha dT (0.1 %), no in-plane stress", f"{szz[:4]} {inplane}")


def bingham():
    deck = """ROUND 0.01
BLOCK 0,-1 0,1 10,1 10,-1
CRACK 0,0 10,0
""" + ELASTIC + """
PROP JMAT=1 JKN=1E10 JKS=1E10 AZERO=1E-4 ARES=1E-4 JPERM=83.3
FIX -1 11 -2 2
FLUID 1000 2E9 {cohw}
BOUND IMPERMEABLE
BOUND -0.01 0.01 -0.01 0.01 PP 1E5
BOUND 9.99 10.01 -0.01 0.01 PP 0
SET SFLOW PTOL 1000
CYCLE 200
PRINT FLOW
STOP
"""
    for cohw, ref in ((0.25, 83.3 * 1e-12 * (1e5 - 2 * 0.25 * 10 / 1e-4) / 10), (0.6, 0.0)):
        rc, out = run_deck(udec, workdir(), "bingham", deck.format(cohw=cohw))
        q_in = printed_number(out, "total boundary inflow")
        q_out = printed_number(out, "total boundary outflow")
        print(f"Bingham COHW {cohw}: in {q_in:.6g}, out {q_out:.6g} ({ref:.6g})")
        check(abs(q_in - ref) <= 1e-3 * max(ref, 1e-9) and abs(q_out - ref) <= 1e-3 * max(ref, 1e-9),
              f"Bingham COHW {cohw}: q = kj a^3 (dp - 2 COHW L / a) / L, none below the threshold (0.1 %)",
              f"{q_in} {q_out}")


def bolt():
    deck = SHEAR_BOX + """PROP MAT=1 DENS=2500 K=1E10 G=1E10
PROP JMAT=1 JKN=1E10 JKS=1E6 JFRIC=0
PROP MAT=2 RASTIFF=1E9 RSSTIFF=2E8 RLENGTH=0.1 RUAXIAL=2E5 RUSHEAR=1E5 RRFAC=1 RSEXP=1 RAEXP=1
REINFORCE 2 1,0.8 1,-0.8
FIX -2 4 -1 0
DAMP AUTO
BOUND -0.01 0.01 -0.001 1.01 XVEL 1E-3
BOUND -0.01 0.01 -0.001 1.01 YVEL 0
BOUND 1.99 2.01 -0.001 1.01 YVEL 0
HIST NCYC 20 RSHEAR 1 XDIS 1 0.5
CYCLE 10000
"""
    h, out = deck_histories("bolt", deck, 2)
    if h is None:
        return
    fb, k = 0.5e5, 2e8
    pairs = [(d, abs(f)) for (_, f), (_, d) in zip(h[0], h[1]) if d > 1e-5]
    worst = max((abs(f - fb * (1 - math.exp(-k * d / fb))) / (fb * (1 - math.exp(-k * d / fb))), d)
                for d, f in pairs)
    print(f"bolt: {len(pairs)} samples, last ds {pairs[-1][0]:.4g} F {pairs[-1][1]:.6g}, worst {100 * worst[0]:.3f} %")
    check(len(pairs) > 100 and pairs[-1][0] > 1e-3 and worst[0] < 1e-3,
          "bolt: F = F_b (1 - exp(-K ds / F_b)), F_b = RUSHEAR / 2 (0.1 %)", str(worst))


def cable():
    deck = """ROUND 0.01
BLOCK 0,-2 0,2 1,2 1,-2
CRACK -1,0.05 2,0.05
""" + STIFF + """
PROP JMAT=1 JKN=1E10 JKS=1E10 JTEN=0
PROP MAT=2 K=1.667E11 G=7.69E10 DENS=7800 YIELD=2E5 YCOMP=2E5
PROP MAT=3 JKS=1E10 JCOH=1E9
CABLE 0.5,-1.5 0.5,1.5 31 2 5E-4 3
FIX -1 2 -3 0.05
BOUND -0.01 1.01 1.99 2.01 YVEL 1E-2
HIST NCYC 20 CAXIAL 16 YDIS 0.5 1.0
DAMP AUTO
CYCLE 3000
"""
    h, out = deck_histories("cable", deck, 2)
    if h is None:
        return
    e = 9 * 1.667e11 * 7.69e10 / (3 * 1.667e11 + 7.69e10)
    k = e * 5e-4 / 0.1
    elastic = [(d, n) for (_, n), (_, d) in zip(h[0], h[1]) if 1e-4 < d < 0.95 * 2e5 * math.sqrt(5) / k]
    plastic = [n for (_, n), (_, d) in zip(h[0], h[1]) if d > 1.05 * 2e5 * math.sqrt(5) / k]
    worst = max((abs(n - k * d / math.sqrt(5)) / (k * d / math.sqrt(5)) for d, n in elastic), default=1.0)
    print(f"cable: {len(elastic)} elastic samples, worst {100 * worst:.3f} %; {len(plastic)} at yield, "
          f"N {min(plastic, default=0):.6g} .. {max(plastic, default=0):.6g}")
    check(len(elastic) > 10 and worst < 5e-3, "cable: N = (EA / L) delta / sqrt(5) (0.5 %)", str(worst))
    check(len(plastic) > 10 and all(abs(n - 2e5) < 200 for n in plastic), "cable: then YIELD 2e5 (0.1 %)",
          str(plastic[:5]))


def wedge():
    deck = """HEAD roof wedge held by two grouted cables
ROUND 0.01
BLOCK -5,-5 -5,5 5,5 5,-5
CRACK -5,-1 5,-1
CRACK -5,1 5,1
CRACK -2,-1 -2,1
CRACK 2,-1 2,1
DELETE -1.9 1.9 -0.9 0.9
CRACK -1.5,1 0,2.5
CRACK 0,2.5 1.5,1
""" + STIFF + """
PROP JMAT=1 JKN=1E10 JKS=1E10 JFRIC=0 JCOH=0 JTEN=0
PROP MAT=2 K=1.667E11 G=7.69E10 DENS=7800 YIELD=1E6 YCOMP=1E6
PROP MAT=3 JKS=1E9 JCOH=1E9
FIX -6 6 -6 0.5
FIX -6 6 2 6
CABLE -0.5,0.5 -0.5,3.9 16 2 5E-4 3
CABLE 0.5,0.5 0.5,3.9 16 2 5E-4 3
GRAV 0 -10
DAMP AUTO
CYCLE 5000
PRINT CABLE
STOP
"""
    rc, out = run_deck(udec, workdir(), "wedge", deck)
    axial = {}
    for n1, n2, length, n in cable_elements(out):
        key = 1 if n1 <= 16 else 2
        axial[key] = max(axial.get(key, 0.0), n)
    # the first node moves to where the line enters the rock (y = 1; CABLE, manual Section 4.5):
    # 16 nodes over 2.9 m; the crossing element is the 6th, nodes 1 .. 6 (5.5 spacings) hang under
    # the joint (y = 2 at x = -0.5 and 0.5)
    ref = 56250 / 2 + 7800 * 5e-4 * 5.5 * (2.9 / 15) * 10
    print(f"wedge: largest axial force of each cable {axial} ({ref:.6g})")
    check(len(axial) == 2 and all(abs(v - ref) < 1e-3 * ref for v in axial.values()),
          "wedge: each cable carries half the wedge and its own weight below the joint (0.1 %)", str(axial))


def mistakes():
    text = """ROUND 0.01
BLOCK 0,0 0,0.2 2,0.2 2,0
GEN QUAD 0.1
PROP MAT=1 DENS=2500 K=6.667E9 G=4E9 CONDUCTIVITY=2 SPEC=1000
PRINT PROP
PROP MAT=1 DENS=2500 K=6.667E9 G=4E9 COND=2
THERMAL
RUN STEP 10
PROP MAT=1 SPECHEAT=1000
TFIX 100 -0.01 0.01 -1 1
THAPP 1.99 2.01 -1 1 CONV 5
PRINT THERMAL
RUN AGE
RUN AGES 1E4
RUN AGE 1E6
DAMP 0.05
HIST XVEL 0.5
FLUID 1000 2E9 COHESION=5
PRINT FLUID
BOUND -0.1 0.1 -1 1 XVISC
STOP
"""
    rc, out = run(udec, [], stdin_text=text)
    errors = [l for l in out.splitlines() if "*** Error" in l]
    want = [("PROPERTY", "'CONDUCTIVITY'", "COND"),
            ("RUN", "SPECHEAT", "PROPERTY"),
            ("THAPP CONVECTION", "line ended", "r r"),
            ("RUN AGE", "line ended", "real number"),
            ("RUN", "'AGES'", "AGE"),
            ("DAMPING", "fcrit freq", "AUTO"),
            ("HISTORY XVEL", "line ended", "r r"),
            ("FLUID", "'COHESION'", "COHW"),
            ("BOUNDARY XVISC", "MAT", "far-field")]
    check(len(errors) == len(want), f"mistakes: {len(want)} errors", "\n".join(errors))
    for e, words in zip(errors, want):
        check(all(w in e for w in words), f"mistakes: '{words[0]}' error names {words[1:]}", e)
    # (at the prompt the commands are not echoed: each print is the only one of its kind)
    check("(no properties given)" in out, "mistakes: the refused PROPERTY line set nothing", out[:1500])
    check("(no THAPP conditions" in out, "mistakes: the refused THAPP set nothing", out[-3000:])
    check("no fluid in the model" in out, "mistakes: the refused FLUID set nothing", out[-3000:])
    check("note: RUN: the AGE 1000000 is not reached: the TEMP limit (20) stopped it first" in out,
          "mistakes: RUN AGE stopped by the default TEMP limit says which limit to raise",
          "\n".join(l for l in out.splitlines() if "RUN" in l))


s_wave_velocity()
s_wave_stress()
ringing_block()
free_field()
thermal_bars()
free_expansion()
bingham()
bolt()
cable()
wedge()
mistakes()
finish()
