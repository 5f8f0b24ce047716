"""docs/study.md's parts on limits and energy (report.py calls them): the damped spring's measured
stability limits against their closed forms, the random shots judged by energy, the order of the
energy error measured over the whole run, and the explanations of the accuracy section's extremes.
Every number here comes from the CSV files; every verdict (matches or not, bounced or not) is chosen
by the measurement.
"""
import math

import study_data as sd
from charts_limits import explicit_limit, symplectic_limit


def wilson(k, n, z=1.96):
    """95 % Wilson interval of a share k/n (the shots are random: their shares have a spread)."""
    if n == 0:
        return math.nan, math.nan
    p = k / n
    centre = (p + z * z / (2 * n)) / (1 + z * z / n)
    half = z * math.sqrt(p * (1 - p) / n + z * z / (4 * n * n)) / (1 + z * z / n)
    return max(0.0, centre - half), min(1.0, centre + half)


# ---- damped spring -------------------------------------------------------------------------------

def damped_section(data_dir, rel, r):
    """r: the report module (fmt, table, image, join). Returns (markdown, facts)."""
    rows = sd.load(data_dir, "damped_stability")
    f = {}
    by = {(x["integrator"], x["zeta"]): x for x in rows}
    zetas = sorted(set(x["zeta"] for x in rows))
    body, misses, worst = [], [], 0.0

    def measured(x):
        if x["none_stable"] == 1:
            return f"none (unstable at ω dt = {x['grid_min_dt'] * x['omega']:g})"
        if x["capped"] == 1:
            return f"every dt tried (to ω dt = {x['grid_max_dt'] * x['omega']:.0f})"
        return f"{x['largest_stable_dt'] * x['omega']:.4f} – {x['smallest_unstable_dt'] * x['omega']:.4f}"

    for z in zetas:
        cells = [f"{z:g}"]
        for integ in ("explicit-euler", "symplectic-euler"):
            x = by.get((integ, z))
            if not x:
                cells += ["—", "—"]
                continue
            exact = x["closed_form_dt"] * x["omega"] if sd.finite(x["closed_form_dt"]) else math.nan
            cells += [measured(x), f"{exact:.4f}" if sd.finite(exact) else "no limit (never stable)"]
            if sd.finite(exact) and x["capped"] == 0 and x["none_stable"] == 0:
                lo, hi = x["largest_stable_dt"] * x["omega"], x["smallest_unstable_dt"] * x["omega"]
                if abs(lo - exact) > hi - lo:
                    misses.append(f"{integ} at ζ = {z:g}")
                worst = max(worst, abs(lo - exact) / exact)
            elif not sd.finite(exact) and x["none_stable"] == 0:
                misses.append(f"{integ} at ζ = {z:g} (stable somewhere, theory says never)")
        imp = [by.get((i, z)) for i in ("implicit-euler", "linearized-implicit-euler")]
        cells.append("every dt tried" if all(x and x["capped"] == 1 for x in imp) else
                     "; ".join(measured(x) for x in imp if x))
        body.append(cells)
    ratio = rows[0]["grid_ratio"]
    out = [r.image(rel, "damped_stability", "largest stable dt of a damped spring against its damping"),
           r.table(["ζ", "explicit Euler: measured ω dt (stable – first unstable)", "explicit: closed form",
                    "symplectic Euler: measured", "symplectic: closed form", "both implicit methods"], body)]
    f["damped_grid"] = f"{100 * (ratio - 1):.0f} %"
    f["damped_steps"] = int(rows[0]["steps"])
    f["damped_omega"] = f"{rows[0]['omega']:g}"
    f["damped_top"] = f"{rows[0]['grid_max_dt'] * rows[0]['omega']:.0f}"
    f["damped_bottom"] = f"{rows[0]['grid_min_dt'] * rows[0]['omega']:g}"
    f["damped_match"] = (f"**Every measured limit is within one grid step of its closed form** (the largest "
                         f"difference: {100 * worst:.2f} % of the limit, against a grid step of "
                         f"{f['damped_grid']})" if not misses else
                         f"**The measured limits do not all match the closed forms**: {r.join(misses)}")
    und = by.get(("explicit-euler", 0.0))
    f["damped_explicit_undamped"] = (f"undamped, explicit Euler was unstable even at the smallest step tried "
                                     f"(ω dt = {f['damped_bottom']})" if und and und["none_stable"] == 1 else
                                     "undamped, explicit Euler held at some step (see the table)")
    crit = by.get(("symplectic-euler", 1.0))
    f["symplectic_critical"] = (f"{crit['largest_stable_dt'] * crit['omega']:.2f}/ω" if crit and crit["capped"] == 0
                                and crit["none_stable"] == 0 else "—")
    f["symplectic_critical_exact"] = f"{symplectic_limit(1.0):.3f}"
    return "\n\n".join(out), f


# ---- random shots --------------------------------------------------------------------------------

OUTCOMES = ("bounced", "gained energy", "lost energy", "tunnelled", "overlapped", "froze", "unstable")


def shots_section(data_dir, rel, r):
    rows = sd.load(data_dir, "robustness_shots")
    f = {}
    targets = sd.unique(rows, "target")
    methods = sd.unique(rows, "method")
    body = []
    summary = {}
    for m in methods:
        for mode in ("default", "compat"):
            mine = [x for x in rows if x["method"] == m and x["mode"] == mode]
            n = len(mine)
            counts = {o: sum(1 for x in mine if x["outcome"] == o) for o in OUTCOMES}
            lo, hi = wilson(counts["bounced"], n)
            gains = [x["energy_ratio"] for x in mine if x["outcome"] == "gained energy"]
            per_target = {t: sum(1 for x in mine if x["target"] == t and x["outcome"] != "bounced") for t in targets}
            summary[(m, mode)] = (counts, n, gains, per_target)
            body.append([m, mode, f"{counts['bounced']}/{n} ({100 * lo:.0f}–{100 * hi:.0f} %)"] +
                        [str(counts[o]) if counts[o] else "·" for o in OUTCOMES[1:]] +
                        [f"×{max(gains):.3g}" if gains else "—"] +
                        [str(per_target[t]) for t in targets])
    n_target = sum(1 for x in rows if x["method"] == methods[0] and x["mode"] == "default" and x["target"] == targets[0])
    out = [r.image(rel, "shots", "outcomes of random shots at thin edges, by energy"),
           r.table(["method", "mode", "bounced within COR's bounds (95 % interval)"] + list(OUTCOMES[1:]) +
                   ["largest energy gain E/E0"] + [f"not bounced: {t}" for t in targets], body)]
    f["shots_per_target"] = n_target
    f["shots_total"] = n_target * len(targets)
    f["shots_targets"] = r.join(targets)
    perfect = [(m, mode) for (m, mode), (c, n, _, _) in summary.items() if c["bounced"] == n]
    words = []
    for mode in ("default", "compat"):
        ok = [m for (m, md) in perfect if md == mode]
        if ok:
            words.append(f"{'in the default mode' if mode == 'default' else 'with `--compat`'} "
                         f"{r.join(f'`{m}`' for m in ok)} bounced within COR's bounds in all "
                         f"{f['shots_total']} shots")
    f["shots_default_perfect"] = [m for (m, md) in perfect if md == "default"]
    f["shots_perfect"] = ("; ".join(words) + ".") if words else "No method bounced within COR's bounds in every shot."
    fails = []
    for (m, mode), (c, n, gains, per_target) in summary.items():
        if c["bounced"] == n:
            continue
        parts = [f"{o} {c[o]}" for o in OUTCOMES[1:] if c[o]]
        worst = max(per_target, key=per_target.get)
        fails.append(f"`{m}`{' (--compat)' if mode == 'compat' else ''}: {', '.join(parts)} of {n}"
                     + (f", energy up to ×{max(gains):.3g}" if gains else "") + f"; most at the {worst}")
    f["shots_failures"] = "\n".join(f"  - {x}" for x in fails)
    # The default mode against --compat for the same method: what the course's formulation adds.
    diff = []
    for m in methods:
        d, c = summary.get((m, "default")), summary.get((m, "compat"))
        if d and c and c[0]["gained energy"] > d[0]["gained energy"]:
            diff.append(f"`{m}` gains energy in {c[0]['gained energy']} shots with `--compat` against "
                        f"{d[0]['gained energy']} by default (largest ×{max(c[2]):.3g})")
    f["shots_compat"] = ("; ".join(diff) + ".") if diff else "`--compat` gained no more energy than the default mode."
    h = summary.get(("hybrid", "default"))
    off = (h[0]["gained energy"] + h[0]["lost energy"]) if h else 0
    bare = summary.get(("hybrid k=0", "default"))
    clean = bare and bare[0]["bounced"] == bare[1]
    f["shots_oddity"] = (f"- In the random shots the default hybrid's penalty layer leaves the energy outside COR's "
                         f"bounds in {off} of {h[1]} shots (gains up to ×{max(h[2]):.3g}"
                         f"{'; without the layer, k = 0, in none' if clean else ''}).\n" if h and off and h[2] else "")
    ct = summary.get(("continuous-time", "default"))
    f["shots_ct"] = (f"`continuous-time` (default mode) bounced within COR's bounds in {ct[0]['bounced']} of {ct[1]} "
                     f"random shots" if ct else "")
    return "\n\n".join(out), f


# ---- energy order and the accuracy section's extremes ------------------------------------------

def energy_facts(acc, r, f):
    """The order of the energy error over the run, and why explicit Euler's spring and implicit
    Euler's orbit end where they do."""
    def rows_of(problem, method):
        return sorted([x for x in acc if x["problem"] == problem and x["method"] == method], key=lambda x: x["dt"])

    def order(problem, method, key):
        pts = [x for x in rows_of(problem, method) if x["outcome"] == "ok" and sd.finite(x[key])][:5]
        return sd.order_of_convergence([x["dt"] for x in pts], [x[key] for x in pts]), pts

    q, pts = order("orbit", "symplectic-euler", "energy_error_max")
    qe, _ = order("orbit", "symplectic-euler", "energy_error")
    words = ("first order" if 0.8 <= q <= 1.2 else "second order" if 1.8 <= q <= 2.2 else f"order {q:.2f}")
    f["orbit_energy_words"] = (
        f"its energy error, measured as the largest over the run, shrinks as dt^{q:.2f} ({words}: "
        f"{', '.join(r.fmt(x['energy_error_max'], 2) for x in reversed(pts[:4]))} at dt = "
        f"{', '.join(f'{x:g}' for x in reversed([p['dt'] for p in pts[:4]]))}), and it does not drift: "
        f"it oscillates (symplectic Euler keeps a nearby energy exactly). At the last step alone it "
        f"reads {', '.join(r.fmt(x['energy_error'], 2) for x in reversed(pts[:4]))} (a fitted slope of "
        f"{qe:.2f}), depending on where in its oscillation the run stops")
    f["orbit_energy_order"] = f"{q:.2f}"
    # The explicit spring's gain against the per-step rule for a linear oscillator.
    spring = rows_of("spring", "explicit-euler")
    coarse = spring[-1] if spring else None
    if coarse and sd.finite(coarse["omega"]):
        s = coarse["omega"] * coarse["dt"]
        rule = (1 + s * s) ** coarse["steps"]
        passed = sd.finite(coarse["min_separation"]) and coarse["min_separation"] < 0
        f["explicit_rule"] = r.fmt(rule, 3) if rule < 1e4 else f"{rule:,.0f}"
        f["explicit_rule_words"] = (
            f"The per-step rule for a linear spring, energy × (1 + ω²dt²) every step, predicts "
            f"×{f['explicit_rule']} after {int(coarse['steps'])} steps; the run gained less because it left the "
            f"linear regime: " + (
                f"its amplitude outgrew the rest length and the bob passed through the anchor (its coordinate "
                f"reached {r.fmt(coarse['min_separation'], 3)} m), where the spring's force −k(|x| − l0)·x/|x| "
                f"flips direction and is not linear in x, so the rule no longer applies." if passed else
                "(the bob did not pass through the anchor in this run; the difference is unexplained here)."))
    else:
        f["explicit_rule_words"] = ""
    failed = [x for x in rows_of("orbit", "implicit-euler") if x["outcome"] != "ok"]
    if failed and sd.finite(failed[-1]["min_separation"]):
        x = failed[-1]
        f["orbit_collapse_words"] = (
            f" By then the orbit has already collapsed: at dt = {x['dt']:g} the bodies came within "
            f"{r.fmt(x['min_separation'], 2)} of each other, inside the true periapsis a(1 − e) = "
            f"{r.fmt(x['exact_min_separation'], 3)} (implicit Euler's damping drains the orbit's energy), and "
            f"Newton fails where the pull is steepest.")
    else:
        f["orbit_collapse_words"] = ""


def energy_order_table(acc, r):
    """Observed order of the largest energy error over the run, per problem and method."""
    body = []
    for p in sd.unique([x for x in acc if x["kind"] == "integrators"], "problem"):
        mine = [x for x in acc if x["problem"] == p]
        cells = sd.order_cells(mine, "energy_error_max", r.fmt)
        body.append([mine[0]["title"], "; ".join(cells)])
    return r.table(["problem", "order of the largest energy error over the run"], body)


def comparison_facts(acc, r, f):
    """How much better symplectic Euler does than explicit Euler at the same dt, and how much cheaper
    it is than implicit Euler for the same accuracy, on the oscillating problems."""
    def err(problem, method):
        return {x["dt"]: x for x in acc if x["problem"] == problem and x["method"] == method and x["outcome"] == "ok"
                and sd.finite(x["error"])}

    ratios, costs = [], []
    for p in ("spring", "orbit"):
        s, e = err(p, "symplectic-euler"), err(p, "explicit-euler")
        ratios += [e[d]["error"] / s[d]["error"] for d in s if d in e and s[d]["error"] > 0]
        # Implicit Euler's best error (its finest dt) against symplectic Euler's cheapest run that is
        # at least as accurate.
        imp = [x for x in err(p, "implicit-euler").values() if sd.finite(x["wall_per_sim_s"])]
        if imp:
            best = min(imp, key=lambda x: x["error"])
            match = [x for x in s.values() if x["error"] <= best["error"] and sd.finite(x["wall_per_sim_s"])]
            if match:
                costs.append(best["wall_per_sim_s"] / min(x["wall_per_sim_s"] for x in match))
    ratios.sort()
    f["sympl_vs_explicit"] = (f"{r.fmt(ratios[len(ratios) // 2], 2)} times smaller (median over the time steps of "
                              f"the spring and the orbit; {r.fmt(ratios[0], 2)} to {r.fmt(ratios[-1], 2)})"
                              if ratios else "—")
    f["sympl_vs_implicit"] = (f"{r.join(r.fmt(c, 2) for c in costs)} times less wall time than implicit Euler to "
                              f"be as accurate as implicit Euler's best run (its finest dt; spring, orbit)"
                              if costs else "less wall time than implicit Euler for the same accuracy")


def audit_section(data_dir, rel, r):
    """The audit over time: its chart and, per problem and integrator, the largest error of each
    quantity over the run and whether it grew (last sample against the median of the first tenth)."""
    import os
    if not os.path.exists(os.path.join(data_dir, "audit_series.csv")):
        return ""
    rows = sd.load(data_dir, "audit_series")
    body, samples = [], 0
    for p in sd.unique(rows, "problem"):
        mine = [x for x in rows if x["problem"] == p]
        for m in sd.unique(mine, "method"):
            pts = [x for x in mine if x["method"] == m]
            samples = max(samples, len(pts))
            cells = [mine[0]["title"].split(" (")[0], m, f"{pts[0]['dt']:g}"]
            for key in ("energy_error", "momentum_error", "angmom_error"):
                vals = [x[key] for x in pts if sd.finite(x[key])]
                cells.append(r.fmt(max(vals), 2) if vals else "—")
            end = pts[-1]
            cells.append("ran to the end" if end["outcome"] == "ok" else f"{end['outcome']} at t = {end['time']:.3g} s")
            body.append(cells)
    return "\n\n".join([
        "### Audit over time\n\nEnergy, momentum and angular momentum against the exact motion at up to "
        f"{samples} step ends of each run (one time step per problem), every integrator on every integrator problem. The anchored springs' "
        "momentum is not conserved (the anchor pushes), so it is compared with the exact m·v(t); their angular "
        "momentum about the anchor is exactly 0 for a motion along the spring.",
        r.image(rel, "audit", "energy, momentum and angular momentum against time"),
        r.table(["problem", "integrator", "dt [s]", "largest energy error", "largest momentum error",
                 "largest angular momentum error", "run"], body)])


def penalty_section(data_dir, rel, r):
    """Penalty contact's limits against stiffness and impact speed (from robustness.csv)."""
    from charts_limits import contact_limit, penalty_limits, tunnel_speed
    rows = [x for x in sd.load(data_dir, "robustness") if x["collision"] == "penalty"]
    if not rows:
        return "", {}
    finest, coarsest = min(x["dt"] for x in rows), max(x["dt"] for x in rows)
    body, words = [], []

    def stable_words(dt):
        return f"every dt tried (to {r.fmt(dt, 2)})" if dt >= coarsest else r.fmt(dt, 2)

    for m, (k, speeds, stable, bounced) in penalty_limits(rows).items():
        lost = [x["speed"] for x in rows if x["method"] == m and x["dt"] == finest and x["outcome"] != "bounced"]
        through = min(lost) if lost else math.nan
        held = [v for v, b in zip(speeds, bounced) if sd.finite(b)]
        first = next(x for x in rows if x["method"] == m)
        limit = contact_limit(first)
        body.append([m, r.fmt(through, 3), r.fmt(tunnel_speed(first), 3),
                     r.fmt(max(held), 3) if held else "—",
                     stable_words(stable[0]) if sd.finite(stable[0]) else "—", r.fmt(limit, 2)])
        if sd.finite(stable[0]) and stable[0] > limit:
            words.append(f"{m} stayed stable up to dt = {r.fmt(stable[0], 2)} s"
                         f"{' (the largest tried)' if stable[0] >= coarsest else ''} at {r.fmt(speeds[0], 2)} m/s, "
                         f"above its contact spring's limit {r.fmt(limit, 2)} s (a contact shorter than "
                         "a few steps has no time to oscillate)")
    out = [r.image(rel, "penalty_limits", "penalty: largest stable and bouncing dt against speed and stiffness"),
           r.table(["method", f"slowest speed that did not bounce at dt = {r.fmt(finest)} s [m/s]",
                    "theory: (radii + thickness)·√(k/m)", "fastest speed that bounced at some dt [m/s]",
                    f"largest stable dt at {r.fmt(min(x['speed'] for x in rows), 2)} m/s [s]",
                    "contact spring's limit 2·√(m/k) [s]"], body)]
    f = {"penalty_limit_words": ("; ".join(words) + ".") if words else ""}
    return "\n\n".join(out), f
