#!/usr/bin/env python3
"""Writes docs/study.md from the study's CSV files: the charts, what they say in plain words (with
the numbers of this run), and the closed forms behind them.

    python3 study/report.py DATA_DIR DOC_PATH [--elapsed SECONDS]

DATA_DIR holds the CSV files and charts (docs/study); the charts are linked relative to DOC_PATH.
The numbers in the text are computed here from the CSV files, so they follow every regeneration;
the sentences around them say what the study found on this machine when it was written.
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import study_data as sd  # noqa: E402
import report_text as text  # noqa: E402
import report_contacts as contacts  # noqa: E402
import report_limits as limits  # noqa: E402
import report_newton as newton_report  # noqa: E402
import report_setup as setup  # noqa: E402


def fmt(x, digits=2):
    if not sd.finite(x):
        return "—"
    if x == 0:
        return "0"
    if abs(x) >= 1e4 or abs(x) < 1e-3:
        return f"{x:.{digits - 1}e}"
    return f"{x:.{digits}g}" if abs(x) < 100 else f"{x:.0f}"


def table(header, rows):
    out = ["| " + " | ".join(header) + " |", "|" + "|".join("---" for _ in header) + "|"]
    out += ["| " + " | ".join(str(c) for c in r) + " |" for r in rows]
    return "\n".join(out)


def image(rel, name, alt):
    return f"![{alt}]({rel}/{name}.png)\n\n(also as [SVG]({rel}/{name}.svg))"


# ---- accuracy ----------------------------------------------------------------------------------

TARGETS = {"billiards": 1e-3}  # relative energy; every other problem: position error in metres
DEFAULT_TARGET = 1e-3


def accuracy_section(data_dir, rel):
    rows = sd.load(data_dir, "accuracy")
    out = [image(rel, "accuracy_integrators", "error against wall time, integrators"),
           image(rel, "accuracy_collisions", "error against wall time, collision methods")]
    # Observed order: slope of log error over log dt on the five finest time steps that ran.
    problems = sd.unique(rows, "problem")
    order_rows, cheapest_rows = [], []
    for p in problems:
        mine = [r for r in rows if r["problem"] == p]
        cells = sd.order_cells(mine, "error", fmt)
        order_rows.append([mine[0]["title"], "; ".join(cells)])
        target = TARGETS.get(p, DEFAULT_TARGET)
        good = [r for r in mine if r["outcome"] == "ok" and sd.finite(r["error"]) and r["error"] <= target
                and sd.finite(r["wall_per_sim_s"])]
        if good:
            best = min(good, key=lambda r: r["wall_per_sim_s"])
            cheapest_rows.append([mine[0]["title"], f"{target:g}", best["method"], f"{best['dt']:g}",
                                  fmt(1e3 * best["wall_per_sim_s"], 2)])
        else:
            cheapest_rows.append([mine[0]["title"], f"{target:g}", "none of the methods", "—", "—"])
    out.append("**Observed order of accuracy** of each chart's error (the position error at the end of the run; "
               "slope of log error against log dt over the five finest time steps that ran; 1 = halving dt "
               "halves the error, 0 = the error does not shrink, negative = it grows):\n")
    out.append(table(["problem", "order per method"], order_rows))
    out.append("\n**Energy error, measured as the largest over the whole run** (an error that oscillates can be "
               "small at the last step by chance, so the study measures the energy this way; the order is the "
               "slope over the five finest time steps that ran):\n")
    out.append(limits.energy_order_table(rows, sys.modules[__name__]))
    out.append(image(rel, "energy_order", "largest energy error over the run against dt"))
    out.append("\n**Cheapest way to be right**: of all the runs whose error is at most the target, the one "
               "with the least wall time per simulated second:\n")
    out.append(table(["problem", "target error", "cheapest method", "its dt [s]", "wall ms per simulated s"],
                     cheapest_rows))
    failed = [r for r in rows if r["outcome"] != "ok"]
    if failed:
        lines = sorted({f"{r['title']}: {r['method']} at dt = {r['dt']:g} ({r['outcome']})" for r in failed})
        out.append("\nRuns that failed (reported, not drawn):\n\n" + "\n".join(f"- {x}" for x in lines))
    return "\n\n".join(out)


# ---- stability ---------------------------------------------------------------------------------

FACTS = {}  # numbers the sections find on the way, for the prose


def stability_section(data_dir, rel):
    rows = sd.load(data_dir, "stability")
    blow_up = setup.facts(data_dir, sys.modules[__name__]).get("blow_up", "—")  # the study's mark (problems.csv)
    out = []
    body = []
    for system in sd.unique(rows, "system"):
        for integ in sd.unique(rows, "integrator"):
            pts = [r for r in rows if r["system"] == system and r["integrator"] == integ]
            capped = [r for r in pts if r["capped"] == 1]
            found = [r["largest_stable_dt"] * r["omega_max"] for r in pts
                     if r["capped"] == 0 and sd.finite(r["largest_stable_dt"])]
            if len(capped) == len(pts):
                measured = f"stable at every dt tried (ω dt up to {pts[0]['dt_tried_max'] * pts[0]['omega_max']:g})"
            elif found and max(found) / min(found) < 1.002:  # the same at every stiffness
                measured = f"{min(found):.3f} at every k"
            elif found:
                measured = f"{min(found):.3f} to {max(found):.3f}"
            else:
                measured = "no stable dt found"
            reasons = sorted({r["failure"] for r in pts if isinstance(r["failure"], str) and r["failure"]})
            body.append([system, integ, measured, text.STABILITY_THEORY[integ].format(blow_up=blow_up),
                         ", ".join(reasons) or "—"])
    out.append(table(["system", "integrator", "measured limit ω_max·dt (over all k)", "theory",
                      "how the unstable runs ended"], body))
    ratio = [r["omega_max"] / math.sqrt(r["k"]) for r in rows if r["bobs"] > 1]
    FACTS["row_ratio"] = fmt(ratio[0], 3) if ratio else "—"
    blown = [r["largest_stable_dt"] * r["omega_max"] for r in rows if r["integrator"] == "explicit-euler"
             and r["capped"] == 0 and sd.finite(r["largest_stable_dt"])]
    FACTS["explicit_blowup"] = f"{min(blown):.3f}" if blown else "—"
    return "\n\n".join(out)


# ---- robustness ------------------------------------------------------------------------------

def robustness_section(data_dir, rel):
    rows = sd.load(data_dir, "robustness")
    out = [image(rel, "robustness", "outcome maps against a thin edge (head-on shots)"),
           image(rel, "penalty_depth", "penalty penetration depth")]
    body = []
    for m in sd.unique(rows, "method"):
        mine = [r for r in rows if r["method"] == m]
        counts = {o: sum(1 for r in mine if r["outcome"] == o) for o in ("bounced", "tunnelled", "stuck", "unstable")}
        lost = [r for r in mine if r["outcome"] != "bounced"]
        first_loss = min((r["speed_dt"] for r in lost), default=math.nan)
        finest = min(r["dt"] for r in mine)
        fastest = max((r["speed"] for r in mine if r["dt"] == finest and r["outcome"] == "bounced"), default=math.nan)
        deep = max((r["max_overlap"] for r in mine if r["outcome"] == "bounced"), default=math.nan)
        body.append([m, f"{counts['bounced']}/{len(mine)}", counts["tunnelled"], counts["stuck"], counts["unstable"],
                     fmt(first_loss, 2), fmt(fastest, 3), fmt(deep, 2)])
    out.append(table(["method", "bounced", "tunnelled", "stuck", "unstable",
                      "smallest speed·dt [m] that did not bounce", f"fastest bounce at dt = {fmt(finest)} s [m/s]",
                      "deepest overlap of a bounce [m]"], body))
    return "\n\n".join(out)


# ---- hybrid ------------------------------------------------------------------------------------

def hybrid_section(data_dir, rel):
    rows = sd.load(data_dir, "hybrid")
    out = [image(rel, "hybrid", "hybrid failsafe use and cost against maxiters")]
    body = []
    for r in rows:
        label = f"hybrid, maxiters {int(r['maxiters'])}" if r["collision"] == "hybrid" else r["method"]
        share = failsafe_share(r)
        body.append([label, r["outcome"], fmt(100 * share, 3) if sd.finite(share) else "—",
                     fmt(r["mean_passes"], 3), fmt(r["largest_zone"], 3), fmt(r["us_per_step"], 3),
                     fmt(r["collisions_per_step"], 3), int(r["overlap_steps"]), fmt(r["max_overlap"], 2),
                     fmt(r["mean_height_end"], 3), fmt(r["kinetic_end"], 2)])
    header = ["method", "run", "failsafe steps [%]", "passes per step", "largest zone",
              "µs per step", "collisions per step", "steps ending with overlap", "deepest overlap [m]",
              f"mean height at the end [m] (start {fmt(rows[0]['mean_height_start'], 3)})",
              "kinetic energy at the end [J]"]
    # The default mode has no impulse passes (its events are counted as collisions): a column that
    # no run filled is left out rather than shown as dashes.
    keep = [i for i in range(len(header)) if any(row[i] != "—" for row in body)]
    out.append(table([header[i] for i in keep], [[row[i] for i in keep] for row in body]))
    return "\n\n".join(out)


def failsafe_share(r):
    """Share of the steps that used the failsafe (the CSV fills it for the hybrid only)."""
    if sd.finite(r["failsafe_fraction"]):
        return r["failsafe_fraction"]
    if r["collision"] in ("continuous-time", "hybrid") and r["steps"] > 0:
        return r["failsafe_steps"] / r["steps"]
    return math.nan


# ---- profile -----------------------------------------------------------------------------------

def profile_parts(r):
    """The profile row's parts per step [µs] with the failsafe taken out of the response where the
    handler times it inside the response: the default mode's continuous-time and hybrid solve their
    zones while responding to an event (src/core/collision/event_handler.cpp), so StepStats'
    response includes the failsafe, and the CSV's "rest" (the collision time outside the itemised
    phases) subtracted it twice. Returns a dict of the PHASES keys of charts.py."""
    parts = {k: r[k] if sd.finite(r[k]) else 0.0 for k in
             ("forces_us", "jacobians_us", "solve_us", "broad_us", "narrow_us", "response_us", "failsafe_us",
              "collision_other_us")}
    if nested_failsafe(r):
        parts["response_us"] = r["response_us"] - r["failsafe_us"]
        itemised = sum(parts[k] for k in ("forces_us", "jacobians_us", "solve_us", "broad_us", "narrow_us",
                                          "response_us", "failsafe_us"))
        parts["collision_other_us"] = max(0.0, r["total_us"] - itemised)
    return parts


def nested_failsafe(r):
    return (r["collision"] in ("continuous-time", "hybrid") and sd.finite(r["failsafe_us"]) and r["failsafe_us"] > 0
            and r["response_us"] >= r["failsafe_us"])


def profile_section(data_dir, rel):
    rows = sd.load(data_dir, "profile")
    out = [image(rel, "profile", "where the time of a step goes")]
    body = []
    for r in rows:
        pairs = []
        for kind, key in (("PP", "pp"), ("PE", "pe"), ("PH", "ph")):
            if r[key + "_pairs"] > 0 and r["collision"] != "none":
                q = r[key + "_queries"]
                pairs.append(f"{kind} {int(r[key + '_pairs'])}" + (f" ({fmt(q, 3)} queried)" if sd.finite(q) and q > 0 else ""))
        forces = r["forces"] if isinstance(r["forces"], str) else "none"
        if forces.count("+") > 2:
            names = forces.split("+")
            forces = ", ".join(f"{names.count(n)} × {n}" for n in dict.fromkeys(names))
        p = profile_parts(r)
        body.append([f"{r['scene']} — {r['method']}", forces, ", ".join(pairs) or "—", fmt(r["total_us"], 3),
                     fmt(p["forces_us"], 2), fmt(p["jacobians_us"], 2), fmt(p["solve_us"], 2),
                     fmt(p["narrow_us"], 3), fmt(p["response_us"], 2), fmt(p["failsafe_us"], 3),
                     fmt(p["collision_other_us"], 2)])
    out.append(table(["scene — method", "forces", "pairs per detection pass (queried per step)", "step µs",
                      "forces µs", "Jacobians µs", "solve µs", "narrow µs", "response µs", "failsafe µs",
                      "rest µs"], body))
    return "\n\n".join(out)


# ---- facts for the prose ---------------------------------------------------------------------

def median(xs):
    xs = sorted(x for x in xs if sd.finite(x))
    return xs[len(xs) // 2] if xs else math.nan


def facts(data_dir):
    """The numbers the prose quotes, from this run's CSV files (report_text.py uses them), and the
    words that depend on what was measured."""
    acc = sd.load(data_dir, "accuracy")
    prof = sd.load(data_dir, "profile")
    hyb = sd.load(data_dir, "hybrid")
    rob = sd.load(data_dir, "robustness")

    def acc_rows(problem, method):
        return [r for r in acc if r["problem"] == problem and r["method"] == method]

    def per_step(problem, method):
        return median(r["us_per_step"] for r in acc_rows(problem, method))

    def prof_total(scene_start, method):
        for r in prof:
            if r["scene"].startswith(scene_start) and r["method"] == method:
                return r["total_us"]
        return math.nan

    f = {}
    ratios = [per_step(p, m) / per_step(p, "symplectic-euler") for p in ("projectile", "spring", "orbit")
              for m in ("implicit-euler", "linearized-implicit-euler")]
    ratios += [prof_total("Row of ", m) / prof_total("Row of ", "symplectic-euler")
               for m in ("implicit-euler", "linearized-implicit-euler")]
    ratios = [r for r in ratios if sd.finite(r)]
    f["implicit_cost"] = f"{min(ratios):.0f}-{max(ratios):.0f}" if ratios else "several"

    coarse = lambda problem, method: max(acc_rows(problem, method), key=lambda r: r["dt"])  # noqa: E731
    f["explicit_gain"] = fmt(coarse("spring", "explicit-euler")["energy_error"] + 1, 2)
    f["explicit_gain_dt"] = f"{coarse('spring', 'explicit-euler')['dt']:g}"
    spring = coarse("spring", "explicit-euler")
    setup = {(r["problem"], r["name"]): r["value"] for r in sd.load(data_dir, "problems")}
    f["spring_periods"] = f"{setup[('spring', 'duration')] * spring['omega'] / (2 * math.pi):.2g}"
    f["explicit_gain_words"] = (f"on the undamped spring its energy grew x{f['explicit_gain']} in "
                                f"{f['spring_periods']} periods at "
                                f"dt = {f['explicit_gain_dt']}")
    f["implicit_loss"] = fmt(100 * coarse("spring", "implicit-euler")["energy_error"], 4)
    failed = sorted(r["dt"] for r in acc_rows("orbit", "implicit-euler") if r["outcome"] != "ok")
    f["orbit_failure"] = (f"at dt ≥ {min(failed):g} (here: {', '.join('%g' % d for d in failed)})" if failed
                          else "not in this run")
    bare = median(r["energy_error"] for r in acc if r["problem"] == "billiards" and r["method"] == "hybrid k=0")
    f["hybrid_k0_gain"] = f"{100 * bare:.0f} %" if sd.finite(bare) and bare >= 5e-3 else fmt(bare, 2)
    gain = median(r["energy_error"] for r in acc if r["problem"] == "billiards" and r["method"] == "hybrid")
    f["hybrid_gain"] = f"{100 * gain:.0f} %" if sd.finite(gain) else "—"
    summed = sd.finite(bare) and bare >= 1e-3  # the course's summed impulses gain at k = 0 too
    f["billiard_words"] = (text.BILLIARD_SUMMED if summed else text.BILLIARD_PENALTY).format(**f)
    f["billiard_oddity"] = (text.ODDITY_SUMMED if summed else text.ODDITY_PENALTY).format(**f)

    accuracy_collision_facts(acc, rob, f)
    robustness_facts(rob, f)
    limits.energy_facts(acc, sys.modules[__name__], f)
    limits.comparison_facts(acc, sys.modules[__name__], f)

    pen = [r for r in acc_rows("cradle", "penalty k=1e4") if r["outcome"] == "ok" and sd.finite(r["error"])]
    best = min(pen, key=lambda r: r["error"]) if pen else None
    half = [r for r in pen if best and abs(r["dt"] - best["dt"] / 2) < 1e-12]
    if best and best["error"] < 1e-9 and half:
        f["cradle_note"] = (f"- The cradle's best point, **penalty k=1e4 at dt = {best['dt']:g} with an error of "
                            f"{best['error']:.0e} m, is a coincidence**: there ω·dt = √2 for the pair (ω² = 2k/m), so "
                            f"each contact lasts exactly two steps and hands the velocity on exactly. At dt = "
                            f"{half[0]['dt']:g} the same method is off by {fmt(half[0]['error'], 2)} m.")
    else:
        f["cradle_note"] = ""

    def prof_ratio(scene, a, b):
        return prof_total(scene, a) / prof_total(scene, b)
    f["ct_over_simple"] = fmt(prof_ratio("Billiard", "continuous-time", "simple"), 2)
    by = {(r["collision"], r["maxiters"] if sd.finite(r["maxiters"]) else None): r for r in hyb}
    # The hybrid's default maxiters (10); a quick run without it speaks of its largest.
    default = by.get(("hybrid", 10.0)) or max((r for r in hyb if r["collision"] == "hybrid"),
                                              key=lambda r: r["maxiters"], default=None)
    simple = by.get(("simple", None))
    ct = by.get(("continuous-time", None))
    f["pile_hybrid_over_simple"] = fmt(default["us_per_step"] / simple["us_per_step"], 2) if default and simple else "—"
    f["pile_hybrid_over_ct"] = fmt(default["us_per_step"] / ct["us_per_step"], 2) if default and ct else "—"
    f["pile_ct_over_simple"] = fmt(ct["us_per_step"] / simple["us_per_step"], 2) if ct and simple else "—"
    f["pile_failsafe"] = f"{100 * default['failsafe_fraction']:.0f} %" if default else "—"
    f["pile_zone"] = (f"{default['mean_failsafe_particles']:.0f} of {default['particles']:.0f}" if default else "—")
    hybrid_pile_facts(hyb, default, simple, ct, f)

    pile = next((r for r in prof if r["scene"].startswith("Dense pile") and r["method"] == "hybrid"), None)
    queries = pile["pp_queries"] + pile["pe_queries"] + pile["ph_queries"] if pile else math.nan
    pairs = pile["pp_pairs"] + pile["pe_pairs"] + pile["ph_pairs"] if pile else math.nan
    passes = default["mean_passes"] if default else math.nan
    repeats = (f"{fmt(passes, 2)} impulse passes per step (plus the failsafe's rounds)" if sd.finite(passes) else
               "the pairs of every particle an event or a zone changed, queried again over the rest of the step")
    broad = any(r["broad_us"] > 0 for r in prof)
    if broad and pile:
        f["detection_words"] = (
            f"- **A broad phase prunes the pairs** before the continuous-time queries: on the pile the hybrid "
            f"queries {fmt(queries, 2)} pairs per step, against {fmt(pairs, 3)} pairs in the scene, counting "
            f"{repeats}; the broad phase itself costs {fmt(pile['broad_us'], 2)} µs of the step's "
            f"{fmt(pile['total_us'], 3)}.")
        f["oddity_broad"] = ""
    else:
        f["detection_words"] = (
            f"- **Collision detection visits every pair every pass** (no broad phase): {fmt(pairs, 3)} pairs "
            f"per pass on the pile, and the hybrid repeats that for {repeats} ({fmt(queries, 2)} queries per step).")
        f["oddity_broad"] = ("- There is no broad phase: every detection pass visits all pairs (O(N²)), "
                             "which dominates the hybrid's cost on a pile.\n")
    if pile:
        parts = profile_parts(pile)
        top = max(("narrow_us", "response_us", "failsafe_us", "forces_us", "broad_us"), key=lambda k: parts[k])
        names = {"narrow_us": "the narrow phase", "response_us": "the impulses", "failsafe_us": "the failsafe's zones",
                 "forces_us": "the forces", "broad_us": "the broad phase"}
        f["pile_profile_words"] = (f"; of its step, {names[top]} take {100 * parts[top] / pile['total_us']:.0f} %")
    else:
        f["pile_profile_words"] = ""
    shares = [r["forces_us"] / r["total_us"] for r in prof if r["collision"] == "penalty" and r["total_us"] > 0]
    f["penalty_share"] = (f"{100 * min(shares):.0f}-{100 * max(shares):.0f} %" if shares else "most")
    stats = []
    simple_rows = [r for r in prof if r["collision"] == "simple"]
    if simple_rows and all(r["narrow_us"] == 0 and r["pp_queries"] == 0 for r in simple_rows):
        stats.append("the simple handler reports no narrow-phase time or queries (its whole cost lands in "
                     "\"rest\")")
    ct_rows = [r for r in prof if r["collision"] == "continuous-time" and r["collisions_per_step"] > 0]
    if ct_rows and all(r["response_us"] == 0 for r in ct_rows):
        stats.append("the continuous-time handler reports no response time (it applies impulses inside its "
                     "detection loop, so they count as narrow phase)")
    if any(nested_failsafe(r) for r in prof + [dict(r, total_us=r["us_per_step"]) for r in hyb]):
        stats.append("the default mode's response time includes its failsafe's (the zones are solved while "
                     "responding to an event), so the tables here show the response without it")
    f["oddity_stats"] = ("- The simulator's own phase timings: " + "; ".join(stats) + ".\n") if stats else ""
    return f


def accuracy_collision_facts(acc, rob, f):
    """Section 1's words on the collision problems: where continuous-time is exact, how it compares
    with simple elsewhere, and what the hybrid's penalty layer does."""
    coll = [r for r in acc if r["kind"] == "collisions" and r["outcome"] == "ok" and sd.finite(r["error"])]
    problems = sd.unique(coll, "problem")
    title = {r["problem"]: r["title"] for r in coll}
    short = lambda p: problem_name(title[p])  # noqa: E731

    def errors(p, m):
        return {r["dt"]: r["error"] for r in coll if r["problem"] == p and r["method"] == m}

    exact, inexact, ratios = [], [], []
    for p in problems:
        e = errors(p, "continuous-time")
        if e and max(e.values()) < 1e-9:
            exact.append(p)
        elif e:
            inexact.append(p)
            s = errors(p, "simple")
            ratios += [s[d] / e[d] for d in e if d in s and e[d] > 0]
    worst_exact = max((max(errors(p, "continuous-time").values()) for p in exact), default=math.nan)
    words = "- **Collisions**: "
    if exact:
        words += (f"`continuous-time` is exact to rounding at every dt on {join(short(p) for p in exact)} (errors "
                  f"at most {fmt(worst_exact, 1)}): the default mode resolves each contact at its own time and the "
                  "particles fly on from there, so a contact adds no error of its own.")
    if inexact and ratios:
        words += (f" On {join(short(p) for p in inexact)} it is not exact: the steps' straight paths and symplectic "
                  f"Euler's flight under gravity leave an error of first order, {fmt(median(ratios), 2)} times "
                  f"smaller than `simple`'s at the same dt (median; {fmt(min(ratios), 2)} to {fmt(max(ratios), 2)}).")
    ov = lambda m: max((r["max_overlap"] for r in coll if r["method"] == m and sd.finite(r["max_overlap"])),  # noqa: E731
                       default=math.nan)
    words += (f" `simple` also leaves disks overlapping at step ends (up to {fmt(ov('simple'), 2)} m here), "
              f"`continuous-time` {'never' if ov('continuous-time') == 0 else 'by up to ' + fmt(ov('continuous-time'), 2) + ' m'}"
              "; and `continuous-time` never misses a contact (section 3).")
    f["collision_words"] = words

    # The hybrid's penalty layer: problems where its error stops shrinking while k = 0's does not.
    def finest(p, m):
        e = errors(p, m)
        return e[min(e)] if e else math.nan

    def order(p, m):
        e = sorted(errors(p, m).items())[:5]
        return sd.order_of_convergence([d for d, _ in e], [x for _, x in e])

    # The hybrid's default layer as the collision table gives it (robustness.csv records it).
    hybrid = next((r for r in rob if r["method"] == "hybrid"), None)
    layer = (f"k = {hybrid['penalty_k']:g}, thickness {hybrid['thickness']:g}" if hybrid else "its defaults")
    stuck = [p for p in problems if sd.finite(finest(p, "hybrid")) and finest(p, "hybrid") > 1e-6
             and finest(p, "hybrid") > 100 * max(finest(p, "hybrid k=0"), 1e-15)
             and not (order(p, "hybrid") > 0.5)]
    if stuck:
        f["layer_words"] = (
            f"- **The hybrid handler's default penalty layer ({layer}) is an error of its own**: it "
            f"pushes disks apart before they touch, so on {join(short(p) for p in stuck)} the hybrid's error stops "
            f"shrinking with dt (at the finest dt: {join(fmt(finest(p, 'hybrid'), 2) for p in stuck)}).")
    else:
        f["layer_words"] = (f"- The hybrid handler's default penalty layer ({layer}) does not keep its "
                            "error from shrinking with dt on any of these problems.")
    same = [p for p in problems if errors(p, "hybrid k=0") and errors(p, "hybrid k=0") == errors(p, "continuous-time")]
    differ = [p for p in problems if errors(p, "hybrid k=0") and p not in same]
    quota = any(r["failsafe_steps"] > 0 for r in coll if r["method"] in ("hybrid k=0", "continuous-time"))
    f["layer_words"] += (
        " Without it (k = 0) the hybrid gives exactly `continuous-time`'s results on every collision problem "
        "(both are the same time-ordered handling; only the quota of impulse events differs" +
        (")." if quota else ", and no run here reached it).") if not differ else
        f" Without it (k = 0) the hybrid matches `continuous-time` except on {join(short(p) for p in differ)}.")
    thickness = f"thickness {hybrid['thickness']:g}" if hybrid else "its thickness"
    f["layer_oddity"] = (f"- The hybrid's default penalty layer ({thickness}, as thick as a typical radius) acts on "
                         "neighbours that are not touching, and keeps the hybrid's error from shrinking with dt "
                         f"({join(short(p) for p in stuck)}).\n" if stuck else "")
    bill = [r for r in coll if r["problem"] == "billiards" and r["method"] in ("simple", "continuous-time")]
    e_bill = max((abs(r["energy_error"]) for r in bill if sd.finite(r["energy_error"])), default=math.nan)
    p_bill = max((abs(r["momentum_error"]) for r in bill if sd.finite(r["momentum_error"])), default=math.nan)
    f["billiards_keep"] = (f"both keep energy (to {fmt(e_bill, 1)} relative) and momentum (to {fmt(p_bill, 1)})"
                           if e_bill < 1e-9 and p_bill < 1e-9 else
                           f"their energy errors reach {fmt(e_bill, 2)} and their momentum errors {fmt(p_bill, 2)}")
    f["ct_exact_collisions"] = join(short(p) for p in exact) if exact else ""
    f["ct_exact_worst"] = fmt(worst_exact, 1)
    f["ct_overlap"] = ov("continuous-time")
    mom = [abs(r["momentum_error"]) for r in coll if r["method"] == "continuous-time" and sd.finite(r["momentum_error"])]
    f["ct_momentum"] = max(mom) if mom else math.nan


def robustness_facts(rob, f):
    """Section 3's words: where simple and penalty stop bouncing, and whether the continuous
    methods ever failed."""
    def mine(m):
        return [r for r in rob if r["method"] == m]

    simple = mine("simple")
    lost = [r for r in simple if r["outcome"] != "bounced"]
    f["simple_band"] = fmt(min((r["speed_dt"] for r in lost), default=math.nan), 2)
    stuck = sum(1 for r in simple if r["outcome"] == "stuck")
    f["simple_stuck"] = "It never got stuck with COR 1." if stuck == 0 else f"It got stuck in {stuck} cells."
    cont = [m for m in ("continuous-time", "hybrid", "hybrid k=0") if mine(m)]
    cells = len(mine(cont[0])) if cont else 0
    fails = {m: sum(1 for r in mine(m) if r["outcome"] != "bounced") for m in cont}
    fastest = max(rob, key=lambda r: r["speed"] * r["dt"]) if rob else None
    names = join(f"`{m}`" for m in cont)
    if cont and not any(fails.values()):
        f["ccd_robust"] = (f"**{names} bounced in every cell** ({cells} of {cells}), up to {fmt(fastest['speed'], 3)} m/s at "
                           f"dt = {fastest['dt']:g} s (a step of {fmt(fastest['speed_dt'], 3)} m against a "
                           f"{2 * fastest['edge_radius']:g} m thick edge).")
        f["tunnel_promise"] = (f"{names} bounced off the thin edge in all {cells} cells of section 3, up to "
                               f"{fmt(fastest['speed'], 3)} m/s at dt = {fastest['dt']:g} s ({fmt(fastest['speed_dt'], 3)} m "
                               "in one step)")
    else:
        f["ccd_robust"] = ("**The continuous methods did not always bounce**: " +
                           "; ".join(f"`{m}` failed in {n} of {cells} cells" for m, n in fails.items()) + ".")
        f["tunnel_promise"] = ("section 3 found cells where they did not bounce: " +
                               "; ".join(f"`{m}` {n} of {cells}" for m, n in fails.items()))
    f["tunnel_ok"] = bool(cont) and not any(fails.values())
    unstable = [r for r in rob if r["outcome"] == "unstable"]
    if unstable:
        who = sd.unique(unstable, "method")
        f["penalty_unstable"] = (f" and {join(who)} is unstable outright with dt of {fmt(min(r['dt'] for r in unstable), 2)} s and "
                                 f"more for disks up to {fmt(max(r['speed'] for r in unstable), 2)} m/s")
    else:
        f["penalty_unstable"] = ""


def lattice_mean_height(n, r, width):
    """Mean centre height of the n lowest sites of a triangular lattice of disks of radius r
    resting on a floor between walls `width` apart (rows alternately shifted by r)."""
    heights, row = [], 0
    while len(heights) < n:
        start = r + (row % 2) * r
        count = max(0, int(math.floor((width - r - start) / (2 * r) + 1e-9)) + 1)
        if count == 0:
            break
        heights += [r + row * math.sqrt(3) * r] * min(count, n - len(heights))
        row += 1
    return sum(heights) / len(heights) if heights else math.nan


def hybrid_pile_facts(hyb, default, simple, ct, f):
    """Section 4's words: what maxiters changes, where the time goes, how the pile ends."""
    runs = sorted([r for r in hyb if r["collision"] == "hybrid"], key=lambda r: r["maxiters"])
    if not runs or not default:
        f["pile_maxiters_words"] = f["pile_outcome_words"] = f["pile_penalty_words"] = ""
        f["pile_maxiters_pick"], f["pile_settles"], f["pile_clean"] = "keep the default", False, ""
        f["pile_simple_overlap"] = f["box_lattice"] = "—"
        f["box_disks"], f["box_dt"], f["box_lo"], f["box_hi"] = "The", "—", "—", "—"
        return
    n = int(default["particles"])
    # The pile's geometry (pile.cpp): disks of radius 0.1 on a grid of pitch 0.22 whose first row
    # is at 0.15, so the start's mean height gives the rows; the box is 0.22 * columns + 0.1 wide.
    rows_ = int(round((default["mean_height_start"] - 0.15) / 0.11)) + 1
    columns = max(1, n // max(1, rows_))
    lattice = lattice_mean_height(n, 0.1, 0.22 * columns + 0.1)
    lo, hi = runs[0], runs[-1]
    share = lambda r: 100 * r["failsafe_fraction"]  # noqa: E731
    parts = []
    for r in runs:
        own = r["response_us"] - r["failsafe_us"] if r["response_us"] >= r["failsafe_us"] > 0 else r["response_us"]
        parts.append({"failsafe": r["failsafe_us"], "narrow": r["narrow_us"], "impulses": own,
                      "integrate": r["integrate_us"], "total": r["us_per_step"]})
    top = [max(("failsafe", "narrow", "impulses", "integrate"), key=lambda k: p[k]) for p in parts]
    names = {"failsafe": "the failsafe's zone solves", "narrow": "the narrow phase", "impulses": "the impulses",
             "integrate": "the integrator and forces"}
    if len(set(top)) == 1:
        fractions = [100 * p[top[0]] / p["total"] for p in parts]
        where = (f"{names[top[0]]} take most of the step at every maxiters ({min(fractions):.0f}-{max(fractions):.0f} %)"
                 if min(fractions) > 50 else f"{names[top[0]]} take the largest share at every maxiters "
                 f"({min(fractions):.0f}-{max(fractions):.0f} %)")
    else:
        where = "; ".join(f"maxiters {int(r['maxiters'])}: {names[t]}" for r, t in zip(runs, top)) + " take the largest share"
    words = (f"On this pile every particle soon uses up its quota of impulse events in a step (maxiters, the "
             f"hybrid's limit per particle and step before its contacts go to the failsafe): with "
             f"maxiters = {int(default['maxiters'])}{' (the default)' if default['maxiters'] == 10 else ''} the failsafe runs in {share(default):.0f} % of the steps, and a failsafe step puts "
             f"{default['mean_failsafe_particles']:.0f} of {n} disks in impact zones on average")
    if default["largest_zone"] >= n:
        words += " (the largest zone is the whole pile)"
    little = abs(share(hi) - share(lo)) < 25 and max(r["us_per_step"] for r in runs) < 2 * min(r["us_per_step"] for r in runs)
    words += (f". More events per particle change {'little' if little else 'this'}: from maxiters {int(lo['maxiters'])} to {int(hi['maxiters'])} the "
              f"failsafe's share goes from {share(lo):.0f} % to {share(hi):.0f} % of the steps, while the step costs "
              f"{fmt(lo['us_per_step'], 3)} and {fmt(hi['us_per_step'], 3)} µs; {where}" +
              (f", and the narrow phase grows with maxiters ({fmt(lo['narrow_us'], 2)} to {fmt(hi['narrow_us'], 2)} µs "
               "per step) as every event's pairs are queried again." if hi["narrow_us"] > lo["narrow_us"] else "."))
    f["pile_maxiters_words"] = words

    def ends(r):
        return f"mean height {fmt(r['mean_height_end'], 3)} m, kinetic energy {fmt(r['kinetic_end'], 2)} J"
    clean = [r for r in hyb if r["overlap_steps"] == 0 and r["outcome"] == "ok"]
    clean_names = sd.unique(clean, "collision")
    dirty = [r for r in hyb if r["overlap_steps"] > 0]
    settled = [r for r in clean if abs(r["mean_height_end"] - lattice) <= 0.05 * lattice]
    keep = "keeps" if len(clean_names) == 1 else "keep"
    s = (f"{join(f'`{c}`' for c in clean_names)} {keep} the pile free of overlap at every step end "
         f"(`continuous-time` uses the same failsafe, after its own quota of events per particle, and "
         f"needed it in {100 * failsafe_share_of(ct):.0f} % of the steps)" if ct in clean else
         f"{join(f'`{c}`' for c in clean_names)} {keep} the pile free of overlap at every step end")
    if len(settled) == len(clean) and clean:
        hs = sorted({fmt(r["mean_height_end"], 3) for r in clean}, key=float)
        s += (f", and the pile settles: every such run ends at a mean height of {hs[0] if len(hs) == 1 else hs[0] + '-' + hs[-1]}"
              f" m against {fmt(lattice, 3)} m for the {n} lowest "
              f"sites of a triangular lattice in the box (start {fmt(default['mean_height_start'], 3)} m), "
              f"with at most {fmt(max(r['kinetic_end'] for r in clean), 2)} J of kinetic energy left.")
    else:
        s += (f"; against {fmt(lattice, 3)} m for the {n} lowest sites of a triangular lattice in the box, they end at "
              + join(f"{r['method']}{' maxiters ' + str(int(r['maxiters'])) if r['collision'] == 'hybrid' else ''}: "
                     f"{ends(r)}" for r in clean if r not in settled) + ".")
    if simple and simple["overlap_steps"] > 0:
        s += (f" `simple` ends {int(simple['overlap_steps'])} of its {int(simple['steps'])} steps with overlap, disks sink "
              f"into each other by up to {fmt(simple['max_overlap'], 2)} m ({fmt(simple['max_overlap'] / 0.1, 2)} radii) "
              f"and the mean height falls to {fmt(simple['mean_height_end'], 3)} m.")
    s += (f" Being right costs: the hybrid's step is {f['pile_hybrid_over_simple']} times `simple`'s" +
          (f" and {f['pile_hybrid_over_ct']} times `continuous-time`'s." if ct else "."))
    f["pile_outcome_words"] = s
    pen = []
    for r in hyb:
        if r["collision"] != "penalty":
            continue
        if r["mean_height_end"] < 0:
            pen.append(f"{r['method']} lets the pile fall through the floor (mean height {fmt(r['mean_height_end'], 3)} m)")
        elif r["kinetic_end"] > 1e3 or r["max_overlap"] > 1:
            pen.append(f"{r['method']} throws the disks about (kinetic energy {fmt(r['kinetic_end'], 2)} J at the end, "
                       f"overlaps up to {fmt(r['max_overlap'], 2)} m)")
        else:
            pen.append(f"{r['method']} holds the pile up with overlaps up to {fmt(r['max_overlap'], 2)} m but never lets it "
                       f"rest (mean height {fmt(r['mean_height_end'], 3)} m, kinetic energy {fmt(r['kinetic_end'], 2)} J at the end)")
    cheap = [r for r in hyb if r["collision"] == "penalty"]
    f["pile_penalty_words"] = (f"Penalty costs what `simple` does ({join(fmt(r['us_per_step'], 2) for r in cheap)} µs per step) "
                               f"but is no substitute: {join(pen)}." if pen else "")
    cheapest = min(runs, key=lambda r: r["us_per_step"])
    spread = max(r["us_per_step"] for r in runs) / min(r["us_per_step"] for r in runs)
    f["pile_maxiters_pick"] = (f"maxiters {'hardly matters' if spread < 2 else 'matters'} on a pile (the step cost {fmt(min(r['us_per_step'] for r in runs), 3)} to "
                               f"{fmt(max(r['us_per_step'] for r in runs), 3)} µs over maxiters {int(lo['maxiters'])}-"
                               f"{int(hi['maxiters'])}, least at {int(cheapest['maxiters'])})" + (", so keep the default" if spread < 2 else ""))
    f["box_disks"], f["box_dt"] = n, f"{default['dt']:g}"
    f["box_lo"], f["box_hi"] = int(lo["maxiters"]), int(hi["maxiters"])
    f["pile_settles"] = bool(clean) and len(settled) == len(clean)
    f["pile_clean"] = join(f"`{c}`" for c in clean_names)
    f["pile_simple_overlap"] = fmt(simple["max_overlap"], 2) if simple else "—"
    f["box_lattice"] = fmt(lattice, 3)


def failsafe_share_of(r):
    return failsafe_share(r) if r else math.nan


def problem_name(title):
    """A problem's name inside a sentence: "the COR 0.5 bounce", "the billiard break"."""
    head = title.split(" (")[0].split(":")[0]
    if ", COR " in head:
        return f"the COR {head.split(', COR ')[1]} bounce"
    if head.startswith("Newton"):
        return head
    return "the " + head[0].lower() + head[1:]


def join(items):
    """"a", "a and b", "a, b and c"."""
    items = list(items)
    if len(items) <= 1:
        return "".join(items)
    return ", ".join(items[:-1]) + " and " + items[-1]


def mode_facts(data_dir, f):
    """The opening section's evidence: what this run measured of the default mode's promises, and
    what --compat's formulation did on the multi-contact problems. Every clause is chosen by the
    measured outcome, so a broken promise is reported as broken."""
    rows = contacts.rows_of(data_dir) or []
    by = {(r["problem"], r["mode"], r["collision"]): r for r in rows}
    types = ("continuous-time", "hybrid")
    short = {r["problem"]: problem_name(r["title"]) for r in rows}

    def runs(problem, mode):
        return [by[(problem, mode, t)] for t in types if (problem, mode, t) in by]

    # Time order.
    order = []
    cradle = runs("cradle", "default")
    if cradle:
        dev = max(abs(r["speed_ratio"] - 1) for r in cradle)
        order.append(f"Newton's cradle of touching balls passes the velocity on "
                     f"{'exactly' if dev == 0 else 'to within ' + fmt(dev, 1)} (section 6)")
    if f.get("ct_exact_collisions"):
        order.append(f"`continuous-time` is exact to rounding at every dt on {f['ct_exact_collisions']} (section 1, "
                     f"errors at most {f['ct_exact_worst']})")
    f["promise_order"] = ("; ".join(order) + ".") if order else "(not measured in this run)."
    # Energy.
    energy, gained = [], []
    joint = runs("joint-drop", "default")
    if joint:
        dev = max(abs(r["speed_ratio"] - 1) for r in joint)
        energy.append(f"the ball dropped on the joint of two floor edges rebounds at its impact speed "
                      f"{'exactly' if dev == 0 else 'to within ' + fmt(dev, 1)}")
        gained += [r for r in joint if r["speed_ratio"] > 1 + 1e-9]
    rack = runs("touching-rack", "default")
    if rack:
        dev = max(r["energy_end"] - 1 for r in rack)
        energy.append("the touching rack's kinetic energy ends " +
                      ("where it started, to the last bit" if dev == 0 else
                       f"within {fmt(abs(dev), 1)} of its start" if dev < 1e-9 else f"{fmt(dev, 2)} above its start"))
        gained += [r for r in rack if r["energy_end"] > 1 + 1e-9]
    energy.append(f"on the billiard break the hybrid without its penalty layer keeps the kinetic energy to "
                  f"{f['hybrid_k0_gain']} (section 1)")
    # Where COR is 1 and no force does work, energy lost is the failsafe's.
    lossy = [r for r in rows if r["mode"] == "default" and "COR 1)" in r["title"] and r["failsafe_steps"] > 0
             and r["energy_end"] < 1 - 1e-9]
    if lossy:
        energy.append(f"the failsafe takes energy away where it runs ({join(sorted({short[r['problem']] for r in lossy}))}, "
                      f"COR 1: {join(fmt(100 * (1 - r['energy_end']), 2) + ' % (' + r['collision'] + ')' for r in lossy)} lost)")
    f["promise_energy"] = "; ".join(energy) + "." + (
        " **Broken in this run**: " + join(f"{short[r['problem']]} ({r['collision']})" for r in gained) + " gained energy."
        if gained else "")
    # Tunnelling.
    tunnel = [f.get("tunnel_promise", "")]
    escaped = [r for r in rows if r["mode"] == "default" and r["escapable"] > 0 and r["escaped"] > 0]
    corridor, slot = runs("corridor", "default"), runs("slot", "default")
    if corridor and not any(r["escaped"] for r in corridor):
        tunnel.append(f"the particle in the corridor stays in at {fmt(min(r['contacts'] / r['steps'] for r in corridor), 3)} "
                      "bounces per step")
    if slot and not any(r["escaped"] for r in slot):
        tunnel.append(f"the slot keeps all {int(slot[0]['escapable'])} disks of its {int(slot[0]['shots'])} shots")
    f["promise_tunnel"] = "; ".join(t for t in tunnel if t) + "." + (
        " **Broken in this run**: " + join(f"{short[r['problem']]} ({r['collision']}: {int(r['escaped'])})"
                                           for r in escaped) + " let particles out." if escaped else "")
    # Momentum and angular momentum.
    mom = []
    if rack:
        mom.append(f"the touching rack keeps momentum to {fmt(max(r['momentum_drift'] for r in rack), 1)} and angular "
                   f"momentum to {fmt(max(r['angular_drift'] for r in rack), 1)} of their scales")
    if sd.finite(f.get("ct_momentum", math.nan)):
        mom.append("`continuous-time` keeps momentum exactly (error 0) on every collision problem of section 1 with "
                   "free bodies" if f["ct_momentum"] == 0 else
                   f"`continuous-time`'s momentum error on the collision problems of section 1 is at most "
                   f"{fmt(f['ct_momentum'], 1)}")
    f["promise_momentum"] = ("; ".join(mom) + ".") if mom else "(not measured in this run)."
    # --compat, measured.
    compat = [r for r in rows if r["mode"] == "compat"]
    gains = [r for r in compat if r["energy_gain"] > 1.01]
    outs = [r for r in compat if r["escapable"] > 0 and r["escaped"] > 0]
    frozen = [r for r in compat if r["frozen"] == 1]
    found = []
    def grouped(runs_, what):
        """ "the joint drop ×1.2 (continuous-time) and ×7.34 (hybrid); the touching rack ..." """
        return "; ".join(f"{short[p]} " + join(f"{what(r)} ({r['collision']})" for r in runs_ if r["problem"] == p)
                         for p in sd.unique(runs_, "problem"))
    if gains:
        found.append("it gains energy (largest E / E0: " + grouped(gains, lambda r: f"×{fmt(r['energy_gain'], 3)}") + ")")
    if outs:
        found.append("its one-pass continuous-time lets particles through walls and edges (" +
                     grouped(outs, lambda r: f"{int(r['escaped'])} of {int(r['escapable'])} out") + ")")
    if frozen:
        found.append("its rigid impact zones freeze what touches a wall (" +
                     grouped(frozen, lambda r: f"at rest from t = {r['stopped_time']:g} s") + ")")
    d_bad = [r for r in rows if r["mode"] == "default" and (r["frozen"] == 1 or (r["escapable"] > 0 and r["escaped"] > 0))]
    f["compat_measured"] = (
        ("; ".join(found) + ". " + ("The default mode does none of these on the same scenes." if not d_bad and not gained
                                    else "The default mode's failures on the same scenes are listed above and in section 6."))
        if found else "On the multi-contact problems of section 6 it behaved like the default mode in this run.")
    kinds = join(k for k, there in (("energy gains", gains), ("escapes through walls", outs), ("frozen motion", frozen))
                 if there)
    f["compat_pick"] = (f"It keeps the course's flaws, which section 6 measured ({kinds}; listed in the next section)."
                        if found else "")
    f["compat_oddity"] = (
        f"- `--compat` reproduces the course's flaws on purpose ({kinds}: section 6). Its rigid zones hold still "
        "whatever touches a wall; the default mode stops only a jammed contact's particles, and only for the rest of "
        "a step.\n" if found else "")


def pick_facts(f):
    """The "What to pick" bullets whose advice depends on what was measured."""
    shots_ok = f.get("shots_default_perfect", [])
    if f["tunnel_ok"] and shots_ok:
        f["fast_pick"] = (f"- **Fast objects or thin obstacles**: {join(f'`{m}`' for m in shots_ok)}: they bounced in every "
                          "cell of section 3 and within COR's bounds in every random shot. `simple` misses contacts "
                          "once speed·dt exceeds the thinnest contact band; penalty lets anything through above "
                          "(radii + thickness)·√(k/m)" + ("" if "hybrid" in shots_ok else
                                                           "; the hybrid's default penalty layer moves the energy of "
                                                           "some shots beyond COR's bounds (section 3)") + ".")
    elif f["tunnel_ok"]:
        f["fast_pick"] = ("- **Fast objects or thin obstacles**: `continuous-time` (or `hybrid`): they bounced in every "
                          "cell of section 3, though no method stayed within COR's bounds in every random shot. "
                          "`simple` misses contacts once speed·dt exceeds the thinnest contact band; penalty lets "
                          "anything through above (radii + thickness)·√(k/m).")
    else:
        f["fast_pick"] = ("- **Fast objects or thin obstacles**: no method bounced in every cell of section 3 in this run "
                          "(see its table); `simple` misses contacts once speed·dt exceeds the thinnest contact band, "
                          "penalty above (radii + thickness)·√(k/m).")
    if f["pile_settles"]:
        f["dense_pick"] = (f"{f['pile_clean']}: no interpenetration, and the pile settles to the packed height, at "
                           f"{f['pile_ct_over_simple']} (`continuous-time`) and {f['pile_hybrid_over_simple']} (`hybrid`) "
                           f"times `simple`'s cost per step (`simple` lets disks sink into each other by up to "
                           f"{f['pile_simple_overlap']} m). Without the penalty layer's push the two are the same method; "
                           f"{f['pile_maxiters_pick']}.")
    else:
        f["dense_pick"] = (f"{f['pile_clean'] or 'no method'} kept the pile free of overlap, but not every such run "
                           f"settled (section 4); {f['pile_maxiters_pick']}.")
    f["compat_pick_line"] = (f"- **Course work** (files the course grades): `--compat`. {f['compat_pick']}"
                             if f.get("compat_pick") else "")


def main(argv):
    args = [a for a in argv[1:] if not a.startswith("--")]
    data_dir = args[0] if args else "docs/study"
    doc = args[1] if len(args) > 1 else "docs/study.md"
    elapsed = None
    if "--elapsed" in argv:
        elapsed = float(argv[argv.index("--elapsed") + 1])
    rel = os.path.relpath(data_dir, os.path.dirname(os.path.abspath(doc)) or ".")
    damped, damped_facts = limits.damped_section(data_dir, rel, sys.modules[__name__])
    shots, shots_facts = limits.shots_section(data_dir, rel, sys.modules[__name__])
    penalty, penalty_facts = limits.penalty_section(data_dir, rel, sys.modules[__name__])
    newton, newton_facts = newton_report.section(data_dir, rel, sys.modules[__name__])
    sections = {
        "accuracy": accuracy_section(data_dir, rel),
        "damped": damped,
        "audit": limits.audit_section(data_dir, rel, sys.modules[__name__]),
        "stability": stability_section(data_dir, rel),
        "robustness": robustness_section(data_dir, rel),
        "shots": shots,
        "penalty": penalty,
        **newton,
        "hybrid": hybrid_section(data_dir, rel),
        "profile": profile_section(data_dir, rel),
        "contacts": contacts.section(data_dir, rel, sys.modules[__name__]),
    }
    all_facts = facts(data_dir)
    all_facts.update(FACTS)
    all_facts.update(damped_facts)
    all_facts.update(shots_facts)
    all_facts.update(penalty_facts)
    all_facts.update(newton_facts)
    all_facts.update(setup.facts(data_dir, sys.modules[__name__]))
    all_facts.update(contacts.facts(data_dir, sys.modules[__name__]))
    mode_facts(data_dir, all_facts)
    pick_facts(all_facts)
    with open(doc, "w") as f:
        f.write(text.document(sections, all_facts, elapsed))
    print(f"report: wrote {doc}")


if __name__ == "__main__":
    main(sys.argv)
