#!/usr/bin/env python3
"""Error against wall time for the verification problems that run today.

usage: python3 bench/accuracy.py path/to/udec [--problems E,F,...] [--quick] [--out table.md]
                                              [--no-repeat] [--png DIR] [--doc FILE] [--json FILE]

For each problem the manual's deck is copied into a temporary folder and
changed only by textual replacements (the deck files are not edited): zone
size (GENERATE AUTO edmax / QUAD width), FRACTION, cycle counts, ROUND,
joint friction. Every variant is run; its wall time (median of 3 runs when
a run takes less than 2 s, one run otherwise) and its error against the
problem's reference are written as one Markdown table.

The references and measures are those of the problem's check.py: its
functions, constants and case tables are taken from the check.py file
itself (`check_helpers`, which executes only its imports, function
definitions and named assignments, so the check does not run), so this
script and the ctest check the same thing. Where a closed form exists that
the check does not use, it is reported in an extra row marked as such.

Problems (letters):
  A  verification A (shear wave at a slipping joint): zone edge, zone FRACTION, history interval
  E  verification E (tunnel, unsupported cases E1 and E3): edmax, FRACTION, cycles
  F  application F (slipping crack): edmax, crack friction, hold cycles
  B  verification B (jointed medium moduli): edmax, cycles per load step
  D  verification D (Prandtl footing): AUTO and QUAD zone size, cycles
  T  the tutorial of Section 2.1 (rigid blocks): ROUND, FRACTION (no
     published number: compared with free frictional sliding)
  C  verification C (crack slip, boundary-element far field): edmax, cycles, ROUND;
     and the converging refinement study of verification/C/refine.py (QUAD 2-0.5)
  VF verification F (unconfined flow): joint spacing, flow cycles, zone edge
  H1..H5  thermal cases 1-5 of Section 7.8: zone size, time step, explicit
     (case_a) vs implicit (case_b)
  AE application E (JCONS 3 direct shear): FRACTION, shear velocity
  AC application C (lined tunnels): zone size of the fine band
  H6 thermal 6 (decaying source, TADD): zone size, implicit step, explicit vs implicit
  AA application A (seismic roof): zone size, zone FRACTION, excavation stage length
  AD application D (dam, earthquake): MSCALE PART step, zone size
  AG application G (grouting): pressure step, cycles per stage
--png DIR draws one chart per problem, DIR/accuracy_<name>.png (names:
bench/accuracy_plot.py PNG_NAMES): |error| against wall time, log-log, one
numbered marker per variant. --doc FILE writes each problem's table between
the lines <!-- accuracy KEY --> and <!-- /accuracy KEY --> of FILE
(docs/accuracy.md). --json FILE keeps the rows (bench/accuracy_plot.py
redraws the charts from them).
Standard library only.
"""
import argparse
import ast
import math
import os
import re
import shutil
import statistics
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
VERIFY = os.path.join(ROOT, "verification")
sys.path.insert(0, VERIFY)
import common  # noqa: E402  (verification/common.py: deck_with, run_deck, read_history)


# ---------------------------------------------------------------- check.py reuse

def check_helpers(path, names=(), **inject):
    """Namespace with the imports, functions and the assignments to `names`
    of a check.py (nothing else of it runs), then `inject` on top (functions
    of the check look their globals up here at call time)."""
    tree = ast.parse(open(path).read(), path)
    keep = []
    for node in tree.body:
        if isinstance(node, (ast.Import, ast.ImportFrom, ast.FunctionDef)):
            keep.append(node)
        elif isinstance(node, ast.Assign) and len(node.targets) == 1:
            target = node.targets[0]
            ids = [e.id for e in target.elts if isinstance(e, ast.Name)] \
                if isinstance(target, ast.Tuple) else [getattr(target, "id", None)]
            if ids and all(i in names for i in ids):
                keep.append(node)
    ns = {"__file__": path, "__name__": "check_helpers"}
    exec(compile(ast.Module(body=keep, type_ignores=[]), path, "exec"), ns)
    ns.update(inject)
    missing = [n for n in names if n not in ns]
    if missing:
        raise RuntimeError(f"{path}: names {missing} not found (check.py changed?)")
    return ns


def case_table(path, ns):
    """The value of the first top-level `for ... in <list>` of a check.py
    (its table of decks and references), evaluated in `ns`."""
    tree = ast.parse(open(path).read(), path)
    for node in tree.body:
        if isinstance(node, ast.For) and isinstance(node.iter, (ast.List, ast.Tuple)):
            return eval(compile(ast.Expression(node.iter), path, "eval"), ns)
    raise RuntimeError(f"{path}: no case table")


def quiet_check(condition, label, detail=""):
    """check() for the reused helpers: remembered, not printed, never fatal."""
    if not condition:
        QUIET_FAILURES.append(f"{label} {detail}"[:300])


QUIET_FAILURES = []


# ---------------------------------------------------------------- running

class Runner:
    """common.run_deck with timing: median of 3 runs below 2 s."""

    def __init__(self, repeat=True):
        self.repeat = repeat
        self.log = []

    def run_deck(self, udec, folder, name, text, timeout=1500):
        rc, out, sec = common.run_deck(udec, folder, name, text, timeout)
        times = [sec]
        if rc == 0 and sec < 2.0 and self.repeat:
            for _ in range(2):
                rc2, out2, sec2 = common.run_deck(udec, folder, name, text, timeout)
                times.append(sec2)
                if rc2 != 0:
                    rc, out = rc2, out2
        sec = statistics.median(times)
        self.log.append((name, rc, out, sec))
        return rc, out, sec

    def take(self):
        log, self.log = self.log, []
        return log


def counts(out):
    """(zones, contacts, cycles, time) from the last PRINT MAX and cycle line."""
    z = re.findall(r"number of zones\s+(\d+)", out)
    c = re.findall(r"number of contacts\s+(\d+)", out)
    cy = re.findall(r"^cycle (\d+), time\s+(\S+),", out, re.M)
    return (int(z[-1]) if z else 0, int(c[-1]) if c else 0,
            int(cy[-1][0]) if cy else 0, float(cy[-1][1]) if cy else 0.0)


def scale_auto(text, factor):
    """Every `AUTO edmax` of the text with edmax multiplied by factor."""
    def sub(m):
        return f"{m.group(1)}{float(m.group(2)) * factor:.6g}"
    new, n = re.subn(r"(AUTO[ \t]+)([0-9]*\.?[0-9]+(?:[eE][-+]?\d+)?)", sub, text, flags=re.I)
    assert n > 0, "no AUTO edmax in deck"
    return new


def variant_file(folder, src, name, transform, extra):
    """Write the deck `src` changed by `transform(text)` (textual) with the
    lines `extra` before the final STOP as folder/name; returns its path."""
    base = os.path.join(folder, "_" + name)
    with open(base, "w") as f:
        f.write(transform(open(src).read()))
    path = os.path.join(folder, name)
    with open(path, "w") as f:
        f.write(common.deck_with(base, extra))
    return path


def fmt(v, digits=4):
    return f"{v:.{digits}g}" if isinstance(v, float) else str(v)


class Table:
    HEAD = ("| problem | knobs | zones | contacts | cycles | wall s | quantity | value | reference "
            "| error % |\n|---|---|---:|---:|---:|---:|---|---:|---:|---:|")

    def __init__(self):
        self.rows = []
        self.key = ""          # the PROBLEMS key being run (main sets it)

    def add(self, problem, knobs, zones, contacts, cycles, wall, quantity, value, ref, err, tag=""):
        # load: the 1-minute load average when the row is written (the
        # machine is shared; wall times are only comparable at like loads)
        row = dict(problem=problem, knobs=knobs, zones=zones, contacts=contacts, cycles=cycles,
                   wall=wall, quantity=quantity, value=value, ref=ref, err=err, tag=tag,
                   key=self.key, load=os.getloadavg()[0])
        self.rows.append(row)
        print("  " + self.line(row), flush=True)

    @staticmethod
    def line(r):
        err = f"{r['err']:+.2f}" if r["err"] is not None and math.isfinite(r["err"]) else "n/a"
        return (f"| {r['problem']} | {r['knobs']} | {r['zones']} | {r['contacts']} | {r['cycles']} "
                f"| {r['wall']:.2f} | {r['quantity']} | {fmt(r['value'])} | {fmt(r['ref'])} | {err} |")

    def markdown(self):
        return "\n".join([self.HEAD] + [self.line(r) for r in self.rows]) + "\n"

    DOC_HEAD = ("| # | case | knobs | zones | contacts | cycles | wall s | load | quantity | value "
                "| reference | error % |\n|---:|---|---|---:|---:|---:|---:|---:|---|---:|---:|---:|")

    @staticmethod
    def doc_line(i, r):
        err = f"{r['err']:+.2f}" if r["err"] is not None and math.isfinite(r["err"]) else "n/a"
        return (f"| {i} | {r['problem']} | {r['knobs']} | {r['zones']} | {r['contacts']} | {r['cycles']} "
                f"| {r['wall']:.2f} | {r['load']:.1f} | {r['quantity']} | {fmt(r['value'])} "
                f"| {fmt(r['ref'])} | {err} |")

    def doc_table(self, key):
        """The rows of problem `key` as the table of its docs/accuracy.md section,
        numbered as in its chart, the load average beside each wall time."""
        rows = [r for r in self.rows if r["key"] == key]
        return "\n".join([self.DOC_HEAD] + [self.doc_line(i, r) for i, r in enumerate(rows, 1)])


# ---------------------------------------------------------------- verification A

def problem_A(udec, table, runner, quick):
    """Verification A (harmonic shear wave, slipping joint). Measure and
    references of verification/A/check.py: Miller's coefficients R, T, A
    from the energy fluxes of the velocity histories over t = 1-2 s (A1
    for the incident wave, A2 for the transmitted and reflected ones)
    against the rigid-plastic interface (check: 3 % each). Knobs: the zone
    edge of `GEN ... EDGE 60`, the zone time-step fraction (`FRACTION 0.1
    fz`; the deck's `FRAC=0.1` leaves fz = 1) and the history interval
    (deck N=25); the cycle count (deck 1500) is scaled so that every
    variant reaches t = 2 s."""
    path = os.path.join(VERIFY, "A", "check.py")
    folder = tempfile.mkdtemp(prefix="udec-acc-A-")
    ns = check_helpers(path, ["rho", "G", "cs", "tau_i", "tau_s", "v_i", "T1", "PERIOD"])
    exact = dict(zip("RTA", ns["clipped_coefficients"](ns["tau_i"] / ns["tau_s"])))
    variants = [(60, 1.0, 25, 1), (30, 1.0, 5, 2)] if quick else \
        [(60, 1.0, 25, 1), (60, 1.0, 5, 1), (60, 0.5, 5, 2), (30, 1.0, 5, 2), (15, 1.0, 5, 3),
         (15, 0.5, 5, 6)]
    for edge, fz, nh, c in variants:
        def transform(text):
            text = text.replace("EDGE 60", f"EDGE {edge:g}")
            text = text.replace("FRAC=0.1", f"FRACTION 0.1 {fz:g}")
            text = text.replace("HIST N=25", f"HIST N={nh}")
            return text.replace("CYC 1500", f"CYC {1500 * c}")
        hists, wall, out = {}, 0.0, ""
        for name in ("A1", "A2"):
            extra = [f"HIST WRITE {h} {name.lower()}_h{h}.txt" for h in (3, 4)] + ["PRINT MAX"]
            p = variant_file(folder, os.path.join(VERIFY, "A", f"{name}.dat"), f"{name}.dat",
                             transform, extra)
            rc, out, sec = runner.run_deck(udec, folder, f"{name}.dat", open(p).read())
            runner.take()
            wall += sec
            if rc != 0:
                break
            for h in (3, 4):
                hists[(name, h)] = common.read_history(os.path.join(folder, f"{name.lower()}_h{h}.txt"))
        z, k, cy, t = counts(out)
        got = dict(R=float("nan"), T=float("nan"), A=float("nan"))
        if len(hists) == 4 and t >= ns["T1"] + ns["PERIOD"]:
            f_inc = ns["sampler"](*hists[("A1", 3)])
            f_b2 = ns["sampler"](*hists[("A2", 3)])
            e_i = ns["flux"](f_inc)
            got["T"] = math.sqrt(ns["flux"](ns["sampler"](*hists[("A2", 4)])) / e_i)
            got["R"] = math.sqrt(ns["flux"](lambda tt: f_b2(tt) - f_inc(tt)) / e_i)
            got["A"] = math.sqrt(max(0.0, 1 - got["R"] ** 2 - got["T"] ** 2))
        knobs = f"EDGE {edge:g}, FRACTION 0.1 {fz:g}, HIST N={nh}, cycles x{c}"
        for q in "RTA":
            table.add("A", knobs, z, k, cy, wall,
                      f"Miller {q} (A1 + A2 wall time)", got[q], exact[q],
                      100 * (got[q] - exact[q]) / exact[q])
    shutil.rmtree(folder, ignore_errors=True)


# ---------------------------------------------------------------- verification E

def problem_E(udec, table, runner, quick):
    """Verification E, unsupported cases. Measure and references of
    verification/E/check.py: mean inward wall displacement of histories 1-4
    after the run, against the manual's 5.2 mm (E1, constant-stress
    boundary) and 4.7 mm (E3, zero-displacement boundary), Table E-1."""
    path = os.path.join(VERIFY, "E", "check.py")
    folder = tempfile.mkdtemp(prefix="udec-acc-E-")
    ns = check_helpers(path, ["extra"], folder=folder)
    cases = case_table(path, ns)       # [(deck, reference, label), ...]
    # knobs: s = edmax factor on every GEN AUTO of E1 (deck: 1.2/0.8/0.6),
    # fz = zone FRACTION (deck default 1.0), c = cycle factor (deck 400)
    if quick:
        variants = [(1.0, 1.0, 1), (0.5, 1.0, 1)]
    else:
        variants = ([(s, 1.0, 1) for s in (1.0, 0.75, 0.5, 0.35, 0.25)]
                    + [(s, 1.0, c) for s, c in ((0.5, 2), (0.35, 3), (0.25, 4))]
                    + [(1.0, 1.0, c) for c in (2, 4, 20)]
                    + [(1.0, fz, c) for fz in (0.5, 0.25) for c in (1, round(1 / fz))])
    for s, fz, c in variants:
        knobs = f"edmax x{s:g} (1.2/0.8/0.6 x{s:g}), FRACTION 0.1 {fz:g}, cycles x{c}"
        for deck, ref, label in cases:
            def transform(text, deck=deck):
                if "GEN" in text and "AUTO" in text:
                    text = scale_auto(text, s)
                if fz != 1.0:
                    text = text.replace("DAMP AUTO", f"DAMP AUTO\nFRACTION 0.1 {fz:g}")
                if c != 1:
                    text = re.sub(r"^CYC 400$", f"CYC {400 * c}", text, flags=re.M)
                    text = re.sub(r"^CYC 399$", f"CYC {400 * c - 1}", text, flags=re.M)
                return text
            p = variant_file(folder, os.path.join(VERIFY, "E", deck), deck, transform,
                             ns["extra"] + ["PRINT MAX"])
            rc, out, sec = runner.run_deck(udec, folder, deck, open(p).read())
            runner.take()
            z, k, cy, _ = counts(out)
            if rc != 0:
                table.add("E " + deck[:2], knobs, z, k, cy, sec, label, float("nan"), ref, float("nan"))
                QUIET_FAILURES.append(f"E {deck} {knobs}: rc {rc}")
                continue
            u, _ = ns["wall_displacement"]()
            table.add("E " + deck[:2], knobs, z, k, cy, sec, f"wall disp. [m], {label}",
                      u, ref, 100 * (u - ref) / ref)
    shutil.rmtree(folder, ignore_errors=True)


# ---------------------------------------------------------------- application F

# Closed form (not used by F's check.py): with the crack not slipping
# (friction 50 deg > 45 deg inclination) the specimen is a uniformly stressed
# plane-strain body of height H = 2 m cut by a 45-degree elastic joint across
# its whole width (laterally free, frictionless platens), so
#   u_a / sigma_a = H (1 - nu^2) / E + (1/kn + 1/ks) / (2 sqrt 2)
# (joint traction sigma/2 normal and sigma/2 shear, each jump projected on y
# by cos 45). Deck: K = 61.8e9, G = 35.3e9, kn = 198e9, ks = 220e9.
def slope_no_slip():
    K, G, kn, ks, H = 61.8e9, 35.3e9, 198.0e9, 220.0e9, 2.0
    E = 9 * K * G / (3 * K + G)
    nu = (3 * K - 2 * G) / (2 * (3 * K + G))
    return 1.0 / (H * (1 - nu * nu) / E + (1 / kn + 1 / ks) / (2 * math.sqrt(2)))


def problem_F(udec, table, runner, quick):
    """Application F. Measure of examples/application/F/check.py: the initial
    unloading slope (points 4 -> 5) with the slipping crack equals the one
    with friction 50 degrees (no slip), Fig. F-3; error = their relative
    difference (check: 2 %). Extra row: the 50-degree initial unloading slope
    against slope_no_slip() above."""
    path = os.path.join(ROOT, "examples", "application", "F", "check.py")
    folder = tempfile.mkdtemp(prefix="udec-acc-F-")
    src = os.path.join(ROOT, "examples", "application", "F", "F1_slipping_crack.dat")
    ns = check_helpers(path, [], udec=udec, check=quiet_check, run_deck=runner.run_deck)
    ref_slope = slope_no_slip()
    # knobs: s = edmax factor (deck AUTO 0.5), phi = crack friction angle
    # (deck 16 deg), h = hold cycles after each velocity step (deck 100)
    if quick:
        variants = [(1.0, 16.0, 100), (0.5, 16.0, 100)]
    else:
        variants = ([(s, 16.0, 100) for s in (1.0, 0.7, 0.5, 0.35, 0.25)]
                    + [(1.0, phi, 100) for phi in (30.0, 40.0)]
                    + [(1.0, 16.0, h) for h in (300, 1000)]
                    + [(s, 16.0, 3000) for s in (0.5, 0.25)])
    for s, phi, h in variants:
        def transform(text):
            text = scale_auto(text, s)
            return text.replace("CYCLE 100\n", f"CYCLE {h}\n") if h != 100 else text
        ns["deck"] = variant_file(folder, src, f"F_{s:g}_{h}.dat", transform, ["PRINT MAX"])
        res = {}
        for angle in (phi, 50.0):
            res[angle] = ns["run"](math.tan(math.radians(angle)), folder)
        log = runner.take()
        sec = sum(r[3] for r in log)
        z, k, cy, _ = counts(log[-1][2])
        knobs = f"edmax {0.5 * s:g}, crack friction {phi:g} deg, hold cycles {h}"
        if not (res[phi] and res[50.0]):
            table.add("appl. F", knobs, z, k, cy, sec, "initial unloading slope", float("nan"),
                      float("nan"), float("nan"))
            continue
        init_phi = ns["slope"](*res[phi], 4, 5)
        init_50 = ns["slope"](*res[50.0], 4, 5)
        tag = f"{0.5 * s:g}" + (f"/{phi:g}D" if phi != 16.0 else "") + (f"/H{h}" if h != 100 else "")
        table.add("appl. F", knobs, z, k, cy, sec,
                  f"initial unloading slope [Pa/m], {phi:g} vs 50 deg (check.py)",
                  init_phi, init_50, 100 * (init_phi - init_50) / init_50, tag)
        table.add("appl. F", knobs, z, k, cy, sec,
                  "same, 50 deg vs plane-strain closed form (not in check.py)",
                  init_50, ref_slope, 100 * (init_50 - ref_slope) / ref_slope, tag)
    shutil.rmtree(folder, ignore_errors=True)


# ---------------------------------------------------------------- verification B

def problem_B(udec, table, runner, quick):
    """Verification B. Measure and references of verification/B/check.py:
    least-squares stress-strain slope of the loading and unloading branch
    against Singh's moduli in the plane-strain relations (slope_s for the x
    cycle of B.dat, slope_n for the y cycle of B_n.dat; check: 4 %)."""
    path = os.path.join(VERIFY, "B", "check.py")
    names = ["Ei", "nui", "knv", "ksv", "knh", "ksh", "sn", "ss", "s", "bnn", "En", "Es", "nuns",
             "slope_s", "slope_n", "samples_per_step"]
    folder = tempfile.mkdtemp(prefix="udec-acc-B-")
    ns = check_helpers(path, names)
    cases = case_table(path, ns)       # [(deck, (hists), reference, label), ...]

    def fit(eps, idx, sig):            # as the fit() inside B/check.py's loop
        xs = [eps[i] for i in idx]
        mx, my = sum(xs) / 5, sum(sig) / 5
        return sum((x - mx) * (y - my) for x, y in zip(xs, sig)) / sum((x - mx) ** 2 for x in xs)

    # knobs: edmax (deck AUTO 0.28), cycles per load step (deck 1500)
    variants = [(0.28, 1500), (0.14, 1500)] if quick else \
        [(0.28, 1500), (0.2, 1500), (0.14, 1500), (0.1, 1500), (0.07, 1500), (0.28, 3000), (0.14, 3000),
         (0.07, 3000), (0.28, 6000)]
    for edmax, steps in variants:
        ns["samples_per_step"] = steps // 50
        knobs = f"edmax {edmax:g}, cycles/step {steps}"
        for deck, hists, ref, label in cases:
            def transform(text):
                text = text.replace("GEN 0,2 0,2 AUTO 0.28", f"GEN 0,2 0,2 AUTO {edmax:g}")
                return text.replace("CYCLE 1500\n", f"CYCLE {steps}\n")
            extra = [f"HIST WRITE {h} h{h}.txt" for h in hists] + ["PRINT MAX"]
            p = variant_file(folder, os.path.join(VERIFY, "B", deck), deck, transform, extra)
            rc, out, sec = runner.run_deck(udec, folder, deck, open(p).read())
            runner.take()
            z, k, cy, _ = counts(out)
            if rc != 0:
                table.add("B " + deck, knobs, z, k, cy, sec, label, float("nan"), ref, float("nan"))
                continue
            a = common.read_history(os.path.join(folder, f"h{hists[0]}.txt"))[1]
            b = common.read_history(os.path.join(folder, f"h{hists[1]}.txt"))[1]
            eps = [(vb - va) / 2.0 for va, vb in zip(ns["step_values"](a), ns["step_values"](b))]
            load = fit(eps, range(0, 5), [-2e6 * i for i in range(5)])
            unload = fit(eps, range(4, 9), [-8e6 + 2e6 * i for i in range(5)])
            for name, val in (("loading", load), ("unloading", unload)):
                table.add("B " + deck, knobs, z, k, cy, sec, f"{label} {name} slope [Pa]",
                          val, ref, 100 * (val - ref) / ref)
    shutil.rmtree(folder, ignore_errors=True)


# ---------------------------------------------------------------- verification D

def problem_D(udec, table, runner, quick):
    """Verification D. Measure and reference of verification/D/check.py:
    footing load q = sum of the prescribed-velocity top reactions (deck's
    PR BOU tables, footing_loads of the check) over the tributary width,
    the larger of the two prints, against (2 + pi) c = 5.14e4 Pa (check:
    3 %). Cycle factor c multiplies both CYC commands (8000 and 2000)."""
    path = os.path.join(VERIFY, "D", "check.py")
    folder = tempfile.mkdtemp(prefix="udec-acc-D-")
    ns = check_helpers(path, ["q_exact"])
    q_exact = ns["q_exact"]
    gen = "GEN 0,12 0,10 AUTO 1.5"
    if quick:
        variants = [("AUTO", 1.5, 1), ("AUTO", 0.75, 1)]
    else:
        variants = ([("AUTO", e, 1) for e in (1.5, 1.0, 0.75, 0.5, 0.375)]
                    + [("QUAD", w, 1) for w in (1.15, 0.575, 0.2875)]
                    + [("AUTO", 1.5, 2), ("AUTO", 0.75, 2), ("AUTO", 0.5, 3), ("AUTO", 0.375, 4),
                       ("AUTO", 0.375, 6), ("QUAD", 0.575, 2), ("QUAD", 0.2875, 3)])
    for kind, size, c in variants:
        def transform(text):
            assert gen in text
            text = text.replace(gen, f"GEN 0,12 0,10 {kind} {size:g}")
            text = text.replace("CYC 8000\n", f"CYC {8000 * c}\n")
            return text.replace("CYC 2000\n", f"CYC {2000 * c}\n")
        p = variant_file(folder, os.path.join(VERIFY, "D", "D.dat"), "D.dat", transform, ["PRINT MAX"])
        rc, out, sec = runner.run_deck(udec, folder, "D.dat", open(p).read())
        runner.take()
        z, k, cy, t = counts(out)
        knobs = f"GEN {kind} {size:g}, cycles x{c}"
        qs = []
        if rc == 0:
            # footing load over its tributary width, as D/check.py measures it
            qs = [q for q, _, _ in ns["footing_loads"](out)]
        q = max(qs) if qs else float("nan")
        table.add("D", knobs, z, k, cy, sec,
                  f"footing load q [Pa] (footing moved {2e-3 * t * 1e3:.1f} mm)",
                  q, q_exact, 100 * (q - q_exact) / q_exact)
    shutil.rmtree(folder, ignore_errors=True)


# ---------------------------------------------------------------- tutorial (rigid)

def problem_T(udec, table, runner, quick):
    """The tutorial of Section 2.1 (examples/tutorial, rigid blocks), stage 2
    (slope1.dat then slope2.dat: left column deleted, friction 0.35): speed
    of the top block (history at (10,20), taken at its corner (5,20)) at the
    history sample nearest to 2 s into stage 2 (free sliding would have
    moved it 0.93 m: it is still fully on the joint and not yet tipping over
    the edge at x = 5, as it does later). The deck's cycle counts (100 in
    stage 1, 1000 in stage 2) are scaled by 0.1/FRACTION.
    No published number (tests/scripts/tutorial_mechanics.py checks only who
    slides). Reference (closed form, not in any check): a block sliding
    freely down the upper joint (slope 6/15 = 0.4, beta = atan 0.4) with
    friction mu = 0.35 under g = 10: v = g (sin beta - mu cos beta) t, t =
    the simulated time of stage 2. The deck runs with DAMP AUTO, which takes
    energy out of the sliding block, so the error measures that damping as
    much as the discretization."""
    tut = os.path.join(ROOT, "examples", "tutorial")
    folder = tempfile.mkdtemp(prefix="udec-acc-T-")
    T_SLIDE = 2.0   # s into stage 2: free sliding travels 0.93 m, the block is still on the joint
    beta = math.atan(6.0 / 15.0)
    accel = 10.0 * (math.sin(beta) - 0.35 * math.cos(beta))
    # knobs: ROUND (deck: none given, the default) and FRACTION fb (deck:
    # default 0.1). ROUND 0.02 is not used: the settling overlap of the top
    # block (weight 1.5e6 N over 15 m of joint at JKN 1.33e7: 7.5 mm static,
    # more in the first cycles) exceeds the overlap tolerance ROUND/2 and
    # stage 1 stops with "Contact Overlap Too Great", as it should.
    variants = [(None, 0.1), (0.05, 0.1)] if quick else \
        [(None, 0.1), (0.2, 0.1), (0.1, 0.1), (0.05, 0.1),
         (None, 0.05), (None, 0.025), (None, 0.0125), (0.05, 0.05)]
    for rnd, fb in variants:
        def t1(text):
            text = text.replace("BLOCK ", f"ROUND {rnd:g}\nBLOCK ", 1) if rnd else text
            text = text.replace("DAMP       AUTO", f"DAMP       AUTO\nFRACTION {fb:g}")
            text = text.replace("CYCLE      100", f"CYCLE      {round(100 * 0.1 / fb)}")
            return "\n".join(l for l in text.split("\n")
                             if not l.upper().startswith(("PLOT", "COPY"))) + "\n"

        def t2(text):
            text = text.replace("CYCLE    1000", f"CYCLE    {round(1000 * 0.1 / fb)}")
            text = text.replace("DELETE   0,5 0,20", "DELETE   0,5 0,20\nHIST XVEL 10,20 YVEL 10,20")
            return "\n".join(l for l in text.split("\n")
                             if not l.upper().startswith(("PLOT", "COPY"))) + "\n"
        p1 = variant_file(folder, os.path.join(tut, "slope1.dat"), "slope1.dat", t1, [])
        p2 = variant_file(folder, os.path.join(tut, "slope2.dat"), "slope2.dat", t2,
                          ["HIST WRITE 2 tx.txt", "HIST WRITE 3 ty.txt", "PRINT MAX"])
        for f in ("tx.txt", "ty.txt"):
            if os.path.exists(os.path.join(folder, f)):
                os.remove(os.path.join(folder, f))
        rc1, out1, sec1 = runner.run_deck(udec, folder, "slope1.dat", open(p1).read())
        rc2, out2, sec2 = runner.run_deck(udec, folder, "slope2.dat", open(p2).read())
        runner.take()
        z, k, cy, t = counts(out2)
        t_stage1 = counts(out1)[3]
        ts = T_SLIDE
        v = float("nan")
        if rc1 == 0 and rc2 == 0:
            times, vx = common.read_history(os.path.join(folder, "tx.txt"))
            vy = common.read_history(os.path.join(folder, "ty.txt"))[1]
            i = min(range(len(times)), key=lambda j: abs(times[j] - t_stage1 - T_SLIDE))
            ts = times[i] - t_stage1
            v = math.hypot(vx[i], vy[i])
        else:
            QUIET_FAILURES.append(f"tutorial ROUND {rnd} FRACTION {fb}: "
                                  + " ".join(l for l in (out1 + out2).splitlines() if "***" in l)[:200])
        knobs = f"ROUND {rnd if rnd else 'default'}, FRACTION {fb:g}"
        table.add("tutorial", knobs, z, k, cy, sec1 + sec2,
                  f"top block speed [m/s] after {ts:.3g} s of stage 2 vs free sliding (closed form)",
                  v, accel * ts, 100 * (v - accel * ts) / (accel * ts))
    shutil.rmtree(folder, ignore_errors=True)


# ---------------------------------------------------------------- verification C

def problem_C(udec, table, runner, quick):
    """Verification C. Measure of verification/C/check.py: crack contacts'
    shear displacement since the friction drop against the closed form
    2 (1 - nu) / G |tau| sqrt(a^2 - x^2); the centre (x = 15) and the worst of
    the contacts with |x - 15| <= 3 m (% of the maximum slip). Knobs: GEN AUTO
    edge (deck 1.5), cycles after the drop (deck 1000), ROUND (deck 0.01)."""
    path = os.path.join(VERIFY, "C", "check.py")
    src = os.path.join(VERIFY, "C", "C.dat")
    folder = tempfile.mkdtemp(prefix="udec-acc-C-")
    ns = check_helpers(path, ("G", "NU", "TAU", "A", "XC", "UMAX"))
    if quick:
        variants = [(1.5, 1000, 0.01), (1.0, 1000, 0.01)]
    else:
        variants = ([(e, 1000, 0.01) for e in (1.5, 1.0, 0.75, 0.5)]
                    + [(1.5, 3000, 0.01), (0.5, 3000, 0.01), (1.5, 1000, 0.005), (1.5, 1000, 0.02)])
    drop = "PROP M=1 JF=0.1667\n"
    for e, cyc, rnd in variants:
        def transform(text):
            text = text.replace("AUTO 1.5", f"AUTO {e:g}").replace("ROUND 0.01", f"ROUND {rnd:g}")
            return text.replace(drop + "CYCLE 1000", "PRINT CONT\n" + drop + f"CYCLE {cyc}")
        name = f"C_{e:g}_{cyc}_{rnd:g}.dat"
        variant_file(folder, src, name, transform, [])
        rc, out, sec = runner.run_deck(udec, folder, name, open(os.path.join(folder, name)).read())
        runner.take()
        z, k, cy, _ = counts(out)
        knobs = f"GEN AUTO {e:g}, cycles {cyc}, ROUND {rnd:g}"
        tag = f"{e:g}" + (f"/C{cyc}" if cyc != 1000 else "") + (f"/R{rnd:g}" if rnd != 0.01 else "")
        if rc != 0 or drop.strip() not in out:
            table.add("C", knobs, z, k, cy, sec, "crack slip", float("nan"), ns["UMAX"], float("nan"))
            continue
        cut = out.index(drop.strip())
        geo0, dis0 = ns["contacts"](out[:cut])
        geo1, dis1 = ns["contacts"](out[cut:])
        rows = [(geo0[c][1], abs(dis1[c] - dis0[c]), ns["closed_form"](geo0[c][1]))
                for c in geo0 if geo0[c][0] == 1 and c in dis1]
        centre = min(rows, key=lambda r: abs(r[0] - ns["XC"]))
        inner = [r for r in rows if abs(r[0] - ns["XC"]) <= 3.0]
        worst = max(inner, key=lambda r: abs(r[1] - r[2]))
        table.add("C", knobs, z, k, cy, sec, "centre slip [m] (contact at x = 15)",
                  centre[1], ns["UMAX"], 100 * (centre[1] - ns["UMAX"]) / ns["UMAX"], tag)
        table.add("C", knobs, z, k, cy, sec,
                  "worst slip within 3 m of the centre [m] (error: % of the centre's)",
                  worst[1], worst[2], 100 * (worst[1] - worst[2]) / ns["UMAX"], tag)
    # the refinement study of verification/C/refine.py (ctest verification.C_refinement):
    # crack tips fixed at 10 and 20, quasi-static friction drop, stiff joint beyond the tips
    rn = check_helpers(os.path.join(VERIFY, "C", "refine.py"),
                       ("G", "NU", "TAU", "A", "XC", "UMAX", "FRICTIONS"))
    for m in ((5, 10) if quick else (5, 10, 15, 20)):
        name = f"C_refine_{m}.dat"
        rc, out, sec = runner.run_deck(udec, folder, name, rn["deck"](m))
        runner.take()
        z, k, cy, _ = counts(out)
        knobs = f"study: GEN QUAD {10 / m:.3g}, tips at 10 / 20, 6-step drop, stiff joint beyond"
        if rc != 0 or "PROP M=1 JF" not in out:
            table.add("C", knobs, z, k, cy, sec, "crack slip", float("nan"), rn["UMAX"], float("nan"))
            continue
        cut = out.index("PROP M=1 JF")
        geo0, dis0 = rn["contacts"](out[:cut])
        geo1, dis1 = rn["contacts"](out[cut:])
        rows = [(geo0[c][1], abs(dis1[c] - dis0[c]), rn["closed_form"](geo0[c][1]))
                for c in geo0 if geo0[c][0] == 1 and c in dis1]
        l2 = math.sqrt(sum((u - e) ** 2 for _, u, e in rows) / sum(e * e for _, _, e in rows))
        centre = min(rows, key=lambda r: abs(r[0] - rn["XC"]))
        table.add("C", knobs, z, k, cy, sec, "study: relative L2 error of the slip (all crack "
                  "contacts)", l2, 0.0, 100 * l2, f"Q{10 / m:.3g}")
        table.add("C", knobs, z, k, cy, sec, "study: slip of the contact nearest the centre "
                  "[m] (error: % of the local closed form)", centre[1], centre[2],
                  100 * (centre[1] - centre[2]) / centre[2], f"Q{10 / m:.3g}")
    shutil.rmtree(folder, ignore_errors=True)


# ---------------------------------------------------------------- verification F

def problem_VF(udec, table, runner, quick):
    """Verification F (steady unconfined flow). Measure of
    verification/F/check.py (its discharge()): the downstream discharge Q
    against Dupuit's closed form 5.625e-6 m3/s and against the manual's UDEC
    5.26e-6. Knobs: the joint spacing of both JSETs (deck 0.5 m; JPERM
    scaled with it, so the equivalent permeability stays 6e-6 m/s: the
    resolution of the aquifer), the flow cycles (deck 1500) and the zone
    edge of `gen edge` (deck 4; the flow runs in the joints, so the zones
    matter only through the mechanical step)."""
    path = os.path.join(VERIFY, "F", "check.py")
    src = os.path.join(VERIFY, "F", "F.dat")
    folder = tempfile.mkdtemp(prefix="udec-acc-VF-")
    ns = check_helpers(path, ("Q_UDEC", "Q_DUPUIT"))
    if quick:
        variants = [(4, 500, 0.5), (4, 1500, 0.5)]
    else:
        variants = [(4, 250, 0.5), (4, 500, 0.5), (4, 1500, 0.5), (4, 3000, 0.5), (0.25, 1500, 0.5),
                    (4, 1500, 1.0), (4, 1500, 0.25), (4, 3000, 0.25)]
    for e, cyc, sp in variants:
        def transform(text):
            text = text.replace("gen edge 4", f"gen edge {e:g}")
            if sp != 0.5:
                # both joint sets at spacing sp; JPERM scaled with it so the
                # equivalent continuum permeability (k = 6e-6 m/s) stays
                assert text.count("0,0 0.5,0") == 2 and "jperm=3.0e8" in text
                text = text.replace("0,0 0.5,0", f"0,0 {sp:g},0")
                text = text.replace("jperm=3.0e8", f"jperm={3.0e8 * sp / 0.5:g}")
            return text.replace("cycle 1500", f"cycle {cyc}")
        name = f"F_{e:g}_{cyc}_{sp:g}.dat"
        variant_file(folder, src, name, transform, ["print max", "print flows"])
        rc, out, sec = runner.run_deck(udec, folder, name, open(os.path.join(folder, name)).read())
        runner.take()
        z, k, cy, _ = counts(out)
        knobs = f"joint spacing {sp:g} m, gen edge {e:g}, flow cycles {cyc}"
        tag = f"S{sp:g}" + (f"/C{cyc}" if cyc != 1500 else "") + (f"/E{e:g}" if e != 4 else "")
        q = ns["discharge"](out)[0] if rc == 0 else float("nan")
        table.add("F", knobs, z, k, cy, sec, "discharge Q [m3/s] vs Dupuit (closed form)",
                  q, ns["Q_DUPUIT"], 100 * (q - ns["Q_DUPUIT"]) / ns["Q_DUPUIT"], tag)
        table.add("F", knobs, z, k, cy, sec, "discharge Q [m3/s] vs UDEC 1989 (check.py)",
                  q, ns["Q_UDEC"], 100 * (q - ns["Q_UDEC"]) / ns["Q_UDEC"], tag)
# ---------------------------------------------------------------- thermal cases 1-5

NUMRE = r"([0-9]*\.?[0-9]+(?:[eE][-+]?\d+)?)"


def scale_steps(text, factor):
    """Every `ste n` of a RUN line times factor (at least 1)."""
    new, n = re.subn(r"(\bste[ \t]+)(\d+)", lambda m: f"{m.group(1)}{max(1, round(int(m.group(2)) * factor))}",
                     text, flags=re.I)
    assert n > 0, "no RUN ste n in deck"
    return new


def scale_delt(text, factor):
    """Every `delt dt` of a RUN line times factor (none: unchanged)."""
    return re.sub(r"(\bdelt[ \t]+)" + NUMRE, lambda m: f"{m.group(1)}{float(m.group(2)) * factor:.6g}",
                  text, flags=re.I)


def thermal_case(udec, table, runner, quick, case, measure, transient, quantity):
    """Thermal verification case `case` (verification/thermal<case>): the
    printed explicit (case_a) and implicit (case_b) decks at several zone
    sizes (GEN AUTO edmax times s) and time steps (delt times f, steps over
    f: the same end time). Steady cases (1, 2) have no delt: their step
    counts grow as 1 / s^2 (explicit: the automatic step follows the zone
    size squared) so every variant reaches the same steady state.
    measure(out) -> (value, reference) of the worst table position, as the
    check measures it; error = value / reference - 1 in %."""
    here = os.path.join(VERIFY, f"thermal{case}")
    folder = tempfile.mkdtemp(prefix=f"udec-acc-H{case}-")
    if transient:
        variants = [("a", 1, 1), ("a", 0.5, 1)] if quick else \
            [("a", 1, 1), ("a", 0.7, 1), ("a", 0.5, 1), ("a", 1, 0.5),
             ("b", 1, 1), ("b", 1, 0.5), ("b", 1, 0.25), ("b", 0.5, 0.25)]
    else:
        # 0.8, not 0.7: at 0.7 case 2's mat-2 zoning puts a corner at x = 0.3917,
        # inside its THAPP CONV range .39-.41, and the convection then also acts
        # on the top and bottom edges there (Section 7.4: between consecutive
        # corners in the range): T3 drops 45 %, a different problem
        variants = [("a", 1, 1), ("a", 0.5, 1)] if quick else \
            [("a", 1, 1), ("a", 0.8, 1), ("a", 0.5, 1), ("b", 1, 1), ("b", 0.8, 1), ("b", 0.5, 1)]
    for deck, sz, f in variants:
        # explicit: the stable step follows the zone size squared (RUN
        # reduces a larger delt to it and would stop short of the end time)
        fe = f * sz ** 2 if deck == "a" else f

        def transform(text):
            text = scale_auto(text, sz)
            if transient:
                return scale_steps(scale_delt(text, fe), 1.0 / fe)
            return scale_steps(text, 1.0 / sz ** 2) if deck == "a" else text
        src = os.path.join(here, f"case_{deck}.dat")
        name = f"case_{deck}_{sz:g}_{f:g}.dat"
        path = variant_file(folder, src, name, transform, [])
        text = text_with(measure.prepare(open(path).read()), ["print max"])
        rc, out, sec = runner.run_deck(udec, folder, name, text)
        runner.take()
        scheme = "explicit" if deck == "a" else "implicit"
        knobs = f"{scheme}, edmax x{sz:g}" + (f", delt x{fe:g}" if transient else "")
        value, ref = measure(out) if rc == 0 else (float("nan"), float("nan"))
        if "reduced to the explicit limit" in out:
            QUIET_FAILURES.append(f"thermal {case} {knobs}: delt reduced, end time not reached")
            value = float("nan")
        steps = re.findall(r"thermal step (\d+), thermal time", out)
        table.add(f"thermal {case}", knobs, counts(out)[0], 0, sum(int(n) for n in steps), sec,
                  quantity, value, ref, 100 * (value - ref) / ref)
    shutil.rmtree(folder, ignore_errors=True)


def text_with(text, extra):
    """Deck text with the lines `extra` before its last STOP."""
    lines = text.rstrip("\n").split("\n")
    stop = max(i for i, l in enumerate(lines) if l.strip().upper().startswith("STOP"))
    lines[stop:stop] = extra
    return "\n".join(lines) + "\n"


class Measure:
    """A measure with the deck preparation it needs (print lines)."""

    def __init__(self, fn, prepare=None):
        self.fn = fn
        self.prepare = prepare or (lambda text: text_with(text, ["print temperature"]))

    def __call__(self, out):
        return self.fn(out)


def worst(pairs):
    """(value, reference) with the largest relative error."""
    return max(pairs, key=lambda p: abs(p[0] - p[1]) / abs(p[1]) if math.isfinite(p[0]) else math.inf)


def problem_H1(udec, table, runner, quick):
    """Thermal 1 (tapered fin, steady): the face temperature at the table's x
    against the analytical column of Table 7-2 (thermal1/check.py)."""
    import thermal_common as tc
    ns = check_helpers(os.path.join(VERIFY, "thermal1", "check.py"), ["TABLE", "SLOPE"])

    def fn(out):
        rows = tc.temperatures(out)
        face = [(x, y) for (x, y) in rows if x >= -1e-9 and abs(y - ns["SLOPE"] * x) < 1e-5]
        return worst([(tc.along(rows, face, r[0]), r[1]) for r in ns["TABLE"][1:]])
    thermal_case(udec, table, runner, quick, 1, Measure(fn), False,
                 "worst face temperature vs analytical (Table 7-2)")


def problem_H2(udec, table, runner, quick):
    """Thermal 2 (furnace wall, steady): T1, T2, T3 against the series
    resistance closed form (thermal2/check.py)."""
    import thermal_common as tc
    ns = check_helpers(os.path.join(VERIFY, "thermal2", "check.py"),
                       ["R", "q", "T1", "T2", "T3", "EXACT", "XPOS", "TABLE"])

    def fn(out):
        rows = tc.temperatures(out)
        return worst([(tc.at(rows, ns["XPOS"][k], 0.0), ns["EXACT"][k]) for k in ("T1", "T2", "T3")])
    thermal_case(udec, table, runner, quick, 2, Measure(fn), False,
                 "worst of T1 T2 T3 vs closed form")


def problem_H3(udec, table, runner, quick):
    """Thermal 3 (heat-generating slab, as printed: source 20000): the
    temperature on y = 0 at the table's x against the 1-D series for the
    printed source (thermal3/check.py, README: Table 7-4 belongs to 40000)."""
    import thermal_common as tc
    ns = check_helpers(os.path.join(VERIFY, "thermal3", "check.py"), ["XS"])

    def fn(out):
        rows = tc.temperatures(out)
        line = [(x, y) for (x, y) in rows if abs(y) < 1e-9]
        return worst([(tc.along(rows, line, x), ns["series"](x, 0.2, 20000)) for x in ns["XS"][1:]])
    thermal_case(udec, table, runner, quick, 3, Measure(fn), True,
                 "worst T(x) at t = 0.2 s vs series, q = 20000")


def problem_H4(udec, table, runner, quick):
    """Thermal 4 (slab with flux): the temperature on y = 0 at the table's x
    (T > 0.05) at t = 0.2 s, against Carslaw and Jaeger's closed form
    (thermal4/check.py); the mechanical restarts of the deck run too."""
    import thermal_common as tc
    path = os.path.join(VERIFY, "thermal4", "check.py")
    ns = check_helpers(path, ["XS"])
    prt = "print -1 2 -0.001 0.001 temperature"

    def prepare(text):
        text = re.sub(r"(save case4_1[ei]\.sav\n)", r"\1" + prt + "\n", text, count=1)
        return text

    def fn(out):
        rows = tc.temperatures(out.split(prt)[1])
        line = [(x, y) for (x, y) in rows if abs(y) < 1e-9 and x <= 5]
        pairs = [(tc.along(rows, line, x), ns["temp"](x, 0.2)) for x in ns["XS"]]
        return worst([p for p in pairs if p[1] > 0.05])
    thermal_case(udec, table, runner, quick, 4, Measure(fn, prepare), True,
                 "worst T(x) at t = 0.2 s vs closed form (T > 0.05)")


def problem_H5(udec, table, runner, quick):
    """Thermal 5 (orthotropic bar with convection): the four points of
    Table 7-6 against its analytical column (thermal5/check.py)."""
    import thermal_common as tc
    ns = check_helpers(os.path.join(VERIFY, "thermal5", "check.py"), ["X", "Y", "TABLE"])

    def fn(out):
        rows = tc.temperatures(out)
        return worst([(tc.at(rows, x, y), t) for x, y, t, _ in ns["TABLE"]])
    thermal_case(udec, table, runner, quick, 5, Measure(fn), True,
                 "worst of 4 points vs analytical (Table 7-6)")


# ---------------------------------------------------------------- application E

def problem_AE(udec, table, runner, quick):
    """Application E (JCONS 3 direct shear), the printed decks (their 1989
    addresses resolve), with the measures of examples/application/E/check.py:
    the peak shear stress at contact 159 (histories 3-6: SDIS NDIS SSTR NSTR)
    against the model's equations at a constant 10 MPa along the contact's
    own shear path, and the dilation (NDIS + NSTR / JKN gained) against the
    same equations (second quantity). Knobs: the zone time-step fraction
    (deck FRAC 0.05) and the shear velocity (deck -0.05 m/s), cycles scaled so
    the joint slides the same 3 mm. The zone size is not varied: the deck's
    AUTO 2.1 is the 1989 layout its addresses name (check.py)."""
    edir = os.path.join(ROOT, "examples", "application", "E")
    ns = check_helpers(os.path.join(edir, "check.py"), ["KN", "KS", "PHI", "R"])
    folder = tempfile.mkdtemp(prefix="udec-acc-AE-")
    variants = [(1, 1), (0.5, 1)] if quick else [(1, 1), (0.5, 1), (0.25, 1), (1, 0.5), (1, 0.25),
                                                 (0.5, 0.5)]
    for deck, jif in (("E1_direct_shear_jif59.dat", 1.035), ("E2_direct_shear_jif40.dat", 0.700)):
        for fr, vel in variants:
            def transform(text):
                text = text.replace("FRAC 0.05 1.0", f"FRAC {0.05 * fr:g} 1.0")
                text = text.replace("XVEL= -0.05", f"XVEL= {-0.05 * vel:g}")
                return text.replace("CYC 750", f"CYC {round(750 / (fr * vel))}")
            name = f"E_{jif:g}_{fr:g}_{vel:g}.dat"
            path = variant_file(folder, os.path.join(edir, deck), name, transform,
                                ["PRINT HIST 3 4 5 6", "PRINT MAX"])
            rc, out, sec = runner.run_deck(udec, folder, name, open(path).read())
            runner.take()
            rows = [[float(v) for v in l.split()]
                    for l in out.split("PRINT HIST 3 4 5 6")[-1].splitlines()
                    if re.match(r"^\s+\d\.\d+E[-+]\d+(\s+-?\d\.\d+E[-+]\d+){4}\s*$", l)]
            peak = ref = dil = rdil = float("nan")
            if rc == 0 and len(rows) > 10:
                sdis = [0.0] + [r[1] for r in rows]
                ndis, sstr, nstr = [r[2] for r in rows], [r[3] for r in rows], [r[4] for r in rows]
                law = ns["law"](sdis, [10.0] * len(sdis), jif)
                peak, ref = max(sstr), max(t for t, _ in law)
                dil, rdil = ns["dilation"](ndis, nstr), law[-1][1]
            z, k, cy, _ = counts(out)
            knobs = f"JIF {jif:g}, FRAC {0.05 * fr:g}, velocity {0.05 * vel:g} m/s"
            table.add("appl. E", knobs, z, k, cy, sec,
                      "peak shear stress [MPa], contact 159, vs equations at 10 MPa", peak, ref,
                      100 * (peak - ref) / ref)
            table.add("appl. E", knobs, z, k, cy, sec,
                      "dilation [m] vs equations at 10 MPa (not in check.py at this rate)", dil, rdil,
                      100 * (dil - rdil) / rdil)
    shutil.rmtree(folder, ignore_errors=True)


def problem_AC(udec, table, runner, quick):
    """Application C (lined tunnels), with the quantities of
    examples/application/C/check.py: the service liner's largest thrust
    against the manual's 1.7e5 N, and the main liner put in at the moment of
    excavation against the closed form p R of the lined tunnel
    (convergence-confinement; u_inf measured in the same zoning's unlined
    run). Knob: the zone size of the fine band (deck GEN ... AUTO 3.0; the
    coarse bands, AUTO 10.0, scaled alike)."""
    cdir = os.path.join(ROOT, "examples", "application", "C")
    src = os.path.join(cdir, "C1_tunnel_support.dat")
    main_liner = "STRUC 30 -70 22.5 4.3 8 5 0.46"
    folder = tempfile.mkdtemp(prefix="udec-acc-AC-")
    sizes = [3.0, 2.0] if quick else [4.0, 3.0, 2.0, 1.5]

    def thrusts(out):
        last = out.rsplit("PR STE STC LM", 1)[1].split("Structural element interfaces")[0]
        res = {}
        for line in last.splitlines():
            f = line.split()
            if len(f) == 10 and f[0].isdigit():
                res[int(f[0])] = (-float(f[6]), float(f[5]))   # thrust, length
        return res

    for h in sizes:
        def zoning(text, h=h):
            text = text.replace("AUTO 3.0", f"AUTO {h:g}")
            return text.replace("AUTO 10.0", f"AUTO {10.0 * h / 3.0:g}")
        text = zoning(open(src).read()).replace("SAVE CHAN3\n", "SAVE CHAN3\nPRINT GRIDPOINT\n")
        rc, out, sec = runner.run_deck(udec, folder, f"C_{h:g}.dat", text)
        runner.take()
        z, k, cy, _ = counts(out)
        el = thrusts(out) if rc == 0 else {}
        t_serv = max((v[0] for e, v in el.items() if e <= 16), default=float("nan"))
        table.add("appl. C", f"fine zones AUTO {h:g}", z, k, cy, sec,
                  "service liner largest thrust [N] vs manual 1.7e5", t_serv, 1.7e5,
                  100 * (t_serv - 1.7e5) / 1.7e5)
        # closed form of the lined tunnel: u_inf from this run's unlined wall
        ur = []
        gp = out.split("SAVE CHAN3", 1)[1].split("GRIDPT", 1)[1] if rc == 0 else ""
        for line in gp.splitlines()[1:]:
            f = line.split()
            if len(f) != 8 or not f[0].isdigit():
                break
            x, y, dx, dy = (float(v) for v in f[2:6])
            r = math.hypot(x - 30, y + 70)
            if 3.8 < r < 4.3:
                ur.append(-((x - 30) * dx + (y + 70) * dy) / r)
        imm = zoning(open(src).read()).replace(main_liner + "\n", "").replace(
            "DEL 28 32 -72 -68\n", "DEL 28 32 -72 -68\nPROP MAT=6 D=24 G=10E9 K=13E9 KN=1E8 "
            "KS=1E7 CFRIC=10.0\n" + main_liner.replace(" 8 5 ", " 8 6 ") + "\n")
        rc2, out2, sec2 = runner.run_deck(udec, folder, f"Cimm_{h:g}.dat", imm)
        runner.take()
        el2 = thrusts(out2) if rc2 == 0 else {}
        val = ref = float("nan")
        if ur and len(el2) >= 24:
            lm = [l.split() for l in
                  out2.rsplit("Structural element lumped masses", 1)[1].splitlines()[2:]]
            lm = [f for f in lm if len(f) == 9 and f[0].isdigit() and 17 <= int(f[0]) <= 24]
            rad = sum(math.hypot(float(f[1]) - 30, float(f[2]) + 70) for f in lm) / len(lm)
            p0, u_inf = 8.36e5, sum(ur) / len(ur)
            e_mod = 9 * 13e9 * 10e9 / (3 * 13e9 + 10e9)
            length = sum(el2[e][1] for e in range(17, 25)) / 8
            ks = 1.0 / (length / 1e8 + rad * rad / (e_mod * 0.46))
            ref = ks * u_inf / (1 + ks * u_inf / p0) * rad
            val = sum(el2[e][0] for e in range(17, 25)) / 8
        z, k, cy, _ = counts(out2)
        table.add("appl. C", f"fine zones AUTO {h:g}, main liner at excavation", z, k, cy, sec2,
                  "main liner mean thrust [N] vs closed form p R", val, ref,
                  100 * (val - ref) / ref if ref == ref else float("nan"))
    shutil.rmtree(folder, ignore_errors=True)


# ---------------------------------------------------------------- thermal 6

def problem_H6(udec, table, runner, quick):
    """Thermal 6 (decaying source plus a TADD pulse, verification/thermal6):
    the worst of its five points at t = 2 against the superposition closed
    form of its check.py (check: 2 %). Knobs: the zone edge (deck `auto
    0.25`; 0.5, 0.125), the scheme (explicit with the automatic step, as the
    check's first run; implicit Crank-Nicolson, the check's `delt 0.05`, and
    0.1, 0.2, 0.025)."""
    import thermal_common as tc
    path = os.path.join(VERIFY, "thermal6", "check.py")
    ns = check_helpers(path, ["Q", "TG", "SOURCES", "T_END", "POINTS", "GX", "GW", "RUNS"])
    runs = dict(ns["RUNS"])
    folder = tempfile.mkdtemp(prefix="udec-acc-H6-")
    variants = [("explicit", 0.25, None), ("explicit", 0.5, None)] if quick else \
        [("explicit", 0.5, None), ("explicit", 0.25, None), ("explicit", 0.125, None),
         ("implicit", 0.25, 0.2), ("implicit", 0.25, 0.1), ("implicit", 0.25, 0.05),
         ("implicit", 0.25, 0.025), ("implicit", 0.125, 0.025)]
    cache = {}
    for scheme, edge, dt in variants:
        run = runs[scheme] if dt is None else runs[scheme].replace("delt 0.05", f"delt {dt:g}")
        name = f"h6_{scheme}_{edge:g}_{dt}.dat"
        rc, out, sec = runner.run_deck(udec, folder, name, text_with(ns["deck"](run, edge), ["print max"]))
        runner.take()
        pairs = []
        if rc == 0:
            rows = tc.temperatures(out)
            for x, y in ns["POINTS"]:
                x, y = min(rows, key=lambda q: math.hypot(q[0] - x, q[1] - y))
                if (x, y) not in cache:
                    cache[(x, y)] = ns["closed_form"](x, y, ns["T_END"])
                pairs.append((tc.at(rows, x, y), cache[(x, y)]))
        value, ref = worst(pairs) if pairs else (float("nan"), float("nan"))
        steps = re.findall(r"thermal step (\d+), thermal time", out)
        knobs = f"{scheme}, auto {edge:g}" + ("" if dt is None else f", delt {dt:g}")
        table.add("thermal 6", knobs, counts(out)[0], 0, sum(int(n) for n in steps), sec,
                  "worst of 5 points at t = 2 vs closed form", value, ref,
                  100 * (value - ref) / ref if pairs else float("nan"))
    shutil.rmtree(folder, ignore_errors=True)


# ---------------------------------------------------------------- application A

def problem_AA(udec, table, runner, quick):
    """Application A (seismic roof collapse, first event), the measure of
    examples/application/A/check.py: the wave's own top velocity, the peak of
    history 6 (YVEL (0,20)) minus the same history of the same deck with the
    wave's amplitude 0. The manual bounds it ("less than 0.06 m/sec", Fig.
    A-5) and gives no value, so the reference is the finest variant's value
    (self-convergence). Knobs: the zone edge (deck `AUTO 9.0`, times 1,
    0.5, 0.3), the zones' FRACTION (deck: the default 1; 0.5 with every stage's
    cycles doubled: the same simulated time) and the excavation stage's length
    (deck CYCLE 2000; 8000: to rest)."""
    deck = os.path.join(ROOT, "examples", "application", "A", "A1_static_seismic_1p25MPa.dat")
    folder = tempfile.mkdtemp(prefix="udec-acc-AA-")
    variants = [(1, None, 2000), (0.5, None, 2000)] if quick else \
        [(1, None, 2000), (0.5, None, 2000), (0.3, None, 2000), (1, None, 8000), (1, 0.5, 2000),
         (0.3, 0.5, 2000)]
    results = []
    for sz, frac, exc in variants:
        series, secs = {}, 0.0
        for label, amp in (("wave", "-1.25"), ("nowave", "0.0")):
            text = open(deck).read().replace("STRESS 0 0 -1.25", f"STRESS 0 0 {amp}")
            text = text.replace("CYCLE 2000", f"CYCLE {exc}")
            if sz != 1:
                text = scale_auto(text, sz)
            if frac:   # the zones' fraction (FRACTION 0.1 fz; the deck's default fz = 1)
                text = text.replace("DAMP AUTO\n", f"DAMP AUTO\nFRACTION 0.1 {frac:g}\n", 1)
                text = text.replace("CYCLE 100\n", f"CYCLE {round(100 / frac)}\n")
                text = text.replace(f"CYCLE {exc}", f"CYCLE {round(exc / frac)}")
                text = text.replace("CYC 800", f"CYC {round(800 / frac)}")
            hist = f"h6_{label}.txt"
            text = text_with(text, [f"HIST WRITE 6 {hist}"])
            if os.path.exists(os.path.join(folder, hist)):
                os.remove(os.path.join(folder, hist))
            rc, out, sec = runner.run_deck(udec, folder, f"A1_{label}.dat", text)
            runner.take()
            secs += sec
            if rc == 0 and os.path.exists(os.path.join(folder, hist)):
                series[label] = common.read_history(os.path.join(folder, hist))
        peak = float("nan")
        if len(series) == 2:
            (tw, vw), (tn, vn) = series["wave"], series["nowave"]
            peak = max(abs(a - b) for a, b in zip(vw, vn))
        z, k, cy, _ = counts(out)
        knobs = (f"AUTO 9.0 x{sz:g}, FRACTION {'default' if frac is None else f'{frac:g}'}, "
                 f"excavation CYCLE {exc}")
        results.append((knobs, z, k, cy, secs, peak))
    ref = results[-1][5] if quick else next(r[5] for r, v in zip(results, variants)
                                            if v == (0.3, 0.5, 2000))
    for knobs, z, k, cy, secs, peak in results:
        table.add("appl. A", knobs, z, k, cy, secs,
                  "wave's top velocity peak [m/s] (wave minus no wave) vs finest variant",
                  peak, ref, 100 * (peak - ref) / ref)
    shutil.rmtree(folder, ignore_errors=True)


# ---------------------------------------------------------------- application D

def problem_AD(udec, table, runner, quick):
    """Application D (dam: gravity, reservoir flow, earthquake), stage 3's
    largest slip in the deck's PRINT -50,55 -35,2 CON (as
    tests/scripts/application_d.py reads it) against the manual's "0.07 m"
    (Fig. D-6; the test prints, does not assert it: -17 %). Knobs: stage 3's
    MSCALE PART step (deck 1.5E-3 with CYCLE 1000; 1.0E-3 and 0.75E-3 with
    the cycles scaled to the same 1.5 s; a smaller tdel is below the model's
    own step and changes nothing) and the zone edge of stage 1 (deck
    AUTO 60 / 30, times 1 and 0.75; the three stages rerun). Wall time: the
    three stages."""
    ddir = os.path.join(ROOT, "examples", "application", "D")
    sys.path.insert(0, os.path.join(ROOT, "tests", "scripts"))
    ns = check_helpers(os.path.join(ROOT, "tests", "scripts", "application_d.py"))
    folder = tempfile.mkdtemp(prefix="udec-acc-AD-")
    decks = [open(os.path.join(ddir, n)).read()
             for n in ("D1_gravity.dat", "D2_reservoir_flow.dat", "D3_dynamic.dat")]
    # MSCALE PART tdel raises masses only where the step would be smaller than
    # tdel: below the model's own step (6.8e-4 s at FRAC 0.15) it changes
    # nothing, so 0.75E-3 is the finest step a user can choose here
    variants = [(1, 1), (1, 0.5)] if quick else [(1, 1), (1, 2 / 3), (1, 0.5), (0.75, 1), (0.75, 0.5)]
    stages12 = {}
    for sz, f in variants:
        if sz not in stages12:
            d1 = decks[0] if sz == 1 else scale_auto(decks[0], sz)
            rc1, out1, s1 = runner.run_deck(udec, folder, "D1.dat", d1)
            rc2, out2, s2 = runner.run_deck(udec, folder, "D2.dat", decks[1])
            runner.take()
            stages12[sz] = (rc1 == 0 and rc2 == 0, s1 + s2)
            if not stages12[sz][0]:
                QUIET_FAILURES.append(f"appl. D zones x{sz:g}: stage 1 or 2 failed")
        ok, s12 = stages12[sz]
        # restarts the DAM2 of this zoning (the variants of one zoning follow each other)
        d3 = decks[2].replace("MSCALE PART 1.5E-3", f"MSCALE PART {1.5e-3 * f:.6g}").replace(
            "CYCLE 1000", f"CYCLE {round(1000 / f)}")
        rc3, out3, s3 = runner.run_deck(udec, folder, f"D3_{sz:g}_{f:g}.dat", d3)
        runner.take()
        slip = float("nan")
        cyc = re.findall(r"cycle \d+, time\s+(\S+), timestep\s+(\S+)", out3)
        if cyc and abs(float(cyc[-1][0]) - 1.5) > 2e-3:
            QUIET_FAILURES.append(f"appl. D x{sz:g} f {f:g}: stage 3 ends at t = {cyc[-1][0]} s, "
                                  f"not 1.5 s (step {cyc[-1][1]})")
            ok = False
        if ok and rc3 == 0:
            tabs = ns["contacts_table"](out3, "PRINT -50,55 -35,2 CON")
            if len(tabs) >= 2:
                slip = max(abs(float(c["SHEAR-DISP"])) for c in tabs[1][1].values())
        z, k, cy, _ = counts(out3)
        table.add("appl. D", f"zones AUTO 60/30 x{sz:g}, MSCALE PART {1.5e-3 * f:.3g}, "
                  f"CYCLE {round(1000 / f)}", z, k, cy, s12 + s3,
                  "largest slip [m] in stage 3 vs manual 0.07 (Fig. D-6)", slip, 0.07,
                  100 * (slip - 0.07) / 0.07)
    shutil.rmtree(folder, ignore_errors=True)


# ---------------------------------------------------------------- application G

def problem_AG(udec, table, runner, quick):
    """Application G (Bingham grout from a pressurised hole), the quantity of
    tests/scripts/fluid_grouting.py: the hole pressure at which grout starts
    to leave the model (total boundary outflow of PRINT FLOWS), against the
    closed form of that test (threshold gradient 2 COHW / a over the 4.4 m
    from the hole's wall to the boundary, a = 9e-5 m: 9778 Pa; the manual:
    "no steady state flow ... until the pressure exceeds 8000 Pa"). The
    onset is the zero of the outflow extrapolated linearly from the first
    two flowing stages (Bingham flow above the threshold grows linearly with
    the pressure). Knobs: the pressure step above 8000 Pa (deck 2000 Pa:
    stages at 10 000 and 12 000; 1000 and 500 Pa up to 12 000) and the cycles
    per stage (deck 1000; 2000)."""
    src = os.path.join(ROOT, "examples", "application", "G", "G1_grouting.dat")
    folder = tempfile.mkdtemp(prefix="udec-acc-AG-")
    variants = [(2000, 1000), (500, 1000)] if quick else \
        [(2000, 1000), (1000, 1000), (500, 1000), (1000, 2000)]
    printed = open(src).read()
    head = printed.split("pfix dom 697 pres 1.0e4")[0]          # stages up to 8000 Pa
    for step, cyc in variants:
        text = re.sub(r"(?m)^save grthol[b-i]\.sav$", "print flows", head)
        text = text.replace("cy 1000", f"cy {cyc}")
        p = 8000 + step
        while p <= 12000:
            text += f"pfix dom 697 pres {p}\ncy {cyc}\nprint flows\n"
            p += step
        text += "print max\nstop\n"
        rc, out, sec = runner.run_deck(udec, folder, f"g_{step}_{cyc}.dat", text)
        runner.take()
        q = [float(m) for m in re.findall(r"total boundary outflow\s+(\S+)", out)]
        pres = [2000 * (i + 1) for i in range(4)] + list(range(8000 + step, 12001, step))
        onset = float("nan")
        flowing = [(pp, qq) for pp, qq in zip(pres, q) if qq > 0]
        print(f"  appl. G step {step} cy {cyc}: outflow at " +
              ", ".join(f"{pp:g} Pa {qq:.3g}" for pp, qq in zip(pres, q)), flush=True)
        if rc == 0 and len(q) == len(pres) and len(flowing) >= 2:
            (p1, q1), (p2, q2) = flowing[:2]
            onset = p1 - q1 * (p2 - p1) / (q2 - q1)
        z, k, cy, _ = counts(out)
        table.add("appl. G", f"pressure step {step} Pa above 8000, cy {cyc} per stage", z, k, cy, sec,
                  "onset pressure [Pa] (outflow extrapolated to 0) vs closed form", onset, 9778.0,
                  100 * (onset - 9778.0) / 9778.0)
    shutil.rmtree(folder, ignore_errors=True)


PROBLEMS = {"A": problem_A, "E": problem_E, "F": problem_F, "B": problem_B, "D": problem_D, "T": problem_T,
            "C": problem_C, "VF": problem_VF,
            "H1": problem_H1, "H2": problem_H2, "H3": problem_H3, "H4": problem_H4, "H5": problem_H5,
            "AE": problem_AE, "AC": problem_AC, "H6": problem_H6, "AA": problem_AA, "AD": problem_AD,
            "AG": problem_AG}


def draw(table_rows, key, folder):
    """One PNG per problem: |error| against wall time, one numbered marker per
    variant (the numbers of its docs/accuracy.md table), bench/accuracy_plot.py."""
    import accuracy_plot
    return accuracy_plot.draw_key(table_rows, key, folder)


def update_doc(path, table, keys):
    """Replace, in the Markdown file `path`, the block between the lines
    `<!-- accuracy KEY -->` and `<!-- /accuracy KEY -->` by the table of
    problem KEY, for every KEY run (written to a temporary, then renamed)."""
    text = open(path).read()
    for key in keys:
        head, tail = f"<!-- accuracy {key} -->", f"<!-- /accuracy {key} -->"
        if head not in text or tail not in text:
            print(f"note: {path} has no block for {key} ({head} ... {tail}); not updated")
            continue
        a, b = text.index(head) + len(head), text.index(tail)
        text = text[:a] + "\n" + table.doc_table(key) + "\n" + text[b:]
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        f.write(text)
    os.replace(tmp, path)


def write_json(path, rows):
    """The rows as JSON (NaN as null), written to a temporary and renamed."""
    import json
    with open(path + ".tmp", "w") as f:
        json.dump([{k: (v if not (isinstance(v, float) and not math.isfinite(v)) else None)
                    for k, v in r.items()} for r in rows], f, indent=1)
    os.replace(path + ".tmp", path)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("udec", help="path to the udec binary")
    ap.add_argument("--problems", default=",".join(PROBLEMS),
                    help="comma-separated names out of " + " ".join(PROBLEMS) + " (default all)")
    ap.add_argument("--quick", action="store_true", help="two resolutions per problem only")
    ap.add_argument("--no-repeat", action="store_true", help="one run per variant, even below 2 s")
    ap.add_argument("--out", help="write the Markdown table here (default: stdout only)")
    ap.add_argument("--png", help="folder: one chart accuracy_<letter>.png per problem")
    ap.add_argument("--json", help="write the rows as JSON here (input of bench/accuracy_plot.py)")
    ap.add_argument("--doc", help="Markdown file whose <!-- accuracy KEY --> blocks get the tables "
                                  "(docs/accuracy.md)")
    ap.add_argument("--from-json", help="no runs: take the rows of this --json file (with --doc, --png)")
    a = ap.parse_args()
    udec = os.path.abspath(a.udec)
    table = Table()
    if a.from_json:
        import json
        table.rows = json.load(open(a.from_json))
        keys = []
        for r in table.rows:
            if r["key"] not in keys:
                keys.append(r["key"])
        for k in keys:
            if a.png:
                os.makedirs(a.png, exist_ok=True)
                print("wrote " + draw(table.rows, k, a.png))
        if a.doc:
            update_doc(a.doc, table, keys)
        return
    runner = Runner(repeat=not a.no_repeat)
    t0 = time.time()
    for p in a.problems.split(","):
        p = p.strip().upper()
        if p not in PROBLEMS:
            ap.error(f"unknown problem {p!r} (choose from {' '.join(PROBLEMS)})")
        print(f"problem {p} ...", flush=True)
        table.key = p
        PROBLEMS[p](udec, table, runner, a.quick)
        if a.png:
            os.makedirs(a.png, exist_ok=True)
            print("wrote " + draw(table.rows, p, a.png), flush=True)
        if a.doc:
            update_doc(a.doc, table, [p])
        if a.json:     # after every problem: a later failure keeps what was measured
            write_json(a.json, table.rows)
    md = table.markdown()
    print(md)
    print(f"total {time.time() - t0:.0f} s")
    for f in QUIET_FAILURES:
        print("note (check of the reused helpers): " + f)
    if a.out:
        with open(a.out, "w") as f:
            f.write(md)


if __name__ == "__main__":
    main()
