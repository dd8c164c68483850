"""The decks of the user's guide physics pages (examples/guide/*.dat) run as
they are and give what the pages say, against closed forms. Label
`examples;e2e`. usage: guide_decks.py udec source_dir deck

deformable (docs/guide/deformable.md): a column of a fixed rigid footing,
    an SDEF block and a zoned Mohr-Coulomb block under a top stress
    s = -2 MPa, frictionless joints, free sides. Reference: plane-strain
    uniaxial stress, eyy = s (1 - nu^2) / E = -6.25e-5 (E = 30 GPa,
    nu = 0.25): the SDEF block's EYY within 0.5 %, the zoned block's strain
    between the gridpoints at y = 1.25 and y = 2 within 1 % (measured
    -0.004 % and -0.14 %); every zone elastic (2 MPa is below the
    unconfined strength 2 c cos(phi) / (1 - sin(phi)) = 3.46 MPa).
dynamics (docs/guide/dynamics.md): a 250 Hz P wave (stress amplitude 1 MPa
    on a viscous base) crosses a joint of normal stiffness kn = 7.75e9 Pa/m
    in a column with rollers on its sides and a viscous top. References:
    the incident velocity amplitude s / (2 rho c_p) (the manual, Section
    3.8: half the applied stress goes into the dashpot), within 1 % below
    the joint before the reflection comes back; the transmitted amplitude
    of a harmonic wave through a spring joint, |T| = 1 / sqrt(1 + (omega
    rho c_p / (2 kn))^2) = 0.707, within 2 % over the steady cycles above
    the joint (measured +0.6 %; the first half cycle, a transient, passes
    at 0.756 and is left out).
flow (docs/guide/flow.md): steady flow along one 10 m joint of aperture
    0.1 mm between pressures of 0.2 and 0.1 MPa, the rock under 1 MPa
    (INSITU) so that the joint stays closed. Reference: the cubic law,
    the manual's Eq. 54, q = kj a^3 dp / L with kj = JPERM: within 0.2 %
    using the printed apertures (their mean), within 1 % using AZERO
    (without INSITU the water opens the joint by up to 1.1e-5 m and the
    flow is 25 % higher: un follows the opening since nu-zoned, session 35;
    before, the aperture froze 0.1 % open); the domain pressures on a straight
    line between the two ends within 0.1 % of dp; inflow = outflow.
heat (docs/guide/heat.md): a rock strip (k = 3 W/(m K), rho Cp = 2.43e6)
    whose face is held at 100 C for ten days. Reference: the semi-infinite
    solid, T = T0 erfc(x / (2 sqrt(kappa t))) (Carslaw and Jaeger, Section
    2.5; the far end at 10 m is out of reach, erfc(4.8) < 1e-10), at 1, 2
    and 3 m within 1 % of T0 (measured within 0.06 C).
structures (docs/guide/structures.md): a concrete liner (E = 30 GPa, t =
    0.2 m) put in a circular tunnel (R = 2 m) as it is excavated in elastic
    rock (G = 4 GPa) under 10 MPa. Reference: the liner, a thin ring,
    shortens by u = p R^2 / (E t) under the rock pressure p; the rock wall
    moves u = (p0 - p) R / (2 G); so p = p0 / (1 + 2 G R / (E t)) and the
    thrust N = p R = 5.455 MN/m: the mean of the elements' thrusts within 3 %
    (measured -0.2 %), every element within 1 % of the mean (a uniform
    load). The liner's 24 nodes (PRINT LM) sit at the midpoints of the
    tunnel's 24 edges and move 1.81 mm; the wall's vertices between them,
    where the history gridpoints are, move 0.07 mm further (+3.7 % on the
    closed form): checked at 0 to +6 %.
"""
import math
import os
import re
import sys
sys.path.insert(0, os.path.dirname(__file__))
from udec_test import check, finish, run, tables, workdir  # noqa: E402

udec, root, name = sys.argv[1], sys.argv[2], sys.argv[3]
deck = os.path.join(root, "examples", "guide", name + ".dat")
folder = workdir()
rc, out = run(udec, [deck], cwd=folder, timeout=1200)
check(rc == 0 and "***" not in out, f"{name}: the deck runs without error or warning", out[-2000:])
check(os.path.getsize(os.path.join(folder, name + ".png")) > 1000 if os.path.exists(
    os.path.join(folder, name + ".png")) else False, f"{name}: the picture {name}.png is written")


def after(text, echo):
    """The output after the echo of `echo` (to the next echoed command)."""
    return text.split(echo, 1)[1] if echo in text else ""


def hist_table(text, echo):
    """Rows of the PRINT HIST / THIST table after `echo`: lists of floats."""
    rows = []
    for line in after(text, echo).splitlines()[2:]:
        try:
            rows.append([float(v) for v in line.split()])
        except ValueError:
            break
    return rows


if name == "deformable":
    E, NU, S = 3.0e10, 0.25, -2.0e6
    ref = S * (1.0 - NU * NU) / E
    sd = tables(out, "PRINT SDEF")
    eyy = sd[0][0]["EYY"] if sd and sd[0] else float("nan")
    print(f"SDEF eyy {eyy:.6e} vs {ref:.6e} ({100 * (eyy / ref - 1):+.3f} %)")
    check(abs(eyy / ref - 1.0) < 0.005, "deformable: SDEF eyy = s (1 - nu^2) / E within 0.5 %")
    gp = {}
    for line in after(out, "PRINT 0.4 0.6 1.2 2.1 GRID DISP").splitlines()[2:]:
        f = line.split()
        if len(f) < 6 or not f[0].isdigit():
            break
        gp[round(float(f[3]), 2)] = float(f[5])
    ok = 1.25 in gp and 2.0 in gp
    check(ok, "deformable: gridpoints at y = 1.25 and 2 printed", str(gp))
    if ok:
        ez = (gp[2.0] - gp[1.25]) / 0.75
        print(f"zoned eyy {ez:.6e} vs {ref:.6e} ({100 * (ez / ref - 1):+.3f} %)")
        check(abs(ez / ref - 1.0) < 0.01, "deformable: zoned block eyy within 1 %")
    zones = [l for l in after(out, "PRINT 0 1 1.5 2 ZONE STRESS").splitlines()[2:]
             if re.match(r"\s+\d+\s+\d+\s", l)]
    check(len(zones) >= 8 and all(l.rstrip().endswith("elastic") for l in zones),
          "deformable: the zones are elastic below the unconfined strength", str(zones[:3]))

elif name == "dynamics":
    RHO, K, G, KN, F, S = 2700.0, 2.0e10, 1.2e10, 7.75e9, 250.0, 1.0e6
    cp = math.sqrt((K + 4.0 * G / 3.0) / RHO)
    z = RHO * cp
    v_in = S / (2.0 * z)
    t_ref = 1.0 / math.sqrt(1.0 + (2.0 * math.pi * F * z / (2.0 * KN)) ** 2)
    rows = hist_table(out, "PRINT HIST 1 2")
    check(len(rows) > 500, "dynamics: the histories are printed", str(len(rows)))
    below = max((abs(r[1]) for r in rows if r[0] < 15.0 / cp), default=0.0)
    print(f"incident {below:.5e} vs {v_in:.5e} ({100 * (below / v_in - 1):+.2f} %)")
    check(abs(below / v_in - 1.0) < 0.01, "dynamics: incident amplitude s / (2 rho c_p) within 1 %")
    t0 = 15.0 / cp + 0.006
    above = max((abs(r[2]) for r in rows if t0 <= r[0] <= t0 + 0.014), default=0.0)
    ratio = above / v_in
    print(f"transmitted {ratio:.4f} vs {t_ref:.4f} ({100 * (ratio / t_ref - 1):+.2f} %)")
    check(abs(ratio / t_ref - 1.0) < 0.02, "dynamics: transmission 1/sqrt(1+(w Z/2kn)^2) within 2 %")

elif name == "flow":
    KJ, A0, DP, L = 83.33, 1.0e-4, 1.0e5, 10.0
    rows = []
    for line in after(out, "PRINT FLOWS").splitlines()[2:]:
        f = line.split()
        if not f or not f[0].isdigit():
            break
        rows.append([float(v) for v in f])
    inner = [r for r in rows if 0.1 < r[3] < 9.9]
    check(len(inner) >= 10, "flow: the joint's contacts are printed", str(len(rows)))
    if inner:
        q = -sum(r[6] for r in inner) / len(inner)
        a = sum(r[5] for r in inner) / len(inner)
        ref_a, ref_0 = KJ * a ** 3 * DP / L, KJ * A0 ** 3 * DP / L
        print(f"q {q:.6e}: cubic law {ref_a:.6e} with the mean aperture {a:.6e} "
              f"({100 * (q / ref_a - 1):+.3f} %), {ref_0:.6e} with AZERO ({100 * (q / ref_0 - 1):+.3f} %)")
        check(abs(q / ref_a - 1.0) < 0.002, "flow: cubic law with the printed aperture within 0.2 %")
        check(abs(q / ref_0 - 1.0) < 0.01, "flow: cubic law with AZERO within 1 %")
        check(max(abs(r[6] / inner[0][6] - 1.0) for r in inner) < 1e-3,
              "flow: the same flow rate through every contact (steady)")
    m = re.search(r"total boundary inflow\s+(\S+)\s+total boundary outflow\s+(\S+)", out)
    check(m is not None and abs(float(m.group(1)) / float(m.group(2)) - 1.0) < 1e-3,
          "flow: inflow = outflow", m.group(0) if m else "")
    doms = []
    for line in after(out, "PRINT DOMAINS").split("PRESSURE", 1)[-1].splitlines()[1:]:
        f = line.split()
        if len(f) < 6 or not f[0].isdigit():
            break
        doms.append((float(f[3]), float(f[1])))
    check(len(doms) >= 10, "flow: domain pressures printed", str(len(doms)))
    err = max((abs(p - (2.0e5 - DP * x / L)) for x, p in doms), default=1e9)
    print(f"domain pressures: largest departure from the straight line {err:.1f} Pa")
    check(err < 1e-3 * DP, "flow: pressure falls linearly along the joint within 0.1 % of dp")

elif name == "heat":
    KAPPA, T0 = 3.0 / (2700.0 * 900.0), 100.0
    rows = hist_table(out, "PRINT THIST 1 2 3")
    check(len(rows) >= 5, "heat: the temperature histories are printed", str(len(rows)))
    if rows:
        t = rows[-1][0]
        check(abs(t / 864000.0 - 1.0) < 0.01, "heat: RUN AGE reached ten days", str(t))
        for k, x in enumerate((1.0, 2.0, 3.0)):
            ref = T0 * math.erfc(x / (2.0 * math.sqrt(KAPPA * t)))
            print(f"T({x:g} m) {rows[-1][k + 1]:.4f} vs erfc {ref:.4f}")
            check(abs(rows[-1][k + 1] - ref) < 0.01 * T0, f"heat: T at {x:g} m within 1 % of T0")

elif name == "structures":
    G, E, T, R, P0 = 4.0e9, 9 * 1.667e10 * 1.25e10 / (3 * 1.667e10 + 1.25e10), 0.2, 2.0, 10.0e6
    p = P0 / (1.0 + 2.0 * G * R / (E * T))
    n_ref, u_ref = p * R, p * R * R / (E * T)
    axial = [float(l.split()[6]) for l in after(out, "PRINT STE").splitlines()
             if re.match(r"\s+\d+\s+\d+\s+\d+\s+2\s", l)]
    check(len(axial) == 24, "structures: 24 liner elements printed", str(len(axial)))
    if axial:
        thrust = -sum(axial) / len(axial)
        print(f"thrust {thrust:.5e} vs {n_ref:.5e} ({100 * (thrust / n_ref - 1):+.2f} %)")
        check(abs(thrust / n_ref - 1.0) < 0.03, "structures: liner thrust p R within 3 %")
        check(max(abs(-a / thrust - 1.0) for a in axial) < 0.01, "structures: uniform thrust (1 %)")
    rows = hist_table(out, "PRINT HIST 1 2")
    check(len(rows) > 10, "structures: wall histories printed", str(len(rows)))
    if rows:
        for k, label in ((1, "springline"), (2, "crown")):
            u = -rows[-1][k]
            print(f"{label}: {u:.5e} vs {u_ref:.5e} ({100 * (u / u_ref - 1):+.2f} %)")
            check(0.0 <= u / u_ref - 1.0 < 0.06, f"structures: {label} convergence within +6 %")
else:
    check(False, f"unknown guide deck {name}")
finish()
