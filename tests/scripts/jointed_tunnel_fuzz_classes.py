"""The unbalanced class of tools/jointed_tunnel_fuzz.py split by what it is (round 4,
docs/robustness.md; label stability). Three quick draws that end a SOLVE at its
8 000-cycle limit:
  152 (rigid, two ARC 180s, DAMP AUTO) still settling after its excavation: the
      generator reads "settling" (the unbalanced force falls through the SOLVE's
      second half fast enough to reach RATIO 1e-5 within SOLVE's default 100 000
      cycles), and the verdict is checked: the same deck with SOLVE CYCLES 100000
      after the excavation balances (it did at 18 600 cycles in round 4);
  174 (rigid, soft joints, DAMP LOCAL 0.8) a floor wedge squeezed into the opening:
      "mechanism" (46 Kirsch scales moved at 8 000 cycles and still 0.076 m/s; at
      40 000 cycles it moved 234 and the force ratio stayed 7.2e-5);
  162 (zoned, BOUNDARY STRESS alone with a shear) a field beyond joint set 2's friction
      (|tau| / sigma_n 0.547 > 0.507): "mechanism" before any excavation.
Each of these read "unbalanced" before round 4. A wrong verdict fails: 152 not
balancing with the longer limit, or any seed classed otherwise."""
import json
import os
import re
import subprocess
import sys
import tempfile

EXPECT = {152: "settling", 174: "mechanism", 162: "mechanism"}


def main():
    udec, src = sys.argv[1], sys.argv[2]
    tool = os.path.join(src, "tools", "jointed_tunnel_fuzz.py")
    bad = 0
    with tempfile.TemporaryDirectory() as tmp:
        res = subprocess.run([sys.executable, tool, udec, tmp, "--seeds",
                              ",".join(map(str, EXPECT)), "--quick", "--timeout", "120"],
                             capture_output=True, text=True)
        print(res.stdout, res.stderr)
        got = {r["seed"]: r["outcome"] for r in
               (json.loads(ln) for ln in res.stdout.splitlines() if ln.startswith("{"))}
        for seed, want in EXPECT.items():
            ok = got.get(seed) == want
            print(f"seed {seed}: {got.get(seed)} (expected {want}) {'ok' if ok else 'FAIL'}")
            bad += not ok
        # the settling verdict: SOLVE's default limit balances the excavation
        work = os.path.join(tmp, "s152")
        deck = open(os.path.join(work, "deck.dat")).read()
        head, tail = deck.split("DELETE ANN")
        tail = tail.replace("SOLVE CYCLES 8000", "SOLVE CYCLES 100000", 1)
        with open(os.path.join(work, "long.dat"), "w") as f:
            f.write(head + "DELETE ANN" + tail)
        out = subprocess.run([udec, "long.dat"], cwd=work, capture_output=True,
                             text=True).stdout
        after = out.split("DELETE ANN")[-1]
        m = re.search(r"SOLVE: balanced after (\d+) cycles", after)
        print("seed 152 with SOLVE CYCLES 100000:", m.group(0) if m else "not balanced")
        bad += m is None
    sys.exit(1 if bad else 0)


if __name__ == "__main__":
    main()
