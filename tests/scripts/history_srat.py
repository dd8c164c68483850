"""HISTORY SRAT n: shear stress ratio of contact n (|shear| / shear strength),
the history Appendix B, Application D records at contact 3445 (the manual's
Section 4.5 list does not name it; its meaning is inferred from that deck).

Closed form: a rigid block (2 m x 1 m, density 2000, weight W = 40000 N per
metre) rests on a fixed base, gravity tilted by theta = 15 degrees (the
block on a 15-degree slope). Statics of the block, exact for a rigid block:
  fn_L + fn_R = W cos(theta), and moments about the base centre
  (fn_R - fn_L) d = W sin(theta) h / 2 (h = 1 m, 2d = the distance between
  the two contacts, from PRINT CONTACT), so fn_L, fn_R;
  fs_L + fs_R = W sin(theta), and with equal joint stiffness and lengths the
  two contacts (same shear displacement under a rigid block) share it:
  fs_L = fs_R = W sin(theta) / 2 (JCONS 2).
References, each within 0.5 % (tolerance for the residual motion of a
damped explicit run after 3000 cycles; measured below 0.01 %):
* JCONS 2, JFRIC 0.8, JCOH 0: SRAT = fs / (fn JFRIC) at each contact;
* JCONS 2, JCOH 2000 Pa: SRAT = fs / (JCOH L + fn JFRIC), L = 1 m the
  contact length PRINT CONTACT gives;
* JCONS 3 (JKN JKS JFRIC 0.5 JIF 0.8 rad, no JR: phi_eff stays at JIF):
  the strength is tau_m = sigma_n tan(phi_eff) (Eq. E-4); the stiffness
  softens toward tau_m, so the two contacts do not share the shear
  equally, but the sum is statics:
  SRAT_L fn_L + SRAT_R fn_R = W sin(theta) / tan(JIF).
And a contact that has opened (the block lifted off by gravity turned
upward) reads 1: it has no strength left.
The test failed before HISTORY SRAT was implemented (it answered "not yet
implemented; history n reads 0").
"""
import math
import os
import re
import sys
sys.path.insert(0, os.path.dirname(__file__))
from udec_test import check, finish, run, workdir, write, tables, history_rows  # noqa: E402

udec = sys.argv[1]
d = workdir()
THETA = math.radians(15.0)
G = 10.0
W = 2000.0 * 2.0 * 1.0 * G

GEOM = """ROUND 0.01
BLOCK 0,0 0,2 4,2 4,0
CRACK 0,1 4,1
CRACK 1,1 1,2
CRACK 3,1 3,2
DELETE 0,0.99 1.01,2
DELETE 2.99,4.01 1.01,2
"""


def deck(props, extra, hist=""):
    return (GEOM + props + "\nFIX 0,4 0,1\n"
            + f"GRAVITY {G * math.sin(THETA):.6f} {-G * math.cos(THETA):.6f}\nDAMP AUTO\n"
            + hist + "CYCLE 3000\nPRINT CONTACT\nPRINT HIST 1 2\n" + extra + "STOP\n")


def contacts(out):
    """{id: row} of the last contact state and force tables."""
    state = tables(out, "PRINT CONTACT")[-1]
    return {int(r["CONTACT"]): r for r in state}


def forces(out):
    lines = out.rsplit("PRINT CONTACT", 1)[1].splitlines()
    i = next(k for k, l in enumerate(lines) if "NORMAL-FORCE" in l)
    res = {}
    for l in lines[i + 1:]:
        f = l.split()
        if not f or not f[0].isdigit():
            break
        res[int(f[0])] = (float(f[4]), float(f[5]), float(f[3]))  # fn, fs, length
    return res


def statics(xl, xr):
    dd = (xr - xl) / 2.0
    diff = W * math.sin(THETA) * 0.5 / dd
    return (W * math.cos(THETA) - diff) / 2.0, (W * math.cos(THETA) + diff) / 2.0


# find the two contacts
rc, out = run(udec, [write(d, "find.dat", GEOM + "PROP MAT=1 D=2000\nPRINT CONTACT\nSTOP\n")],
              cwd=d)
c0 = contacts(out)
check(rc == 0 and len(c0) == 2, "two contacts under the block", out[-1500:])
left = min(c0, key=lambda k: c0[k]["X"])
right = max(c0, key=lambda k: c0[k]["X"])
xl, xr = c0[left]["X"], c0[right]["X"]
hist = f"HIST SRAT {left} SRAT {right}\n"

cases = [("JCONS 2, JCOH 0", "PROP MAT=1 D=2000 JKN=1E9 JKS=1E9 JFRIC=0.8", 0.0, 0.8, None),
         ("JCONS 2, JCOH 2000", "PROP MAT=1 D=2000 JKN=1E9 JKS=1E9 JFRIC=0.8 JCOH=2000", 2000.0,
          0.8, None),
         ("JCONS 3, JIF 0.8", "PROP MAT=1 D=2000 JKN=1E9 JKS=1E9 JFRIC=0.5 JIF=0.8\n"
          "CHANGE JCONS=3", 0.0, 0.5, 0.8)]
for name, props, coh, fric, jif in cases:
    rc, out = run(udec, [write(d, "srat.dat", deck(props, "", hist))], cwd=d, timeout=120)
    check(rc == 0 and "not yet implemented" not in out, f"{name}: runs, SRAT implemented",
          out[-1500:])
    rows = history_rows(out, "PRINT HIST 1 2")
    check(len(rows) > 10, f"{name}: SRAT histories sampled", str(len(rows)))
    if len(rows) <= 10:
        continue
    s_l, s_r = rows[-1][1], rows[-1][2]
    f = forces(out)
    cf = contacts(out)  # the contact points where the run ends (rounded corners)
    fnl, fnr = statics(cf[left]["X"], cf[right]["X"])
    check(abs(f[left][0] / fnl - 1) < 0.005 and abs(f[right][0] / fnr - 1) < 0.005,
          f"{name}: normal forces are the block's statics", f"{f[left][0]:.5g} / {fnl:.5g}, "
          f"{f[right][0]:.5g} / {fnr:.5g}")
    if jif is None:
        fs = W * math.sin(THETA) / 2.0
        for side, s, fn, c in (("left", s_l, fnl, left), ("right", s_r, fnr, right)):
            ref = fs / (coh * f[c][2] + fn * fric)
            check(abs(s / ref - 1) < 0.005, f"{name}: SRAT at the {side} contact {s:.5g} = "
                  f"fs / (JCOH L + fn JFRIC) = {ref:.5g} within 0.5 %", f"{100 * (s / ref - 1):+.3f} %")
    else:
        lhs = (s_l * fnl + s_r * fnr) * math.tan(jif)
        check(abs(lhs / (W * math.sin(THETA)) - 1) < 0.005, f"{name}: (SRAT_L fn_L + SRAT_R fn_R) "
              f"tan(JIF) = {lhs:.5g} N = W sin(theta) = {W * math.sin(THETA):.5g} N within 0.5 %",
              f"{100 * (lhs / (W * math.sin(THETA)) - 1):+.3f} %; SRAT {s_l:.4f} {s_r:.4f}")
        check(abs(s_l - s_r) > 0.01, f"{name}: the two contacts' ratios differ (tau_m differs)",
              f"{s_l:.4f} {s_r:.4f}")

# an opened contact reads 1: turn gravity upward, the block lifts off
rc, out = run(udec, [write(d, "open.dat", deck(cases[0][1], "GRAVITY 0 10\nCYCLE 200\n"
                                                "PRINT HIST 1 2\n", hist))], cwd=d, timeout=120)
rows = history_rows(out.rsplit("CYCLE 200", 1)[1], "PRINT HIST 1 2")
check(rc == 0 and rows and rows[-1][1] == 1.0 and rows[-1][2] == 1.0,
      "a contact that has opened reads 1 (no strength left)", str(rows[-1:]))
# a number that is no contact's address (nor id): a history changes nothing,
# so it is not refused but takes the contact whose record starts nearest,
# with a warning naming the command, the number and the contact taken
rc, out = run(udec, [write(d, "bad.dat", GEOM + "HIST SRAT 99\nSTOP\n")], cwd=d)
check(rc == 0 and "Warning: HISTORY SRAT 99: no contact has address 99 here" in out
      and re.search(r"recording the contact whose address is nearest: contact \(address \d+, id \d+\)", out)
      is not None, "HIST SRAT of a missing contact: the nearest contact, with a warning naming 99", out[-600:])
# no contact at all: refused, naming the command and the number
rc, out = run(udec, [write(d, "none.dat", "BLOCK 0,0 0,1 1,1 1,0\nHIST SRAT 99\nSTOP\n")], cwd=d)
check(rc != 0 and "HISTORY SRAT 99: no contact has address 99" in out and "Error" in out,
      "HIST SRAT in a model without contacts is refused naming the command and the number", out[-600:])
finish()
