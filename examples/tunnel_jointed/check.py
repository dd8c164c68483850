"""The worked example runs as a user would run it (label examples): the deck
of examples/tunnel_jointed cycles to equilibrium, is excavated and cycled
again without an error, and shows what a rock engineer expects of an
unsupported tunnel in blocky rock at 400 m depth:
- the floor heaves and stops: YDIS at (20, 16.9) is positive, between 0.1 and
  5 mm, and changes by less than 2 % over the last 2000 cycles (rigid
  blocks on joints of 2e10 Pa/m under about 10 MPa: a few joints close by
  about 0.5 mm each);
- the roof key block, cut by the two steep sets meeting at 90 degrees with a
  friction angle of 31 degrees (< 45: the wedge cannot wedge itself), moves
  down more than the floor moves up and is still moving at the end;
- the four plots and the save file are written.
"""
import os
import re
import shutil
import sys
here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, "..", "..", "tests", "scripts"))
from udec_test import check, finish, run, workdir  # noqa: E402

udec = sys.argv[1]
folder = workdir()
shutil.copy(os.path.join(here, "tunnel.dat"), folder)
deck = open(os.path.join(folder, "tunnel.dat")).read()
# histories to a file so the curves can be read back
deck = deck.replace("SAVE tunnel.sav", "HIST WRITE 1 roof.his\nHIST WRITE 2 floor.his\n"
                    "SAVE tunnel.sav")
open(os.path.join(folder, "tunnel.dat"), "w").write(deck)
rc, out = run(udec, ["tunnel.dat"], cwd=folder, timeout=900)
check(rc == 0 and "Error" not in out, "the example runs without an error", out[-2000:])
for name in ("blocks.png", "displacement.png", "slip.png", "roof_floor.png", "tunnel.sav"):
    check(os.path.exists(os.path.join(folder, name)), f"{name} written")


def series(name):
    path = os.path.join(folder, name)
    if not os.path.exists(path):
        return []
    values = []
    for line in open(path):
        parts = line.split()
        if len(parts) >= 2 and re.fullmatch(r"[-+0-9.Ee]+", parts[-1]):
            try:
                values.append(float(parts[-1]))
            except ValueError:
                pass
    return values


roof, floor = series("roof.his"), series("floor.his")
check(len(roof) > 100 and len(floor) > 100, "the histories are written", out[-1500:])
if len(roof) > 100 and len(floor) > 100:
    last = floor[-1]
    before = floor[-1 - len(floor) // 4]
    print(f"  floor heave {last:.4e} m (2000 cycles before: {before:.4e}); roof {roof[-1]:.4e} m")
    check(1e-4 < last < 5e-3, "the floor heaves by 0.1 to 5 mm", str(last))
    check(abs(last - before) < 0.02 * abs(last), "the floor has stopped", f"{before} -> {last}")
    check(-roof[-1] > last, "the roof key block moves down more than the floor moves up",
          f"roof {roof[-1]}, floor {last}")
    check(abs(roof[-1] - roof[-1 - len(roof) // 8]) > 1e-5, "the key block is still moving",
          str(roof[-20:]))
finish()
