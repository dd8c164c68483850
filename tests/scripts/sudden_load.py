"""A static load given at once on a balanced model under DAMP AUTO reaches its static
answer without the dynamic overshoot breaking a joint the static answer does not break
(label stability; docs/closed_form.md finding A, docs/mechanics.md DAMP AUTO).

The model (campaign round 8, deck 6): a 2 x 1 m rigid block (2000 kg/m3, weight 4e4 N
under g = 10) on a horizontal joint between two 1 m contacts, JTEN 5e4 Pa (JCONS 2:
5e4 N a contact), on a FIXed base. After 1000 cycles at rest each contact carries 2e4 N
of compression. A pull P upward at once (LOAD on the block, or BOUNDARY YLOAD on its
two top corners, no history) has the static answer (P - 4e4) / 2 of tension a contact
(statics of the symmetric block). Cases:
  1. LOAD 1.3e5 (4.5e4 N a contact, 90 % of the strength): holds, each contact
     -4.5e4 N within 0.1 % (1e-3: the joint's elastic force after 4000 cycles), block
     displacement below 1e-4 m. Before the fix the first swing, met by an adaptive
     alpha that had drifted down at rest to 240 1/s (critical for the block 4 470 1/s),
     rang to about twice the static change and broke the joint from a pull of 0.8e5 on.
  2. BOUND YLOAD 0.65e5 on the two top corners at once (the same 1.3e5): as 1.
  3. LOAD 1.42e5 (5.1e4 N a contact, past the strength): the joint breaks (no contact
     left), so the check of 1 can fail.
  4. SOLVE after LOAD 0.6e5 balances (force ratio 1e-5) within 150 cycles (100 measured;
     170 before the fix)."""
import os
import sys
sys.path.insert(0, os.path.dirname(__file__))
from udec_test import check, finish, run_deck, workdir  # noqa: E402
from shared_decks import TENSILE_BLOCK  # noqa: E402

udec = sys.argv[1]

BASE = TENSILE_BLOCK + """{load}
{run}
PRINT CONT FORCE
PRINT RIGID
STOP
"""


def pulled(name, load, run="CYCLE 4000"):
    """Normal forces of the joint's contacts and the block's y displacement."""
    _, out = run_deck(udec, workdir(), name, BASE.format(load=load, run=run))
    part = out.split("PRINT CONT FORCE")[-1].split("PRINT RIGID")[0]
    forces = [float(f[4]) for f in (l.split() for l in part.splitlines())
              if len(f) == 8 and f[0].isdigit()]
    blk = [l.split() for l in out.split("PRINT RIGID")[-1].splitlines()
           if len(l.split()) == 9 and l.split()[0] == "3"]
    uy = float(blk[0][6]) if blk else float("nan")
    return forces, uy, out


for name, load in (("load_at_once", "LOAD 1 3 0 1 0 1.3E5"),
                   ("corner_load_at_once", "BOUND 0.9 3.1 0.9 1.1 YLOAD 0.65E5")):
    forces, uy, _ = pulled(name, load)
    print(f"{name}: contact normal forces {forces}, block uy {uy:.3e}")
    check(len(forces) == 2 and all(abs(f + 4.5e4) <= 45.0 for f in forces),
          f"{name}: the joint holds, each contact at the static -4.5e4 N", str(forces))
    check(abs(uy) < 1e-4, f"{name}: the block stays", f"{uy}")

forces, uy, _ = pulled("load_past_strength", "LOAD 1 3 0 1 0 1.42E5")
print(f"load_past_strength: contacts {forces}, block uy {uy:.3e}")
check(not forces and uy > 1e-3, "load past the strength: the joint breaks, the block rises",
      f"{forces} {uy}")

_, _, out = pulled("solve_after_load", "LOAD 1 3 0 1 0 0.6E5", run="SOLVE")
m = [l for l in out.splitlines() if l.startswith("SOLVE: balanced after")]
n = int(m[0].split()[3]) if m else -1
print(f"solve_after_load: {m[:1]}")
check(0 < n <= 150, "SOLVE after a load given at once balances within 150 cycles", str(m))

finish()
