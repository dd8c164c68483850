"""Ctrl-C and SIGTERM reaching a long command other than CYCLE / SOLVE / RUN.

A GENERATE of 1681 blocks into about half a million zones takes tens of
seconds; the signal arrives about a second into it. Batch, SIGTERM: the
GENERATE stops within seconds (it polls between blocks), says so, the rest of
the deck is skipped (its SAVE writes nothing) and the run ends with 143.
Interactive, SIGINT: back at the prompt with no block zoned (a GENERATE after
it zones all 1681 blocks, none "already zoned").
(tests/unit/test_command_forms.f90 checks JSET, PLOT and SAVE the same way,
with the signal pending when the command starts.)"""
import os
import signal
import subprocess
import sys
import time
sys.path.insert(0, os.path.dirname(__file__))
from udec_test import (check, finish, finish_process, interrupt_then,  # noqa: E402
                       wait_for, workdir, write)

udec = sys.argv[1]

MODEL = """ROUND 0.02
BLOCK 0,0 0,40 40,40 40,0
JSET 0 0 100 0 0 0 1 0 0 0.5
JSET 90 0 100 0 0 0 1 0 0.5 0
CHANGE CONS 1
"""
LONG_GEN = "GEN AUTO 0.08\n"


# --- batch, SIGTERM
b = workdir()
write(b, "deck.dat", MODEL + LONG_GEN + "SAVE never.sav\nSTOP\n")
p = subprocess.Popen([udec, "deck.dat"], cwd=b, stdout=subprocess.PIPE,
                     stderr=subprocess.STDOUT, text=True, bufsize=1)
lines = []
started = wait_for(p, lines, r"^GEN AUTO", 60)
check(started, "batch: the GENERATE starts", "".join(lines[-10:]))
time.sleep(1.0)
t0 = time.time()
p.send_signal(signal.SIGTERM)
out = finish_process(p, 120)
waited = time.time() - t0
out = "".join(lines) + out
check(p.returncode == 143, "batch SIGTERM: exit status 143 (got %s)" % p.returncode, out[-1500:])
check("GENERATE interrupted" in out and "nothing was zoned" in out,
      "batch SIGTERM: GENERATE says it stopped and zoned nothing", out[-1500:])
check("GENERATE: 1681 block(s) zoned" not in out, "batch SIGTERM: GENERATE did not finish",
      out[-1500:])
check(waited < 10.0, "batch SIGTERM: the run ends within 10 s of the signal (%.1f s)" % waited)
check("rest of the input is skipped" in out and "input error" not in out,
      "batch SIGTERM: the rest is skipped, no input error reported", out[-1500:])
check(not os.path.exists(os.path.join(b, "never.sav")), "batch SIGTERM: the deck's SAVE is skipped")

# --- interactive, SIGINT: back at the prompt, nothing zoned
d = workdir()
p = subprocess.Popen([udec], cwd=d, stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                     stderr=subprocess.STDOUT, text=True, bufsize=1)
p.stdin.write(MODEL + "PRINT STATUS\n" + LONG_GEN)
p.stdin.flush()
lines = []
wait_for(p, lines, r"JPLOT", 60)     # the last line of PRINT STATUS: GEN is next
time.sleep(1.0)
out = interrupt_then(p, lines, "GEN AUTO 4\nSTOP\n")
check(p.returncode == 0, "interactive: the session ends normally (status %s)" % p.returncode,
      out[-1500:])
check("GENERATE interrupted" in out and "back at the prompt" in out,
      "interactive SIGINT: GENERATE stops, back at the prompt", out[-1500:])
check("GENERATE: 1681 block(s) zoned" in out and "already zoned" not in out,
      "interactive SIGINT: the interrupted GENERATE zoned no block", out[-1500:])
finish()
