"""New users' decks of campaign round 8, written from the UDEC manual (ICG1.5,
1989) Sections 2 and 4 alone (docs/closed_form.md lists every deck of the round,
its reference and our number).

1. A second BLOCK command (a new user builds a slope as two BLOCKs: the base and
   the block on it). The manual allows one (Section 4.5, BLOCK: "Only one BLOCK
   command may be used per run. Further blocks may be created with a CRACK,
   SPLIT, TUNNEL, ARC or JSET command and unwanted ones deleted with the DELETE
   command"). The error must say how to make the second block, and the model
   stays as it was. Before: "only one BLOCK command may be used per run" and no
   remedy.
   PROPERTY MAT=1 DENS=2500 E=10E9 NU=0.25 (Young's modulus and Poisson's
   ratio, as a new user types them): refused, and the message gives the
   manual's conversion to K and G (Section 4.5, PROPERTY note). Before:
   "unknown keyword 'E' (closest: K, G ...)" without it.
2. A direct shear test of one rigid block on a joint (Section 3.3, Eq. 8, and
   Section 4.5, CHANGE JCONS 5): the upper 2 x 1 block is cut out of one BLOCK
   by CRACKs, the lower one FIXed, the normal stress held by BOUNDARY STRESS
   0 0 -1E6 on its top, the block driven by BOUNDARY XVEL 1E-3 on its left
   corners (a constraint on the rigid block's motion). JKS 5e9, JCOH 2e5,
   JFRIC 0.5, JDIL 0.1 (tan psi). References: JCONS 2 slides at
   tau = c + sigma_n tan(phi) = 7e5 Pa; JCONS 5 loses its cohesion at the first
   slip and slides at sigma_n tan(phi) = 5e5 Pa; while sliding the block rises
   tan(psi) = 0.1 per unit of slip. Tolerances: the sliding stress 0.5 %
   (measured below 1e-4), the normal stress 1e6 on average 0.5 %, the
   dilation rate 0.1 % (measured below 1e-5). Before: -0.3 % (-3 % under
   DAMP 0 0, exact under heavy mass damping): the opening was tan(psi) times
   the smaller of the step's plastic slip and its shear increment, so where
   the normal force fell within a step (the block's vertical ringing) the
   slip that turned elastic shear into plastic did not dilate.
3. A 2 x 1 rigid block (weight 4e4 N) on a joint of JTEN 5e4 Pa over 2 m
   (1e5 N), pulled up at its two top corners by BOUND YLOAD 0.65E5 YHIS LINEAR
   (1.3e5 N in all, ramped over the CYCLE; manual Section 4.5, BOUNDARY):
   static answer, net pull 9e4 N, 4.5e4 N per corner contact (0.1 %), the
   block stays (below 1e-4 m). The same pull given at once (LOAD) breaks the
   joint from 0.8e5 N on: the first swing under DAMP AUTO was nearly undamped
   (docs/closed_form.md finding A; fixed in session 42 and asserted by
   stability.sudden_load).
"""
import os
import sys
sys.path.insert(0, os.path.dirname(__file__))
from udec_test import check, finish, run, run_deck, workdir  # noqa: E402
from shared_decks import SHEAR_BOX, TENSILE_BLOCK  # noqa: E402

udec = sys.argv[1]


def second_block():
    rc, out = run(udec, [], stdin_text="ROUND 0.01\nBLOCK 0,0 10,5.7735 10,0\n"
                  "BLOCK 3.4641,2.0 2.9641,2.86603 4.69615,3.86603 5.19615,3.0\n"
                  "PRINT STATUS\nSTOP\n")
    errors = [l for l in out.splitlines() if "*** Error" in l]
    check(len(errors) == 1 and "BLOCK" in errors[0] and "CRACK" in errors[0] and "SPLIT" in errors[0]
          and "DELETE" in errors[0], "second BLOCK: refused, saying how to cut further blocks",
          "\n".join(errors) or out[-1500:])
    blocks = [l.split() for l in out.splitlines() if l.strip().startswith("blocks")]
    check(blocks and blocks[-1][-1] == "1", "second BLOCK: the model keeps its one block", str(blocks))
    rc, out = run(udec, [], stdin_text="PROP MAT=1 DENS=2500 E=10E9 NU=0.25\nPROP MAT=1 POISSON=0.25\n"
                  "PRINT PROP\nSTOP\n")
    errors = [l for l in out.splitlines() if "*** Error" in l]
    check(len(errors) == 2 and all("'E'" in errors[0] or "'POISSON'" in e for e in errors) and
          all("K = E / (3 (1 - 2 nu)), G = E / (2 (1 + nu))" in e for e in errors),
          "PROPERTY E= / POISSON=: refused with the conversion to K and G", "\n".join(errors) or out[-1500:])
    check("(no properties given)" in out, "PROPERTY E=: the refused line set nothing (no DENSITY)",
          out[-1500:])


SHEAR = "HEAD direct shear test, JCONS {jcons}\n" + SHEAR_BOX + """PROP MAT=1 DENS=2500 K=1E10 G=1E10
PROP JMAT=1 JKN=1E10 JKS=5E9 JFRIC=0.5 JCOH=2E5 JTEN=0 JDIL=0.1
FIX -2 4 -1 0
CHANGE JCONS={jcons}
BOUND -0.01 2.01 0.99 1.01 STRESS 0 0 -1E6
DAMP AUTO
CYCLE 2000
BOUND -0.01 0.01 -0.001 1.01 XVEL 1E-3
HIST NCYC 20 SSTR 1 SSTR 2 NSTR 1 NSTR 2 NDIS 1 SDIS 1
CYCLE 20000
HIST WRITE 1 s1.txt
HIST WRITE 2 s2.txt
HIST WRITE 3 n1.txt
HIST WRITE 4 n2.txt
HIST WRITE 5 nd.txt
HIST WRITE 6 sd.txt
STOP
"""


def shear_box(jcons, tau_ref):
    folder = workdir()
    rc, out = run_deck(udec, folder, f"shear{jcons}", SHEAR.format(jcons=jcons))

    def col(name):
        with open(os.path.join(folder, name)) as f:
            return [float(l.split()[1]) for l in f if l.strip() and not l.startswith("#")]
    try:
        s1, s2, n1, n2, nd, sd = (col(n) for n in ("s1.txt", "s2.txt", "n1.txt", "n2.txt",
                                                  "nd.txt", "sd.txt"))
    except OSError as e:
        check(False, f"shear JCONS {jcons}: histories written", str(e) + out[-1500:])
        return
    tau = abs(0.5 * (s1[-1] + s2[-1]))
    sn = abs(0.5 * (n1[-1] + n2[-1]))
    half = len(nd) // 2
    rate = abs((nd[-1] - nd[half]) / (sd[-1] - sd[half]))
    print(f"JCONS {jcons}: tau {tau:.6g} (ref {tau_ref:g}), sigma_n {sn:.6g}, dn/ds {rate:.5f}")
    check(abs(tau - tau_ref) <= 0.005 * tau_ref, f"shear JCONS {jcons}: slides at {tau_ref:g} Pa",
          f"{tau:.6g}")
    check(abs(sn - 1e6) <= 0.005e6, f"shear JCONS {jcons}: normal stress held at 1e6 Pa", f"{sn:.6g}")
    check(abs(rate - 0.1) <= 1e-4, f"shear JCONS {jcons}: rises tan(psi) = 0.1 per unit of slip",
          f"{rate:.5f}")


PULL = TENSILE_BLOCK + """BOUND 0.9 3.1 0.9 1.1 YLOAD 0.65E5 YHIS LINEAR
CYCLE 4000
PRINT CONT FORCE
PRINT RIGID
STOP
"""


def ramped_pull():
    rc, out = run_deck(udec, workdir(), "ramped_pull", PULL)
    rows = [l.split() for l in out.split("PRINT CONT FORCE")[-1].split("PRINT RIGID")[0].splitlines()
            if len(l.split()) == 8 and l.split()[0].isdigit()]
    check(len(rows) == 2 and all(abs(float(r[4]) + 4.5e4) <= 45.0 for r in rows),
          "ramped pull: each contact carries the static -4.5e4 N", str(rows))
    blk = [l.split() for l in out.split("PRINT RIGID")[-1].splitlines()
           if len(l.split()) == 9 and l.split()[0] == "3"]
    check(len(blk) == 1 and abs(float(blk[0][6])) < 1e-4, "ramped pull: the block stays", str(blk))


second_block()
ramped_pull()
shear_box(2, 7.0e5)
shear_box(5, 5.0e5)
finish()
