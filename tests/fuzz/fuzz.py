#!/usr/bin/env python3
"""Deck fuzzer (issue 20): seeded mutations of every deck in examples/ and
verification/, each run by udec in its own folder under a time and memory
limit, and classified:

  success      status 0
  error        status 1 with a clean '*** Error' message
  long         still cycling at the time limit, and SIGINT ended it cleanly
               (status 130): a CYCLE of 2e9 steps is what was asked for
  hang         no answer at the time limit, nor 10 s after SIGINT
  crash        any other end: a signal, a runtime error or backtrace, a
               sanitizer report, a failed allocation, status not 0/1/130

Mutations: line and token deletion, duplication and swaps; numbers replaced by
0, -1, 1e300, NaN, huge integers; truncated keywords; truncated files; binary
lines; very long lines. CYCLE and RUN STEP counts of the original decks are
capped (--max-cycles) so a variant runs in seconds; a mutation may still ask
for more.

  python3 tests/fuzz/fuzz.py --udec build/bin/udec --count 2000 --seed 1
Exit status 1 when any crash or hang was found; the failing variants are kept
in --keep (default: a folder under /tmp) with their output."""
import argparse
import glob
import os
import random
import re
import resource
import shutil
import signal
import subprocess
import sys
import tempfile
import time
from concurrent.futures import ThreadPoolExecutor

CRASH_MARKS = ("Fortran runtime error", "Backtrace", "Program received signal",
               "Error termination", "Error allocating", "AddressSanitizer",
               "runtime error:", "LeakSanitizer", "Segmentation fault", "free():",
               "malloc():", "double free", "stack smashing")
NUMBER = re.compile(r"(?<![A-Za-z_])[-+]?(\d+\.?\d*|\.\d+)([eEdD][-+]?\d+)?")
REPLACEMENTS = ["0", "-1", "1e300", "-1e300", "NaN", "2147483648", "9223372036854775808",
                "99999999", "1e-300", "-0", "Inf", "1e15"]


def decks(source):
    found = []
    for top in ("examples", "verification"):
        found += sorted(glob.glob(os.path.join(source, top, "**", "*.dat"), recursive=True))
    return found


def cap_cycles(text, limit):
    def cycle(m):
        return m.group(1) + str(min(int(m.group(2)), limit))
    text = re.sub(r"(?im)^(\s*(?:cycle|cy|c)\s+)(\d+)", cycle, text)
    text = re.sub(r"(?i)(\bste\w*\s+)(\d+)", cycle, text)
    return text


def mutate(rng, text):
    lines = text.splitlines()
    if not lines:
        lines = [""]
    for _ in range(rng.choice([1, 1, 1, 2, 3])):
        kind = rng.randrange(12)
        i = rng.randrange(len(lines))
        if kind == 0:                                   # delete a line
            del lines[i]
        elif kind == 1:                                 # duplicate a line
            lines.insert(i, lines[i])
        elif kind == 2:                                 # swap two lines
            j = rng.randrange(len(lines))
            lines[i], lines[j] = lines[j], lines[i]
        elif kind in (3, 4, 5):                         # replace a number
            nums = list(NUMBER.finditer(lines[i]))
            if nums:
                m = rng.choice(nums)
                lines[i] = lines[i][:m.start()] + rng.choice(REPLACEMENTS) + lines[i][m.end():]
        elif kind == 6:                                 # delete / duplicate / swap a token
            words = lines[i].split()
            if words:
                k = rng.randrange(len(words))
                op = rng.randrange(3)
                if op == 0:
                    del words[k]
                elif op == 1:
                    words.insert(k, words[k])
                else:
                    j = rng.randrange(len(words))
                    words[k], words[j] = words[j], words[k]
                lines[i] = " ".join(words)
        elif kind == 7:                                 # truncate a keyword
            words = lines[i].split()
            alpha = [k for k, w in enumerate(words) if w[:1].isalpha()]
            if alpha:
                k = rng.choice(alpha)
                words[k] = words[k][:rng.randrange(1, max(2, len(words[k])))]
                lines[i] = " ".join(words)
        elif kind == 8:                                 # truncate the file
            cut = rng.randrange(len(text) + 1)
            return text[:cut]
        elif kind == 9:                                 # a binary line
            lines.insert(i, "".join(chr(rng.randrange(0, 256)) for _ in range(rng.randrange(1, 60))))
        elif kind == 10:                                # a very long line
            lines.insert(i, lines[i] + " 1.0" * rng.randrange(100, 20000))
        else:                                           # a line of another deck's shape
            lines.insert(i, rng.choice(["NEW", "CALL .", "SAVE .", "RESTART", "PLOT BLOCK",
                                        "PRINT MAX", "DEL -1e9 1e9 -1e9 1e9", "CYCLE 5",
                                        "SET LOG ON", "HIST WRITE 1 x.his", "COPY"]))
    return "\n".join(lines) + "\n"


def limit_memory(megabytes):
    def apply():
        if megabytes > 0:
            size = megabytes * 1024 * 1024
            resource.setrlimit(resource.RLIMIT_AS, (size, size))
        resource.setrlimit(resource.RLIMIT_CORE, (0, 0))
        os.setsid()
    return apply


def run_variant(args, index, deck, text):
    folder = tempfile.mkdtemp(prefix="udec-fuzz-")
    try:
        # sibling files (CALLed decks, tables) beside the variant
        for f in glob.glob(os.path.join(os.path.dirname(deck), "*.dat")):
            shutil.copy(f, folder)
        name = "variant.dat"
        with open(os.path.join(folder, name), "w", encoding="latin-1", errors="replace") as f:
            f.write(text)
        t0 = time.time()
        p = subprocess.Popen([args.udec, name], cwd=folder, stdout=subprocess.PIPE,
                             stderr=subprocess.STDOUT, preexec_fn=limit_memory(args.memory))
        kind = None
        try:
            out, _ = p.communicate(timeout=args.timeout)
        except subprocess.TimeoutExpired:
            p.send_signal(signal.SIGINT)
            try:
                out, _ = p.communicate(timeout=10)
                kind = "long" if p.returncode == 130 and b"CYCLE interrupted" in out else "hang"
                if p.returncode == 130 and b"RUN stopped by the interrupt" in out:
                    kind = "long"
            except subprocess.TimeoutExpired:
                os.killpg(p.pid, signal.SIGKILL)
                out, _ = p.communicate()
                kind = "hang"
        seconds = time.time() - t0
        text_out = out.decode("latin-1")
        rc = p.returncode
        if kind is None:
            if any(m in text_out for m in CRASH_MARKS) or rc not in (0, 1):
                kind = "crash"
            elif rc == 0:
                kind = "success"
            else:
                kind = "error" if "*** Error" in text_out else "crash"
        if kind in ("crash", "hang"):
            keep = os.path.join(args.keep, "%s-%06d" % (kind, index))
            os.makedirs(keep, exist_ok=True)
            shutil.copy(os.path.join(folder, name), keep)
            with open(os.path.join(keep, "output.txt"), "w") as f:
                f.write("deck %s\nstatus %s, %.1f s\n\n" % (deck, rc, seconds))
                f.write(text_out[-20000:])
        return kind, seconds, deck, index
    finally:
        shutil.rmtree(folder, ignore_errors=True)


def variant(args, sources, i):
    """Variant i of the run: its own generator, seeded by the run's seed and i,
    so any stretch of a run (--start) is the same variants as in the whole run."""
    rng = random.Random("%d-%d" % (args.seed, i))
    deck, text = sources[i % len(sources)]
    return i, deck, mutate(rng, text)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--udec", required=True)
    ap.add_argument("--source", default=os.path.join(os.path.dirname(__file__), "..", ".."))
    ap.add_argument("--count", type=int, default=2000)
    ap.add_argument("--start", type=int, default=0, help="first variant (a run in parts)")
    ap.add_argument("--seed", type=int, default=20)
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--timeout", type=float, default=20.0, help="seconds per variant")
    ap.add_argument("--memory", type=int, default=2048, help="MB of address space (0: none)")
    ap.add_argument("--max-cycles", type=int, default=50)
    ap.add_argument("--max-seconds", type=float, default=0.0,
                    help="stop starting variants after this many seconds (0: no limit)")
    ap.add_argument("--keep", default=None, help="folder for crashing / hanging variants")
    args = ap.parse_args()
    # a private copy: a rebuild during a long run must not change the program
    binary_folder = tempfile.mkdtemp(prefix="udec-fuzz-bin-")
    args.udec = shutil.copy(os.path.abspath(args.udec), binary_folder)
    if args.keep is None:
        args.keep = tempfile.mkdtemp(prefix="udec-fuzz-found-")
    sources = [(d, cap_cycles(open(d, encoding="latin-1").read(), args.max_cycles))
               for d in decks(args.source)]
    counts = {k: 0 for k in ("success", "error", "long", "hang", "crash")}
    t0 = time.time()
    done = 0
    pending = []
    upcoming = iter(range(args.start, args.start + args.count))
    # variants are made as they are needed (a 1e5 run does not hold 1e5 decks)
    with ThreadPoolExecutor(max_workers=args.jobs) as pool:
        while True:
            while len(pending) < 4 * args.jobs:
                if args.max_seconds > 0 and time.time() - t0 > args.max_seconds:
                    break
                i = next(upcoming, None)
                if i is None:
                    break
                pending.append(pool.submit(run_variant, args, *variant(args, sources, i)))
            if not pending:
                break
            kind, seconds, deck, index = pending.pop(0).result()
            counts[kind] += 1
            done += 1
            if kind in ("crash", "hang"):
                print("%s: variant %d of %s (%.1f s)" % (kind, index, os.path.relpath(deck, args.source),
                                                        seconds), flush=True)
            if done % 500 == 0:
                print("%d variants, %s, %.0f s" % (done, counts, time.time() - t0), flush=True)
    wall = time.time() - t0
    print("fuzz: seed %d, variants %d to %d (%d) of %d decks in %.0f s: %s" %
          (args.seed, args.start, args.start + done - 1, done, len(sources), wall,
           ", ".join("%s %d" % kv for kv in counts.items())))
    shutil.rmtree(binary_folder, ignore_errors=True)
    if counts["crash"] or counts["hang"]:
        print("failing variants kept in", args.keep)
        return 1
    shutil.rmtree(args.keep, ignore_errors=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
