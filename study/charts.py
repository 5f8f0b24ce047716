#!/usr/bin/env python3
"""Charts of the study, from the CSV files fosssim-study writes.

    python3 study/charts.py DATA_DIR    writes DATA_DIR/<chart>.png and .svg

Every chart has labelled axes with units, a legend, and log scales where values span decades.
"""
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.colors import ListedColormap  # noqa: E402
from matplotlib.lines import Line2D  # noqa: E402
from matplotlib.patches import Patch  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import study_data as sd  # noqa: E402
from report import profile_parts  # noqa: E402

plt.rcParams.update({
    "svg.fonttype": "none",  # text stays text: small, searchable SVG files
    "svg.hashsalt": "fosssim-study",  # the same ids every time: regenerated files differ only in data
    "font.size": 9,
    "axes.titlesize": 10,
    "legend.fontsize": 8,
    "axes.grid": True,
    "grid.alpha": 0.3,
})

ERROR_FLOOR = 1e-16  # errors at rounding level are drawn here (a log axis has no zero)

STYLE = {  # one look per method, the same in every chart
    "explicit-euler": ("#d62728", "o"),
    "symplectic-euler": ("#1f77b4", "s"),
    "implicit-euler": ("#2ca02c", "^"),
    "linearized-implicit-euler": ("#9467bd", "v"),
    "simple": ("#d62728", "o"),
    "continuous-time": ("#1f77b4", "s"),
    "hybrid": ("#2ca02c", "^"),
    "hybrid k=0": ("#17becf", "v"),
    # The three penalty stiffnesses: three different hues and markers (not shades of one colour).
    "penalty k=1e2": ("#e377c2", "P"),
    "penalty k=1e4": ("#bcbd22", "X"),
    "penalty k=1e6": ("#8c564b", "D"),
}


def style(method):
    return STYLE.get(method, ("#7f7f7f", "x"))


def save(fig, out_dir, name):
    for ext in ("png", "svg"):
        # No creation date in the files, so that a regeneration with the same data changes nothing.
        metadata = {"Date": None} if ext == "svg" else {"Software": None}
        fig.savefig(os.path.join(out_dir, f"{name}.{ext}"), dpi=80, bbox_inches="tight", metadata=metadata)
    plt.close(fig)


# ---- Chart 1: accuracy against cost ----------------------------------------------------------

def accuracy_panel(ax, rows):
    methods = sd.unique(rows, "method")
    points, unstable = [], {}
    for m in methods:
        mine = sorted([r for r in rows if r["method"] == m], key=lambda r: -r["dt"])
        good = [r for r in mine if r["outcome"] == "ok" and sd.finite(r["wall_per_sim_s"]) and sd.finite(r["error"])]
        bad = [r for r in mine if r["outcome"] != "ok"]
        if bad:
            unstable[m] = bad
        xs = [r["wall_per_sim_s"] for r in good]
        ys = [max(r["error"], ERROR_FLOOR) for r in good]
        color, marker = style(m)
        ax.plot(xs, ys, color=color, marker=marker, ms=4, lw=1.2, label=m)
        # The spread of the repeated timings: from the least (the point) to the median repeat.
        if good and "wall_s_median" in good[0]:
            slow = [r["wall_s_median"] / r["sim_time"] if sd.finite(r["wall_s_median"]) else x
                    for r, x in zip(good, xs)]
            ax.errorbar(xs, ys, xerr=[[0] * len(xs), [max(0.0, s - x) for s, x in zip(slow, xs)]], fmt="none",
                        ecolor=color, elinewidth=0.7, capsize=1.5, alpha=0.7)
        # dt at both ends of the line (the sweep runs between them, in the order of the table's dts)
        for x, y, r in list(zip(xs, ys, good))[:: max(1, len(good) - 1)][:2]:
            ax.annotate(f"{r['dt']:g}", (x, y), textcoords="offset points", xytext=(3, 3), fontsize=6, color=color)
        points += [(x, y, r["dt"], m) for x, y, r in zip(xs, ys, good)]
    front = sd.pareto([(p[0], p[1]) for p in points])
    fx = [points[i][0] for i in front]
    fy = [points[i][1] for i in front]
    ax.step(fx, fy, where="post", color="black", lw=1.0, ls="--", zorder=1)
    ax.plot(fx, fy, ls="none", marker="o", ms=9, mfc="none", mec="black", mew=1.0, zorder=5)
    ax.set_xscale("log")
    ax.set_yscale("log")
    title = rows[0]["title"]
    if unstable:
        parts = []
        for m, bad in unstable.items():
            parts.append(f"{m} at dt = {', '.join('%g' % r['dt'] for r in bad)} ({bad[0]['outcome']})")
        title += "\nfailed, not drawn: " + "; ".join(parts)
    ax.set_title(title, fontsize=9)
    ax.set_xlabel("wall time per simulated second [s]")
    ax.set_ylabel(rows[0]["error_label"])
    lo = min(fy) if fy else ERROR_FLOOR
    if lo <= ERROR_FLOOR * 1.0001:
        ax.axhline(ERROR_FLOOR, color="0.5", lw=0.8, ls=":")


def chart_accuracy(data_dir, kind, name, shape):
    rows = [r for r in sd.load(data_dir, "accuracy") if r["kind"] == kind]
    problems = sd.unique(rows, "problem")
    fig, axes = plt.subplots(*shape, figsize=(5.2 * shape[1], 4.2 * shape[0]), squeeze=False)
    for ax, p in zip(axes.flat, problems):
        accuracy_panel(ax, [r for r in rows if r["problem"] == p])
    for ax in list(axes.flat)[len(problems):]:
        ax.axis("off")
    handles = [Line2D([], [], color=style(m)[0], marker=style(m)[1], label=m) for m in sd.unique(rows, "method")]
    handles.append(Line2D([], [], ls="--", color="black", marker="o", mfc="none", label="Pareto front"))
    what = "integrator" if kind == "integrators" else "collision method (with symplectic Euler)"
    fig.legend(handles=handles, loc="upper center", ncol=min(len(handles), 5), bbox_to_anchor=(0.5, 0.965))
    fig.suptitle(f"Accuracy against cost, one line per {what}. Each line runs from the largest dt (left, cheap,\n"
                 f"its dt written at the point) to the smallest (right, dt written too); circled points form the Pareto "
                 f"front; errors at {ERROR_FLOOR:g} are rounding. Bars: from the fastest repeat of a timed run "
                 f"(the point) to the median one.",
                 y=1.0, fontsize=10)
    fig.tight_layout(rect=(0, 0, 1, 0.93 if shape[0] > 1 else 0.88))
    save(fig, data_dir, name)


# ---- Chart 2: stability, energy order and the random shots are in charts_limits.py ----------


# ---- Chart 3: collision robustness -----------------------------------------------------------

OUTCOMES = ["bounced", "tunnelled", "stuck", "unstable"]
OUTCOME_COLORS = ["#66bb6a", "#e53935", "#fb8c00", "#424242"]


def edges(values):
    """Cell edges halfway (in log) between sorted grid values."""
    logs = [math.log10(v) for v in values]
    mids = [(a + b) / 2 for a, b in zip(logs, logs[1:])]
    first, last = 2 * logs[0] - mids[0], 2 * logs[-1] - mids[-1]
    return [10 ** x for x in [first] + mids + [last]]


def chart_robustness(data_dir):
    rows = sd.load(data_dir, "robustness")
    methods = sd.unique(rows, "method")
    speeds = sorted(set(r["speed"] for r in rows))
    dts = sorted(set(r["dt"] for r in rows))
    cols = 4
    nrows = math.ceil((len(methods) + 1) / cols)
    fig, axes = plt.subplots(nrows, cols, figsize=(3.6 * cols, 3.3 * nrows), squeeze=False)
    cmap = ListedColormap(OUTCOME_COLORS)
    for ax, m in zip(axes.flat, methods):
        grid = [[math.nan] * len(dts) for _ in speeds]
        for r in rows:
            if r["method"] == m:
                grid[speeds.index(r["speed"])][dts.index(r["dt"])] = OUTCOMES.index(r["outcome"])
        # Rasterised in the SVG too: a few hundred cells as vector paths would make it large.
        ax.pcolormesh(edges(dts), edges(speeds), grid, cmap=cmap, vmin=-0.5, vmax=3.5, edgecolors="white", lw=0.3,
                      rasterized=True)
        band = 2 * (rows[0]["disk_radius"] + rows[0]["edge_radius"])  # the contact band's thickness
        ax.plot(dts, [band / d for d in dts], color="black", lw=1, ls="--")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlim(edges(dts)[0], edges(dts)[-1])
        ax.set_ylim(edges(speeds)[0], edges(speeds)[-1])
        ax.set_title(m)
        ax.set_xlabel("time step dt [s]")
        ax.set_ylabel("disk speed [m/s]")
        ax.grid(False)
    legend_ax = list(axes.flat)[len(methods)]
    for ax in list(axes.flat)[len(methods):]:
        ax.axis("off")
    handles = [Patch(color=c, label=o) for o, c in zip(OUTCOMES, OUTCOME_COLORS)]
    band = 2 * (rows[0]["disk_radius"] + rows[0]["edge_radius"])
    handles.append(Line2D([], [], color="black", ls="--",
                          label=f"speed x dt = {band:g} m\n(one step crosses the\ncontact band)"))
    legend_ax.legend(handles=handles, loc="center", title="outcome at the end")
    cors = " or ".join(f"{c:g}" for c in sorted(set(r["cor"] for r in rows)))
    fig.suptitle(f"A disk (r = {rows[0]['disk_radius']:g} m) thrown at a thin fixed edge "
                 f"(r = {rows[0]['edge_radius']:g} m), COR {cors}: what became of it", fontsize=10)
    fig.tight_layout(rect=(0, 0, 1, 0.96))
    save(fig, data_dir, "robustness")


# Where chart_penalty_depth draws what has no depth (chart positions, not measurements).
THROUGH_AT, UNSTABLE_AT, FLOOR_AT = 0.06, 0.1, 1e-6


def chart_penalty_depth(data_dir):
    rows = [r for r in sd.load(data_dir, "robustness") if r["collision"] == "penalty"]
    methods = sd.unique(rows, "method")
    dts = sorted(set(r["dt"] for r in rows))
    shown = [d for d in dts if abs(math.log10(d) - round(math.log10(d))) < 1e-9]  # whole decades
    speeds = sorted(set(r["speed"] for r in rows))
    reach, thickness = rows[0]["disk_radius"] + rows[0]["edge_radius"], rows[0]["thickness"]
    fig, axes = plt.subplots(1, len(methods), figsize=(4.4 * len(methods), 4.0), squeeze=False, sharey=True)
    cmap = plt.get_cmap("viridis")
    for ax, m in zip(axes.flat, methods):
        k = [r["k"] for r in rows if r["method"] == m][0]
        # Energy balance of a unit mass against the fixed edge: the penalty spring, which starts
        # `thickness` before contact, is compressed by v sqrt(m/k) at the turn; the disk overlaps the
        # edge by that minus the thickness, and goes through once the compression reaches
        # reach + thickness (its centre crosses the edge's line).
        vmax = (reach + thickness) * math.sqrt(k)
        vs = [v for v in (speeds[0] * (speeds[-1] / speeds[0]) ** (i / 200) for i in range(201))
              if thickness * math.sqrt(k) < v < vmax]
        ax.plot(vs, [v / math.sqrt(k) - thickness for v in vs], color="black", lw=1.5, alpha=0.5,
                label="energy balance: v$\\sqrt{m/k}$ - thickness")
        ax.axvline(vmax, color="#e53935", lw=1, ls="--", label=f"goes through above {vmax:.3g} m/s")
        for i, d in enumerate(shown):
            pts = sorted([r for r in rows if r["method"] == m and r["dt"] == d], key=lambda r: r["speed"])
            color = cmap(i / max(1, len(shown) - 1))
            bounced = [r for r in pts if r["outcome"] == "bounced"]
            ax.plot([r["speed"] for r in bounced], [max(r["max_overlap"], FLOOR_AT) for r in bounced], color=color,
                    marker="o", ms=3, lw=1, label=f"bounced, dt = {d:g} s")
            lost = [r for r in pts if r["outcome"] != "bounced"]
            ax.plot([r["speed"] for r in lost],
                    [THROUGH_AT if r["outcome"] == "tunnelled" else UNSTABLE_AT for r in lost],
                    ls="none", marker="x" if lost and lost[0]["outcome"] == "tunnelled" else "*", color=color, ms=5)
        ax.axhline(reach, color="0.3", lw=0.8, ls=":")
        ax.text(speeds[0], reach * 1.08, "centre on the edge's line", fontsize=7)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_ylim(FLOOR_AT, 1.5 * UNSTABLE_AT)
        ax.set_title(f"{m} (thickness {thickness:g} m)")
        ax.set_xlabel("disk speed [m/s]")
        ax.legend(loc="lower right", fontsize=6.5)
    axes.flat[0].set_ylabel("deepest overlap with the edge at a step end [m]")
    floor = f"{FLOOR_AT:g}".replace("e-0", "e-")
    fig.suptitle(f"Penalty: how deep a bouncing disk sinks into the thin edge (x at {THROUGH_AT:g} m: went through; "
                 f"* at {UNSTABLE_AT:g} m: unstable; {floor} or less drawn at {floor})", fontsize=10)
    fig.tight_layout(rect=(0, 0, 1, 0.93))
    save(fig, data_dir, "penalty_depth")


# ---- Chart 4: hybrid cost --------------------------------------------------------------------

def plot_if_any(ax, x, ys, **kw):
    """Plots only series that have data (counters some builds of the simulator do not fill)."""
    if any(sd.finite(y) for y in ys):
        ax.plot(x, ys, **kw)
        return True
    return False


def chart_hybrid(data_dir):
    rows = sd.load(data_dir, "hybrid")
    hyb = sorted([r for r in rows if r["collision"] == "hybrid"], key=lambda r: r["maxiters"])
    others = [r for r in rows if r["collision"] != "hybrid"]
    x = [r["maxiters"] for r in hyb]
    fig, axes = plt.subplots(1, 3, figsize=(15, 5.6))
    ax = axes[0]
    ax.plot(x, [100 * r["failsafe_fraction"] for r in hyb], marker="o", color="#2ca02c", label="steps that used the failsafe [%]")
    ax.set_ylabel("steps that used the failsafe [%]")
    ax.set_ylim(-3, 103)
    ax.set_title("How often a step needs the failsafe")
    passes = [r["mean_passes"] for r in hyb]
    if any(sd.finite(p) for p in passes):
        ax2 = ax.twinx()
        ax2.plot(x, passes, marker="s", color="#1f77b4", ls="--", label="impulse passes per step (right axis)")
        ax2.set_ylabel("impulse passes per step (mean)")
        ax2.grid(False)
        lines = ax.get_legend_handles_labels()[0] + ax2.get_legend_handles_labels()[0]
        ax.legend(lines, [ln.get_label() for ln in lines], loc="upper center", bbox_to_anchor=(0.5, -0.2),
                  fontsize=7)
    else:
        ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.2), fontsize=7)
    ax = axes[1]
    ax.plot(x, [r["mean_failsafe_particles"] for r in hyb], marker="o", color="#2ca02c",
            label="disks in zones per failsafe step (mean)")
    ax.plot(x, [r["most_failsafe_particles"] for r in hyb], marker="^", color="#d62728",
            label="disks in zones in one step (most)")
    plot_if_any(ax, x, [r["largest_zone"] for r in hyb], marker="s", color="#9467bd", ls="--",
                label="largest single zone (handler's count)")
    plot_if_any(ax, x, [r["mean_zones"] for r in hyb], marker="v", color="#8c564b", ls=":",
                label="zones per failsafe step (handler's count)")
    ax.set_ylim(0, hyb[0]["particles"] * 1.05)
    ax.set_ylabel("disks (or zones)")
    ax.set_title(f"Impact zones ({int(hyb[0]['particles'])} disks; in a zone = moved by the failsafe)")
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.2), ncol=1, fontsize=7)
    ax = axes[2]
    ax.plot(x, [r["us_per_step"] for r in hyb], marker="o", color="black", label="hybrid: whole step")
    phases = [("integrate_us", "hybrid: integrator + forces"), ("narrow_us", "hybrid: narrow phase"),
              ("response_us", "hybrid: impulses"), ("failsafe_us", "hybrid: failsafe")]
    for (key, label), c in zip(phases, ["#7f7f7f", "#1f77b4", "#ff7f0e", "#2ca02c"]):
        # The default mode's response time includes its failsafe (report.nested_failsafe): shown without it.
        own = lambda r: r[key] - r["failsafe_us"] if key == "response_us" and r[key] >= r["failsafe_us"] > 0 else r[key]  # noqa: E731
        ys = [own(r) if own(r) > 0 else math.nan for r in hyb]
        plot_if_any(ax, x, ys, marker=".", color=c, label=label)
    for r, ls in zip(others, ["--", ":", "-.", (0, (5, 1)), (0, (1, 3))]):
        ax.axhline(r["us_per_step"], color="0.4", ls=ls, lw=0.9, label=f"{r['method']} (same pile, for comparison)")
    ax.set_yscale("log")
    ax.set_ylabel("wall time per step [µs]")
    ax.set_title(f"Cost per step (dt = {hyb[0]['dt']:g} s)")
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.2), ncol=2, fontsize=7)
    for ax in axes:
        ax.set_xscale("symlog", linthresh=1)
        ax.set_xlim(-0.3, max(x) * 1.3)
        ax.set_xticks(x)
        ax.set_xticklabels([f"{int(v)}" for v in x])
        ax.set_xlabel("maxiters (impulse events per particle and step before the failsafe)")
    fig.suptitle(f"Hybrid handler (default mode) on a dense pile: {int(hyb[0]['particles'])} disks dropped into a box, "
                 f"COR {hyb[0]['cor']:g}, {hyb[0]['steps'] * hyb[0]['dt']:g} s", fontsize=10)
    fig.tight_layout(rect=(0, 0, 1, 0.94))
    save(fig, data_dir, "hybrid")


# ---- Chart 5: where the time goes ------------------------------------------------------------

PHASES = [("forces_us", "force evaluation", "#8c564b"), ("jacobians_us", "force Jacobians", "#e377c2"),
          ("solve_us", "integrator (solve, vectors)", "#7f7f7f"), ("broad_us", "broad phase", "#bcbd22"),
          ("narrow_us", "narrow phase (CCD)", "#1f77b4"), ("response_us", "response", "#ff7f0e"),
          ("failsafe_us", "failsafe", "#2ca02c"), ("collision_other_us", "rest of the step (collision handling not itemised, state copy, checks)", "#aec7e8")]


def chart_profile(data_dir):
    rows = sd.load(data_dir, "profile")
    fig, ax = plt.subplots(figsize=(11, 0.42 * len(rows) + 1.6))
    labels = [f"{r['scene']} — {r['method']}" for r in rows]
    for i, r in enumerate(rows):
        parts = profile_parts(r)  # the failsafe taken out of the default mode's response
        total = sum(parts[k] for k, _, _ in PHASES)
        left = 0.0
        for key, _, color in PHASES:
            v = parts[key]
            share = 100 * v / total if total > 0 else 0
            ax.barh(i, share, left=left, color=color, height=0.7)
            left += share
        ax.text(101, i, f"{r['total_us']:.3g} µs", va="center", fontsize=8)
    ax.set_yticks(range(len(rows)))
    ax.set_yticklabels(labels)
    ax.invert_yaxis()
    ax.set_xlim(0, 112)
    ax.set_xlabel("share of the step's wall time [%] (the step's total per step on the right)")
    ax.grid(axis="y", visible=False)
    ax.legend(handles=[Patch(color=c, label=l) for _, l, c in PHASES], loc="upper center",
              bbox_to_anchor=(0.4, -0.06), ncol=3, fontsize=8)
    ax.set_title("Where a step's time goes, per scene (forces timed by wrapping them; the rest from the simulator's "
                 "own phase timings)")
    save(fig, data_dir, "profile")


def main(argv):
    data_dir = argv[1] if len(argv) > 1 else "docs/study"
    chart_accuracy(data_dir, "integrators", "accuracy_integrators", (2, 2))
    chart_accuracy(data_dir, "collisions", "accuracy_collisions", (2, 3))
    import charts_limits  # after plt's settings above, which it shares
    charts_limits.chart_damped(data_dir, style, save)
    charts_limits.chart_shots(data_dir, save)
    charts_limits.chart_energy_order(data_dir, style, save)
    charts_limits.chart_penalty_limits(data_dir, style, save)
    charts_limits.chart_newton(data_dir, save)
    charts_limits.chart_newton_iterations(data_dir, save)
    if os.path.exists(os.path.join(data_dir, "audit_series.csv")):
        charts_limits.chart_audit(data_dir, style, save)
    chart_robustness(data_dir)
    chart_penalty_depth(data_dir)
    chart_hybrid(data_dir)
    chart_profile(data_dir)
    if os.path.exists(os.path.join(data_dir, "contacts_series.csv")):
        import charts_contacts  # after plt's settings above, which it shares
        charts_contacts.chart_contacts(data_dir)
        charts_contacts.chart_contact_outcomes(data_dir)
    print(f"charts: written to {data_dir}")


if __name__ == "__main__":
    main(sys.argv)
