"""Issue 24: EXPORT name.vtu (VTK XML unstructured grid, ASCII) and EXPORT
HISTORY name.csv. The .vtu is read with Python's standard XML parser and its
counts and sums are checked against PRINT: blocks (PRINT BLOCK), zones and
the sum of their SXX and SYY (PRINT ZONE STRESS, printed to 6 digits:
within 1e-5 of the sum of magnitudes), contacts and the sum of their normal
forces (PRINT CONTACT FORCE). The CSV is read with the csv module: a header
naming each history with its unit, and each column equal to what HIST WRITE
writes for it (both carry 16 digits). A bad name or a folder is refused and
no temporary is left behind. A thermal model exports its temperatures."""
import csv
import os
import sys
import xml.etree.ElementTree as ET
sys.path.insert(0, os.path.dirname(__file__))
from udec_test import check, finish, run, workdir, write, tables  # noqa: E402

udec = sys.argv[1]
source = sys.argv[2]

DECK = """HEADING
two blocks, the upper one zoned
ROUND 0.01
BLOCK 0,0 0,2 2,2 2,0
CRACK 0,1 2,1
CRACK 1,0 1,1
CHANGE 0 2 1 2 FDEF
GEN 0 2 1 2 EDGE 0.5
PROP MAT=1 DENS=2000 K=1e9 G=0.6e9 JKN=1e9 JKS=1e9 JFRIC=30
GRAV 0 -10
FIX 0 2 0 0.5
DAMP AUTO
HIST YVEL 1,2 UNBAL
CYCLE 50
HIST SXX 1,1.5
CYCLE 150
EXPORT model.vtu
EXPORT HISTORY hist.csv
HIST WRITE 1 h1.txt
HIST WRITE 2 h2.txt
HIST WRITE 3 h3.txt
PRINT BLOCK
PRINT ZONE STRESS
PRINT CONTACT FORCE
STOP
"""
d = workdir()
write(d, "deck.dat", DECK)
rc, out = run(udec, ["deck.dat"], cwd=d, timeout=120)
check(rc == 0, "the deck runs (status %s)" % rc, out[-2000:])

root = ET.parse(os.path.join(d, "model.vtu")).getroot()
check(root.tag == "VTKFile" and root.get("type") == "UnstructuredGrid",
      "a VTK XML UnstructuredGrid file")
piece = root.find("UnstructuredGrid/Piece")
npts, ncells = int(piece.get("NumberOfPoints")), int(piece.get("NumberOfCells"))


def array(section, name):
    for a in piece.find(section).findall("DataArray"):
        if a.get("Name") == name:
            check(a.get("format") == "ascii", name + " is ASCII")
            return [float(v) for v in a.text.split()]
    return None


pts = [float(v) for v in piece.find("Points/DataArray").text.split()]
check(len(pts) == 3 * npts, "NumberOfPoints points")
conn = [int(v) for v in array("Cells", "connectivity")]
offsets = [int(v) for v in array("Cells", "offsets")]
types = [int(v) for v in array("Cells", "types")]
check(len(offsets) == ncells and len(types) == ncells and offsets[-1] == len(conn)
      and all(0 <= i < npts for i in conn), "cells, offsets and connectivity agree")
kind = [int(v) for v in array("CellData", "kind")]
ids = [int(v) for v in array("CellData", "id")]
blocks = tables(out, "PRINT BLOCK")[0]
zones = tables(out, "PRINT ZONE STRESS")[0]
contacts = tables(out, "PRINT CONTACT FORCE")[0]
nb, nz, nc = kind.count(1), kind.count(2), kind.count(3)
check(nb == len(blocks) == 3, "blocks: %d in the .vtu, %d in PRINT BLOCK" % (nb, len(blocks)))
check(nz == len(zones) > 10, "zones: %d in the .vtu, %d in PRINT ZONE" % (nz, len(zones)))
check(nc == len(contacts) > 4, "contacts: %d in the .vtu, %d in PRINT CONTACT" % (nc, len(contacts)))
check([ids[i] for i in range(ncells) if kind[i] == 1] == [int(b["BLOCK"]) for b in blocks],
      "block ids as PRINT BLOCK")
check(all(types[i] == {1: 7, 2: 5, 3: 3}[kind[i]] for i in range(ncells)),
      "polygons, triangles and lines")
mat = [int(v) for v in array("CellData", "material")]
check([mat[i] for i in range(ncells) if kind[i] == 1] == [int(b["MAT"]) for b in blocks],
      "block materials as PRINT BLOCK")
for comp in ("SXX", "SYY"):
    vtu = sum(v for v, k in zip(array("CellData", comp.lower()), kind) if k == 2)
    printed = [z[comp] for z in zones]
    tol = 1e-5 * sum(abs(v) for v in printed)
    check(abs(vtu - sum(printed)) <= tol, "sum of zone %s: %.6g in the .vtu, %.6g printed"
          % (comp, vtu, sum(printed)))
fn = sum(v for v, k in zip(array("CellData", "normal_force"), kind) if k == 3)
printed = sum(c["NORMAL-FORCE"] for c in contacts)
check(abs(fn - printed) <= 1e-5 * printed, "sum of contact normal forces: %.6g in the .vtu, "
      "%.6g printed" % (fn, printed))
for name, ncomp in (("velocity", 3), ("displacement", 3), ("state", 1), ("shear_force", 1),
                    ("aperture", 1), ("szz", 1), ("sxy", 1)):
    a = array("CellData", name)
    check(a is not None and len(a) == ncomp * ncells, "cell array " + name)
for name in ("velocity", "displacement"):
    a = array("PointData", name)
    check(a is not None and len(a) == 3 * npts, "point array " + name)
check(array("PointData", "temperature") is None, "no temperature without heat conduction")

# the CSV: a header naming each history and its unit, columns as HIST WRITE
with open(os.path.join(d, "hist.csv"), newline="") as f:
    rows = list(csv.reader(f))
header = rows[0]
check(header[:2] == ["cycle", "time [s]"] and len(header) == 5, "CSV header: cycle, time, "
      "three histories", str(header))
check(header[2].startswith("1 YVEL") and header[2].endswith("[m/s]")
      and header[3] == "2 UNBAL [N]" and header[4].startswith("3 SXX")
      and header[4].endswith("[Pa]"), "each history named with its unit", str(header))
data = rows[1:]
check(len(data) == 20 and [int(r[0]) for r in data] == list(range(10, 201, 10)),
      "one row per sample (every 10 cycles)")
for h in (1, 2, 3):
    written = [l.split() for l in open(os.path.join(d, "h%d.txt" % h)) if not l.startswith("#")]
    col = [(float(r[1]), float(r[1 + h])) for r in data if r[1 + h] != ""]
    same = len(col) == len(written) and all(
        abs(t - float(w[0])) <= 1e-12 * abs(t) and abs(v - float(w[1])) <= 1e-12 * max(abs(v), 1e-300)
        for (t, v), w in zip(col, written))
    check(same, "history %d: the CSV column is HIST WRITE's samples (%d rows)" % (h, len(col)))
check(all(r[4] == "" for r in data[:5]) and data[5][4] != "",
      "a history defined at cycle 50 is empty before its first sample")

# refusals: name, folder; nothing left behind
os.mkdir(os.path.join(d, "folder.vtu"))
for line, expect in (("EXPORT model.txt", ".vtu"), ("EXPORT folder.vtu", "folder"),
                     ("EXPORT HISTORY", "file name")):
    write(d, "bad.dat", DECK.replace("STOP\n", "") + line + "\nSTOP\n")
    rc, out = run(udec, ["bad.dat"], cwd=d, timeout=120)
    check(rc == 1 and "*** Error: EXPORT" in out and expect in out.split("*** Error:")[-1],
          "'%s' is refused naming the problem" % line, out[-600:])
check(not [f for f in os.listdir(d) if "model.vtu" in f and f != "model.vtu"],
      "no temporary file is left", str(os.listdir(d)))

# heat conduction: temperatures at the gridpoints
fin = open(os.path.join(source, "verification", "thermal1", "case_a.dat")).read()
t = workdir()
write(t, "fin.dat", fin.split("run ")[0] + "run ste 100\nEXPORT fin.vtu\nstop\n")
rc, out = run(udec, ["fin.dat"], cwd=t, timeout=120)
root = ET.parse(os.path.join(t, "fin.vtu")).getroot()
piece = root.find("UnstructuredGrid/Piece")
temp = array("PointData", "temperature")
check(rc == 0 and temp is not None and len(temp) == int(piece.get("NumberOfPoints"))
      and abs(max(temp) - 1100.0) < 1e-9, "a thermal model exports its temperatures "
      "(the fixed 1100 degrees at most)", out[-800:])
finish()
