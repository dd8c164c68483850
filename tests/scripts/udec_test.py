"""Small helpers shared by the script tests."""
import math
import os
import re
import signal
import subprocess
import sys
import tempfile
import time

FAILURES = []


def check(condition, label, detail=""):
    if not condition:
        FAILURES.append(label)
        print("FAIL:", label)
        if detail:
            print("   ", detail.replace("\n", "\n    ")[:3000])


def finish():
    print(f"{len(FAILURES)} failures")
    sys.exit(1 if FAILURES else 0)


def run(udec, args=(), cwd=None, stdin_text=None, timeout=60):
    """Run udec; returns (returncode, stdout+stderr)."""
    proc = subprocess.run([udec, *args], cwd=cwd, input=stdin_text,
                          stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                          timeout=timeout, text=True, errors="replace")
    return proc.returncode, proc.stdout


def workdir():
    return tempfile.mkdtemp(prefix="udec-test-")


def write(folder, name, text):
    path = os.path.join(folder, name)
    with open(path, "w") as f:
        f.write(text)
    return path


def run_deck(udec, folder, name, text, timeout=120, forbidden=("*** Error",), files=None):
    """Write `text` as folder/name.dat (and `files`, name -> text, beside it),
    run udec on it there, check that it exits 0 and that no output line holds
    one of the `forbidden` markers ("***" refuses warnings as well as errors);
    returns (returncode, output)."""
    write(folder, name + ".dat", text)
    for fname, body in (files or {}).items():
        write(folder, fname, body)
    rc, out = run(udec, [name + ".dat"], cwd=folder, timeout=timeout)
    check(rc == 0, f"{name}: deck runs (exit 0)", out[-3000:])
    if forbidden:
        bad = [line for line in out.splitlines() if any(m in line for m in forbidden)]
        check(not bad, f"{name}: no error or refusal in the output", "\n".join(bad)[:2000])
    return rc, out


def run_clean(udec, name, text, timeout=300):
    """Run `text` as name.dat in a fresh work folder; check that udec exits
    0 and prints no error, refusal or warning line ("***", "Error");
    returns the output."""
    return run_deck(udec, workdir(), name, text, timeout, forbidden=("***", "Error"))[1]


def check_walls(label, spring, crown, spring_ref, crown_ref, tol):
    """Print and check a hole's wall displacements at the springline and
    the crown against their closed forms within tol times the crown's (the
    larger); label: the check's, its first word (up to ':') the case's."""
    print(f"{label.split(':')[0]}: springline {spring:.5g} m ({spring_ref:.5g}), "
          f"crown {crown:.5g} m ({crown_ref:.5g})")
    check(abs(spring - spring_ref) < tol * abs(crown_ref) and abs(crown - crown_ref) < tol * abs(crown_ref),
          label, f"springline {spring:.5g} ({spring_ref:.5g}), crown {crown:.5g} ({crown_ref:.5g})")


def printed_rows(out, command, ncol, flag=False):
    """Numeric rows of ncol columns printed after the last echo of `command`
    (flag: each row ends with one more word, PRINT FLUID's FIXED)."""
    rows = []
    for line in out.split(command)[-1].splitlines():
        f = line.split()
        if flag and len(f) == ncol + 1:
            f = f[:ncol]
        if len(f) == ncol:
            try:
                rows.append([float(v) for v in f])
            except ValueError:
                pass
    return rows


NUM = re.compile(r"^[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$")


def header_rows(out, head, ncol):
    """Rows (lists of fields) of every table whose header line starts with
    `head`: the lines that follow it with at least ncol fields and an
    integer first field."""
    rows, inside = [], False
    for line in out.splitlines():
        if line.startswith(head):
            inside = True
            continue
        if inside:
            f = line.split()
            if len(f) >= ncol and re.match(r"^\d+$", f[0]):
                rows.append(f)
            else:
                inside = False
    return rows


def tables(out, command):
    """Every table printed after the echo of `command` (case-insensitive,
    blanks squeezed): a list of tables, each a list of dicts keyed by the
    header's column names (numeric columns as float)."""
    lines = out.splitlines()
    want = " ".join(command.lower().split())
    result = []
    for i, line in enumerate(lines):
        if " ".join(line.lower().split()) != want:
            continue
        # the header: the line (within 3 after the echo) followed by a row
        # starting with an integer
        j = next((j for j in range(i + 1, min(i + 4, len(lines) - 1))
                  if lines[j + 1].split() and re.fullmatch(r"\d+", lines[j + 1].split()[0])), None)
        if j is None:
            continue
        names = lines[j].split()
        rows = []
        for l in lines[j + 1:]:
            f = l.split()
            if not f or not re.fullmatch(r"\d+", f[0]):
                break
            row = {}
            for k, name in enumerate(names):
                if k < len(f) and NUM.match(f[k]):
                    row[name] = float(f[k])
            rows.append(row)
        result.append(rows)
    return result


def contact_parts(out, column):
    """{contact: row} of the last PRINT CONTACT part whose header names
    `column` (PRINT CONTACT prints three tables, each keyed by CONTACT)."""
    result, names = {}, None
    for line in out.splitlines():
        f = line.split()
        if f and f[0] == "CONTACT":
            names = f if column in f else None
            if names:
                result = {}
            continue
        if names and f and f[0].isdigit() and len(f) >= len(names):
            try:
                result[int(f[0])] = {n: float(v) for n, v in zip(names, f) if n not in ("STATE",)}
            except ValueError:
                names = None
        else:
            names = None
    return result


def rows_after(out, marker, skip, ncol):
    """The field lists of the rows of the last table printed after `marker`:
    from the line `skip` lines after it, while a line has at least ncol
    fields and an integer first field."""
    rows = []
    for line in out.split(marker)[-1].splitlines()[skip:]:
        f = line.split()
        if len(f) < ncol or not f[0].isdigit():
            break
        rows.append(f)
    return rows


def cable_elements(out):
    """The last PRINT CABLE element table: list of (n1, n2, length, axial)."""
    return [(int(f[2]), int(f[3]), float(f[6]), float(f[7])) for f in rows_after(out, "Cable elements", 2, 8)]


def cable_nodes(out):
    """The last PRINT CABLE node table: list of (x, y, slip, grout force)."""
    return [tuple(float(v) for v in f[5:9]) for f in rows_after(out, "Cable nodes", 2, 9)]


def check_acceleration(name, h, acc, law):
    """Check that the displacement history h ([(t, x)], evenly sampled)
    accelerates at acc within 0.5 %: the second difference of x at the
    last sample and the samples a third and two thirds of the history
    before it (closed_forms_r3.py case 6, closed_forms_r4.py case 1);
    law: the closed form's formula, for the message."""
    k = (len(h) - 1) // 3
    (t0, x0), (t1, x1), (t2, x2) = h[-1 - 2 * k], h[-1 - k], h[-1]
    got = (x2 - 2 * x1 + x0) / (t2 - t1) ** 2
    print(f"{name}: acceleration {got:.5g} m/s^2 ({acc:.5g}, {100 * (got / acc - 1):+.2f} %)")
    check(abs(got / acc - 1) < 5e-3, f"{name}: above the limit it accelerates at {law} (0.5 %)", f"{got} {acc}")


def zone_rows(out, stress_cmd="PRINT ZONE STRESS", state_cmd="PRINT ZONE STATE", grid_cmd="PRINT GRID"):
    """(zone stress row, centroid x, y, vertex ids) of the last prints."""
    gp = {int(r["GRIDPT"]): (r["X"], r["Y"]) for r in tables(out, grid_cmd)[-1]}
    st = {int(r["ZONE"]): r for r in tables(out, state_cmd)[-1]}
    rows = []
    for z in tables(out, stress_cmd)[-1]:
        s = st[int(z["ZONE"])]
        ids = [int(s[k]) for k in ("GP1", "GP2", "GP3")]
        x = sum(gp[i][0] for i in ids) / 3
        y = sum(gp[i][1] for i in ids) / 3
        rows.append((z, x, y, ids))
    return rows


def polar_stress(z, t):
    """(s_rr, s_tt, s_rt) of a PRINT ZONE STRESS row at the angle t (radians
    from the x axis)."""
    c2, s2 = math.cos(2 * t), math.sin(2 * t)
    sm, dd = 0.5 * (z["SXX"] + z["SYY"]), 0.5 * (z["SXX"] - z["SYY"])
    return sm + dd * c2 + z["SXY"] * s2, sm - dd * c2 - z["SXY"] * s2, -dd * s2 + z["SXY"] * c2


def printed_number(out, label, missing=float("nan")):
    """The number printed after `label` (PRINT MAX's "max gridpoint
    displacement", PRINT FLOWS' "total boundary outflow"): its first
    occurrence, or `missing`."""
    m = re.search(re.escape(label) + r"\s+(\S+)", out)
    return float(m.group(1)) if m else missing


def rel(a, b):
    return abs(a - b) / abs(b)


def history_rows(out, command):
    """Numeric rows (time, value 1, value 2, ...) printed after the line
    `command` (a PRINT HIST of several histories), in order."""
    rows = []
    for line in out.split(command, 1)[-1].splitlines():
        parts = line.split()
        if len(parts) >= 2:
            try:
                rows.append([float(v) for v in parts])
            except ValueError:
                pass
    return rows


def histories(out):
    """Rows (time, value) of each PRINT HIS table of `out`, in order."""
    tables, rows = [], None
    for line in out.splitlines():
        f = line.split()
        if len(f) == 3 and f[0] == "TIME":
            rows = []
            tables.append(rows)
            continue
        if rows is not None and len(f) == 2:
            try:
                rows.append((float(f[0]), float(f[1])))
                continue
            except ValueError:
                pass
        rows = None
    return tables


def wait_for(proc, lines, pattern, seconds):
    """Read proc's output lines into `lines` until one matches `pattern`
    (True) or `seconds` have passed or the output ends (False)."""
    t0 = time.time()
    while time.time() - t0 < seconds:
        line = proc.stdout.readline()
        if not line:
            break
        lines.append(line)
        if re.search(pattern, line):
            return True
    return False


def finish_process(proc, timeout):
    """Wait for `proc` to end (killed after `timeout` seconds); its output."""
    try:
        out, _ = proc.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        proc.kill()
        out, _ = proc.communicate()
    return out


def interrupt_then(proc, lines, commands, timeout=120):
    """Send SIGINT to the interactive udec `proc`, then the `commands` text on
    its standard input, and wait for it to end: the whole output, `lines`
    (what was read before the interrupt) first."""
    proc.send_signal(signal.SIGINT)
    proc.stdin.write(commands)
    proc.stdin.flush()
    return "".join(lines) + finish_process(proc, timeout)
