"""A TUNNEL ring grazed by a joint (label e2e): the lead's random tunnel
deck, seed 234 (session 39). A 20 m square cut by two joint sets, one joint
of the first set 2.163 m from the centre of a 24-sided ring of radius 2.201 m
(apothem 2.182 m): one corner of the ring lies 3.8 cm past the joint, ROUND
0.02. Before, the ring crossed the joint at 6 to 9 degrees, the piece
between them was a sliver whose merge was undone by a pending JSET segment
along the joint (48 refused cuts), and GENERATE made a zone 1/1760 of the
mean (it set the time step: SOLVE did not balance within 40000 cycles after
the excavation). Now the ring's corners within 2 ROUND (4 cm; side x
sin(3.75 deg) is less) of the joint lie on it (docs/geometry.md). Checked:
- the TUNNEL refuses no cut and warns of nothing;
- GENERATE names no zone below 1/500 of the mean (its small-zone warning);
- SOLVE balances before and after DELETE ANN (force ratio 1e-5, the
  default RATIO) with no error.
"""
import sys
from grazing_deck import grazing_deck
from udec_test import check, finish, run, workdir, write

udec = sys.argv[1]
DECK = grazing_deck("tunnel 10.0,10.0 2.201 24")
d = workdir()
write(d, "grazing.dat", DECK)
rc, out = run(udec, ["grazing.dat"], cwd=d, timeout=300)
lines = out.splitlines()
tunnel = [l for l in lines if "TUNNEL" in l and not l.lower().startswith("tunnel ")]
check(len(tunnel) == 1 and "refused" not in out and "Warning: TUNNEL" not in out,
      "the TUNNEL grazed by a joint refuses no cut and warns of nothing", "\n".join(tunnel))
check(not any("Warning: GENERATE" in l for l in lines), "GENERATE makes no zone below 1/500 of the mean",
      "\n".join(l for l in lines if "GENERATE" in l))
solves = [l for l in lines if l.startswith("SOLVE:")]
check(rc == 0 and "***" not in out, "the deck runs without error",
      "\n".join(l for l in lines if "***" in l))
check(len(solves) == 2 and all("balanced after" in l for l in solves),
      "SOLVE balances before and after the excavation", "\n".join(solves))
finish()
