"""Issue 24: on a terminal CYCLE, SOLVE and RUN show one progress line
updated in place (carriage return): cycles done of the total, percent,
cycles per second, time left and the force ratio (RUN: the temperature
change), at most four updates a second. In batch output (a pipe, the file
OUT) the manual's rows stay exactly as they are.

The terminal is a pseudo-terminal (python's pty module)."""
import os
import pty
import re
import select
import subprocess
import sys
import time
sys.path.insert(0, os.path.dirname(__file__))
from udec_test import check, finish, run, workdir, write  # noqa: E402

udec = sys.argv[1]
source = sys.argv[2]

slope = open(os.path.join(source, "examples", "tutorial", "slope1.dat")).read()
DECK = slope.split("CYCLE")[0] + "CYCLE 1000000\nSOLVE RATIO 1e-9 CYCLES 1000\nSTOP\n"
fin = open(os.path.join(source, "verification", "thermal1", "case_a.dat")).read()
THERMAL = fin.split("run ")[0] + "run ste 200000 tem 1500 tol 0.001\nstop\n"


def on_terminal(folder, deck):
    """Run udec on `deck` with stdout and stderr a pseudo-terminal; returns
    (status, everything the terminal received, wall seconds)."""
    master, slave = pty.openpty()
    t0 = time.time()
    p = subprocess.Popen([udec, deck], cwd=folder, stdin=subprocess.DEVNULL, stdout=slave,
                         stderr=slave, close_fds=True)
    os.close(slave)
    chunks = []
    while True:
        r, _, _ = select.select([master], [], [], 1.0)
        if r:
            try:
                data = os.read(master, 65536)
            except OSError:      # EIO: the child closed the terminal
                break
            if not data:
                break
            chunks.append(data)
        elif p.poll() is not None:
            break
        if time.time() - t0 > 300:
            p.kill()
            break
    p.wait()
    os.close(master)
    return p.returncode, b"".join(chunks).decode(errors="replace"), time.time() - t0


def rows_of(text):
    """The CYCLE rows and headers, without the summary's wall-time figures."""
    keep = []
    for line in text.splitlines():
        if line.startswith("cycle ") and " s, " in line:
            line = line.split(", max unbalanced")[0]
        keep.append(line)
    return keep


# --- mechanical: CYCLE and SOLVE
tty_dir, pipe_dir = workdir(), workdir()
write(tty_dir, "deck.dat", DECK)
write(pipe_dir, "deck.dat", DECK)
rc, screen, wall = on_terminal(tty_dir, "deck.dat")
check(rc == 0, "the deck runs on a terminal (status %s)" % rc, screen[-1500:])
updates = re.findall(r"\rcycle (\d+) of (\d+) \((\d+) %\), (\S+)/s(?:, (\S+) s left)?, "
                     r"(force ratio|max unbalanced force) ([^\s\x1b]+)", screen)
check(len(updates) >= 2, "the progress line appears on the terminal (%d updates)" % len(updates),
      repr(screen[-1500:]))
if updates:
    done, total, percent, rate, left, what, value = updates[-1]
    check(int(total) in (1000000, 1000) and int(done) <= int(total)
          and int(percent) == int(100 * int(done) / int(total)),
          "it shows cycles done of the total and the percent", str(updates[-1]))
    check(float(rate) > 0 and left != "" and what == "force ratio" and float(value) >= 0,
          "it shows cycles per second, the time left and the force ratio", str(updates[-1]))
check(len(updates) <= 4 * wall + 4,
      "at most four updates a second (%d in %.1f s)" % (len(updates), wall))
check("\x1b[K" in screen, "the line is erased at the end (no stale text)")
check(re.search(r"^\s+\d+0\s+\S", screen.replace("\r", "\n"), re.M) is None,
      "the terminal gets the progress line instead of the rows", screen[:800])
check(re.search(r"^cycle 1000000, time", screen.replace("\x1b[K", "").replace("\r", "\n"), re.M)
      is not None,
      "CYCLE's summary line is on the terminal", screen[-800:])
check("SOLVE: " in screen, "SOLVE's result is on the terminal")

rc2, piped = run(udec, ["deck.dat"], cwd=pipe_dir, timeout=300)
check(rc2 == 0 and "\r" not in piped and "of 1000000" not in piped,
      "batch output (a pipe) has no progress line", piped[-800:])
check(re.search(r"^\s+1000000\s+\S", piped, re.M) is not None, "batch output keeps the rows",
      piped[-800:])
out_tty = open(os.path.join(tty_dir, "OUT")).read()
out_pipe = open(os.path.join(pipe_dir, "OUT")).read()
check(rows_of(out_tty) == rows_of(out_pipe) and len(rows_of(out_pipe)) > 15000,
      "OUT holds the same rows whether the screen is a terminal or not")
ROW = re.compile(r"^\s+\d+(\s+\S+)+$|^\s+cycle\s+max unbalanced force")
piped_rows = [l for l in piped.splitlines() if ROW.match(l)]
check(piped_rows == [l for l in out_pipe.splitlines() if ROW.match(l)] and len(piped_rows) > 15000,
      "the piped screen output has OUT's rows (%d)" % len(piped_rows))

# --- thermal: RUN
tdir = workdir()
write(tdir, "fin.dat", THERMAL)
rc, screen, wall = on_terminal(tdir, "fin.dat")
updates = re.findall(r"\rthermal step (\d+) of 200000 \((\d+) %\), \S+/s, \S+ s left, "
                     r"max temperature change \S+", screen)
check(rc == 0 and len(updates) >= 1,
      "RUN shows the progress line on a terminal (%d updates)" % len(updates), repr(screen[-800:]))
check("RUN stopped by the STEP limit" in screen, "RUN's result is on the terminal", screen[-800:])
rc, piped = run(udec, ["fin.dat"], cwd=tdir, timeout=300)
check(rc == 0 and "\r" not in piped and "RUN stopped by the STEP limit" in piped,
      "RUN's batch output has no progress line", piped[-800:])
finish()
