"""A block on a shaken base: two-way sliding against Newmark's integration
(label `verification`).

A 2 x 1 m rigid block (density 2000) rests on a 4 x 1 m base block on a
horizontal joint, JFRIC 0.2 under GRAVITY 0 -10, so the joint holds the
block until the base accelerates faster than mu g = 2 m/s^2. The base is
held at its two bottom corners by BOUNDARY XVEL 0.5 XHIST SINE 2 1.0 and
YVEL 0 (UDEC manual (ICG1.5, 1989), Section 4.5, BOUNDARY, history types:
a sine of 2 Hz applied for 1 s), i.e. base velocity 0.5 sin(4 pi t), peak
acceleration 2 pi m/s^2, and no damping during the shaking (DAMP 0 1 MASS).

Reference: the rigid-plastic sliding block (Newmark 1965, two-way
sliding on a horizontal plane), integrated in this script with a step of
1e-6 s: while the block slides on the base its acceleration is
-mu g sign(v - v_base); it sticks when the relative velocity reaches zero
and the base acceleration is below mu g. The block's permanent
displacement relative to the base at t = 1.276 s (after the shaking) is
57.1 mm. The model's joint is elastic (JKS 1e10 Pa/m, a few micrometres
of elastic shear), so the tolerance is 2 % (measured +0.7 %). The base
returns to its start (the sine's velocity integrates to zero over whole
periods): within 1e-4 m.
"""
import math
import re
import sys
from udec_test import check, finish, run, workdir, write

udec, source = sys.argv[1], sys.argv[2]

DECK = """HEAD block on a shaken base: two-way sliding (Newmark)
ROUND 0.01
BLOCK 0,0 0,2 4,2 4,0
CRACK 0,1 4,1
CRACK 1,1 1,2
CRACK 3,1 3,2
DEL 0,1 1,2
DEL 3,4 1,2
PROP MAT=1 D=2000
PROP JMAT=1 JKN=1e10 JKS=1e10 JFRIC=0.2
GRAV 0 -10
BOUND -1,5 -0.1,0.1 XVEL 0 YVEL 0
DAMP AUTO
SOLVE
DAMP 0 1 MASS
RESET TIME DISP JDISP
BOUND -1,5 -0.1,0.1 XVEL 0.5 XHIST SINE 2 1.0
HIST NCYC 20 XDIS 2,1.9 XDIS 0.1,0.1
CYCLE 12000
HIST WRITE 1 top.his
HIST WRITE 2 base.his
STOP
"""


def newmark(t_end, mu_g=2.0, dt=1e-6):
    """Relative displacement of a rigid-plastic block on the base."""
    t = v = d = db = 0.0
    while t < t_end:
        vb = 0.5 * math.sin(4 * math.pi * t) if t < 1.0 else 0.0
        ab = 2 * math.pi * math.cos(4 * math.pi * t) if t < 1.0 else 0.0
        rel = v - vb
        if abs(rel) > 1e-9:
            a = -mu_g * math.copysign(1.0, rel)
        else:
            a = ab if abs(ab) <= mu_g else mu_g * math.copysign(1.0, ab)
        vn = v + a * dt
        vbn = 0.5 * math.sin(4 * math.pi * (t + dt)) if t + dt < 1.0 else 0.0
        if abs(rel) > 1e-9 and (vn - vbn) * rel < 0:
            vn = vbn            # the block catches the base: it sticks
        d += 0.5 * (v + vn) * dt
        db += 0.5 * (vb + vbn) * dt
        v = vn
        t += dt
    return d - db


def last(path):
    with open(path) as f:
        rows = [l.split() for l in f if l.strip() and not l.startswith("#")]
    return float(rows[-1][0]), float(rows[-1][1])


d = workdir()
write(d, "newmark.dat", DECK)
rc, out = run(udec, ["newmark.dat"], cwd=d, timeout=300)
check(rc == 0 and "Error" not in out, "the deck runs", out[-1500:])
try:
    t, top = last(d + "/top.his")
    _, base = last(d + "/base.his")
except (OSError, IndexError, ValueError):
    t, top, base = None, None, None
check(top is not None, "histories written")
if top is not None:
    ref = newmark(t)
    check(abs((top - base) - ref) < 0.02 * ref,
          "permanent slip within 2 % of Newmark's rigid-plastic block",
          f"udec {top - base:.5g} m, reference {ref:.5g} m at t = {t:.4g} s")
    check(abs(base) < 1e-4, "the base returns to its start (1e-4 m)", str(base))
finish()
