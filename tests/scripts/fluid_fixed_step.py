"""A fluid whose pressures are all PFIXed does not bound the time step (label
e2e; UDEC manual (ICG1.5, 1989), Section 3.12: the fluid filling a joint
raises its apparent normal stiffness by Kw / a because a domain's pressure
follows its volume, Eq. 56; a PFIXed domain's pressure does not).

A new user's drained tunnel: rigid blocks, JPERM/AZERO, FLUID BULK 2e9 and
`PFIX pressure` over every domain (as the manual's `PFix pressure=10`): the
step was bounded by Kw / a = 1e13 Pa/m against JKN 2e10, 31 times smaller
than the joints' own, for a fluid that could not act; SOLVE ran 100 000
cycles unbalanced. Checked: with every domain PFIXed the step equals the
step of the same model without fluid (to the digits printed); with the
pressures free the step is smaller again (the bound is still applied where it
acts).
"""
import re
import sys
from udec_test import check, finish, run, workdir, write

udec = sys.argv[1]
d = workdir()
BASE = """round 0.05
block -20,-20 -20,20 20,20 20,-20
jset 20,0 60,0 0,0 3,0 (0,0)
jset 110,0 60,0 0,0 4,0 (0,0)
prop mat=1 dens=2600
prop jmat=1 jkn=2e10 jks=1e10 jfric=0.7 {flow}
{fluid}
bound stress -8e6 0 -8e6
insitu stress -8e6 0 -8e6
{pfix}
damp auto
cycle {n}
print domain -2,2 -2,2
stop
"""


def step(name, **kw):
    write(d, name, BASE.format(**kw))
    rc, out = run(udec, [name], cwd=d)
    m = re.search(r"cycle %d, time .*?timestep +(\S+)," % kw["n"], out)
    check(rc == 0 and m is not None, name + ": runs its cycles", out[-1500:])
    if name == "fixed.dat":
        # PRINT DOMAIN with a range: the pressure table lists the same domains
        # as the domain table (it listed every domain of the model)
        tail = out.split("print domain -2,2 -2,2", 1)[-1]
        rows = re.findall(r"^ +(\d+) +\S+ +\d+ +F +\d+", tail, re.M)  # inner domains
        prows = re.findall(r"^ +(\d+) +500000 +\S+ +\S+ +\S+ +T$", tail, re.M)
        check(rows and rows == prows, "PRINT DOMAIN range: pressures of the same %d domains (got %d)"
              % (len(rows), len(prows)), tail[:2000])
    return float(m.group(1)) if m else float("nan")


flow = "jperm=1e8 azero=2e-4 ares=1e-4"
dry = step("dry.dat", flow="", fluid="", pfix="", n=10)
fixed = step("fixed.dat", flow=flow, fluid="fluid den=1000 bul=2e9", pfix="pfix -21,21 -21,21 pres 5e5",
             n=10)
# free pressures (one step: the flow takes thousands of sub-steps a step, as
# CYCLE's note says): Kw / a = 2e8 / 2e-4 = 1e12 Pa/m against JKN 2e10, a step
# about sqrt(50) = 7 times smaller
free = step("free.dat", flow=flow, fluid="fluid den=1000 bul=2e8", pfix="", n=1)
check(fixed == dry, "every domain PFIXed: the step is the joints' own (%g vs %g)" % (fixed, dry))
check(free < dry / 3.0, "free pressures: the fluid's stiffness bounds the step (%g vs %g)" % (free, dry))
finish()
