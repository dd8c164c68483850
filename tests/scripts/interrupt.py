"""Issue 20: Ctrl-C and SIGTERM stop a running CYCLE, not the program.

Interactive (stdin a pipe, as a terminal sends SIGINT to the process): SIGINT
during a long CYCLE ends it at the end of a step, the session goes on, the
model prints, SAVE works, and a new process RESTARTs the file and cycles on.
A second SIGINT within two seconds quits. Batch: SIGINT or SIGTERM stops the
cycle, skips the rest of the deck, closes OUT and ends with 128 + signal."""
import os
import re
import signal
import subprocess
import sys
import time
sys.path.insert(0, os.path.dirname(__file__))
from udec_test import (check, finish, finish_process, interrupt_then, run,  # noqa: E402
                       wait_for, workdir, write)

udec = sys.argv[1]
source = sys.argv[2]

slope = open(os.path.join(source, "examples", "tutorial", "slope1.dat")).read()
LONG = slope.split("CYCLE")[0] + "CYCLE 100000000\n"   # hours of cycling


# --- interactive: SIGINT ends the CYCLE, the session goes on
d = workdir()
p = subprocess.Popen([udec], cwd=d, stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                     stderr=subprocess.STDOUT, text=True, bufsize=1)
p.stdin.write(LONG)
p.stdin.flush()
lines = []
cycling = wait_for(p, lines, r"^\s+\d+0\s+\S", 60)   # a progress line: cycles running
check(cycling, "the long CYCLE runs", "".join(lines[-20:]))
time.sleep(0.5)
out = interrupt_then(p, lines, "PRINT BLOCK\nSAVE slope.sav\nCYCLE 10\nSTOP\n")
check(p.returncode == 0, "interactive session ends normally after the interrupt (status %s)"
      % p.returncode, out[-2000:])
m = re.search(r"CYCLE interrupted after (\d+) of 100000000 cycles: cycle (\d+), time\s+(\S+)", out)
check(m is not None, "the interrupted CYCLE reports the cycle and time reached", out[-2000:])
check("Interrupted: back at the prompt" in out, "back at the prompt", out[-2000:])
check(re.search(r"^\s+4\s+1\s+1\s+4", out, re.M) is not None, "PRINT BLOCK after the interrupt",
      out[-2000:])
check("Model saved to 'slope.sav'" in out, "SAVE after the interrupt", out[-2000:])
reached = int(m.group(2)) if m else -1
summaries = re.findall(r"^cycle (\d+), time", out, re.M)   # one per CYCLE
check(len(summaries) == 2 and int(summaries[-1]) == reached + 10,
      "a later CYCLE 10 goes on from the cycle reached", out[-1500:])

# a new process restarts the file and cycles on
write(d, "again.dat", "RESTART slope.sav\nCYCLE 20\nSTOP\n")
rc, out2 = run(udec, ["again.dat"], cwd=d, timeout=120)
m3 = re.search(r"^cycle (\d+), time", out2, re.M)
check(rc == 0 and m3 is not None and int(m3.group(1)) == reached + 20,
      "a new process RESTARTs the file saved after the interrupt and cycles on", out2[-1500:])

# --- interactive: a second SIGINT within two seconds quits
p = subprocess.Popen([udec], cwd=d, stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                     stderr=subprocess.STDOUT, text=True, bufsize=1)
p.stdin.write(LONG)
p.stdin.flush()
lines = []
wait_for(p, lines, r"^\s+\d+0\s+\S", 60)
p.send_signal(signal.SIGINT)
time.sleep(0.2)
p.send_signal(signal.SIGINT)
out = finish_process(p, 30)
check(p.returncode == 130, "a second Ctrl-C within 2 s quits with status 130 (got %s)"
      % p.returncode, out[-1000:])

# --- batch: SIGINT and SIGTERM stop the cycle, skip the rest, close OUT
for sig, status in ((signal.SIGINT, 130), (signal.SIGTERM, 143)):
    b = workdir()
    write(b, "deck.dat", LONG + "SAVE never.sav\nSTOP\n")
    p = subprocess.Popen([udec, "deck.dat"], cwd=b, stdout=subprocess.PIPE,
                         stderr=subprocess.STDOUT, text=True, bufsize=1)
    lines = []
    wait_for(p, lines, r"^\s+\d+0\s+\S", 60)
    p.send_signal(sig)
    out = finish_process(p, 60)
    out = "".join(lines) + out
    name = signal.Signals(sig).name
    check(p.returncode == status, "batch %s: exit status %d (got %s)" % (name, status, p.returncode),
          out[-1500:])
    check("CYCLE interrupted after" in out and "rest of the input is skipped" in out,
          "batch %s: the cycle stops and the rest is skipped" % name, out[-1500:])
    check(not os.path.exists(os.path.join(b, "never.sav")), "batch %s: the deck's SAVE is skipped"
          % name)
    text = open(os.path.join(b, "OUT")).read()
    check("rest of the input is skipped" in text, "batch %s: OUT is complete and closed" % name,
          text[-800:])
finish()
