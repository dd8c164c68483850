"""Drive the interactive UDEC> prompt through a pipe (manual Section 2.2)."""
import os
import sys
sys.path.insert(0, os.path.dirname(__file__))
from udec_test import check, finish, run, workdir, write  # noqa: E402

udec = sys.argv[1]

# A session with errors keeps going; HEAD prompts HEAD>; STOP ends with status 0.
d = workdir()
session = "\n".join([
    "PROP MAT=1 DENS=-5",          # out-of-range value: error, no exit
    "FOO 1",                       # unknown command: error naming close commands
    "CY 1.5",                      # integer expected
    "HEAD",
    "A SIMPLE SLOPE STABILITY EXAMPLE",
    "BLOCK (0,0) (0,20) (20,20) (20,0)",
    "* a comment line",
    "STOP",
    "PROP MAT=1 DENS=2000",        # after STOP: never read
]) + "\n"
rc, out = run(udec, cwd=d, stdin_text=session)
check(rc == 0, "interactive session ends with status 0 after STOP", out)
check(out.count("UDEC> ") >= 7, "prompt UDEC> shown for each command", out)
check("HEAD> " in out, "HEAD prompts HEAD>", out)
check("PROPERTY DENSITY: expected a real number >= 0, got '-5'" in out,
      "negative density is a clear error", out)
check("unknown command 'FOO'" in out and "closest known commands" in out,
      "unknown command names the closest commands", out)
check("CYCLE: argument 1 (n): expected an integer >= 0" in out, "CYCLE needs an integer (n, the manual's name)", out)
check(out.count("*** Error") == 3, "exactly three errors reported", out)
check("in file" not in out, "interactive errors do not cite a file", out)
check(not os.path.exists(os.path.join(d, "OUT")), "interactive mode writes no OUT file")

# HELP and a short command name the arguments as the manual prints them
# (Section 4.5: "TUnnel xc yc r n", "STRUcture xc yc fang rrange npoin mat
# thick <ang>"), beside the kinds the parser checks.
rc, out = run(udec, cwd=d, stdin_text="HELP TUNNEL\nBLOCK 0 0 0 10 10 10 10 0\nTUNNEL 5 5 2\n"
              "STRUCT 5 5 0 2 0.1 1 0.3\nLOAD 0 1 0 1 3 x\nSTOP\n")
check("syntax: TUNNEL r r r q" in out and "as the manual writes it: TUNNEL xc yc r n" in out,
      "HELP TUNNEL: the parser's kinds and the manual's names", out)
check("TUNNEL: expected an integer >= 1 (line ended); usage: TUNNEL r r r q, i.e. TUNNEL xc yc r n" in out,
      "TUNNEL short of n: the usage names xc yc r n", out)
check("STRUCTURE: argument 5 (npoin): expected an integer >= 1" in out,
      "STRUCTURE 0.1 for npoin: the argument named", out)
check("LOAD: argument 2 after the range (yload): expected a real number, got 'x'" in out,
      "LOAD: the numbers after its range are counted apart from it", out)
rc, out = run(udec, cwd=d, stdin_text="BLOCK 0 0 0 10 10 10 10 0\nSTRESS x 1 0 1 3 3\nSTOP\n")
check("STRESS: argument 1 (xl): expected a real number, got 'x'" in out,
      "STRESS xl xu yl yu nx ny (plain numbers, not a range): xl named", out)

# A rejected command changes nothing: the bad JKN rejects the whole line.
rc, out = run(udec, cwd=d, stdin_text="PROP MAT=1 DENS=2000 JKN=-1\nPROP MAT=2 DENS=2500\n"
              "PRINT PROP\nSTOP\n")
check("JKN: expected a real number >= 0, got '-1'" in out, "negative JKN rejected", out)
check("2.000000E+03" not in out and "2.500000E+03" in out,
      "a rejected PROPERTY line stores none of its values", out)

# The tutorial typed at the prompt (manual Section 2.2) runs to its STOP.
with open(os.path.join(sys.argv[2], "examples", "tutorial", "interactive.txt")) as f:
    tutorial = f.read()
rc, out = run(udec, cwd=d, stdin_text=tutorial)
check(rc == 0 and "*** Error" not in out, "Section 2.2 session runs without input errors", out)
check(out.count("HEAD> ") == 3, "three headings typed at HEAD>", out)

# End of input without STOP also ends with status 0.
rc, out = run(udec, cwd=d, stdin_text="HEAD\ntitle\n")
check(rc == 0, "end of input ends interactive mode with status 0", out)

# A '+' continuation line cannot work at the prompt: clear error, no exit.
rc, out = run(udec, cwd=d, stdin_text="+ DENS 1\nSTOP\n")
check(rc == 0 and "works only in files" in out, "'+' at the prompt explained", out)

# SET LOG ON records the session in UDEC.LOG.
rc, out = run(udec, cwd=d, stdin_text="SET LOG ON\nSPLIT 0 0 1 1\nSET LOG OFF\nSTOP\n")
log = open(os.path.join(d, "UDEC.LOG")).read() if os.path.exists(os.path.join(d, "UDEC.LOG")) else ""
check("UDEC> SPLIT 0 0 1 1" in log, "UDEC.LOG records commands typed at the prompt", log)
check("UDEC> STOP" not in log, "SET LOG OFF stops logging", log)

# An error in a CALLed file at the prompt ends the reading of that file and
# of the files that CALLed it: the model is as after the last good command
# (GRAV -5, not the -20 below the bad line) and the session goes on.
write(d, "inner.dat", "GRAV 0 -5\nBOUND 0 10 0 1 YV 0\nGRAV 0 -20\n")
write(d, "outer.dat", "CALL inner.dat\nHEAD\nafter inner\n")
rc, out = run(udec, cwd=d, stdin_text="BLOCK 0,0 0,10 10,10 10,0\nCALL outer.dat\n"
              "PRINT STATUS\nGRAV 0 -7\nPRINT STATUS\nSTOP\n")
check(rc == 0 and out.count("*** Error") == 1, "one error, the session survives", out)
check("after YVISC (read from 'YV')" in out and "in file inner.dat, line 2" in out,
      "the error names the keyword as read, the file and the line", out)
check("the rest of inner.dat (after line 2) is not read" in out, "the skip is reported", out)
check("after inner" not in out, "the CALLing file is left too", out)
status = [ln for ln in out.splitlines() if "gravity (x, y)" in ln]
check(len(status) == 2 and status[0].split()[-1] == "-5" and status[1].split()[-1] == "-7",
      "the model is as after the last good line; the prompt then works", out)

# UDEC.INI is read before the prompt.
write(d, "UDEC.INI", "HEAD\nfrom ini\nFOO\n")
rc, out = run(udec, cwd=d, stdin_text="STOP\n")
check("unknown command 'FOO'" in out and "in file UDEC.INI, line 3" in out,
      "UDEC.INI is read at start-up with file/line error locations", out)
check(rc == 0, "an error in UDEC.INI does not end an interactive session", out)
finish()
