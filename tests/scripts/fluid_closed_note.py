"""Water pumped into joints that the in-situ stress has closed is told why
it does not flow (label e2e).

A new user's deck (UDEC manual (ICG1.5, 1989), Sections 4 FLUID, INSITU,
PFIX and PROPERTY): four zoned blocks cut by two crossing joints, INSITU and
BOUNDARY STRESS of 5 MPa, joints of JKN 1e10 Pa/m and AZERO 1e-4 m, water
fixed at 2 MPa in the domain at the crossing. The joints close by
5e6 / 1e10 = 5e-4 m, more than AZERO, so Eq. 55 gives a hydraulic aperture
of 0 unless ARES (default 0) keeps one: no flow at all, and nothing said.
It was taken for an effect of the order of INSITU and FLUID; the order does
not matter (case 1 checks both give the same flows). CYCLE now notes it.

1. Without ARES, FLUID before and after INSITU: the note, naming ARES, in
   both; no outflow; the two PRINT FLOWS tables the same.
2. With ARES 5e-5 m: no note, water flows out of the model's sides.
"""
import sys
from udec_test import check, finish, printed_number, run_deck, workdir

udec = sys.argv[1]
folder = workdir()
NOTE = "CYCLE: note: no joint conducts water"


def deck(name, ares, fluid_first):
    fluid = "fluid bulkw=2e9 rhow=1000\n"
    stress = "insitu stress -5e6 0 -5e6\nbound stress -5e6 0 -5e6\n"
    return run_deck(udec, folder, name, f"""round 0.05
block -10,-10 -10,10 10,10 10,-10
crack -10,0 10,0
crack 0,-10 0,10
gen edge 2
prop mat=1 dens=2600 k=2e10 g=1.2e10
prop jmat=1 jkn=1e10 jks=1e10 jfric=0.6 azero=1e-4 jperm=83.3{ares}
{fluid + stress if fluid_first else stress + fluid}pfix 4,6 -1,1 pres 2e6
damp auto
cycle 300
print flows
stop
""")[1]


def outflow(out):
    return printed_number(out, "total boundary outflow")


def flows(out):
    return out[out.rfind("print flows"):]


a = deck("fluid_first", "", True)
b = deck("insitu_first", "", False)
for name, out in (("fluid_first", a), ("insitu_first", b)):
    line = next((l for l in out.splitlines() if l.startswith(NOTE)), "")
    check(line != "", f"{name}: closed joints noted", out[-2000:])
    check("ARES" in line and "2000000" in line, f"{name}: note names ARES and the pressure", line)
    check(outflow(out) == 0.0, f"{name}: no outflow", flows(out))
check(flows(a) == flows(b), "the order of FLUID and INSITU does not change the flows",
      flows(a)[:1500] + "\n---\n" + flows(b)[:1500])

c = deck("residual", " ares=5e-5", False)
check(NOTE not in c, "residual aperture: no note", c[-2000:])
check(outflow(c) > 1e-8, "residual aperture: water flows out", flows(c))

finish()
