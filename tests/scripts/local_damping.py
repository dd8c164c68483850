"""DAMP LOCAL alpha, an extension (not in the UDEC manual (ICG1.5, 1989), whose
Section 3.6 and Section 4.5 DAMP give AUTO and Rayleigh damping only): every
degree of freedom (x, y and rotation of a rigid or SDEF block, the three
strain modes of an SDEF block, x and y of a zone gridpoint) takes the force
-alpha |F| sign(v) of its own unbalanced force F (label `verification`).
Damping must not change a static answer, so each case is a closed form that
holds whatever brought the model to rest:

1. A column of five 1 x 1 m blocks (density 2000: 20 kN each under g = 10)
   on a FIXed base, horizontal joints JKN = JKS = 1e9 (the column of
   closed_forms_r3.py case 1), brought to rest by SOLVE RATIO 1e-7 under
   DAMP LOCAL (alpha 0.8, the default), rigid, SDEF (CHANGE SDEF, CONS 1) and
   zoned (GEN AUTO 0.3, CONS 1). Statics (exact): the joint at height y
   carries the weight of the blocks above it, (6 - y) 20 kN, summed over its
   contacts. Tolerance 5e-6 relative: half a unit in the sixth printed
   digit of each contact's force (the 1e-7 ratio is far below; measured 0
   rigid and SDEF, 8.8e-7 zoned, the same as under AUTO).
   Rigid and SDEF have no damping but LOCAL here (Rayleigh INTERNAL is not
   given), so their balancing shows that LOCAL damps the rigid motion, the
   strain modes and the gridpoints. The cycles SOLVE needs are printed
   against DAMP AUTO's (measured 2026-11-27, Release: rigid 740 against 370,
   SDEF 1 400 against 1 110, zoned 11 390 against 6 960: LOCAL is slower on
   this chain; docs/mechanics.md "Time step and damping").
2. Kirsch loaded by BOUNDARY STRESS alone (the deck of closed_forms_hm.py
   case 1: a = 1, G = 1e9, kappa = 2, sxx = -5, syy = -10 MPa on the sides
   of a 16 a quarter square, no INSITU) under DAMP LOCAL 0.3, 15 000 cycles.
   Reference (Kirsch; Jaeger, Cook and Zimmerman, Section 8.4, the far
   field's displacement added): u_r(a) = a (kappa + 1) (P + 2 Q cos 2 theta)
   / (4 G); tolerance 1 % of the crown's (as there; measured springline
   +0.53 %, crown +0.13 %, DAMP AUTO's final state after 40 000 cycles within
   0.05 %), and settled: the walls move by less than 0.1 % of the crown's
   over the last 2 000 cycles. Measured cycles to stay within 1 % / 0.1 % of
   the final walls: LOCAL 0.3 7 300 / 9 200, DAMP AUTO 22 300 / 38 100,
   mass damping 0.8 of critical at the first mode (DAMP 0.8 17 MASS, the
   case there) 8 400 / 12 200, LOCAL 0.8 42 200 / over 60 000 (too much
   damping: the walls creep in).
   Since the gridpoints' step under LOCAL is divided by sqrt(1 + alpha)
   (case 4; session 41) LOCAL 0.3 needs 8 500 / 10 700 cycles (its step
   0.877 of the one above), hence 15 000 cycles here, 12 000 before.
3. Input and state: DAMP LOCAL 1.5, DAMP LOCAL 0, DAMP LOCAL AUTO and DAMP
   LOCAL 0.5 0.2 are refused naming the command and what was expected, and
   change nothing (PRINT STATUS still names the damping given before);
   PRINT STATUS names LOCAL and its alpha; SAVE and RESTART keep them; HIST
   DAMP records alpha under LOCAL.
4. The step of the gridpoints. -alpha |F| sign(v) adds alpha |F| to the
   restoring force while a point moves away from rest, so the central-
   difference step of an oscillator of frequency w is stable only for
   w dt < 2 / sqrt(1 + alpha) (closed form of the piecewise-linear map; 1.49
   at alpha 0.8 instead of 2). The zones' step is Gershgorin's critical one
   taken whole (FRACTION fz = 1, manual Section 4.5), so under LOCAL it is
   divided by sqrt(1 + alpha): the printed step against DAMP AUTO's on the
   same model, 1 / sqrt(1 + alpha) within 1e-4 (the step is printed to 5
   digits) for alpha 0.3 and 0.8. And the model that showed it (random
   jointed tunnel seed 46, docs/robustness.md, round 2): a 2 x 1 m block cut
   by a joint into a 7 degree wedge, zoned (GEN AUTO 0.25: flat zones at the
   tip), INSITU equal to BOUNDARY STRESS (1 MPa), 500 cycles of DAMP LOCAL
   0.8 must stay at rest: every gridpoint slower than 1e-9 m/s (the field is
   exact; measured 9e-16; at the whole step the tip grew to 0.1 m/s and
   moved 1.2 cm).
"""
import re
import sys
from shared_decks import COLUMN_FIVE, check_kirsch_bs, kirsch_boundary_stress
from udec_test import check, contact_parts, finish, printed_number, run, run_clean, workdir

udec = sys.argv[1]

COLUMN = COLUMN_FIVE + """{kind}FIX 0,1 0,1
GRAV 0 -10
DAMP {damp}
SOLVE RATIO 1E-7 CYCLES 40000
PRINT CONTACT
STOP
"""
KINDS = {"rigid": "",
         "SDEF": "CHANGE 0,1 1,6 SDEF CONS 1\nPROP MAT=1 K=2E9 G=1E9\n",
         "zoned": "GEN 0,1 1,6 AUTO 0.3\nCHANGE 0,1 1,6 CONS 1\nPROP MAT=1 K=2E9 G=1E9\n"}
WEIGHT = 2000.0 * 10.0


def solve_cycles(out):
    m = re.search(r"SOLVE: balanced after (\d+) cycles", out)
    return int(m.group(1)) if m else None


for kind, extra in KINDS.items():
    cycles = {}
    for damp in ("AUTO", "LOCAL"):
        out = run_clean(udec, f"column_{kind}_{damp.lower()}", COLUMN.format(kind=extra, damp=damp))
        cycles[damp] = solve_cycles(out)
        if damp != "LOCAL":
            continue
        where = contact_parts(out, "NORMAL-DISP")
        force = contact_parts(out, "NORMAL-FORCE")
        sums = {}
        for c, r in where.items():
            y = round(r["Y"], 6)
            if c in force and abs(y - round(y)) < 1e-3 and 1 <= round(y) <= 5:
                sums[round(y)] = sums.get(round(y), 0.0) + force[c]["NORMAL-FORCE"]
        worst = max((abs(f - (6 - y) * WEIGHT) / ((6 - y) * WEIGHT) for y, f in sums.items()),
                    default=float("inf"))
        print(f"column {kind}: joint forces {dict(sorted(sums.items()))}, worst {worst:.2g}")
        check(cycles["LOCAL"] is not None, f"column {kind}: SOLVE balances under DAMP LOCAL (ratio 1e-7)",
              out[-1500:])
        check(sorted(sums) == [1, 2, 3, 4, 5] and worst < 5e-6,
              f"column {kind}: under DAMP LOCAL each joint carries the weight above it (5e-6)", str(sums))
    print(f"column {kind}: SOLVE RATIO 1e-7 after {cycles['LOCAL']} cycles under DAMP LOCAL, "
          f"{cycles['AUTO']} under DAMP AUTO")

# --- 2. Kirsch under BOUNDARY STRESS alone, DAMP LOCAL 0.3 -------------------
out = run_clean(udec, "kirsch_local", kirsch_boundary_stress("DAMP LOCAL 0.3", 15000))
check_kirsch_bs("kirsch LOCAL", out, 150, 20, 1e-3)

# --- 3. input, PRINT, SAVE / RESTART, HIST DAMP --------------------------------
BLOCK = """ROUND 0.01
BLOCK 0,0 0,1 1,1 1,0
CRACK -1,0.5 2,0.5
PROP MAT=1 DENS=2000 JKN=1E9 JKS=1E9 JFRIC=1
FIX 0,1 0,0.5
GRAV 0 -10
"""
folder = workdir()
BAD = ["DAMP LOCAL 1.5", "DAMP LOCAL 0", "DAMP LOCAL AUTO", "DAMP LOCAL 0.5 0.2"]
# at the prompt (stdin), where a refused command does not end the session
session = BLOCK + "DAMP AUTO\n" + "".join(f"{b}\nPRINT STATUS\n" for b in BAD) + \
    "DAMP LOCAL 0.6\nHIST DAMP\nCYCLE 20\nPRINT STATUS\nPRINT HIST 1\nSAVE loc.sav\nRESTART loc.sav\n" \
    "PRINT STATUS\nSTOP\n"
rc, out = run(udec, [], cwd=folder, stdin_text=session, timeout=120)
check(rc == 0, "input: the session ends with STOP (exit 0)", out[-2000:])
errors = re.findall(r"\*\*\* Error: (DAMPING[^\n]*)", out)
print("input:", errors)
check(len(errors) == len(BAD) and all("LOCAL" in e for e in errors),
      "input: each bad DAMP LOCAL is refused naming DAMPING LOCAL", str(errors))
status = re.findall(r"damping\s+(.*)", out)
print("status:", status)
check(len(status) == len(BAD) + 2 and all(s.startswith("auto") for s in status[:len(BAD)]),
      "input: a refused DAMP LOCAL leaves the damping as it was (AUTO)", str(status))
check(all("local" in s and "0.6" in s for s in status[len(BAD):]),
      "state: PRINT STATUS names LOCAL and alpha 0.6, also after SAVE and RESTART", str(status))
table = re.search(r"TIME\s+1 DAMP\n(.*?)\n\s*column 1", out, re.S)
hist = re.findall(r"^\s*[0-9.Ee+-]+\s+([0-9.Ee+-]+)\s*$", table.group(1) if table else "", re.M)
check(len(hist) > 0 and all(abs(float(v) - 0.6) < 1e-12 for v in hist),
      "state: HIST DAMP records alpha under DAMP LOCAL", str(hist[:5]))

# --- 4. the step of the gridpoints under DAMP LOCAL ------------------------------
WEDGE = """ROUND 0.01
BLOCK 0,0 0,1 2,1 2,0
CRACK 0,0.75 2,1
GEN AUTO 0.25
PROP MAT 1 DENS 2600 K 3.3333E9 G 2E9
PROP JMAT 1 JKN 1E10 JKS 1E10 JFRIC 0.5
INSITU STRESS -1E6 0 -1E6
BOUND STRESS -1E6 0 -1E6
DAMP {damp}
CYCLE 500
PRINT MAX
STOP
"""
steps = {}
for damp in ("AUTO", "LOCAL 0.3", "LOCAL 0.8"):
    out = run_clean(udec, "wedge_" + damp.replace(" ", "_").lower(), WEDGE.format(damp=damp))
    m = re.search(r"timestep\s+(\S+),", out)
    steps[damp] = float(m.group(1)) if m else float("nan")
    vel = printed_number(out, "max gridpoint velocity")
    print(f"wedge {damp}: step {steps[damp]:.5g}, max gridpoint velocity {vel:.3g}")
    check(vel < 1e-9, f"wedge {damp}: the zoned 7 degree wedge stays at rest (< 1e-9 m/s)", out[-1500:])
for alpha in (0.3, 0.8):
    ratio = steps[f"LOCAL {alpha}"] / steps["AUTO"]
    print(f"wedge: step under LOCAL {alpha} / AUTO = {ratio:.6f}, closed form {1 / (1 + alpha) ** 0.5:.6f}")
    check(abs(ratio * (1 + alpha) ** 0.5 - 1) < 1e-4,
          f"wedge: the gridpoints' step under DAMP LOCAL {alpha} is AUTO's / sqrt(1 + alpha)", str(steps))
finish()
