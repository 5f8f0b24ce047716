"""Charts of where methods break and how the energy error goes (charts.py calls them):

    damped_stability   measured largest stable dt of a damped spring against its damping ratio,
                       with the closed forms (damped_stability.csv)
    shots              shares of the random shots' outcomes, judged by energy, per method and
                       mode (robustness_shots.csv)
    energy_order       the largest energy error over a run against dt, per integrator problem,
                       with symplectic Euler's end-point error for comparison (accuracy.csv)
    newton             where implicit Euler's Newton fails on orbits (newton_failure.csv)
    newton_iterations  Newton's iterations per step against dt and stiffness, on a swinging spring
                       and on the orbits (newton_iterations.csv, newton_failure.csv)
"""
import math

import matplotlib.pyplot as plt
from matplotlib.patches import Patch
from matplotlib.ticker import ScalarFormatter

import study_data as sd


def explicit_limit(zeta):
    """w h at explicit Euler's limit on u'' = -w^2 u - 2 zeta w u' (damped_stability.h)."""
    if zeta <= 0:
        return math.nan
    return 2 * zeta if zeta <= 1 else 2 / (zeta + math.sqrt(zeta * zeta - 1))


def symplectic_limit(zeta):
    return 2 / (zeta + math.sqrt(zeta * zeta + 1))


def chart_damped(data_dir, style, save):
    rows = sd.load(data_dir, "damped_stability")
    fig, ax = plt.subplots(figsize=(8.5, 5.6))
    zs = sorted(set(r["zeta"] for r in rows))
    zmax = max(zs)
    dense = [0] + [10 ** (-2.5 + i * (math.log10(zmax * 1.5) + 2.5) / 300) for i in range(301)]
    ax.plot(dense, [explicit_limit(z) for z in dense], color=style("explicit-euler")[0], lw=1.2, ls="--",
            label="closed form, explicit Euler: ω dt = 2ζ (ζ ≤ 1), 2/(ζ + √(ζ² − 1)) (ζ > 1)")
    ax.plot(dense, [symplectic_limit(z) for z in dense], color=style("symplectic-euler")[0], lw=1.2, ls="--",
            label="closed form, symplectic Euler: ω dt = 2/(ζ + √(ζ² + 1))")
    top = max(r["grid_max_dt"] * r["omega"] for r in rows)
    bottom = min(r["grid_min_dt"] * r["omega"] for r in rows)
    for integ in ("explicit-euler", "symplectic-euler"):
        color, marker = style(integ)
        pts = [r for r in rows if r["integrator"] == integ and r["capped"] == 0 and r["none_stable"] == 0]
        lo = [r["largest_stable_dt"] * r["omega"] for r in pts]
        hi = [r["smallest_unstable_dt"] * r["omega"] for r in pts]
        ax.errorbar([r["zeta"] for r in pts], lo, yerr=[[0] * len(lo), [h - l for h, l in zip(hi, lo)]], ls="none",
                    color=color, marker=marker, ms=6, capsize=2,
                    label=f"{integ}: measured (largest stable dt; bar: up to the first unstable one)")
        none = [r for r in rows if r["integrator"] == integ and r["none_stable"] == 1]
        if none:
            ax.plot([r["zeta"] for r in none], [bottom] * len(none), ls="none", color=color, marker="v", ms=8,
                    label=f"{integ}: unstable even at the smallest dt tried (ω dt = {bottom:g})")
    implicit = [r for r in rows if r["integrator"] in ("implicit-euler", "linearized-implicit-euler")]
    if implicit and all(r["capped"] == 1 for r in implicit):
        ax.plot(sorted(set(r["zeta"] for r in implicit)), [top] * len(set(r["zeta"] for r in implicit)), ls="none",
                color=style("implicit-euler")[0], marker="^", ms=8,
                label=f"implicit and linearized implicit Euler: stable at every dt tried (up to ω dt = {top:.0f})")
    ax.set_xscale("symlog", linthresh=0.02)
    ax.set_yscale("log")
    ax.set_xlim(-0.002, zmax * 1.5)
    ax.set_ylim(bottom / 1.5, top * 1.8)
    ax.set_xlabel("damping ratio ζ = γ/ω (b = 2ζ√(k m))")
    ax.set_ylabel("largest stable ω·dt")
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.13), fontsize=7.5, ncol=1)
    omega = rows[0]["omega"]
    ax.set_title(f"Damped spring u'' = −ω²u − 2γu' (ω = {omega:g} rad/s): the largest stable step, measured by "
                 f"bisection\non a grid of ratio {rows[0]['grid_ratio']:.2f} (each probe: the simulator, "
                 f"{int(rows[0]['steps'])} steps), against the closed forms", fontsize=9)
    fig.tight_layout()
    save(fig, data_dir, "damped_stability")


SHOT_OUTCOMES = [("bounced", "#66bb6a"), ("gained energy", "#e53935"), ("lost energy", "#8e24aa"),
                 ("tunnelled", "#fb8c00"), ("overlapped", "#6d4c41"), ("froze", "#1e88e5"), ("unstable", "#424242")]


def chart_shots(data_dir, save):
    rows = sd.load(data_dir, "robustness_shots")
    targets = sd.unique(rows, "target")
    methods = sd.unique(rows, "method")
    fig, axes = plt.subplots(1, len(targets), figsize=(3.4 * len(targets) + 1.5, 4.6), squeeze=False, sharey=True)
    labels = [f"{m} ({mode})" for m in methods for mode in ("default", "compat")]
    for ax, t in zip(axes.flat, targets):
        for i, (m, mode) in enumerate((m, mode) for m in methods for mode in ("default", "compat")):
            mine = [r for r in rows if r["target"] == t and r["method"] == m and r["mode"] == mode]
            left = 0.0
            for o, color in SHOT_OUTCOMES:
                share = 100 * sum(1 for r in mine if r["outcome"] == o) / max(1, len(mine))
                ax.barh(i, share, left=left, color=color, height=0.75, hatch="//" if mode == "compat" else None,
                        edgecolor="white", lw=0.3)
                left += share
        n = sum(1 for r in rows if r["target"] == t and r["method"] == methods[0] and r["mode"] == "default")
        ax.set_title(f"{t} ({n} shots)")
        ax.set_xlim(0, 100)
        ax.set_xlabel("share of the shots [%]")
        ax.grid(axis="y", visible=False)
    ax0 = axes.flat[0]
    ax0.set_yticks(range(len(labels)))
    ax0.set_yticklabels(labels, fontsize=8)
    ax0.invert_yaxis()
    handles = [Patch(color=c, label=o) for o, c in SHOT_OUTCOMES]
    handles.append(Patch(facecolor="white", edgecolor="0.3", hatch="//", label="--compat"))
    fig.legend(handles=handles, loc="lower center", ncol=len(handles), fontsize=8, bbox_to_anchor=(0.5, -0.01))
    # Every number of the title from the shots themselves: the radii and leeway they ran with, the
    # ranges their random draws covered.
    first = rows[0]
    speeds, dts = [r["speed"] for r in rows], [r["dt"] for r in rows]
    elastic = sum(1 for r in rows if r["cor"] == 1)
    lossy = [r["cor"] for r in rows if r["cor"] != 1]
    cor = f"COR 1 ({100 * elastic / len(rows):.0f} % of shots)" + (
        f" or {min(lossy):.2g}-{max(lossy):.2g}" if lossy else "")
    fig.suptitle(f"Random shots of a disk (r = {first['disk_radius']:g} m) at thin fixed edges "
                 f"(r = {first['edge_radius']:g} m), judged by energy: bounced = ended clear on its own side with "
                 f"its energy\nwithin COR's bounds ({100 * first['tolerance']:g} % leeway); speeds "
                 f"{min(speeds):.2g}-{max(speeds):.2g} m/s, dt {min(dts):.2g}-{max(dts):.2g} s, {cor}, "
                 "symplectic Euler", fontsize=9)
    fig.tight_layout(rect=(0, 0.07, 1, 0.92))
    save(fig, data_dir, "shots")


def chart_energy_order(data_dir, style, save):
    rows = [r for r in sd.load(data_dir, "accuracy") if r["kind"] == "integrators"]
    problems = sd.unique(rows, "problem")
    fig, axes = plt.subplots(1, len(problems), figsize=(4.2 * len(problems), 4.4), squeeze=False)
    for ax, p in zip(axes.flat, problems):
        mine = [r for r in rows if r["problem"] == p]
        for m in sd.unique(mine, "method"):
            pts = sorted([r for r in mine if r["method"] == m and sd.finite(r["energy_error_max"])
                          and r["outcome"] == "ok"], key=lambda r: r["dt"])
            color, marker = style(m)
            ax.plot([r["dt"] for r in pts], [max(r["energy_error_max"], 1e-16) for r in pts], color=color,
                    marker=marker, ms=4, lw=1.2, label=f"{m}: largest over the run")
            if m == "symplectic-euler":
                ax.plot([r["dt"] for r in pts], [max(r["energy_error"], 1e-16) for r in pts], color=color, ls=":",
                        marker=marker, mfc="none", ms=4, lw=1, label=f"{m}: at the end only")
        dts = sorted(set(r["dt"] for r in mine))
        ref = [d for d in dts]
        base = min(max(r["energy_error_max"], 1e-16) for r in mine if sd.finite(r["energy_error_max"])
                   and r["outcome"] == "ok")
        for order, ls in ((1, "-"), (2, "--")):
            ax.plot(ref, [base * (d / ref[0]) ** order for d in ref], color="0.6", lw=0.8, ls=ls,
                    label=f"slope {order} (dt^{order})")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("time step dt [s]")
        ax.set_title(mine[0]["title"], fontsize=8.5)
    axes.flat[0].set_ylabel("relative energy error")
    handles, labels = axes.flat[0].get_legend_handles_labels()
    fig.legend(handles, labels, loc="lower center", ncol=4, fontsize=7.5, bbox_to_anchor=(0.5, -0.02))
    fig.suptitle("Energy error against dt: the largest relative error over the run (solid); for symplectic Euler also "
                 "the error at the last step (dotted), which an oscillating error makes erratic", fontsize=9)
    fig.tight_layout(rect=(0, 0.1, 1, 0.94))
    save(fig, data_dir, "energy_order")



def chart_audit(data_dir, style, save):
    rows = sd.load(data_dir, "audit_series")
    problems = sd.unique(rows, "problem")
    quantities = [("energy_error", "energy"), ("momentum_error", "momentum"), ("angmom_error", "angular momentum")]
    fig, axes = plt.subplots(len(quantities), len(problems), figsize=(4.0 * len(problems), 2.7 * len(quantities)),
                             squeeze=False, sharex="col")
    for j, p in enumerate(problems):
        mine = [r for r in rows if r["problem"] == p]
        for i, (key, name) in enumerate(quantities):
            ax = axes[i][j]
            for m in sd.unique(mine, "method"):
                pts = [r for r in mine if r["method"] == m and sd.finite(r[key])]
                color, marker = style(m)
                ax.plot([r["time"] for r in pts], [max(r[key], 1e-16) for r in pts], color=color, lw=1.1,
                        ls="--" if m.startswith("linearized") else "-", label=m)
                failed = [r for r in mine if r["method"] == m and r["outcome"] != "ok"]
                if failed and pts:
                    ax.plot([pts[-1]["time"]], [max(pts[-1][key], 1e-16)], marker="x", color=color, ms=7)
            ax.set_yscale("log")
            ax.set_ylim(1e-17, None)
            if i == 0:
                ax.set_title(f"{mine[0]['title']}\ndt = {mine[0]['dt']:g} s", fontsize=8.5)
            if j == 0:
                ax.set_ylabel(f"{name} error (relative)")
            if i == len(quantities) - 1:
                ax.set_xlabel("time [s]")
    handles, labels = axes[0][0].get_legend_handles_labels()
    handles.append(plt.Line2D([], [], ls="none", marker="x", color="0.3"))
    labels.append("run failed here")
    fig.legend(handles, labels, loc="lower center", ncol=5, fontsize=8, bbox_to_anchor=(0.5, -0.01))
    fig.suptitle("Audit over time: energy, momentum and angular momentum against the exact motion, per problem and "
                 "integrator (errors at 1e-16 are rounding; the anchored springs' angular momentum about the anchor "
                 "is exactly 0)", fontsize=9)
    fig.tight_layout(rect=(0, 0.04, 1, 0.96))
    save(fig, data_dir, "audit")


def tunnel_speed(row):
    """(radii + thickness)·√(k/m) of a robustness.csv row: by energy balance, a faster disk compresses
    the penalty spring by more than the thickness plus the radii and goes through."""
    return (row["disk_radius"] + row["edge_radius"] + row["thickness"]) * math.sqrt(row["penalty_k"] / row["disk_mass"])


def contact_limit(row):
    """2·√(m/k): the largest stable step of the penalty contact spring (symplectic Euler's 2/ω)."""
    return 2 * math.sqrt(row["disk_mass"] / row["penalty_k"])


def penalty_limits(rows):
    """Per penalty stiffness and impact speed (robustness.csv, head-on shots at a thin edge): the
    largest dt at which the run stayed stable and the largest at which the disk bounced."""
    out = {}
    for m in sd.unique(rows, "method"):
        mine = [r for r in rows if r["method"] == m]
        k = mine[0]["k"]
        speeds = sorted(set(r["speed"] for r in mine))
        stable, bounced = [], []
        for v in speeds:
            cells = sorted([r for r in mine if r["speed"] == v], key=lambda r: r["dt"])
            # the largest dt below which every dt tried was stable (bounced) as well
            s = b = math.nan
            for r in cells:
                if r["outcome"] == "unstable":
                    break
                s = r["dt"]
            for r in cells:
                if r["outcome"] != "bounced":
                    break
                b = r["dt"]
            stable.append(s)
            bounced.append(b)
        out[m] = (k, speeds, stable, bounced)
    return out


def chart_penalty_limits(data_dir, style, save):
    rows = [r for r in sd.load(data_dir, "robustness") if r["collision"] == "penalty"]
    limits = penalty_limits(rows)
    dts = sorted(set(r["dt"] for r in rows))
    fig, ax = plt.subplots(figsize=(8.5, 5.4))
    for m, (k, speeds, stable, bounced) in limits.items():
        color, marker = style(m)
        first = next(r for r in rows if r["method"] == m)
        ax.plot(speeds, bounced, color=color, marker=marker, ms=5, lw=1.4, label=f"{m}: largest dt that bounced")
        ax.plot(speeds, stable, color=color, marker=marker, mfc="none", ms=5, lw=0.9, ls=":",
                label=f"{m}: largest dt that stayed stable")
        ax.axvline(tunnel_speed(first), color=color, lw=0.8, ls="--")
        ax.axhline(contact_limit(first), color=color, lw=0.8, ls="-.")
    ax.plot([], [], color="0.4", ls="--", lw=0.8, label="theory: goes through above v = (radii + thickness)·√(k/m)")
    ax.plot([], [], color="0.4", ls="-.", lw=0.8, label="theory: contact spring stable for dt < 2·√(m/k)")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_ylim(dts[0] / 1.5, dts[-1] * 1.5)
    ax.set_xlabel("impact speed [m/s]")
    ax.set_ylabel("time step dt [s] (grid of quarter decades; no point: not even the smallest dt)")
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.13), fontsize=7.5, ncol=2)
    ax.set_title("Penalty contact (head-on at a thin edge, unit mass): the largest step that bounced and the largest "
                 "that stayed stable,\nagainst impact speed and stiffness k", fontsize=9)
    fig.tight_layout()
    save(fig, data_dir, "penalty_limits")


def chart_newton(data_dir, save):
    import os
    if not os.path.exists(os.path.join(data_dir, "newton_failure.csv")):
        return
    rows = sd.load(data_dir, "newton_failure")
    setup = {(r["problem"], r["name"]): r["value"] for r in sd.load(data_dir, "problems")}
    blow_up = f"energy x{setup[('study', 'blow_up')]:.0e}".replace("e+0", "e")
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.4), squeeze=False)
    for ax, integ in zip(axes.flat, ("implicit-euler", "linearized-implicit-euler")):
        mine = [r for r in rows if r["integrator"] == integ]
        for outcome, marker, color in (("ok", "o", "#66bb6a"), ("solver-failure", "X", "#e53935"),
                                       ("energy-blow-up", "*", "#424242")):
            pts = [r for r in mine if r["outcome"] == outcome]
            if pts:
                sc = ax.scatter([r["eccentricity"] for r in pts], [r["dt_omega"] for r in pts], marker=marker, s=60,
                                c=[r["min_separation"] / r["periapsis"] for r in pts], cmap="viridis", vmin=0, vmax=1,
                                edgecolors=color, linewidths=1.5, label={"ok": "ran to the end",
                                                                          "solver-failure": "Newton did not converge",
                                                                          "energy-blow-up": blow_up}[outcome])
        ax.set_yscale("log")
        ax.set_xlabel(f"eccentricity e (started at apoapsis r = {rows[0]['apoapsis']:g})")
        ax.set_ylabel("dt · ω_p,  ω_p = √(μ / r_p³) at periapsis")
        ax.set_title(integ, fontsize=9)
        ax.legend(fontsize=7.5, loc="upper left")
    fig.colorbar(sc, ax=axes.ravel().tolist(), label="closest approach / true periapsis")
    fig.suptitle(f"Implicit Euler on two-body orbits ({rows[0]['periods']:g} periods): where Newton fails against dt "
                 "and the periapsis's "
                 "stiffness; colour: how far the orbit had fallen inside its periapsis", fontsize=9)
    save(fig, data_dir, "newton")


def chart_newton_iterations(data_dir, save):
    import os
    if not os.path.exists(os.path.join(data_dir, "newton_iterations.csv")):
        return
    rows = sd.load(data_dir, "newton_iterations")
    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4.4))
    spring = [r for r in rows if r["rest_length"] > 0]
    colors = plt.cm.viridis([i / max(1, len(sd.unique(spring, "k")) - 1) * 0.9
                             for i in range(len(sd.unique(spring, "k")))])
    for color, k in zip(colors, sd.unique(spring, "k")):
        mine = sorted([r for r in spring if r["k"] == k], key=lambda r: r["dt"])
        left.plot([r["dt"] for r in mine], [r["mean_iterations"] for r in mine], "o-", color=color,
                  label=f"k = {k:g} (ω = {mine[0]['omega']:.3g}/s): mean")
        left.plot([r["dt"] for r in mine], [r["max_iterations"] for r in mine], "v:", color=color, ms=4)
        failed = [r for r in mine if r["outcome"] != "ok"]
        if failed:
            left.scatter([r["dt"] for r in failed], [r["max_iterations"] for r in failed], marker="X", s=80,
                         color="#e53935", zorder=5)
    control = [r for r in rows if r["rest_length"] == 0]
    if control:
        left.plot(sorted(sd.unique(control, "dt")), [max(r["max_iterations"] for r in control if r["dt"] == d)
                                                      for d in sorted(sd.unique(control, "dt"))],
                  "s--", color="0.5", label="rest length 0 (linear), most over every k")
    left.plot([], [], "kv:", ms=4, label="most in one step")
    left.set_xscale("log")
    left.set_xlabel("time step dt [s]")
    left.set_ylabel("Newton iterations per step")
    left.legend(fontsize=7, loc="upper left")
    left.set_title(f"A particle between two fixed anchors on springs of rest length "
                   f"{', '.join(f'{x:g}' for x in sd.unique(spring, 'rest_length'))} (nonlinear)", fontsize=9)
    if os.path.exists(os.path.join(data_dir, "newton_failure.csv")):
        orbits = [r for r in sd.load(data_dir, "newton_failure") if r["integrator"] == "implicit-euler"]
        es = sd.unique(orbits, "eccentricity")
        for i, e in enumerate(es):
            mine = sorted([r for r in orbits if r["eccentricity"] == e], key=lambda r: r["dt_omega"])
            color = plt.cm.plasma(i / max(1, len(es) - 1) * 0.85)
            right.plot([r["dt_omega"] for r in mine], [r["mean_iterations"] for r in mine], "o-", color=color,
                       label=f"e = {e:.2f}: mean until the end or the failure")
            failed = [r for r in mine if r["outcome"] == "solver-failure"]
            right.scatter([r["dt_omega"] for r in failed], [r["max_iterations"] for r in failed], marker="X", s=60,
                          color=color, edgecolors="#e53935")
        right.scatter([], [], marker="X", color="0.5", edgecolors="#e53935", label="failed step (the limit)")
        right.set_xscale("log")
        right.set_yscale("log")
        right.yaxis.set_major_formatter(ScalarFormatter())
        right.set_xlabel("dt · ω_p,  ω_p = √(μ / r_p³) at periapsis")
        right.set_ylabel("Newton iterations per step")
        right.legend(fontsize=7, loc="center left")
        right.set_title(f"Two-body orbits ({orbits[0]['periods']:g} periods)", fontsize=9)
    fig.suptitle("Implicit Euler: Newton iterations per step against dt and stiffness (solid: mean over the steps "
                 "done; red X: the step where Newton gave up)", fontsize=9)
    fig.tight_layout()
    save(fig, data_dir, "newton_iterations")
