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
2. A direct shear test of one rigid block on a joint (Section 3.3, Eq. 8, and
   Section 4.5, CHANGE JCONS 5): the upper 2 x 1 block is cut out of one BLOCK
   by CRACKs, the lower one FIXed, the normal stress held by BOUNDARY STRESS
   0 0 -1E6 on its top, the block driven by BOUNDARY XVEL 1E-3 on its left
   corners (a constraint on the rigid block's motion). JKS 5e9, JCOH 2e5,
   JFRIC 0.5, JDIL 0.1 (tan psi). References: JCONS 2 slides at
   tau = c + sigma_n tan(phi) = 7e5 Pa; JCONS 5 loses its cohesion at the first
   slip and slides at sigma_n tan(phi) = 5e5 Pa; while sliding the block rises
   tan(psi) = 0.1 per unit of slip. Tolerances: the sliding stress 0.5 %
   (measured below 1e-4), the dilation rate 1 % (measured -0.3 %, cause not
   traced), the normal stress 1e6 on average 0.5 %.
"""
import os
import sys
sys.path.insert(0, os.path.dirname(__file__))
from udec_test import check, finish, run, run_deck, workdir  # noqa: E402

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


SHEAR = """HEAD direct shear test, JCONS {jcons}
ROUND 0.01
BLOCK -1,-1 -1,1 3,1 3,-1
CRACK -1,0 3,0
CRACK 0,-0.5 0,1.5
CRACK 2,-0.5 2,1.5
DELETE -1 0 0 1
DELETE 2 3 0 1
PROP MAT=1 DENS=2500 K=1E10 G=1E10
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
    check(abs(rate - 0.1) <= 0.001, f"shear JCONS {jcons}: rises tan(psi) = 0.1 per unit of slip",
          f"{rate:.5f}")


second_block()
shear_box(2, 7.0e5)
shear_box(5, 5.0e5)
finish()
