"""Non-reflecting (viscous) boundaries, BOUNDARY XVISC / YVISC / MAT n
(manual Section 3.8.1.2, Eq. 30), against closed forms of plane waves and
of a dashpot-driven rigid block.

Model for the waves: a 1 m x 20 m zoned column (GEN QUAD 0.25), rho = 2000,
K = 1e9, G = 6e8 Pa, so c_p = sqrt((K + 4G/3)/rho) = 948.68 m/s and
c_s = sqrt(G/rho) = 547.72 m/s. The base carries a sine stress pulse (50 Hz,
one period) and a viscous boundary; the top is viscous. For a P pulse the
sides are rollers (x-velocity 0), for an S pulse the sides are held in y.

Closed forms (normal incidence, Lysmer-Kuhlemeyer dashpots are exact):
* a stress s applied on a viscous boundary whose far field has the model's
  impedance Z = rho c drives the wave v = s / (2 Z) (half the stress goes
  into the dashpot; the manual, Section 5: "double the applied stress");
* with a far field of impedance Z_ff: v = s / (Z + Z_ff);
* the viscous top absorbs the wave: nothing comes back, against 100 % of
  the amplitude for a free top.
Tolerances: amplitudes 1 % (the column has 76 zones per P wavelength, 44
per S wavelength). The discrete boundary does reflect a little: the
dashpot force comes from the velocity of the step just taken (half a step
late, as the manual's Section 3.8.1.2 says of its scheme), an error of
order omega dt, and the lumped boundary mass adds one of order k h.
Measured (gauge at y = 5) for the P pulse: 1.12 % at the default
FRACTION, 0.43 % at FRACTION 0.1; for the S pulse (shorter waves) 1.77 %. So
the checks are: P reflection below 2 % at the default step and below
0.6 % at FRACTION 0.1 (it must fall with the step), S reflection below
2.5 %. A wrong impedance fails by far: c_s instead of c_p in the normal
dashpot reflects (c_p - c_s)/(c_p + c_s) = 27 %.

Rigid block: a 1 m x 1 m block pushed by 2000 N with a viscous face of
length 1 m (far field rho = 1000, K = G = 1e6): terminal velocity
F / (rho c_p L) = 0.041404 m/s, to 1e-6 relative.

The "stiff" mode (label stability) runs a far field 100 times denser and
100 times stiffer (impedance 100 Z) for 40 000 steps: the step is reduced to
the dashpots' stable step, nothing blows up and v = s / (Z + 100 Z).
"""
import math
import sys
from udec_test import check, finish, histories, run, workdir, write

udec = sys.argv[1]
mode = sys.argv[3] if len(sys.argv) > 3 else "mechanics"

RHO, K, G = 2000.0, 1.0e9, 6.0e8
ZP = math.sqrt(RHO * (K + 4.0 * G / 3.0))
ZS = math.sqrt(RHO * G)

COLUMN = """ROUND 0.01
BLOCK 0,0 0,20 1,20 1,0
GEN QUAD 0.25
CHANGE CONS 1 MAT 1
PROP MAT 1 D 2000 K 1E9 G 6E8
{farfield}
BOUND -0.1 1.1 -0.1 0.1 XVISC YVISC
BOUND -0.1 1.1 19.9 20.1 {top}
BOUND -0.1 1.1 -0.1 0.1 STRESS {stress}
BOUND -0.1 0.1 0.1 19.9 {side}
BOUND 0.9 1.1 0.1 19.9 {side}
BOUND HIST SINE 50 0.02
{fraction}
HIST N 1 {comp} 0.5 5 {comp} 0.5 20
CYCLE {ncyc}
PRINT HIS 1
PRINT HIS 2
STOP
"""




def column(name, stress, comp, side, top, farfield, ncyc, fraction=""):
    d = workdir()
    write(d, "c.dat", COLUMN.format(stress=stress, comp=comp, side=side, top=top,
                                     farfield=farfield, ncyc=ncyc, fraction=fraction))
    rc, out = run(udec, ["c.dat"], cwd=d)
    check(rc == 0, f"{name}: deck runs", out[-1500:])
    h = histories(out)
    check(len(h) == 2 and all(len(t) > 10 for t in h), f"{name}: two histories printed",
          str([len(t) for t in h]))
    return out, h


def peak(rows, t0=0.0, t1=1.0e9):
    return max((abs(v) for t, v in rows if t0 <= t <= t1), default=0.0)


if mode == "mechanics":
    s = 2.0e6
    # P wave: stress syy at the base, rollers on the sides
    for top, label, expect_reflection, fraction, ncyc, limit in (
            ("XVISC YVISC", "viscous top", False, "", 1000, 0.02),
            ("XVISC YVISC", "viscous top, FRACTION 0.1", False, "FRACTION 0.1 0.1", 9200, 0.006),
            ("XLOAD 0", "free top", True, "", 1000, 0.0)):
        out, h = column(f"P wave, {label}", "0 0 -2E6", "YVEL", "XVEL 0", top, "BOUND MAT 1", ncyc,
                        fraction)
        if len(h) < 2:
            continue
        v = s / (2.0 * ZP)
        mid = h[0]
        # the incident pulse passes the gauge at y = 5 between 5/cp and 5/cp + 0.02 s
        t_in = 5.0 / math.sqrt((K + 4 * G / 3) / RHO)
        a = peak(mid, 0.0, t_in + 0.03)
        check(abs(a / v - 1.0) < 0.01, f"P wave, {label}: amplitude s / (2 rho c_p)",
              f"{a:.5e} vs {v:.5e} ({100 * (a / v - 1):+.2f} %)")
        # a reflection from the top reaches y = 5 after 35 / c_p and is gone by
        # 35 / c_p + 0.02 (the numerical tail of the incident pulse is gone by then)
        back = peak(mid, 7.0 * t_in + 0.001, 7.0 * t_in + 0.019)
        if expect_reflection:
            check(back > 0.9 * v, f"P wave, {label}: the free top reflects the wave",
                  f"{back:.3e} vs {v:.3e}")
            check(peak(h[1]) > 1.9 * v, f"P wave, {label}: free surface velocity doubles",
                  f"{peak(h[1]):.4e} vs 2 x {v:.4e}")
        else:
            print(f"P wave, {label}: amplitude {a:.5e} (exact {v:.5e}), reflection {100 * back / v:.2f} %")
            check(back < limit * v, f"P wave, {label}: reflection below {100 * limit:g} % "
                  "of the amplitude", f"{back:.3e} vs {v:.3e} ({100 * back / v:.2f} %)")
            top_peak = peak(h[1])
            check(abs(top_peak / v - 1.0) < 0.01, f"P wave, {label}: the top moves with the wave "
                  "(no doubling)", f"{top_peak:.5e} vs {v:.5e}")
    # S wave: shear stress at the base, sides held in y (shear column)
    out, h = column("S wave", "0 -2E6 0", "XVEL", "YVEL 0", "XVISC YVISC", "BOUND MAT 1", 1700)
    if len(h) == 2:
        v = s / (2.0 * ZS)
        t_in = 5.0 / math.sqrt(G / RHO)
        a = peak(h[0], 0.0, t_in + 0.03)
        check(abs(a / v - 1.0) < 0.01, "S wave: amplitude tau / (2 rho c_s)",
              f"{a:.5e} vs {v:.5e} ({100 * (a / v - 1):+.2f} %)")
        back = peak(h[0], 7.0 * t_in + 0.001, 7.0 * t_in + 0.019)
        print(f"S wave: amplitude {a:.5e} (exact {v:.5e}), reflection {100 * back / v:.2f} %")
        check(back < 0.025 * v, "S wave: reflection from the viscous top below 2.5 %",
              f"{back:.3e} vs {v:.3e} ({100 * back / v:.2f} %)")

    # a held base made viscous keeps its static reaction (and RESET HIST
    # renumbers): a 1 m x 10 m column under gravity (rho g H = 2e5 Pa at the
    # base) on a YVEL 0 base, rollers on the sides, brought to equilibrium with
    # DAMP AUTO; then RESET HIST, two new velocity histories (numbered 1 and
    # 2), the base made XVISC YVISC, no damping, 2000 steps. Reference: the
    # column stays at rest. Had the base lost its reaction, it would start down
    # at rho g H / (rho c_p) = 0.105 m/s; the check allows 1e-3 of that
    # (measured 6e-6 m/s: what DAMP AUTO left of the static run).
    d = workdir()
    write(d, "s.dat", """ROUND 0.01
BLOCK 0,0 0,10 1,10 1,0
GEN QUAD 0.5
CHANGE CONS 1 MAT 1
PROP MAT 1 D 2000 K 1E9 G 6E8
GRAV 0 -10
BOUND -0.1 1.1 -0.1 0.1 YVEL 0
BOUND -0.1 0.1 -0.1 10.1 XVEL 0
BOUND 0.9 1.1 -0.1 10.1 XVEL 0
DAMP AUTO
HIST N 10 YDIS 0.5 10 UNBAL
CYCLE 4000
RESET HIST
HIST N 5 YVEL 0.5 0 YVEL 0.5 10
BOUND MAT 1
BOUND -0.1 1.1 -0.1 0.1 XVISC YVISC
DAMP 0 0
CYCLE 2000
PRINT HIS 1
PRINT HIS 2
PRINT HIS 3
STOP
""")
    rc, out = run(udec, ["s.dat"], cwd=d)
    check(rc == 0, "held base made viscous: deck runs", out[-1500:])
    h = histories(out)
    check(len(h) == 2 and all(len(t) == 400 for t in h),
          "RESET HIST: the next HISTORY numbers from 1 (two histories, 400 samples each)",
          str([len(t) for t in h]))
    check("history 3 is not defined (2 defined)" in out,
          "RESET HIST: the old third history is gone (PRINT HIS 3 says so)", out[-600:])
    v_drop = RHO * 10.0 * 10.0 / ZP
    vmax = max((peak(t) for t in h), default=1.0)
    check(vmax < 1e-3 * v_drop, "held base made viscous: the column stays at rest "
          "(the static reaction becomes the base load)", f"{vmax:.3e} m/s vs {v_drop:.3e}")

    # rigid block driven against a dashpot
    d = workdir()
    write(d, "r.dat", """BLOCK 0,0 0,1 1,1 1,0
PROP MAT 1 D 1000
PROP MAT 2 D 1000 K 1E6 G 1E6
BOUND MAT 2
BOUND -0.1 0.1 -0.1 1.1 XVISC
BOUND 0.9 1.1 -0.1 1.1 XLOAD 1000
CYCLE 100
PRINT RIGID
STOP
""")
    rc, out = run(udec, ["r.dat"], cwd=d)
    check(rc == 0, "rigid block: deck runs", out[-1500:])
    vel = [float(f[2]) for f in (l.split() for l in out.splitlines()) if len(f) == 9 and f[0] == "1"]
    vt = 2000.0 / (math.sqrt(1000.0 * (1.0e6 + 4.0e6 / 3.0)) * 1.0)
    check(len(vel) == 1 and abs(vel[0] / vt - 1.0) < 1e-6, "rigid block: terminal velocity "
          "F / (rho c_p L)", f"{vel} vs {vt:.6e}")

    # errors: no far-field material, a bad material number, a material without density
    d = workdir()
    session = """ROUND 0.01
BLOCK 0,0 0,1 1,1 1,0
GEN QUAD 0.5
PROP MAT 1 D 1000 K 1E9 G 1E9
BOUND -0.1 1.1 -0.1 0.1 XLOAD 0
BOUND -0.1 1.1 -0.1 0.1 XVISC
BOUND MAT 0
PRINT BOUNDARY STATE
BOUND -0.1 1.1 -0.1 0.1 MAT 3 YVISC
CYCLE 1
STOP
"""
    # typed at the prompt (standard input): an error does not end the session
    rc, out = run(udec, [], cwd=d, stdin_text=session)
    check("has no far-field material: give BOUNDARY MAT n" in out,
          "XVISC without MAT is refused, naming the corner", out[-1500:])
    check("BOUNDARY MAT: expected an integer >= 1" in out, "MAT 0 is refused", out[-1500:])
    # PRINT BOUNDARY STATE rows: COR .. MAT (12 fields) and ADDRESS
    states = [f for f in (l.split() for l in out.splitlines()) if len(f) == 13 and f[0].isdigit()]
    check(len(states) == 8 and all(f[5] != "3" and f[6] != "3" and f[11] == "0" for f in states),
          "a refused XVISC leaves the boundary unchanged", str(states[:3]))
    check("far-field material 3 of the viscous boundary" in out and "needs DENSITY > 0" in out,
          "CYCLE refuses a far-field material without properties", out[-1500:])
else:
    # stiff far field: impedance 100 Z, long run
    out, h = column("stiff far field", "0 0 -2E6", "YVEL", "XVEL 0", "XVISC YVISC",
                    "PROP MAT 2 D 2E5 K 1E11 G 6E10\nBOUND MAT 2", 40000)
    if len(h) == 2:
        v = 2.0e6 / (ZP + 100.0 * ZP)
        a = peak(h[0])
        check(abs(a / v - 1.0) < 0.01, "stiff far field: amplitude s / (Z + Z_ff)",
              f"{a:.5e} vs {v:.5e} ({100 * (a / v - 1):+.2f} %)")
        check(all(math.isfinite(x) for _, x in h[0] + h[1]) and peak(h[1]) < 2.0 * v,
              "stiff far field: 40 000 steps, bounded velocities", f"{peak(h[1]):.3e}")
        check("limits the time step" in out, "stiff far field: the step limit is reported",
              out[:3000])
finish()
