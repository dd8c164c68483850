"""PLOT TEMPERATURE (manual Section 7.4.2, "temperature contours"): a slab
held at 32 on both sides starts at 60 everywhere; after a short explicit RUN
the contours span exactly the gridpoint temperatures PRINT TEMPERATURE lists
(the legend's minimum and maximum, four digits), and a model without THERMAL
draws the layer at 0 instead of failing."""
import os
import re
import sys
sys.path.insert(0, os.path.dirname(__file__))
from udec_test import check, finish, run, workdir, write  # noqa: E402

udec = sys.argv[1]
DECK = """thermal
rou 0.001
bl 0,0 0,1 1,1 1,0
gen -1 2 -1 2 auto 0.2
prop mat=1 dens=500 cond=20 spec=0.2
initem 60 -1 2 -1 2
tfix 32 -1 0.001 -1 2
tfix 32 0.999 1.1 -1 2
run ste 50 delt 8e-4
print temperature
plot block temperature
copy t.ps
stop
"""
d = workdir()
write(d, "t.dat", DECK)
rc, out = run(udec, ["t.dat"], cwd=d, timeout=120)
check(rc == 0 and "***" not in out, "thermal deck with PLOT TEMPERATURE runs", out[-1500:])
rows = out.split("print temperature")[-1].split("plot block")[0].splitlines()
temps = [float(r.split()[4]) for r in rows if re.match(r"\s+\d+\s+\d+\s", r) and len(r.split()) >= 5]
check(len(temps) > 10, f"PRINT TEMPERATURE lists the gridpoints ({len(temps)})")
ps = open(os.path.join(d, "t.ps")).read() if os.path.exists(os.path.join(d, "t.ps")) else ""
check("(temperature contours \\(deg C\\))" in ps, "the legend names the layer and its unit", ps[-300:])
m = re.search(r"\(minimum (\S+), maximum (\S+)\)", ps)
check(m is not None, "the legend gives the range", ps[-800:])
if m and temps:
    check(abs(float(m.group(1)) - min(temps)) <= 1e-3 * max(temps), "legend minimum = coldest gridpoint")
    check(abs(float(m.group(2)) - max(temps)) <= 1e-3 * max(temps), "legend maximum = hottest gridpoint")
    check(min(temps) >= 31.99 and max(temps) <= 60.01, "temperatures between the fixed 32 and the initial 60")
write(d, "n.dat", "rou 0.01\nbl 0,0 0,1 1,1 1,0\ngen auto 0.5\nplot block temp\ncopy n.ps\nstop\n")
rc, out = run(udec, ["n.dat"], cwd=d, timeout=60)
check(rc == 0 and "not yet implemented" not in out and "*** Error" not in out,
      "PLOT TEMPERATURE without THERMAL draws zeros", out[-800:])
finish()
