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
        cells = []
        for m in sd.unique(mine, "method"):
            pts = sorted([r for r in mine if r["method"] == m and r["outcome"] == "ok" and sd.finite(r["error"])],
                         key=lambda r: r["dt"])[:5]
            if pts and max(r["error"] for r in pts) < 1e-12:
                cells.append(f"{m}: exact")
                continue
            q = sd.order_of_convergence([r["dt"] for r in pts], [r["error"] for r in pts])
            cells.append(f"{m}: {fmt(q)}")
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
    out.append("**Observed order of accuracy** (slope of log error against log dt over the five finest "
               "time steps that ran; 1 = halving dt halves the error, 0 = the error does not shrink, "
               "negative = it grows):\n")
    out.append(table(["problem", "order per method"], order_rows))
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

def stability_section(data_dir, rel):
    rows = sd.load(data_dir, "stability")
    out = [image(rel, "stability", "largest stable dt against stiffness")]
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
            body.append([system, integ, measured, text.STABILITY_THEORY[integ], ", ".join(reasons) or "—"])
    out.append(table(["system", "integrator", "measured limit ω_max·dt (over all k)", "theory",
                      "how the unstable runs ended"], body))
    return "\n\n".join(out)


# ---- robustness ------------------------------------------------------------------------------

def robustness_section(data_dir, rel):
    rows = sd.load(data_dir, "robustness")
    out = [image(rel, "robustness", "outcome maps against a thin edge"),
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
        body.append([label, r["outcome"], fmt(100 * r["failsafe_fraction"], 3) if sd.finite(r["failsafe_fraction"]) else "—",
                     fmt(r["mean_passes"], 3), fmt(r["largest_zone"], 3), fmt(r["us_per_step"], 3),
                     fmt(r["collisions_per_step"], 3), int(r["overlap_steps"]), fmt(r["max_overlap"], 2),
                     fmt(r["mean_height_end"], 3), fmt(r["kinetic_end"], 2)])
    out.append(table(["method", "run", "failsafe steps [%]", "passes per step", "largest zone",
                      "µs per step", "collisions per step", "steps ending with overlap", "deepest overlap [m]",
                      f"mean height at the end [m] (start {fmt(rows[0]['mean_height_start'], 3)})",
                      "kinetic energy at the end [J]"], body))
    return "\n\n".join(out)


# ---- profile -----------------------------------------------------------------------------------

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
        body.append([f"{r['scene']} — {r['method']}", forces, ", ".join(pairs) or "—", fmt(r["total_us"], 3),
                     fmt(r["forces_us"], 2), fmt(r["jacobians_us"], 2), fmt(r["solve_us"], 2),
                     fmt(r["narrow_us"], 3), fmt(r["response_us"], 2), fmt(r["failsafe_us"], 3),
                     fmt(r["collision_other_us"], 2)])
    out.append(table(["scene — method", "forces", "pairs per detection pass (queried per step)", "step µs",
                      "forces µs", "Jacobians µs", "solve µs", "narrow µs", "response µs", "failsafe µs",
                      "rest µs"], body))
    return "\n\n".join(out)


# ---- facts for the prose ---------------------------------------------------------------------

def median(xs):
    xs = sorted(x for x in xs if sd.finite(x))
    return xs[len(xs) // 2] if xs else math.nan


def facts(data_dir):
    """The numbers the prose quotes, from this run's CSV files (report_text.py uses them)."""
    acc = sd.load(data_dir, "accuracy")
    prof = sd.load(data_dir, "profile")
    hyb = sd.load(data_dir, "hybrid")

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
    ratios += [prof_total("Row of 10", m) / prof_total("Row of 10", "symplectic-euler")
               for m in ("implicit-euler", "linearized-implicit-euler")]
    ratios = [r for r in ratios if sd.finite(r)]
    f["implicit_cost"] = f"{min(ratios):.0f}-{max(ratios):.0f}" if ratios else "several"

    coarse = lambda problem, method: max(acc_rows(problem, method), key=lambda r: r["dt"])  # noqa: E731
    f["explicit_gain"] = fmt(coarse("spring", "explicit-euler")["energy_error"] + 1, 2)
    f["explicit_gain_dt"] = f"{coarse('spring', 'explicit-euler')['dt']:g}"
    f["implicit_loss"] = fmt(100 * coarse("spring", "implicit-euler")["energy_error"], 4)
    failed = sorted(r["dt"] for r in acc_rows("orbit", "implicit-euler") if r["outcome"] != "ok")
    f["orbit_failure"] = (f"at dt ≥ {min(failed):g} (here: {', '.join('%g' % d for d in failed)})" if failed
                          else "not in this run (it did at dt ≥ 0.01 before)")
    gain = median(r["energy_error"] for r in acc if r["problem"] == "billiards" and r["method"].startswith("hybrid"))
    f["hybrid_gain"] = f"{100 * gain:.0f} %" if sd.finite(gain) else "—"
    bare = median(r["energy_error"] for r in acc if r["problem"] == "billiards" and r["method"] == "hybrid k=0")
    f["hybrid_k0_gain"] = f"{100 * bare:.0f} %" if sd.finite(bare) and bare >= 5e-3 else fmt(bare, 2)
    gain = median(r["energy_error"] for r in acc if r["problem"] == "billiards" and r["method"] == "hybrid")
    f["hybrid_gain"] = f"{100 * gain:.0f} %" if sd.finite(gain) else "—"
    summed = sd.finite(bare) and bare >= 1e-3  # the course's summed impulses gain at k = 0 too
    f["billiard_words"] = (text.BILLIARD_SUMMED if summed else text.BILLIARD_PENALTY).format(**f)
    f["billiard_oddity"] = (text.ODDITY_SUMMED if summed else text.ODDITY_PENALTY).format(**f)

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
    default = by.get(("hybrid", 10.0))
    simple = by.get(("simple", None))
    ct = by.get(("continuous-time", None))
    f["pile_hybrid_over_simple"] = fmt(default["us_per_step"] / simple["us_per_step"], 2) if default and simple else "—"
    f["pile_hybrid_over_ct"] = fmt(default["us_per_step"] / ct["us_per_step"], 2) if default and ct else "—"
    f["pile_failsafe"] = f"{100 * default['failsafe_fraction']:.0f} %" if default else "—"
    f["pile_zone"] = (f"{default['mean_failsafe_particles']:.0f} of {default['particles']:.0f}" if default else "—")
    pile = next((r for r in prof if r["scene"].startswith("Dense pile") and r["method"] == "hybrid"), None)
    queries = pile["pp_queries"] + pile["pe_queries"] + pile["ph_queries"] if pile else math.nan
    pairs = pile["pp_pairs"] + pile["pe_pairs"] + pile["ph_pairs"] if pile else math.nan
    passes = default["mean_passes"] if default else math.nan
    broad = any(r["broad_us"] > 0 for r in prof)
    if broad:
        f["detection_words"] = (
            f"- **A broad phase prunes the pairs** before the continuous-time queries: on the pile the hybrid "
            f"queries {fmt(queries, 2)} pairs per step, against {fmt(pairs, 3)} pairs per detection pass and "
            f"{fmt(passes, 2)} impulse passes per step (plus the failsafe's rounds); the broad phase itself "
            f"costs {fmt(pile['broad_us'], 2)} µs of the step's {fmt(pile['total_us'], 3)}.")
        f["oddity_broad"] = ""
    else:
        f["detection_words"] = (
            f"- **Collision detection visits every pair every pass** (no broad phase): {fmt(pairs, 3)} pairs "
            f"per pass on the pile of 40 disks, and the hybrid repeats that for every impulse pass and "
            f"failsafe round ({fmt(queries, 2)} queries per step).")
        f["oddity_broad"] = ("- There is no broad phase: every detection pass visits all pairs (O(N²)), "
                             "which dominates the hybrid's cost on a pile.\n")
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
    f["oddity_stats"] = ("- `StepStats`: " + "; ".join(stats) + ".\n") if stats else ""
    return f


def main(argv):
    args = [a for a in argv[1:] if not a.startswith("--")]
    data_dir = args[0] if args else "docs/study"
    doc = args[1] if len(args) > 1 else "docs/study.md"
    elapsed = None
    if "--elapsed" in argv:
        elapsed = float(argv[argv.index("--elapsed") + 1])
    rel = os.path.relpath(data_dir, os.path.dirname(os.path.abspath(doc)) or ".")
    sections = {
        "accuracy": accuracy_section(data_dir, rel),
        "stability": stability_section(data_dir, rel),
        "robustness": robustness_section(data_dir, rel),
        "hybrid": hybrid_section(data_dir, rel),
        "profile": profile_section(data_dir, rel),
        "contacts": contacts.section(data_dir, rel, sys.modules[__name__]),
    }
    all_facts = facts(data_dir)
    all_facts.update(contacts.facts(data_dir, sys.modules[__name__]))
    with open(doc, "w") as f:
        f.write(text.document(sections, all_facts, elapsed))
    print(f"report: wrote {doc}")


if __name__ == "__main__":
    main(sys.argv)
