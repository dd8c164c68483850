"""Free-field lateral boundaries (FFIELD, BOUNDARY FF; UDEC manual (ICG1.5,
1989), Section 3.8.2, Eqs. 31-36), checked against a closed form.

Model: a column 5 m wide and 100 m high cut by a vertical joint at x = 2
(JSET 90: "jointed"; elastic joints JKN = JKS = 1e10 Pa/m), zoned GEN QUAD
0.5, rho = 2000, K = 1e9, G = 6e8 Pa, so c_s = sqrt(G / rho) = 547.72 m/s.
The base is viscous (far field of the same material) and carries the shear
stress sxy = -2e6 sin(2 pi 8 t) for one period (BOUND STRESS, HIST SINE
8 0.125); the top is free. Both sides are viscous and tied to a free
field of 401 gridpoints (FFIELD GEN 0 100 401) whose base carries the same
stress and dashpots (FFIELD SXY, XVISC, YVISC).

Closed form (1-D shear wave, normal incidence): the stress s on a viscous
base whose far field has the model's impedance rho c_s drives the upward
wave v_x(y, t) = s / (2 rho c_s) sin(2 pi f (t - y / c_s)) for
0 <= t - y / c_s <= 1 / f (amplitude 0.91287 m/s), the same at every x; a
vertical joint sees no relative motion in it. 1700 steps reach t = 0.149 s:
the wave front (100 / c_s = 0.183 s) has not reached the top, so nothing
comes back. Checks:
* the gridpoints of the lateral boundaries move as the interior at the same
  height (x = 0 and x = 5 against x = 2.5, at y = 10 and y = 40): largest
  difference over the run below 1 % of the amplitude (no wave is reflected
  from the sides);
* the model moves as the free-field column: at the end (the pulse between
  y = 13 and 82 m) the x-velocity of the gridpoints of the line x = 2.5
  against PRINT FF at the same heights: below 1 %;
* against the closed form: peak within 1 % and the arrival of the peak at
  y / c_s + 1 / (4 f) within 1 % of the period;
* no vertical motion (below 1 % of the amplitude) at the side;
* control: the same model with plain viscous sides (no free field): the
  dashpots against a far field at rest take the wave out of this narrow
  column, the interior peak at y = 10 is more than 20 % below the closed
  form (measured -97 % at 650 steps). So the checks can fail.
Measured (Release): peak +0.09 % (y = 10), +0.13 % (y = 40); sides
against interior 0.48 % and 0.61 %; model against column 0.60 %.
The free field's spacing matters: GEN QUAD zones have a centre gridpoint,
so the model's rows of gridpoints are 0.25 m apart; a column of that
spacing (401 gridpoints) follows the model best (at 12.5 Hz: 0.6 % side
against interior for 401 gridpoints, 1.9 % for 201). The shorter the
waves the larger the difference between the model's grid and the column's
(25 Hz, 0.5 m zones: 1.4 %; 50 Hz: 3.5 %). The manual says as much ("The
free-field mesh should be fine enough", Section 3.8.2.3).
"""
import math
import sys
from udec_test import check, finish, histories, run, workdir, write

udec = sys.argv[1]
RHO, K, G = 2000.0, 1.0e9, 6.0e8
CS = math.sqrt(G / RHO)
S = 2.0e6
F = 8.0
V0 = S / (2.0 * math.sqrt(RHO * G))
NCYC = 1700

DECK = """ROUND 0.01
BLOCK 0,0 0,100 5,100 5,0
JSET 90,0 200,0 0,0 5,0 (2,0)
GEN QUAD 0.5
CHANGE CONS 1 MAT 1
CHANGE JMAT 1 JCONS 2
PROP MAT 1 D 2000 K 1E9 G 6E8 JKN 1E10 JKS 1E10 JF 0.5 JCOH 1E9 JTENS 1E9
BOUND MAT 1
BOUND -0.1 5.1 -0.1 0.1 XVISC YVISC
BOUND -0.1 5.1 -0.1 0.1 STRESS 0 -2E6 0
BOUND -0.1 0.1 -0.1 100.1 XVISC YVISC {ff}
BOUND 4.9 5.1 -0.1 100.1 XVISC YVISC {ff}
BOUND HIST SINE 8 0.125
{ffield}
HIST N 1 XVEL 2.5 10 XVEL 0 10 XVEL 5 10 XVEL 2.5 40 XVEL 0 40 XVEL 5 40 YVEL 0 10
CYCLE {ncyc}
{prints}
PRINT 2.4 2.6 -0.1 100.1 GRIDPOINTS
STOP
"""
FFIELD = """FFIELD GEN 0 100 401
FFIELD MAT 1 CONS 1
FFIELD SXY -2E6 XVISC YVISC"""




def ff_column(out):
    """{y: vx} of the free-field gridpoints (PRINT FF)."""
    col, mode = {}, False
    for line in out.splitlines():
        f = line.split()
        if f[:2] == ["GP", "Y"]:
            mode = True
            continue
        if mode and len(f) == 6:
            col[round(float(f[1]), 2)] = float(f[2])
            continue
        mode = False
    return col


def model_column(out):
    """{y: vx} of the model's gridpoints on x = 2.5 (PRINT range GRIDPOINTS)."""
    col, names = {}, None
    for line in out.splitlines():
        f = line.split()
        if f[:2] == ["GRIDPT", "BLOCK"]:
            # columns by name: only the table with the velocities, which may gain columns
            names = f if "X-VEL" in f else None
            continue
        if names and len(f) == len(names):
            col[round(float(f[names.index("Y")]), 2)] = float(f[names.index("X-VEL")])
            continue
        names = None
    return col


def model(ff, ncyc=NCYC):
    d = workdir()
    prints = "\n".join("PRINT HIS %d" % i for i in range(1, 8))
    if ff:
        prints += "\nPRINT FF"
    deck = DECK.format(ff="FF" if ff else "", ffield=FFIELD if ff else "", ncyc=ncyc,
                       prints=prints)
    write(d, "ff.dat", deck)
    rc, out = run(udec, ["ff.dat"], cwd=d, timeout=300)
    check(rc == 0, f"free field {ff}: deck runs", out[-2000:])
    return out


def window(rows, y):
    return rows


out = model(True)
h = histories(out)
check(len(h) == 7, "seven histories printed", str(len(h)))
if len(h) == 7:
    for y, (ci, cl, cr) in ((10.0, (0, 1, 2)), (40.0, (3, 4, 5))):
        mid, left, right = window(h[ci], y), window(h[cl], y), window(h[cr], y)
        peak = max(abs(v) for _, v in mid)
        dl = max(abs(a[1] - b[1]) for a, b in zip(mid, left))
        dr = max(abs(a[1] - b[1]) for a, b in zip(mid, right))
        print(f"y = {y:g}: interior peak {peak:.5f} (closed form {V0:.5f}, "
              f"{100 * (peak / V0 - 1):+.2f} %); left side differs by {100 * dl / V0:.3f} %, "
              f"right side by {100 * dr / V0:.3f} % of the amplitude")
        check(dl < 0.01 * V0 and dr < 0.01 * V0,
              f"y = {y:g}: the lateral boundary moves as the interior (within 1 %)",
              f"left {dl:.4e}, right {dr:.4e}, amplitude {V0:.4e}")
        check(abs(peak / V0 - 1) < 0.01, f"y = {y:g}: peak within 1 % of s / (2 rho c_s)",
              f"{peak:.5f} vs {V0:.5f}")
        tp = max(mid, key=lambda r: r[1])[0]
        expect = y / CS + 0.25 / F
        print(f"y = {y:g}: peak at t = {tp:.5f} s, closed form {expect:.5f} s")
        check(abs(tp - expect) < 0.01 / F, f"y = {y:g}: peak arrives at y / c_s + T / 4 "
              "(within 1 % of the period)", f"{tp:.5f} vs {expect:.5f}")
    vy = max(abs(v) for _, v in window(h[6], 10.0))
    check(vy < 0.01 * V0, "no vertical motion at the side (S wave only)", f"{vy:.3e}")
    # the model against the free-field column at the same instant, all heights
    ffc, mc = ff_column(out), model_column(out)
    common = sorted(set(ffc) & set(mc))
    check(len(common) == 201, "the model's 201 heights on x = 2.5 are in the free field",
          str(len(common)))
    if common:
        worst = max(abs(ffc[y] - mc[y]) for y in common)
        peak = max(abs(ffc[y]) for y in common)
        print(f"t = end: model (x = 2.5) vs free-field column over 201 heights: largest "
              f"difference {100 * worst / V0:.3f} % of the amplitude (column peak {peak:.5f})")
        check(peak > 0.9 * V0, "the snapshot holds the pulse", f"{peak:.4e}")
        check(worst < 0.01 * V0, "the model moves as the free-field column (within 1 %)",
              f"{worst:.4e}")

# bad input: a clear error naming the command, and a rejected line changes nothing
SMALL = """ROUND 0.01
BLOCK 0,0 0,10 2,10 2,0
GEN QUAD 1
CHANGE CONS 1 MAT 1
PROP MAT 1 D 2000 K 1E9 G 6E8
BOUND MAT 1
BOUND -0.1 2.1 -0.1 0.1 XVISC YVISC STRESS 0 -1E5 0
BOUND -0.1 0.1 -0.1 10.1 XVISC YVISC FF
BOUND 1.9 2.1 -0.1 10.1 XVISC YVISC FF
{body}
STOP
"""
for line, words in (("FFIELD MAT 2", "FFIELD GEN"),
                    ("FFIELD GEN 0 10 11\nFFIELD GEN 5 1 11", "yu > yl"),
                    ("FFIELD GEN 0 10 11\nFFIELD 3 MAT 2", "two y-coordinates"),
                    ("FFIELD GEN 0 10 11\nFFIELD CONS 4", "CONS"),
                    ("FFIELD GEN 0 10 11\nFFIELD 0 5", "MAT n / CONS n")):
    d = workdir()
    write(d, "e.dat", SMALL.format(body=line))
    rc, out = run(udec, ["e.dat"], cwd=d)
    check(rc != 0 and "*** Error: FFIELD" in out and words in out,
          f"bad input refused with a message: {line.splitlines()[-1]}", out[-600:])

# a scene pays only for what it uses: the stage is in the list only when on
d = workdir()
write(d, "s.dat", SMALL.format(body="PRINT CYCLE\nFFIELD GEN 0 10 11\nPRINT CYCLE\n"
                                     "FFIELD OFF\nPRINT CYCLE"))
rc, out = run(udec, ["s.dat"], cwd=d)
parts = out.split("Stages of a step")
stage = "the 1-D free-field column"
check(rc == 0 and len(parts) == 4 and stage not in parts[1]
      and stage in parts[2] and stage not in parts[3],
      "the free-field stage runs only with FFIELD GEN / ON", out[-1500:])

# SAVE / RESTART keeps the column: CYCLE 100 twice in one run against
# CYCLE 100, SAVE, RESTART, CYCLE 100 (PRINT FF identical)
BODY = """FFIELD GEN 0 10 21
FFIELD SXY -1E5 XVISC YVISC
CYCLE 100
{mid}
CYCLE 100
PRINT FF"""
res = []
for mid in ("", "SAVE ff.sav\nRESTART ff.sav"):
    d = workdir()
    write(d, "r.dat", SMALL.format(body=BODY.format(mid=mid)))
    rc, out = run(udec, ["r.dat"], cwd=d)
    check(rc == 0, "save/restart deck runs", out[-800:])
    res.append(out[out.rfind("FREE FIELD"):])
check(len(res[0]) > 200 and res[0] == res[1], "the free field continues the same after RESTART",
      res[0][:400] + "\n---\n" + res[1][:400])

# control: plain viscous sides reflect
# (650 steps, t = 0.057 s: past the peak at y = 10, 0.0495 s)
out = model(False, 650)
h = histories(out)
if len(h) == 7:
    mid, left = window(h[0], 10.0), window(h[1], 10.0)
    dl = max(abs(a[1] - b[1]) for a, b in zip(mid, left))
    peak = max(abs(v) for _, v in mid)
    print(f"control (viscous sides, no free field): the side differs by {100 * dl / V0:.1f} %, "
          f"interior peak {peak:.5f} ({100 * (peak / V0 - 1):+.1f} %)")
    check(peak < 0.8 * V0, "control: without the free field the lateral dashpots distort the "
          "wave (interior peak more than 20 % below the closed form)", f"{peak:.4e}")
finish()
