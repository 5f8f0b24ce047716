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
# fmt, table, image and join are also what the section modules use of this module (their `rep`).
from report_format import fmt, image, join, table  # noqa: E402,F401
from report_facts import facts, profile_parts  # noqa: E402
from report_piles import failsafe_share, mode_facts, pick_facts  # noqa: E402


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
        p = profile_parts(r)
        body.append([f"{r['scene']} — {r['method']}", forces, ", ".join(pairs) or "—", fmt(r["total_us"], 3),
                     fmt(p["forces_us"], 2), fmt(p["jacobians_us"], 2), fmt(p["solve_us"], 2),
                     fmt(p["narrow_us"], 3), fmt(p["response_us"], 2), fmt(p["failsafe_us"], 3),
                     fmt(p["collision_other_us"], 2)])
    out.append(table(["scene — method", "forces", "pairs per detection pass (queried per step)", "step µs",
                      "forces µs", "Jacobians µs", "solve µs", "narrow µs", "response µs", "failsafe µs",
                      "rest µs"], body))
    return "\n\n".join(out)



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
