"""A jointed tunnel loaded by BOUNDARY STRESS alone: the stop names the step load (label e2e).

The new user's deck of docs/robustness.md (round 3; the generator's quick seed
7): a 15.3 m box of rigid blocks cut by two persistent joint sets (81.42 and
-15.66 degrees, spacings 2.0548 and 3.055 m), ROUND 0.0306, soft joints (JKN
2.92e9 Pa/m = 0.3 E / spacing), a field of -79.6 / -40.1 MPa, an ARC 360
opening of radius 1.5617 m. Given by BOUNDARY STRESS alone, the field reaches
joints that carry no stress at once: they close by up to twice their static
closure (79.6e6 / 2.92e9 = 2.7 cm against tolerances of 3 to 4 cm) and slide
before their normal stress gives them friction; the run stops on Contact
Overlap Too Great within the first 500 steps. With SET OVTOL lifted the same
deck moved blocks by 0.31 m (the full draw): the stop is right, but its message
named only a softer JKN or a larger ROUND. Given by INSITU with the same field
first (UDEC manual (ICG1.5, 1989), Section 4, INSITU: it "sets initial zone
stresses in all fully-deformable blocks and joints"), the model is at rest.

1. BOUNDARY STRESS alone: the first CYCLE's note and the stop name the step
   load on unloaded joints and INSITU as its remedy; the stop says which bound
   of its rounded corners set the contact's tolerance and why the geometry is
   lost past it (manual Section 3.3, Fig. 3-3d), with the bound's measure
   consistent with the tolerance it prints (half the sum of the radii, or 0.9
   of it for a corner-edge contact, to the printed 4 digits).
2. INSITU with the same field, then the same BOUNDARY STRESS: at rest after
   2000 cycles, the largest block displacement below 1e-9 of the Kirsch scale
   a (|sxx| + |syy|) / (4 G_eq) = 3.26e-2 m (G_eq = E_eq / 2.5, E_eq the
   joints in series: 1 / (1 / (JKN s1) + 1 / (JKN s2)), the generator's
   scale); measured 2.5e-14 m. The excavation's stop (the hoop stress 3 s1 -
   s2 = 199 MPa closes these joints by 6.8 cm: the soft joints' limit) names
   its bound but no step load: the joints carried INSITU's stress.
"""
import re
import sys
from udec_test import check, finish, run, workdir, write

udec = sys.argv[1]
folder = workdir()
DECK = """HEAD jointed tunnel, step load
ROUND 0.0306
BLOCK 0,0 0,15.3 15.3,15.3 15.3,0
JSET 81.42,4.5 30.6,0 0,0 2.0548,0 (8.184,10.912)
JSET -15.66,0.0 30.6,0 0,0 3.055,0.3055 (6.4231,2.4963)
ARC 7.2896,7.4583 8.8513,7.4583 360 32
PROP MAT 1 DENS 2600 K 1.3333e+10 G 8e+09
PROP JMAT 1 JKN 2.92e+09 JKS 2.92e+08 JFRIC 0.820 JCOH 4.0148e+06 JTENS 2.0074e+06
CHANGE JCONS 2
{insitu}
BOUND STRESS -7.9603e+07 0 -4.0148e+07
DAMP AUTO
CYCLE 2000
PRINT MAX
DELETE ANN 7.2896,7.4583 0 1.546
CYCLE 5000
STOP
"""
STEP = "the joints carried no stress when this CYCLE began"
REMEDY = "INSITU STRESS with the field the loads make"
RADII = re.compile(r"its tolerance is half the overlap\s+(\S+) \(the sum of its corners' rounding "
                   r"radii\) at which their circle centres meet")
SWITCH = re.compile(r"its tolerance is 0\.90 of the overlap\s+(\S+) \(the sum of the rounding radii "
                    r"of its corner and of its edge's nearer end\)")
EDGE = "its tolerance is a quarter of the shortest edge at the contact"
ROUND2 = "its tolerance is 2 ROUND, the width of a corner's rounded zone"


def stop_line(out):
    return re.search(r"\*\*\* Error: Contact Overlap Too Great.*", out)


def bound_named(text):
    """The tolerance the stop prints, and whether the bound named agrees with it."""
    lim = re.search(r"overlap\s+\S+\s+>\s+(\S+);", text)
    m = RADII.search(text)
    if lim and m:
        return abs(float(m.group(1)) / 2 - float(lim.group(1))) <= 1e-3 * float(lim.group(1))
    m = SWITCH.search(text)
    if lim and m:
        return abs(0.9 * float(m.group(1)) - float(lim.group(1))) <= 1e-3 * float(lim.group(1))
    return EDGE in text or ROUND2 in text


# 1. BOUNDARY STRESS alone
write(folder, "bound.dat", DECK.format(insitu=""))
rc, out = run(udec, ["bound.dat"], cwd=folder)
m = stop_line(out)
check(rc == 1 and m is not None, "BOUNDARY alone: stops on Contact Overlap Too Great", out[-2000:])
note = re.search(r"CYCLE: note: the joints of material 1 take a normal stress change.*", out)
check(note is not None and STEP in note.group(0) and REMEDY in note.group(0),
      "BOUNDARY alone: the first CYCLE's note names the step load and INSITU", out[:3000])
if m:
    check(STEP in m.group(0) and REMEDY in m.group(0),
          "BOUNDARY alone: the stop names the step load on unloaded joints and INSITU", m.group(0))
    check(bound_named(m.group(0)), "BOUNDARY alone: the stop names the bound of its tolerance",
          m.group(0))
    cyc = re.search(r"model kept as after cycle (\d+)", m.group(0))
    check(cyc is not None and int(cyc.group(1)) < 2000,
          "BOUNDARY alone: the stop comes in the loading CYCLE", m.group(0))

# 2. INSITU first: at rest; the excavation's stop names no step load
write(folder, "insitu.dat", DECK.format(insitu="INSITU STRESS -7.9603e+07 0 -4.0148e+07"))
rc, out = run(udec, ["insitu.dat"], cwd=folder)
jkn, s1, s2, a = 2.92e9, 2.0548, 3.055, 1.5617
e_eq = 1.0 / (1.0 / (jkn * s1) + 1.0 / (jkn * s2))
u_kirsch = a * (7.9603e7 + 4.0148e7) / (4 * e_eq / 2.5)
rest = re.search(r"max block displacement\s+(\S+)", out)
check(rest is not None and float(rest.group(1)) < 1e-9 * u_kirsch,
      f"INSITU: at rest (max block displacement < 1e-9 x Kirsch scale {u_kirsch:.3e})",
      rest.group(0) if rest else out[-2000:])
check("CYCLE: note: the joints of material 1" not in out or STEP not in out,
      "INSITU: no step-load words (the joints carry the field)", out[:3000])
m = stop_line(out)
if m:
    check(bound_named(m.group(0)), "INSITU: the excavation's stop names its bound", m.group(0))
finish()
