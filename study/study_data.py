"""Reading the study's CSV files (written by fosssim-study) for charts.py and report.py.

Empty cells are the study's "does not apply" and read as NaN; numbers read as floats; the rest
stays text. Only the standard library and numpy, so the reader works wherever matplotlib does.
"""
import csv
import math
import os


def _cell(text):
    if text == "":
        return math.nan
    try:
        return float(text)
    except ValueError:
        return text


def load(data_dir, name):
    """Rows of data_dir/name.csv as dicts of floats (NaN for empty cells) and strings."""
    path = os.path.join(data_dir, name + ".csv")
    with open(path, newline="") as f:
        return [{k: _cell(v) for k, v in row.items()} for row in csv.DictReader(f)]


def finite(x):
    return isinstance(x, float) and math.isfinite(x)


def unique(rows, key):
    """Values of `key` in first-seen order."""
    seen = []
    for r in rows:
        if r[key] not in seen:
            seen.append(r[key])
    return seen


def pareto(points):
    """Indices of the points (cost, error) that no other point beats in both, sorted by cost."""
    order = sorted(range(len(points)), key=lambda i: (points[i][0], points[i][1]))
    front, best = [], math.inf
    for i in order:
        if points[i][1] < best:
            front.append(i)
            best = points[i][1]
    return front


def order_of_convergence(dts, errors):
    """Least-squares slope of log(error) against log(dt): the observed order (NaN if < 3 points)."""
    pts = [(math.log(d), math.log(e)) for d, e in zip(dts, errors) if finite(d) and finite(e) and e > 0]
    if len(pts) < 3:
        return math.nan
    n = len(pts)
    mx = sum(p[0] for p in pts) / n
    my = sum(p[1] for p in pts) / n
    sxx = sum((p[0] - mx) ** 2 for p in pts)
    sxy = sum((p[0] - mx) * (p[1] - my) for p in pts)
    return sxy / sxx if sxx > 0 else math.nan


# Stability theory (docs/study.md states it). For a mode of angular frequency w and s = w*dt:
#   explicit Euler multiplies the mode's energy by |1 + i s|^2 = 1 + s^2 every step: unstable for
#   every dt; what the chart can show is where the growth reaches the study's blow-up mark (1e6)
#   within the probe's horizon of max(10 periods, 200 steps).
#   symplectic Euler is stable for s < 2; implicit Euler for every s.
BLOW_UP = 1e6


def horizon_steps(s):
    return max(200, math.ceil(10 * 2 * math.pi / s))


def explicit_limit(blow_up=BLOW_UP):
    """The s = w*dt at which explicit Euler's energy reaches 1 + blow_up times its start within
    the horizon, by bisection on the monotone growth (1 + s^2)^N(s)."""
    lo, hi = 1e-3, 10.0
    target = math.log1p(blow_up)
    for _ in range(200):
        mid = math.sqrt(lo * hi)
        if horizon_steps(mid) * math.log1p(mid * mid) > target:
            hi = mid
        else:
            lo = mid
    return lo


def highest_frequency(bobs, k):
    """Highest angular frequency of the study's row of unit masses (stability.h)."""
    return 2 * math.sqrt(k) * math.sin((2 * bobs - 1) * math.pi / (4 * bobs + 2))


def order_cells(rows, key, fmt):
    """"method: order" per method of one problem's rows: the observed order of `key` on the five
    finest time steps that ran ("exact" when the error is at rounding level throughout)."""
    cells = []
    for m in unique(rows, "method"):
        pts = sorted([x for x in rows if x["method"] == m and x["outcome"] == "ok" and finite(x[key])],
                     key=lambda x: x["dt"])[:5]
        if pts and max(x[key] for x in pts) < 1e-12:
            cells.append(f"{m}: exact")
            continue
        q = order_of_convergence([x["dt"] for x in pts], [x[key] for x in pts])
        cells.append(f"{m}: {fmt(q)}")
    return cells
