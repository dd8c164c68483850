"""Robustness: thousands of mutated command lines (random bytes, truncated
numbers, huge exponents, very long lines) must never crash or hang udec, in
interactive mode, batch mode and --check mode."""
import os
import random
import re
import subprocess
import sys
sys.path.insert(0, os.path.dirname(__file__))
from udec_test import check, finish, workdir  # noqa: E402

udec = sys.argv[1]
rng = random.Random(20261121)   # fixed seed: reproducible failures

SEEDS = [
    "BLOCK (0,0) (0,20) (20,20) (20,0)", "SPLIT (0,2) (20,8)", "FIX 0,20 0,5",
    "PROP MAT=1 DENS=2000", "PROP JMAT=1 JKN=1.33E7 JKS=1.33E7 JFRIC=0.35",
    "GRAVITY 0 -10", "DAMP AUTO", "HIST YVEL(10,20) TYPE 1", "CYCLE 100",
    "PLOT HISTORY 1", "BOUND -201,201 -201,-199 XVIS YVIS", "BOUND HIST SINE (1.0,5.0)",
    "JSET 90.0,0 5.0,0 0.0,0 4.0,0 (0.0,0.0, 0.0)", "CHANGE REG 0,0 0,10 10,10 10,0 JMAT 2",
    "PRINT ANN 0 0 1 2 BLOCK", "GEN MAN GRID 5,15 0,20 0,10 10,10 10,20 ZONE 1,2,5 2,3,5",
    "SET LOG OFF", "INSITU STRESS -1e6 0 -2e6 YGRAD 0 0 1e4", "WINDOW AUTO",
]
# Commands that end the session or touch files are kept out of the stream.
SAFE_DROP = ("STOP", "QUIT", "END", "CALL", "RETURN", "SAVE", "RESTART", "COPY", "SET")


def mutate(line):
    kind = rng.randrange(9)
    if kind == 0:      # random bytes
        return "".join(chr(rng.randrange(1, 256)) for _ in range(rng.randrange(1, 80)))
    if kind == 1:      # truncate
        return line[: rng.randrange(len(line) + 1)]
    if kind == 2:      # huge / tiny / malformed numbers
        return line + " " + rng.choice(["1e999", "-1e-999", "1e", "1.2.3", "--5", "1e+",
                                         "9" * 400, ".", "+", "-", "1d99999", "0x10", "NaN",
                                         "Inf", "1,,", "(((", "==="])
    if kind == 3:      # very long line
        return line + " 1.0" * rng.randrange(1000, 20000)
    if kind == 4:      # character substitution
        chars = list(line)
        for _ in range(rng.randrange(1, 5)):
            if chars:
                chars[rng.randrange(len(chars))] = chr(rng.randrange(32, 127))
        return "".join(chars)
    if kind == 5:      # dangling continuation
        return line + " &"
    if kind == 6:      # keyword salad
        words = line.split()
        rng.shuffle(words)
        return " ".join(words)
    if kind == 7:
        return "+" + line
    return line


lines = []
while len(lines) < 4000:
    m = mutate(rng.choice(SEEDS))
    first = re.split(r"[\s(),/=]+", m.strip().upper() + " ")[0]
    if first and any(name.startswith(first) or first.startswith(name[:2])
                     for name in SAFE_DROP):
        continue
    lines.append(m.replace("\n", " ").replace("\r", " "))
    if len(lines) % 100 == 0:
        lines.append("NEW")   # bound the geometry the executed commands build up
# Blank lines end any dangling "&"; the marker commands prove the stream was read
# to its end (interactive mode does not echo input, but reports unknown commands).
text = "\n".join(lines) + "\n\n\nMARKERONE\nMARKERTWO\nSTOP\n"

d = workdir()
data = os.path.join(d, "fuzz.dat")
with open(data, "w", encoding="latin-1") as f:
    f.write(text)


def run_bytes(args, stdin=None):
    p = subprocess.run([udec, *args], cwd=d, input=stdin, stdout=subprocess.PIPE,
                       stderr=subprocess.STDOUT, timeout=300)
    return p.returncode, p.stdout.decode("latin-1")


# Interactive: never exits on input errors, so it must reach the final STOP.
rc, out = run_bytes([], stdin=text.encode("latin-1"))
check(rc == 0, "interactive session survives 4000 mutated lines", out[-2000:])
check("unknown command 'MARKERTWO'" in out, "interactive session reaches the end", out[-2000:])
check("Fortran runtime error" not in out and "Backtrace" not in out,
      "no runtime error in interactive mode", out[-3000:])

# --check: reports errors, exit 1, no crash.
rc, out = run_bytes(["--check", data])
check(rc in (0, 1), "--check survives the mutated deck", out[-2000:])
check("Fortran runtime error" not in out and "Backtrace" not in out,
      "no runtime error in --check mode", out[-3000:])

# Batch: each mutated line alone in a batch run ends cleanly (status 0 or 1).
crashes = 0
for i, line in enumerate(lines[:400]):
    with open(data, "w", encoding="latin-1") as f:
        f.write(line + "\nSTOP\n")
    rc, out = run_bytes([data])
    if rc not in (0, 1) or "Fortran runtime error" in out:
        crashes += 1
        print("crash on line:", repr(line[:200]), rc, out[-500:])
check(crashes == 0, "400 single-line batch runs end cleanly")
finish()
