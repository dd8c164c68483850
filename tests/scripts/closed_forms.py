"""Blocks on joints (rigid, and one zoned block) against closed forms,
decks written from the command syntax of the UDEC manual (ICG1.5, 1989),
Section 4.5 (label `verification`). Each case states its reference and tolerance.

1. A block on an inclined joint (a 2 x 1 block, density 2000, m = 4000 kg
   per metre, on a fixed base; the model is a rectangle turned by the slope
   angle a and cut by CRACK; GRAVITY 0 -10). The joint is first held by a
   large friction and the block settled (DAMP AUTO), then given its real
   properties and released with no damping (DAMP 0 1): the joint carries
   the block's weight from the start, so no normal bounce disturbs the
   friction. Reference (Newton, the Mohr-Coulomb law of Section 3.3,
   Eq. 8, c and phi the joint's): the block slides when
   m g sin a > c L + m g cos a tan phi and then accelerates at
   g sin a - g cos a tan phi - c L / m (L = 2 m, JCONS 2 keeps its
   cohesion); JCONS 5 loses cohesion at the first slip (Section 4.5,
   CHANGE JCONS 5), so it accelerates as if c = 0. The acceleration is
   taken from the second difference of the displacement along the slope at
   three times 1/3 s apart: 0.1 % (measured: below 1e-5 relative). When
   the joint holds (a = 15 degrees, tan phi = tan 20 degrees; or
   c = 7000 Pa with JCONS 5, where each contact of the block holds, the
   uphill one 12320 Pa normal under the moment of the slope force), the
   block moves less than 1e-6 m.
   The same with JCONS 1 (point contacts: KN, KS, CFRIC of Section 4.5,
   PROPERTY) and with the block zoned (GEN QUAD 0.5: five contacts on the
   joint, at its gridpoints), friction alone and with JCOH 2000 (JCONS 2):
   the same accelerations (measured: below 1e-5 relative) and holds. The
   zoned block slides with stiffness-proportional damping (DAMP 0.2 850
   STIFF: its first mode; the steady slide has no strain rate and no
   normal relative velocity, and the shear dashpot is off while sliding).
   Undamped, its ringing after the release grows while it slides with
   friction (the normal stress of the uphill contact swings from 0 to 30
   kPa about 5 kPa after 0.5 s, the same at a 2.5 times smaller zone step:
   a friction-driven flutter of the elastic block, not the scheme's), the
   uphill contact opens a fifth of the time, its cohesion is then lost and
   the block accelerates 4 % faster than the rigid block's closed form.
2. A block hanging under a fixed block on a horizontal joint (JKN 1e9,
   tension 2e4 Pa on 2 m): with JTENS 3e4 it hangs, the joint open by
   sigma / JKN = 2e-5 m (0.1 %); with JTENS 1e4 it breaks away and falls:
   y = -g t^2 / 2 (0.1 %).
3. Dilation (JDIL = tan psi = 0.1, JFRIC 0.5, JKN = JKS = 1e9): the block
   resting on the base is pushed along the joint by LOAD 30000 N (above
   the friction 20000 N) with mass-proportional damping above critical,
   so it creeps at a few cm/s: it rises by tan(psi) times its slide,
   dn = 0.1 ds, within 1e-4 m over 0.28 m of slide (28 mm of rise, more
   than twice the contact search margin, the rounding length 0.01). The joint is then locked
   (JFRIC 100), the block lifted off by a reversed gravity and set down
   again: it comes back to rest on the asperities it has ridden up, at
   the same height (within 1e-4 m). Before the dilation ridden up was
   recorded per contact (state ud) the contact, open by its geometric gap,
   let the block fall 19 mm.
4. An open dilatant joint carries nothing: the block of 3 with no gravity,
   pushed by LOAD 4000 N along the joint and 400 N away from it, leaves
   the joint at once (no tensile strength) and flies: x = F_x t^2 / (2 m),
   y = F_y t^2 / (2 m), within 1 % (the histories are sampled every 10
   cycles). Before the fix each step of shear of the open contact made a
   normal force kn tan(psi) |du_s| out of nothing: y came out 8.4 times
   the free flight.
5. A dilatant joint keeps its friction at speed: the 10 x 5 block of
   probe_rigid_decks' dilation deck (JFRIC 0.3, JDIL 0.1, JKN 1e9, a load
   of half its weight, DAMP AUTO) slides up to about 1 m/s, where one
   step's dilation, JKN L tan(psi) v dt, is as large as the normal force.
   Reference: Mohr-Coulomb while sliding, tau = tan(phi) sigma_n, at both
   contacts whenever the block moves faster than 0.05 m/s (1 %, measured
   below 1e-3). Before the slip took the dilation's strength into account
   (contact_joint_law) the ratio fell with the speed, to 0.01 at 1.3 m/s,
   and the contacts then opened in tension.
6. A block hanging on one bolt: the block of 2, its joint without tensile
   strength, held by REINFORCE across the joint at its middle (RASTIFF
   Ka = 1e7 N/m, RUAXIAL Fb = 1e5 N, RAEXP 1), mass damping above
   critical so that the load comes on monotonically. Reference: the
   manual's law for the axial force (Section 3.10.1.3, Eqs. 43, 44, "an
   identical yield function involving axial forces"): dF = Ka du (1 - F /
   Fb) integrates to F = Fb (1 - exp(-Ka u / Fb)), so the joint opens by
   u = -(Fb / Ka) ln(1 - W / Fb) = 5.108e-3 m under W = 4e4 N (0.5 %,
   measured -0.04 %).
"""
import math
import os
import sys
from shared_decks import turned
from udec_test import check, finish, run, workdir, write

udec = sys.argv[1]


def rows(path):
    with open(path) as f:
        return [[float(v) for v in l.split()] for l in f
                if l.strip() and not l.startswith("#")]


def slope_deck(adeg, fric, coh, jcons, zoned=False):
    a = math.radians(adeg)
    p, box = turned(a)
    x, y = p(5, 0.5).split(",")
    # JCONS 1 (point contacts) has its own keywords (Section 4.5, PROPERTY)
    kn, ks, fr, ch, te = ("KN", "KS", "CFRIC", "CCOH", "CTEN") if jcons == 1 else \
        ("JKN", "JKS", "JFRIC", "JCOH", "JTEN")
    lines = [f"HEAD block on a {adeg} degree joint, jfric {fric:.5f} jcoh {coh} jcons {jcons}",
             "ROUND 0.01",
             "BLOCK " + " ".join(p(*q) for q in [(0, -1), (0, 1), (10, 1), (10, -1)]),
             f"CRACK {p(-1, 0)} {p(11, 0)}",
             # the cuts go on into the base, where they end inside it and are
             # dropped: an end written exactly on the joint might stop short
             f"CRACK {p(4, -0.5)} {p(4, 1.5)}",
             f"CRACK {p(6, -0.5)} {p(6, 1.5)}",
             f"DELETE {box(2, 0.5)}",
             f"DELETE {box(8, 0.5)}",
             "PROP MAT=1 DENS=2000 K=1e10 G=1e10",
             f"PROP JMAT=1 {kn}=1e10 {ks}=1e10 {fr}=100 {ch}=1e9 {te}=1e9"]
    if jcons != 2:
        lines.append(f"CHANGE JCONS={jcons}")
    lines.append(f"FIX {box(5, -0.5)}")
    if zoned:
        lines.append(f"GEN {box(5, 0.5)} QUAD 0.5")
    lines += ["GRAV 0 -10",
              "DAMP AUTO",
              "CYCLE 3000",
              f"HIST NCYC 50 XDIS {x},{y} YDIS {x},{y}",
              f"PROP JMAT=1 {fr}={fric} {ch}={coh} {te}=0",
              # a zoned block: stiffness-proportional damping of its ringing
              # (0.2 of critical at its first mode, about 850 Hz), which the
              # steady slide (no strain rate, no normal relative velocity, the
              # shear dashpot off while sliding) does not feel
              "DAMP 0.2 850 STIFF" if zoned else "DAMP 0 1",
              # a zoned block's step is smaller: a longer run for a slide of
              # the same size against its elastic ringing
              f"CYCLE {24000 if zoned else 8000}",
              "HIST WRITE 1 xd.his",
              "HIST WRITE 2 yd.his",
              "STOP"]
    return "\n".join(lines) + "\n"


def slope_case(name, adeg, fric, coh, jcons, zoned=False):
    d = workdir()
    write(d, "d.dat", slope_deck(adeg, fric, coh, jcons, zoned))
    rc, out = run(udec, ["d.dat"], cwd=d, timeout=120)
    check(rc == 0 and "Error" not in out, f"{name}: the deck runs", out[-1500:])
    try:
        xs, ys = rows(os.path.join(d, "xd.his")), rows(os.path.join(d, "yd.his"))
    except OSError:
        check(False, f"{name}: histories written")
        return
    a = math.radians(adeg)
    # displacement down the slope from the release
    s = [-((xs[i][1] - xs[0][1]) * math.cos(a) + (ys[i][1] - ys[0][1]) * math.sin(a))
         for i in range(len(xs))]
    t = [r[0] for r in xs]
    g, m, length = 10.0, 4000.0, 2.0
    c_eff = coh if jcons == 2 else 0.0
    slides = m * g * math.sin(a) > coh * length + m * g * math.cos(a) * fric
    if slides:
        ref = g * math.sin(a) - g * math.cos(a) * fric - c_eff * length / m
        n = len(t)
        i1, i2, i3 = n // 3, 2 * n // 3, n - 1
        h1, h2 = t[i2] - t[i1], t[i3] - t[i2]
        acc = 2 * ((s[i3] - s[i2]) / h2 - (s[i2] - s[i1]) / h1) / (h1 + h2)
        check(abs(acc - ref) < 1e-3 * ref,
              f"{name}: slides at g (sin a - cos a tan phi) - c L / m within 0.1 %",
              f"acceleration {acc:.6g}, reference {ref:.6g}")
        print(f"{name}: acceleration {acc:.6g} m/s2, reference {ref:.6g}")
    else:
        moved = max(abs(v) for v in s)
        check(moved < 1e-6, f"{name}: the joint holds (moves < 1e-6 m)", f"moved {moved:.3g} m")
        print(f"{name}: holds, moved {moved:.3g} m")


tan20 = math.tan(math.radians(20.0))
slope_case("slope 30, friction", 30, tan20, 0.0, 2)
slope_case("slope 15, friction holds", 15, tan20, 0.0, 2)
slope_case("slope 30, JCOH 2000 JCONS 2", 30, tan20, 2000.0, 2)
slope_case("slope 30, JCOH 2000 JCONS 5", 30, tan20, 2000.0, 5)
slope_case("slope 30, JCOH 7000 JCONS 5 holds", 30, tan20, 7000.0, 5)
slope_case("slope 45, no friction", 45, 0.0, 0.0, 2)
slope_case("slope 30, JCONS 1 CFRIC", 30, tan20, 0.0, 1)
slope_case("slope 15, JCONS 1 CFRIC holds", 15, tan20, 0.0, 1)
slope_case("slope 30, zoned block", 30, tan20, 0.0, 2, zoned=True)
slope_case("slope 15, zoned block holds", 15, tan20, 0.0, 2, zoned=True)
slope_case("slope 30, zoned block, JCOH 2000", 30, tan20, 2000.0, 2, zoned=True)


# --- 2. hanging block: tension cut-off -------------------------------------
def flat_deck(hang, joint, tail, gravity="GRAV 0 -10"):
    s = -1 if hang else 1
    lo, hi = sorted((0.2 * s, 0.8 * s))
    return "\n".join([
        "HEAD block " + ("hanging under" if hang else "resting on") + " a fixed block",
        "ROUND 0.01",
        "BLOCK 0,-1 0,1 10,1 10,-1",
        "CRACK -1,0 11,0",
        f"CRACK 4,{-0.5 * s} 4,{1.5 * s}",
        f"CRACK 6,{-0.5 * s} 6,{1.5 * s}",
        f"DELETE 1.7,2.3 {lo},{hi}",
        f"DELETE 7.7,8.3 {lo},{hi}",
        "PROP MAT=1 DENS=2000 K=1e10 G=1e10",
        f"PROP JMAT=1 JKN=1e9 JKS=1e9 {joint}",
        f"FIX 4.7,5.3 {-hi},{-lo}",
        gravity] + tail + ["STOP"]) + "\n"


def flat_run(name, deck):
    d = workdir()
    write(d, "d.dat", deck)
    rc, out = run(udec, ["d.dat"], cwd=d, timeout=120)
    check(rc == 0 and "Error" not in out, f"{name}: the deck runs", out[-1500:])
    try:
        return [rows(os.path.join(d, f)) for f in ("xd.his", "yd.his")]
    except OSError:
        check(False, f"{name}: histories written")
        return None


HIST = ["HIST NCYC 10 XDIS 5,{y} YDIS 5,{y}"]
WRITE = ["HIST WRITE 1 xd.his", "HIST WRITE 2 yd.his"]
h = flat_run("hangs", flat_deck(True, "JFRIC=0.5 JTEN=3e4",
                                [HIST[0].format(y=-0.5), "DAMP AUTO", "CYCLE 3000"] + WRITE))
if h:
    dn = h[1][-1][1]
    check(abs(dn + 2e-5) < 2e-8, "hangs: JTENS above the tension, open by sigma / JKN (0.1 %)",
          f"{dn:.6g}")
    print(f"hangs: y {dn:.6g} m, reference -2e-5")
h = flat_run("breaks", flat_deck(True, "JFRIC=0.5 JTEN=1e4",
                                 [HIST[0].format(y=-0.5), "DAMP 0 1", "CYCLE 4000"] + WRITE))
if h:
    t, y = h[1][-1]
    check(abs(y + 5.0 * t * t) < 1e-3 * 5.0 * t * t,
          "breaks: JTENS below the tension, free fall -g t^2 / 2 (0.1 %)", f"{y:.6g} at {t:.5g}")
    print(f"breaks: y {y:.6g} m at t {t:.5g} s, reference {-5.0 * t * t:.6g}")

# --- 3. dilation: the block rises by tan(psi) ds and keeps it -------------
tail = ["DAMP AUTO", "CYCLE 2000",
        "PROP JMAT=1 JFRIC=0.5 JDIL=0.1",
        "LOAD 4.5,5.5 0.2,0.8 30000 0",
        HIST[0].format(y=0.5),
        "DAMP 1.0 2 MASS", "CYCLE 9000",
        "PROP JMAT=1 JFRIC=100", "DAMP AUTO", "CYCLE 1000",
        "GRAV 0 10", "DAMP 0 1", "CYCLE 150",
        "GRAV 0 -10", "DAMP AUTO", "CYCLE 3000"] + WRITE
h = flat_run("dilation", flat_deck(False, "JFRIC=100 JTEN=0", tail))
if h:
    xs, ys = h
    # the slide: the first 900 samples (9000 cycles)
    dev = max(abs((ys[i][1] - ys[0][1]) - 0.1 * (xs[i][1] - xs[0][1])) for i in range(900))
    ds, dn = xs[899][1] - xs[0][1], ys[899][1] - ys[0][1]
    check(ds > 0.25 and dev < 1e-4, "dilation: rises by tan(psi) ds (1e-4 m) over > 0.25 m",
          f"ds {ds:.4g} dn {dn:.4g} largest deviation {dev:.3g}")
    back = ys[-1][1] - ys[0][1]
    check(abs(back - dn) < 1e-4, "dilation: lifted off and set down, rests on the ridden-up "
          "asperities again (1e-4 m)", f"before {dn:.5g}, after {back:.5g}")
    print(f"dilation: ds {ds:.5g} dn {dn:.5g} (dev {dev:.3g}); after the lift {back:.5g}")

# --- 4. an open dilatant joint carries nothing ----------------------------
h = flat_run("open dilatant", flat_deck(
    False, "JFRIC=0.5 JDIL=0.1",
    ["LOAD 4.5,5.5 0.2,0.8 4000 400", HIST[0].format(y=0.5), "DAMP 0 1", "CYCLE 1200"] + WRITE,
    gravity="* no gravity"))
if h:
    (t, x), (_, y) = h[0][-1], h[1][-1]
    rx, ry = 0.5 * 1.0 * t * t, 0.5 * 0.1 * t * t
    check(abs(x - rx) < 0.01 * rx and abs(y - ry) < 0.01 * ry,
          "open dilatant: the block flies free, x and y = F t^2 / (2 m) (1 %)",
          f"x {x:.5g} ({rx:.5g}), y {y:.5g} ({ry:.5g})")
    print(f"open dilatant: x {x:.5g} ({rx:.5g}), y {y:.5g} ({ry:.5g})")

# --- 5. a dilatant joint keeps its friction at speed ----------------------
FAST = """round 0.1
block 0,0 0,10 10,10 10,0
split 0,5 10,5
fix 0,10 0,5
prop mat=1 dens=2000
prop jmat=1 jkn=1e9 jks=1e9 jfric=0.3 jdil=0.1
grav 0 -10
damp auto
cycle 2000
load 0,10 5,10 5e5,0
hist ncyc 25 xvel 5,7.5 nstr 1 sstr 1 nstr 2 sstr 2
cycle 1500
hist write 1 v.his
hist write 2 n1.his
hist write 3 s1.his
hist write 4 n2.his
hist write 5 s2.his
stop
"""
d = workdir()
write(d, "fast.dat", FAST)
rc, out = run(udec, ["fast.dat"], cwd=d, timeout=120)
check(rc == 0 and "Error" not in out, "fast dilatant slide: the deck runs", out[-1500:])
try:
    v, n1, s1, n2, s2 = (rows(os.path.join(d, f)) for f in
                         ("v.his", "n1.his", "s1.his", "n2.his", "s2.his"))
    worst, vmax = 0.0, 0.0
    for i in range(len(v)):
        if v[i][1] < 0.05:
            continue
        vmax = max(vmax, v[i][1])
        for n, sh in ((n1, s1), (n2, s2)):
            if n[i][1] > 0.0:
                worst = max(worst, abs(abs(sh[i][1]) / n[i][1] - 0.3))
    check(vmax > 0.5 and worst < 3e-3,
          "fast dilatant slide: shear stress = tan(phi) sigma_n at every contact (1 %)",
          f"largest |tau / sigma_n - 0.3| {worst:.3g} up to {vmax:.3g} m/s")
    print(f"fast dilatant slide: |tau/sigma_n - 0.3| <= {worst:.3g} up to {vmax:.3g} m/s")
except OSError:
    check(False, "fast dilatant slide: histories written")

# --- 6. a block hanging on one bolt (REINFORCE, axial) ----------------------
tail = ["PROP MAT=5 RASTIFF=1e7 RSSTIFF=1e7 RLENGTH=0.1 RUAXIAL=1e5 RUSHEAR=1e5 RRFAC=1 "
        "RSEXP=1 RAEXP=1",
        "REINFORCE 5 5,-0.5 5,0.5",
        HIST[0].format(y=-0.5), "DAMP 2 8 MASS", "CYCLE 20000"] + WRITE
h = flat_run("bolt", flat_deck(True, "JFRIC=0.5 JTEN=0", tail))
if h:
    u = -h[1][-1][1]
    ref = -(1e5 / 1e7) * math.log(1.0 - 4e4 / 1e5)
    check(abs(u - ref) < 5e-3 * ref, "bolt: opening -(Fb / Ka) ln(1 - W / Fb) (0.5 %)",
          f"{u:.6g} against {ref:.6g}")
    print(f"bolt: opening {u:.6g} m, reference {ref:.6g}")
finish()
