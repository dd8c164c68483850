"""Helpers shared by the thermal verification checks (verification/thermal*)."""


def temperatures(out):
    """{(x, y): T} of the last PRINT TEMPERATURE table in udec output."""
    rows, inside = {}, False
    for line in out.splitlines():
        if line.startswith("  GRIDPT   BLOCK             X             Y   TEMPERATURE"):
            rows, inside = {}, True
            continue
        if inside:
            f = line.split()
            try:
                rows[(float(f[2]), float(f[3]))] = float(f[4])
            except (ValueError, IndexError):
                inside = False
    return rows


def at(rows, x, y, tol=1e-6):
    """Temperature of the gridpoint at (x, y) (NaN if none)."""
    vals = [t for (px, py), t in rows.items() if abs(px - x) < tol and abs(py - y) < tol]
    return vals[0] if vals else float("nan")


def along(rows, points, x):
    """Linear interpolation in x of the temperatures at `points` [(x, y)]."""
    pts = sorted((px, rows[(px, py)]) for px, py in points)
    for (x0, t0), (x1, t1) in zip(pts, pts[1:]):
        if x0 - 1e-9 <= x <= x1 + 1e-9:
            return t0 + (t1 - t0) * (x - x0) / (x1 - x0)
    return float("nan")
