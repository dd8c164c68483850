"""Verification F (manual Appendix A, Test F): steady unconfined flow with a
free surface through an 8 m x 4 m jointed aquifer between reservoirs of 4 m
and 1 m head (-EFF total pressures, SET SFLOW steady-state algorithm).

Deck F.dat runs as printed (its PLOT lines too); PRINT FLOWS is added
before STOP. The discharge Q is the sum of the outflow rates of the boundary
contacts on the downstream face (x = 4), as the manual sums PRINT FLOW.

References (README.md):
* UDEC 1989: Q = 5.26e-6 m3/s (6.5 % below Dupuit). Our Q must lie within
  5 % of it. Justification: both are the same joint network (7 horizontal
  joints over a 4 m height, impermeable base, seepage face above 1 m), whose
  discrete transmissivity is below the continuum's by about the ratio of
  joints to 0.5 m layers; what may differ between the two programs is how
  the gravity head is referred to a domain (its position) and how dry
  domains are treated, a few per cent.
* Dupuit: Q = k (h1^2 - h2^2) / 2L = 5.625e-6 m3/s (k = 6e-6 m/s): Q within
  10 % (the discretisation alone costs about 7-10 %, see above).
* Steady state: total boundary inflow and outflow agree within 2 % of Q
  after the deck's 1500 cycles.
"""
import os
import re
import sys
sys.path.insert(0, os.path.join(os.path.dirname(__file__), ".."))
from common import check, finish, workdir, deck_with, run_deck  # noqa: E402

udec = sys.argv[1]
here = os.path.dirname(os.path.abspath(__file__))
Q_UDEC, Q_DUPUIT = 5.26e-6, 5.625e-6

folder = workdir()
text = deck_with(os.path.join(here, "F.dat"), ["print flows"])
rc, out, secs = run_deck(udec, folder, "F.dat", text)
check(rc == 0, "F.dat runs", f"rc={rc}, {secs:.1f} s")


def discharge(out):
    """(q_out, q_in_left, totals found, q_in_all, q_out_all) from PRINT FLOWS:
    the downstream discharge is the sum of the outflow rates of the boundary
    contacts on the face x = 4."""
    rows = []
    inside = False
    for line in out.splitlines():
        if line.startswith(" CONTACT    DOM1    DOM2"):
            inside = True
            continue
        if inside:
            f = line.split()
            if len(f) == 8:
                rows.append([float(v) for v in f])
            elif line.startswith("total"):
                inside = False
    q_out = -sum(r[7] for r in rows if r[3] > 3.9 and r[7] < 0)
    q_in_left = sum(r[7] for r in rows if r[3] < -3.9 and r[7] > 0)
    m_in = re.search(r"total boundary inflow\s+(\S+)", out)
    m_out = re.search(r"total boundary outflow\s+(\S+)", out)
    found = m_in is not None and m_out is not None
    return (q_out, q_in_left, found, float(m_in.group(1)) if m_in else 0.0,
            float(m_out.group(1)) if m_out else 0.0)


q_out, q_in_left, found, q_in_all, q_out_all = discharge(out)
check(found, "PRINT FLOWS totals printed")
print(f"Q downstream = {q_out:.4e} m3/s (UDEC 1989 {Q_UDEC:.3e}, Dupuit {Q_DUPUIT:.3e}); "
      f"upstream inflow {q_in_left:.4e}; all boundaries in {q_in_all:.4e} out {q_out_all:.4e}")
check(abs(q_out - Q_UDEC) <= 0.05 * Q_UDEC, "discharge within 5 % of UDEC's 5.26e-6",
      f"Q = {q_out:.4e}, {100 * (q_out / Q_UDEC - 1):+.1f} %")
check(abs(q_out - Q_DUPUIT) <= 0.10 * Q_DUPUIT, "discharge within 10 % of Dupuit's 5.625e-6",
      f"{100 * (q_out / Q_DUPUIT - 1):+.1f} %")
check(abs(q_in_all - q_out_all) <= 0.02 * q_out, "steady state: inflow = outflow within 2 %",
      f"in {q_in_all:.4e}, out {q_out_all:.4e}")
finish()
