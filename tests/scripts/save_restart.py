"""SAVE / RESTART from the command line: the tutorial decks (manual Section
2.1: slope1 saves SLOPE.SAV, slope2 and slope3 restart from it), the model
after RESTART prints as before SAVE, bad files are refused with a clear
message and no HDF5 error dump, a failed SAVE keeps the older file, h5dump
shows self-explaining names, SET XFORM is accepted, the default file name."""
import os
import re
import resource
import shutil
import signal
import subprocess
import sys
sys.path.insert(0, os.path.dirname(__file__))
from udec_test import check, finish, run, workdir, write  # noqa: E402

udec = sys.argv[1]
source = sys.argv[2]

GEOMETRY = ("HEAD\nsave test\nBLOCK (0,0) (0,20) (20,20) (20,0)\nSPLIT (0,2) (20,8)\n"
            "SPLIT (5,3) (5,20)\nPROP MAT=1 DENS=2000\nPROP JMAT=1 JKN=1.33E7 JFRIC=0.35\n")


def block_table(text):
    """The rows of PRINT BLOCK (block number first)."""
    return [line for line in text.splitlines() if re.match(r"^\s+\d+\s+\d+\s+\d+\s+\d+", line)]


def no_hdf5_dump(out, label):
    check("HDF5-DIAG" not in out and "H5F" not in out, label + ": no HDF5 error dump", out)


def leftovers(folder):
    return [name for name in os.listdir(folder) if ".tmp" in name]


# --- the tutorial decks, run in order in one folder (as `make run` does)
d = workdir()
for deck in ("slope1", "slope2", "slope3"):
    shutil.copy(os.path.join(source, "examples", "tutorial", deck + ".dat"), d)
rc, out = run(udec, ["slope1.dat"], cwd=d)
check(rc == 0 and "Model saved to 'SLOPE.SAV'" in out, "slope1 saves SLOPE.SAV", out)
check(os.path.isfile(os.path.join(d, "SLOPE.SAV")), "SLOPE.SAV exists")
saved = open(os.path.join(d, "SLOPE.SAV"), "rb").read() if os.path.isfile(
    os.path.join(d, "SLOPE.SAV")) else b""
for deck in ("slope2", "slope3"):
    rc, out = run(udec, [deck + ".dat"], cwd=d)
    check(rc == 0 and "Model restored from 'SLOPE.SAV'" in out, deck + " restarts", out)
check(open(os.path.join(d, "SLOPE.SAV"), "rb").read() == saved,
      "restarting leaves SLOPE.SAV as it was")
check(leftovers(d) == [], "no temporary files left", str(os.listdir(d)))

# --- h5dump shows what the file holds by name
if shutil.which("h5dump"):
    proc = subprocess.run(["h5dump", "-H", "SLOPE.SAV"], cwd=d, stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, text=True)
    for name in ("schema_version", "program_version", "heading", 'GROUP "geometry"',
                 'GROUP "blocks"', 'DATASET "xc"', 'GROUP "contacts"', 'GROUP "state"',
                 'DATASET "fn"', 'GROUP "mechanics"', 'GROUP "history"',
                 "property_names", "allocated_size", "rng_state"):
        check(name in proc.stdout, "h5dump shows " + name, proc.stdout[:2000])
else:
    print("h5dump not installed: names not checked")

# --- the restored model prints as the saved one
d = workdir()
write(d, "a.dat", GEOMETRY + "PRINT BLOCK\nSAVE geo.sav\nSTOP\n")
write(d, "b.dat", "RESTART geo.sav\nPRINT BLOCK\nSTOP\n")
rc, out_a = run(udec, ["a.dat"], cwd=d)
check(rc == 0, "a deck that saves runs", out_a)
rc, out_b = run(udec, ["b.dat"], cwd=d)
check(rc == 0 and "save test" in out_b, "restart shows the heading", out_b)
check(block_table(out_a) and block_table(out_a) == block_table(out_b),
      "PRINT BLOCK after RESTART equals PRINT BLOCK before SAVE", out_a + out_b)

# --- bad files: refused, clear message, no HDF5 dump, model kept
good = open(os.path.join(d, "geo.sav"), "rb").read()
with open(os.path.join(d, "half.sav"), "wb") as f:
    f.write(good[:len(good) // 2])
write(d, "text.sav", "this is not a save file\n")
cases = [("nosuch.sav", "no such file"), ("half.sav", "truncated or damaged"),
         ("text.sav", "not an HDF5 file")]
for name, phrase in cases:
    write(d, "bad.dat", "RESTART " + name + "\n")
    rc, out = run(udec, ["bad.dat"], cwd=d)
    check(rc != 0 and "cannot read save file '" + name + "'" in out and phrase in out,
          "RESTART " + name + ": refused with '" + phrase + "'", out)
    check("the model in memory is unchanged" in out, name + ": says the model is kept", out)
    no_hdf5_dump(out, name)
    # interactively the session goes on with the model it had
    rc, out = run(udec, [], cwd=d, stdin_text="RESTART geo.sav\nRESTART " + name +
                  "\nPRINT BLOCK\nSTOP\n")
    check(block_table(out) == block_table(out_a), name + ": model in memory unchanged", out)

# --- a committed save file of schema version 1 still loads and holds the model
# its deck builds today (tests/data/save_schema1.dat wrote it)
d = workdir()
shutil.copy(os.path.join(source, "tests", "data", "save_schema1.dat"), d)
rc, fresh = run(udec, ["save_schema1.dat"], cwd=d)
# (a copy under another name: a leading '/' is a delimiter in UDEC's syntax)
shutil.copy(os.path.join(source, "tests", "data", "save_schema1.sav"), os.path.join(d, "v1.sav"))
write(d, "old.dat", "RESTART v1.sav\nPRINT BLOCK\nPRINT PROPERTY\nSTOP\n")
rc, restored = run(udec, ["old.dat"], cwd=d)
check(rc == 0 and "schema 1 reference file" in restored, "the schema 1 file restarts", restored)


def property_rows(text):
    return [line for line in text.splitlines() if re.match(r"^\s+\d+\s+[A-Z]+\s+\S+$", line)]


# a file older than schema 11 has no 1989 addresses: they are given afresh on
# RESTART (in id order), so the ADDRESS column (last) may differ from the deck's
def without_address(rows):
    return [row.rsplit(None, 1)[0] for row in rows]


check(block_table(fresh) and without_address(block_table(fresh)) == without_address(block_table(restored)),
      "schema 1 file: PRINT BLOCK as built by its deck", fresh + restored)
check(property_rows(fresh) and property_rows(fresh) == property_rows(restored),
      "schema 1 file: PRINT PROPERTY as built by its deck", fresh + restored)

# --- a committed save file of schema version 2 (zones, gridpoints, boundary
# conditions; written before SET ZPRESS came with schema 3) still loads and
# holds what its deck builds today (tests/data/save_schema2.dat wrote it)
shutil.copy(os.path.join(source, "tests", "data", "save_schema2.dat"), d)
shutil.copy(os.path.join(source, "tests", "data", "save_schema2.sav"), os.path.join(d, "v2.sav"))
rc2, fresh2 = run(udec, ["save_schema2.dat"], cwd=d)
write(d, "old2.dat", "RESTART v2.sav\nPRINT ZONE STRESS\nPRINT GRIDPOINT\nPRINT BOUNDARY STATE\nSTOP\n")
rc, restored2 = run(udec, ["old2.dat"], cwd=d)
check(rc == 0 and "schema 2 reference file" in restored2, "the schema 2 file restarts", restored2)


def zone_tables(text):
    """Output lines from the first PRINT ZONE up to SAVE or STOP."""
    lines = text.splitlines()
    start = next((i for i, l in enumerate(lines) if l.strip().startswith("PRINT ZONE")), None)
    if start is None:
        return []
    out = []
    addressed = False
    for line in lines[start:]:
        if line.strip().startswith(("SAVE", "STOP")):
            break
        # the ADDRESS column of a state table: given afresh for a file older
        # than schema 11 (see without_address above)
        if line.rstrip().endswith("ADDRESS"):
            addressed = True
            line = line.rstrip()[:-len("ADDRESS")]
        elif not re.match(r"^\s+\d", line):
            addressed = False
        elif addressed:
            line = line.rstrip().rsplit(None, 1)[0]
        out.append(line.rstrip())
    return out


check(rc2 == 0 and len(zone_tables(fresh2)) > 40 and zone_tables(fresh2) == zone_tables(restored2),
      "schema 2 file: zone stresses, gridpoints and boundary as built by its deck", fresh2 + restored2)

# --- default file name: UDEC.SAV
write(d, "default.dat", GEOMETRY + "SAVE\nSTART\nRESTART\nPRINT BLOCK\nSTOP\n")
rc, out = run(udec, ["default.dat"], cwd=d)
check(rc == 0 and os.path.isfile(os.path.join(d, "UDEC.SAV")), "SAVE without a name: UDEC.SAV",
      out)
check(block_table(out) == block_table(out_a), "RESTART without a name reads UDEC.SAV", out)

# --- SET XFORM ON|OFF accepted, a bare XFORM is not
write(d, "xform.dat", "SET XFORM ON\nSET XFORM OFF\nSTOP\n")
rc, out = run(udec, ["xform.dat"], cwd=d)
check(rc == 0 and "Error" not in out, "SET XFORM ON / OFF accepted", out)
write(d, "xform2.dat", "SET XFORM\n")
rc, out = run(udec, ["xform2.dat"], cwd=d)
check(rc != 0 and "expected ON or OFF after XFORM" in out, "SET XFORM alone refused", out)


# --- a SAVE that fails part-way (file size limit: the disk is "full") keeps the
# older file byte for byte and leaves no temporary file; works as root too
def limited():
    signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
    resource.setrlimit(resource.RLIMIT_FSIZE, (4096, 4096))


d = workdir()
write(d, "g.dat", GEOMETRY + "SAVE old.sav\nSTOP\n")
rc, out = run(udec, ["g.dat"], cwd=d)
old = open(os.path.join(d, "old.sav"), "rb").read()
check(len(old) > 4096, "the save file is larger than the size limit used below")
proc = subprocess.run([udec], cwd=d, input=GEOMETRY + "SPLIT (5,12) (20,18)\n"
                      "SAVE old.sav\nSTOP\n", stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                      text=True, preexec_fn=limited, timeout=60)
check("SAVE: cannot write save file 'old.sav'" in proc.stdout,
      "SAVE beyond the file size limit is reported", proc.stdout)
no_hdf5_dump(proc.stdout, "failed SAVE")
check(open(os.path.join(d, "old.sav"), "rb").read() == old, "failed SAVE keeps the older file")
check(leftovers(d) == [], "failed SAVE leaves no temporary file", str(os.listdir(d)))

# --- no write permission in the folder (root ignores permissions: skipped)
if os.geteuid() != 0:
    sub = os.path.join(d, "locked")
    os.mkdir(sub)
    shutil.copy(os.path.join(d, "old.sav"), sub)
    os.chmod(sub, 0o555)
    try:
        rc, out = run(udec, [], cwd=d, stdin_text=GEOMETRY + "SAVE locked/old.sav\nSTOP\n")
        check("cannot write save file 'locked/old.sav'" in out, "SAVE without permission "
              "is reported", out)
        check(open(os.path.join(sub, "old.sav"), "rb").read() == old,
              "SAVE without permission keeps the older file")
    finally:
        os.chmod(sub, 0o755)
else:
    print("running as root: the no-permission case is skipped (the size-limit case covers it)")

finish()
