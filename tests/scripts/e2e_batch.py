"""Batch mode: DATA, udec FILE, OUT, exit status, CALL/RETURN, UDEC.INI, options."""
import os
import sys
sys.path.insert(0, os.path.dirname(__file__))
from udec_test import check, finish, run, workdir, write  # noqa: E402

udec = sys.argv[1]

# --help / --version / bad options
rc, out = run(udec, ["--help"])
check(rc == 0 and "Usage: udec" in out, "--help prints usage and exits 0", out)
rc, out = run(udec, ["--version"])
check(rc == 0 and out.startswith("udec ") and "HDF5" in out and "LAPACK" in out,
      "--version names the program and linked libraries", out)
rc, out = run(udec, ["--frobnicate"])
check(rc == 2 and "unknown option" in out, "unknown option is a usage error (2)", out)

# DATA in the working folder runs in batch; output on screen and in OUT.
d = workdir()
write(d, "DATA", "* tutorial start\nBLOCK (0,0) (0,20) (20,20) (20,0)\nHEAD\nmy title\nSTOP\n")
rc, out = run(udec, cwd=d)
check(rc == 0, "batch DATA ends with status 0 after STOP", out)
outfile = open(os.path.join(d, "OUT")).read()
check("* tutorial start" in outfile and "BLOCK (0,0)" in outfile,
      "OUT holds the echoed input, comments included", outfile)
check("* tutorial start" in out, "comments are echoed to the screen", out)

# HEADING: the manual's form takes the next line; a title on HEADING's own
# line (udec extension, what a new user writes) is taken as is and the next
# line is read as a command.
write(d, "head.dat", "HEAD RIGID TUNNEL 2\nBLOCK (0,0) (0,20) (20,20) (20,0)\nPRINT STATUS\n"
      "HEAD\nsecond title\nPRINT STATUS\nSTOP\n")
rc, out = run(udec, ["head.dat"], cwd=d)
check(rc == 0 and "*** Error" not in out, "HEAD with the title on its own line runs", out)
check("RIGID TUNNEL 2" in out and "second title" in out, "both titles are shown by PRINT STATUS", out)
# the title on HEADING's line is taken as typed: commas and spacing stay
write(d, "head2.dat", "HEAD Tunnel, 3 m wide,  joints at 30, 120\nPRINT STATUS\nSTOP\n")
rc, out = run(udec, ["head2.dat"], cwd=d)
check(rc == 0 and "Tunnel, 3 m wide,  joints at 30, 120" in out,
      "a title on HEADING's line keeps its commas", out)
# ... and its brackets: a `)` or `(` at either end of the title was lost
write(d, "head3.dat", "HEAD tunnel (no INSITU) * a comment\nPRINT STATUS\n"
      "HEAD (first word bracketed)\nPRINT STATUS\nSTOP\n")
rc, out = run(udec, ["head3.dat"], cwd=d)
titles = [ln.split(None, 1)[1] for ln in out.splitlines() if ln.strip().startswith("heading ")]
check(rc == 0 and titles == ["tunnel (no INSITU)", "(first word bracketed)"],
      "a title on HEADING's line keeps its brackets, not the comment", out)

# a command short of arguments names what it takes (TUNNEL without its sides)
write(d, "tun.dat", "BLOCK 0,0 0,10 10,10 10,0\nTUNNEL 5,5 2\nSTOP\n")
rc, out = run(udec, ["tun.dat"], cwd=d)
check(rc == 1 and "usage: TUNNEL r r r q" in out and "number of sides" in out,
      "TUNNEL without its number of sides shows the syntax and names the argument", out)
write(d, "pj.dat", "BLOCK 0,0 0,10 10,10 10,0\nPLOT BLOCK JOINT\nSTOP\n")
rc, out = run(udec, ["pj.dat"], cwd=d)
check(rc == 1 and "usage: PLOT JOINT r r r r" in out,
      "a keyword short of arguments shows that keyword's syntax", out)

# udec FILE runs FILE (OUT written too); error -> non-zero with file and line.
write(d, "bad.dat", "HEAD\ntitle\nPROP MAT=1 DENS=2000\nCYCLE 1.5\nCYCLE 10\nSTOP\n")
rc, out = run(udec, ["bad.dat"], cwd=d)
check(rc != 0, "batch input error gives non-zero status", out)
check("in file bad.dat, line 4" in out, "error names file and line", out)
check("CYCLE 10" not in out, "batch run stops at the first input error", out)
check("line 4" in open(os.path.join(d, "OUT")).read(), "OUT holds the error too")

# A numerical failure is not an input error: a block on a joint far too soft
# for its weight (JKN 1e5 Pa/m, 5e4 N over 2 m: 0.25 m of closure) overlaps
# beyond half the rounding. The message names the causes of UDEC manual
# (ICG1.5, 1989), Section 5.3, and the run stops saying the calculation failed.
write(d, "soft.dat", "ROUND 0.1\nBLOCK 0,0 0,2 2,2 2,0\nSPLIT 0,1 2,1\nFIX 0 2 0 1\n"
      "PROP MAT=1 DENS=2500\nPROP JMAT=1 JKN=1e5 JKS=1e5 JFRIC=0.5\nGRAV 0 -10\n"
      "CYCLE 2000\nPRINT MAX\nSTOP\n")
rc, out = run(udec, ["soft.dat"], cwd=d)
check(rc == 1 and "Contact Overlap Too Great" in out and "manual Section 5.3" in out
      and "in file soft.dat, line 8" in out,
      "a numerical failure names the manual's causes and the CYCLE's line", out[-1500:])
check("Run stopped because the calculation failed" in out and "input error" not in out
      and "PRINT MAX" not in out.split("Overlap")[-1],
      "a numerical failure stops the batch run as a failed calculation, not an input error",
      out[-1500:])

# Missing input file
rc, out = run(udec, ["nosuch.dat"], cwd=d)
check(rc != 0 and "cannot open file 'nosuch.dat'" in out, "missing FILE reported", out)

# End of input without STOP is fine; END is accepted (legacy)
write(d, "nostop.dat", "HEAD\nx\n")
rc, out = run(udec, ["nostop.dat"], cwd=d)
check(rc == 0, "end of file without STOP exits 0", out)
write(d, "end.dat", "END\nFOO\n")
rc, out = run(udec, ["end.dat"], cwd=d)
check(rc == 0 and "FOO" not in out.split("END", 1)[1], "END stops the run (legacy)", out)

# Continuations in files: '&' at the end and '+' at the start of a line
write(d, "cont.dat", "PROP MAT=1 &\n  DENS=2000\nPROP MAT=1\n+ DENS=-1\nSTOP\n")
rc, out = run(udec, ["cont.dat"], cwd=d)
check(rc != 0 and "DENSITY: expected a real number >= 0, got '-1'" in out
      and "line 3" in out, "'+' continuation joins the next line (error on line 3)", out)

# HISTORY FUNCTION (the 1989 user-written FPLHIS) has no counterpart: it is
# refused as an input error naming the alternatives, and the batch stops.
write(d, "ni.dat", "DAMP AUTO\nHIST FUNCTION 1\nHEAD\nreached\nSTOP\n")
rc, out = run(udec, ["ni.dat"], cwd=d)
check(rc == 1 and "FPLHIS" in out and "reached" not in out,
      "HISTORY FUNCTION is refused with a message and the batch stops", out)

# CALL nesting four deep, RETURN, recursion error.
write(d, "c1.dat", "HEAD\nin c1\nCALL c2.dat\nHEAD\nback in c1\n")
write(d, "c2.dat", "CALL c3.dat\nHEAD\nback in c2\n")
write(d, "c3.dat", "CALL c4.dat\nHEAD\nback in c3\nRETURN\nHEAD\nnever\n")
write(d, "c4.dat", "HEAD\ndeepest\nRETURN\nFOO\n")
write(d, "main.dat", "CALL c1.dat\nHEAD\nback in main\nSTOP\n")
rc, out = run(udec, ["main.dat"], cwd=d)
check(rc == 0, "CALL nesting four deep runs", out)
for text in ["deepest", "back in c3", "back in c2", "back in c1", "back in main"]:
    check(text in out, f"CALL chain reached '{text}'", out)
check("never" not in out and "FOO" not in out, "RETURN leaves the CALLed file", out)
order = [out.find(t) for t in ["deepest", "back in c3", "back in c2", "back in c1", "back in main"]]
check(order == sorted(order), "CALLs return in order", out)

write(d, "r1.dat", "CALL r2.dat\n")
write(d, "r2.dat", "CALL r1.dat\n")
write(d, "rec.dat", "CALL r1.dat\nSTOP\n")
rc, out = run(udec, ["rec.dat"], cwd=d)
check(rc != 0 and "recursive CALL" in out and "in file r2.dat, line 1" in out,
      "recursive CALL is a clear error", out)
write(d, "ret.dat", "RETURN\n")
rc, out = run(udec, ["ret.dat"], cwd=d)
check(rc != 0 and "RETURN: not inside a CALLed file" in out, "RETURN at top level", out)
write(d, "stopcall.dat", "CALL s2.dat\nHEAD\nnot reached\n")
write(d, "s2.dat", "STOP\n")
rc, out = run(udec, ["stopcall.dat"], cwd=d)
check(rc == 0 and "not reached" not in out, "STOP inside a CALLed file ends the run", out)

# UDEC.INI is read first in batch mode too.
e = workdir()
write(e, "UDEC.INI", "HEAD\nini title\n")
write(e, "DATA", "HEAD\ndata title\nSTOP\n")
rc, out = run(udec, cwd=e)
check(rc == 0 and out.find("ini title") < out.find("data title") and out.find("ini title") >= 0,
      "UDEC.INI runs before DATA", out)

# An error in UDEC.INI (manual 4.3: a file of site defaults read on start-up, "any
# valid UDEC commands") is reported with the file name and line, that line is skipped,
# the rest of UDEC.INI and then the deck still run (exit status 0).
f = workdir()
write(f, "UDEC.INI", "GRAV 0 -10\nSET NOSUCH\nHEAD\nafter bad ini line\n")
write(f, "DATA", "HEAD\ndata title\nPRINT STATUS\nSTOP\n")
rc, out = run(udec, cwd=f)
check("in file UDEC.INI, line 2" in out and "skipped" in out,
      "UDEC.INI error: names UDEC.INI and its line", out[-2000:])
check(rc == 0 and "after bad ini line" in out and "data title" in out
      and "Run stopped" not in out, "UDEC.INI error: the run goes on to the deck", out[-2000:])
# an error in the deck itself still stops the batch run (manual 4.4 batch mode)
write(f, "DATA", "HEAD\ndata title\nSET NOSUCH\nHEAD\nnot reached\n")
rc, out = run(udec, cwd=f)
check(rc == 1 and "not reached" not in out and "Run stopped" in out,
      "an error in DATA after a UDEC.INI error still stops the run", out[-2000:])

# START / NEW
write(d, "new.dat", "HEAD\nx\nSTART\nNEW\nSTOP\n")
rc, out = run(udec, ["new.dat"], cwd=d)
check(rc == 0 and out.count("New problem") == 2, "START and NEW begin a new problem", out)

# --check: every error of a file is listed, status 1; a clean file says ok.
write(d, "chk.dat", "BLOCK 0 0 0 1 1 1\nPROP MAT=1 DENZ=3\nFIX 1 2 0\nHEAD\nPROP FOO\nCYCLE 1\nSTOP\n")
rc, out = run(udec, ["--check", "chk.dat"], cwd=d)
check(rc == 1 and out.count("*** Error") == 2, "--check lists every error (2)", out)
check("line 2" in out and "line 3" in out, "--check names lines", out)
check("not yet implemented" not in out, "--check does not execute", out)
write(d, "ok.dat", "BLOCK 0 0 0 1 1 1\nSTOP\n")
rc, out = run(udec, ["--check", "ok.dat"], cwd=d)
check(rc == 0 and "ok.dat: ok" in out, "--check of a clean file", out)
finish()
