"""Shared helpers of the verification checks (verification/<case>/check.py).

Each check copies the manual's deck(s) into a fresh folder, inserts
`HIST WRITE` lines (or extra PRINT lines) just before the final STOP so the
deck itself stays as printed, runs udec in batch mode and compares the
numbers with the manual's published results or a closed form.
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

FAILURES = []


def check(condition, label, detail=""):
    print(("ok:   " if condition else "FAIL: ") + label + (f"  [{detail}]" if detail else ""))
    if not condition:
        FAILURES.append(label)


def finish():
    print(f"{len(FAILURES)} failures")
    sys.exit(1 if FAILURES else 0)


def workdir():
    return tempfile.mkdtemp(prefix="udec-verify-")


def deck_with(path, extra_before_stop, replace=None):
    """Deck text with lines inserted before the last STOP (and optional
    (old, new) textual replacements applied first)."""
    text = open(path).read()
    for old, new in (replace or []):
        assert old in text, f"{old!r} not in {path}"
        text = text.replace(old, new)
    lines = text.rstrip("\n").split("\n")
    stop = max(i for i, l in enumerate(lines) if l.strip().upper().startswith("STOP"))
    lines[stop:stop] = extra_before_stop
    return "\n".join(lines) + "\n"


def run_deck(udec, folder, name, text, timeout=1500):
    """Write `text` as `name` in `folder` and run it; returns (rc, output, seconds)."""
    with open(os.path.join(folder, name), "w") as f:
        f.write(text)
    t0 = time.time()
    p = subprocess.run([udec, name], cwd=folder, stdout=subprocess.PIPE,
                       stderr=subprocess.STDOUT, text=True, errors="replace", timeout=timeout)
    return p.returncode, p.stdout, time.time() - t0


def read_history(path):
    """(times, values) of a HIST WRITE file ('#' header lines, then 'time value')."""
    t, v = [], []
    for line in open(path):
        if line.startswith("#") or not line.strip():
            continue
        a, b = line.split()[:2]
        t.append(float(a))
        v.append(float(b))
    return t, v


def boundary_tables(out, title):
    """Rows of every PRINT BOUNDARY table whose heading starts with `title`
    ("BOUNDARY FORCES", "BOUNDARY DISPLACEMENTS"): one list of float rows
    per print, the COR header line skipped, ended by a blank or non-numeric line."""
    result, rows, inside = [], None, False
    for line in out.splitlines():
        if line.startswith(title):
            rows = []
            result.append(rows)
            inside = True
            continue
        if inside:
            f = line.split()
            if not f:
                inside = False
                continue
            if f[0] == "COR":
                continue
            try:
                rows.append([float(v) for v in f])
            except ValueError:
                inside = False
    return result


def footing_loads(out, top=9.5):
    """(q, force, width) of every PRINT BOUNDARY FORCES table, for a footing
    driven by a prescribed y-velocity on the model's top (y > top): the sum
    of the footing gridpoints' reactions FY over the footing's tributary
    width, the last loaded gridpoint's x plus half the distance to the next
    top gridpoint (the edge zone is half dragged down by the footing).
    Verification D and tests/scripts/probe_plastic_decks.py."""
    loads = []
    for rows in boundary_tables(out, "BOUNDARY FORCES"):
        top_rows = sorted((r for r in rows if r[2] > top), key=lambda r: r[1])
        loaded = [r for r in top_rows if r[4] == 4]
        if not loaded:
            continue
        xl = max(r[1] for r in loaded)
        nxt = [r[1] for r in top_rows if r[1] > xl + 1e-6]
        width = xl + 0.5 * (min(nxt) - xl) if nxt else xl
        force = abs(sum(r[6] for r in loaded))
        loads.append((force / width, force, width))
    return loads


def contacts(text):
    """{id: (jmat, x)} from the geometry table and {id: shear disp} from the
    displacement table of the last PRINT CONTACTS in text."""
    geo, dis, mode = {}, {}, None
    for line in text.splitlines():
        if "TYPE  JMAT" in line:
            mode, geo = "g", {}
            continue
        if "SHEAR-DISP" in line:
            mode, dis = "d", {}
            continue
        p = line.split()
        if mode and (len(p) < 6 or not p[0].isdigit()):
            mode = None
            continue
        if mode == "g":
            geo[int(p[0])] = (int(p[4]), float(p[8]))
        elif mode == "d":
            dis[int(p[0])] = float(p[5])
    return geo, dis
