"""File names of the manual's DOS decks in any letter case, and a new user's
session at the prompt (label e2e).

1. CALL / RESTART (reading commands): the manual's decks (UDEC manual
   (ICG1.5, 1989), Section 4.5, CALL / RESTART / SAVE; written under DOS)
   give CALL TUNNEL.DAT, RESTART X.SAV in any case. When the exact name
   does not exist the one file of its folder whose name differs only in
   case is read and a note names it; SAVE keeps the user's spelling; with
   two such files the name is not guessed (a note and the usual error).
2. The prompt (`udec` with no file, commands piped on stdin, ending with
   end of input as CTRL-D): a typo, a bad number, an empty line, a 5000
   character line, HELP, CALL of a missing file, SAVE into a missing
   folder, RESTART of a truncated save file: each gives an error, the model
   built before stays (PRINT MAX still shows its block) and the session
   ends cleanly at the end of input.
"""
import os
import sys
from udec_test import check, finish, run, workdir

udec = sys.argv[1]
folder = workdir()
with open(os.path.join(folder, "Tun.Dat"), "w") as f:
    f.write("block 0,0 0,1 1,1 1,0\nsave Mixed.Sav\nret\n")
code, out = run(udec, [], cwd=folder, stdin_text="call TUN.DAT\nrestart MIXED.SAV\nprint max\n"
                "save MIXED.SAV\nrestart mixed.sav\n")
check(code == 0, "case: session ends cleanly", out)
check("note: CALL: no file 'TUN.DAT'; reading 'Tun.Dat'" in out, "case: CALL names the file read", out)
check("note: RESTART: no file 'MIXED.SAV'; reading 'Mixed.Sav'" in out
      and "Model restored from 'Mixed.Sav'." in out, "case: RESTART reads Mixed.Sav", out)
check(sorted(os.listdir(folder)) == ["MIXED.SAV", "Mixed.Sav", "Tun.Dat"],
      f"case: SAVE keeps the spelling {sorted(os.listdir(folder))}", out)
check("2 files differ from it only in letter case" in out
      and "cannot read save file 'mixed.sav': no such file" in out, "case: two matches not guessed", out)
# a DOS path: the folder separator '\' read as '/' (GEOM\TUNNEL.DAT, in any case;
# before: "cannot open file 'geom\tun.dat': no such file" and the run stopped)
os.mkdir(os.path.join(folder, "geom"))
with open(os.path.join(folder, "geom", "Tun.Dat"), "w") as f:
    f.write("round 0.05\nblock 0,0 0,1 1,1 1,0\nret\n")
with open(os.path.join(folder, "geom", "tunnel.dat"), "w") as f:
    f.write("split -1,0.5 2,0.5\nret\n")
with open(os.path.join(folder, "dos.dat"), "w") as f:
    f.write("call geom\\TUN.DAT\ncall geom\\tunnel.dat\nprint max\ncall geom\\none.dat\nstop\n")
code, out = run(udec, ["dos.dat"], cwd=folder)
check("note: CALL: no file 'geom\\TUN.DAT'; reading 'geom/Tun.Dat' (the DOS folder separator "
      "'\\' read as '/', the name differs only in letter case)" in out
      and "note: CALL: no file 'geom\\tunnel.dat'; reading 'geom/tunnel.dat' (the DOS folder "
      "separator '\\' read as '/')" in out and "SPLIT: 1 -> 2 blocks" in out,
      "case: CALL of a DOS path", out)
check(code == 1 and "CALL: cannot open file 'geom\\none.dat': no such file" in out,
      "case: a missing DOS path named as typed", out)
# the batch file named on the command line too
with open(os.path.join(folder, "Batch.Dat"), "w") as f:
    f.write("block 0,0 0,1 1,1 1,0\nsave Mixed.Sav\nstop\n")
code, out = run(udec, ["batch.dat"], cwd=folder)
check(code == 0 and "reading 'Batch.Dat'" in out and "Model saved to 'Mixed.Sav'" in out,
      "case: batch file", out)

# a truncated save file: the first half of a real one
data = open(os.path.join(folder, "Mixed.Sav"), "rb").read()
with open(os.path.join(folder, "half.sav"), "wb") as f:
    f.write(data[:len(data) // 2])
session = ["blok 0,0 0,1 1,1 1,0", "block 0,0 0,2 2,2 2,0", "prop mat=1 dens=abc", "",
           "x" * 5000, "help", "help boundary", "call missing.dat", "save nodir/x.sav",
           "cycle -5", "restart half.sav", "print max"]
code, out = run(udec, [], cwd=folder, stdin_text="\n".join(session) + "\n")
check(code == 0, f"prompt: ends cleanly at end of input (exit {code})", out[-2000:])
check("unknown command 'blok'" in out, "prompt: typo named", out[-3000:])
check("PROPERTY DENSITY: expected a real number >= 0, got 'abc'" in out, "prompt: bad number", out[-3000:])
check("unknown command 'xxxxxxxx" in out, "prompt: long line", out[-3000:])
check("CALL: cannot open file 'missing.dat': no such file" in out, "prompt: missing CALL", out[-3000:])
check("the folder 'nodir' does not exist" in out, "prompt: SAVE to a missing folder", out[-3000:])
check("CYCLE: argument 1 (n): expected an integer >= 0, got '-5'" in out, "prompt: CYCLE -5", out[-3000:])
check("RESTART: cannot read save file 'half.sav'" in out and "the model in memory is unchanged" in out,
      "prompt: truncated save", out[-3000:])
blocks = [ln.split()[-1] for ln in out.splitlines() if "number of blocks" in ln]
check(blocks == ["1"], f"prompt: the model built before stays ({blocks})", out[-2000:])
check("*** Error" not in out.split("UDEC>")[2], "prompt: BLOCK accepted", out[-2000:])
finish()
