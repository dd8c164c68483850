"""Application Problem G (cement grouting, Bingham fluid) against the
manual's one published number: "No steady state flow occurs until the
pressure in the hole exceeds 8000 Pa" (Appendix B, Problem G).

The deck is examples/application/G/G1_grouting.dat with its memory address
`pfix dom 697` (the hole's domain in the 1989 program) replaced by a range
around the hole, `pfix 4.5 5.5 4.5 5.5`, which selects that one domain, and
each SAVE replaced by PRINT FLOWS. Checks (the outflow is the total flow
through the outer boundary, PRINT FLOWS):
- the deck runs all eight pressure stages;
- no grout leaves the model at 2000 ... 8000 Pa (exactly 0: below the
  threshold gradient 2 COHW / a no contact on a path to the boundary flows);
- grout leaves it at 10,000 Pa and more, increasing with the pressure
  (measured 0.092, 0.324, 0.621, 0.920; checked > 0 and increasing only).
- the same deck with COHW 0 (Newtonian) already flows at 2000 Pa.
"""
import os
import re
import sys
sys.path.insert(0, os.path.dirname(__file__))
from udec_test import check, finish, run, workdir, write  # noqa: E402

udec, source = sys.argv[1], sys.argv[2]
folder = workdir()
deck = open(os.path.join(source, "examples", "application", "G", "G1_grouting.dat")).read()
check("pfix dom 697 pres" in deck, "the printed deck uses pfix dom 697")
deck = deck.replace("pfix dom 697 pres", "pfix 4.5 5.5 4.5 5.5 pres")
deck = re.sub(r"(?m)^save grthol[b-i]\.sav$", "print flows", deck)


def outflows(text):
    return [float(m) for m in re.findall(r"total boundary outflow\s+(\S+)", text)]


write(folder, "g.dat", deck)
rc, out = run(udec, ["g.dat"], cwd=folder, timeout=600)
check(rc == 0, "grouting deck runs", out[-2000:])
q = outflows(out)
check(len(q) == 8, "eight pressure stages", str(q))
if len(q) == 8:
    check(all(v == 0.0 for v in q[:4]), "no flow through the model up to 8000 Pa", str(q))
    check(all(v > 0.0 for v in q[4:]), "flow from 10,000 Pa on", str(q))
    check(all(b > a for a, b in zip(q[4:], q[5:])), "outflow grows with the pressure", str(q))

write(folder, "n.dat", deck.replace("coh .1", "coh 0"))
rc, out = run(udec, ["n.dat"], cwd=folder, timeout=600)
q = outflows(out)
check(rc == 0 and len(q) == 8 and q[0] > 0.0, "Newtonian grout flows at 2000 Pa", str(q))
finish()
