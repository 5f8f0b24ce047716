"""docs/study.md's part on implicit Euler's Newton iteration (report.py calls it): where it fails on
orbits (newton_failure.csv) and how many iterations it takes per step against dt and stiffness
(newton_iterations.csv, and the orbits' counts). Every number comes from the CSV files; the set-up
(mu, apoapsis, periods, Newton's tolerance and iteration limit) too, as the experiments wrote it.
"""
import os

import study_data as sd
from report_setup import num


def intro_facts(data_dir, r):
    """The set-up's numbers for the section's introduction (report_text.py)."""
    f = {}
    if os.path.exists(os.path.join(data_dir, "newton_failure.csv")):
        o = sd.load(data_dir, "newton_failure")[0]
        f.update(newton_mu=r.fmt(o["mu"], 3), newton_apoapsis=r.fmt(o["apoapsis"], 3),
                 newton_periods=r.fmt(o["periods"], 3))
    if os.path.exists(os.path.join(data_dir, "newton_iterations.csv")):
        s = sd.load(data_dir, "newton_iterations")[0]
        f.update(newton_tolerance=num(s["tolerance"]), newton_limit=f"{int(s['iteration_limit'])}")
    return f


def failure_words(rows, r):
    imp = [x for x in rows if x["integrator"] == "implicit-euler"]
    failed = [x for x in imp if x["outcome"] == "solver-failure"]
    ran = [x for x in imp if x["outcome"] == "ok"]
    inside = [x for x in failed if x["min_separation"] < x["periapsis"]]
    lin = [x for x in rows if x["integrator"] == "linearized-implicit-euler"]
    lin_bad = [x for x in lin if x["outcome"] == "ok" and x["min_separation"] < 0.5 * x["periapsis"]]
    return (f"Newton failed in {len(failed)} of {len(imp)} runs"
            + (f"; the largest dt·ω_p that ran to the end was {r.fmt(max(x['dt_omega'] for x in ran), 3)} and "
               f"the smallest that failed {r.fmt(min(x['dt_omega'] for x in failed), 3)}" if ran and failed else "")
            + (". Every failed run had first fallen inside its true periapsis" if failed and len(inside) == len(failed)
               else f". {len(inside)} of the {len(failed)} failed runs had first fallen inside their true periapsis"
               if failed else "")
            + f". Linearized implicit Euler never stops with a solver failure, yet {len(lin_bad)} of its {len(lin)} "
            "runs came within half the true periapsis (no sign of trouble in its output).")


def orbit_iteration_words(rows, r):
    """The orbits' iteration counts: the mean per step against dt·ω_p, and the failed runs' last step."""
    imp = [x for x in rows if x["integrator"] == "implicit-euler" and sd.finite(x["mean_iterations"])]
    ran = sorted([x for x in imp if x["outcome"] == "ok"], key=lambda x: x["dt_omega"])
    failed = [x for x in imp if x["outcome"] == "solver-failure"]
    lin = [x for x in rows if x["integrator"] == "linearized-implicit-euler"]
    if not ran:
        return ""
    words = (f"On the orbits, the runs that reached the end took {r.fmt(min(x['mean_iterations'] for x in ran), 3)} to "
             f"{r.fmt(max(x['mean_iterations'] for x in ran), 3)} iterations per step on average (at dt·ω_p = "
             f"{r.fmt(ran[0]['dt_omega'], 3)}: {r.fmt(ran[0]['mean_iterations'], 3)}; at "
             f"{r.fmt(ran[-1]['dt_omega'], 3)}: {r.fmt(ran[-1]['mean_iterations'], 3)}), and at most "
             f"{max(int(x['max_iterations']) for x in ran)} in one step")
    if failed:
        words += (f"; the {len(failed)} failed runs had averaged {r.fmt(min(x['mean_iterations'] for x in failed), 3)} "
                  f"to {r.fmt(max(x['mean_iterations'] for x in failed), 3)} per step before the step where Newton "
                  f"reached its limit of {max(int(x['max_iterations']) for x in failed)}")
    if lin:
        words += (f". Linearized implicit Euler reported {sorted(set(int(x['max_iterations']) for x in lin))[0]} "
                  f"per step in all {len(lin)} of its runs" if len(set(int(x['max_iterations']) for x in lin)) == 1
                  else ". Linearized implicit Euler's counts varied")
    return words + "."


def spring_iteration_words(rows, r):
    """The two-spring particle's counts against k and dt, and the linear control."""
    spring = [x for x in rows if x["rest_length"] > 0]
    control = [x for x in rows if x["rest_length"] == 0]
    if not spring:
        return ""
    s0 = spring[0]
    ks, dts = sorted(sd.unique(spring, "k")), sorted(sd.unique(spring, "dt"))
    ok = [x for x in spring if x["outcome"] == "ok"]
    at = lambda k, dt: next(x for x in spring if x["k"] == k and x["dt"] == dt)  # noqa: E731
    small, large = [at(k, dts[0]) for k in ks], [at(k, dts[-1]) for k in ks]
    rising = sum(all(at(k, a)["mean_iterations"] <= at(k, b)["mean_iterations"] for a, b in zip(dts, dts[1:]))
                 for k in ks)
    most = max(ok, key=lambda x: x["max_iterations"]) if ok else None
    words = (f"A particle of mass {r.fmt(s0['mass'], 3)} held between two fixed anchors at "
             f"(±{r.fmt(s0['anchor'], 3)}, 0) by two springs of rest length {r.fmt(s0['rest_length'], 3)}, started at "
             f"({r.fmt(s0['start_x'], 3)}, {r.fmt(s0['start_y'], 3)}) moving at {r.fmt(s0['speed'], 3)} m/s along the "
             "anchors' line: the springs pull in different directions that turn within each step, so the force is "
             "nonlinear in the unknown velocity. (One spring alone would not show it: every Newton iterate stays on "
             "the ray from the anchor through x + h·v, along which the spring's force is affine in the length, so "
             "Newton is done after one update.) Each run lasts "
             f"{r.fmt(s0['steps'] * s0['dt'], 3)} s, with k from {num(ks[0])} to {num(ks[-1])} N/m and dt from "
             f"{num(dts[0])} to {num(dts[-1])} s; ω = √(2k/m) is the stiffer mode's frequency. At dt = "
             f"{num(dts[0])} s Newton took {r.fmt(min(x['mean_iterations'] for x in small), 3)} to "
             f"{r.fmt(max(x['mean_iterations'] for x in small), 3)} iterations per step on average over the "
             f"stiffnesses; at dt = {num(dts[-1])} s, {r.fmt(min(x['mean_iterations'] for x in large), 3)} to "
             f"{r.fmt(max(x['mean_iterations'] for x in large), 3)}. The mean never fell as dt grew for "
             f"{rising} of the {len(ks)} stiffnesses")
    if most:
        words += (f"; the most in one step was {int(most['max_iterations'])} (k = {num(most['k'])} N/m, dt = "
                  f"{num(most['dt'])} s, dt·ω = {r.fmt(most['dt_omega'], 3)})")
    failed = [x for x in spring if x["outcome"] != "ok"]
    words += (f"; Newton failed in {len(failed)} of the {len(spring)} runs"
              + (f" (smallest dt·ω that failed: {r.fmt(min(x['dt_omega'] for x in failed), 3)})" if failed else "")
              + f", far from the limit of {int(s0['iteration_limit'])} iterations.")
    if control:
        most_control = max(int(x["max_iterations"]) for x in control)
        below = [x for x in control if x["mean_iterations"] < most_control]
        words += (" The control, the same runs with rest length 0 (F = −k·(x − a) per spring, linear: Newton's first "
                  "update solves the step exactly and the second is round-off), took at most "
                  f"{most_control} iterations in any step of its {len(control)} runs"
                  + (f"; in {len(below)} of them the mean is below {most_control} (down to "
                     f"{r.fmt(min(x['mean_iterations'] for x in below), 3)}) because the stiff springs damp the motion "
                     f"out within the run, and a step whose first update is already below {num(s0['tolerance'])} of its "
                     "velocities takes one" if below else "") + ".")
    return words


def section(data_dir, rel, r):
    """The charts (sections "newton" with the table of failures per eccentricity, "newton_iterations")
    and the paragraphs and set-up numbers (facts) for report_text."""
    if not os.path.exists(os.path.join(data_dir, "newton_failure.csv")):
        return {}, {"newton_words": "", "newton_iteration_words": ""}
    rows = sd.load(data_dir, "newton_failure")
    imp = [x for x in rows if x["integrator"] == "implicit-euler"]
    body = []
    for e in sorted(set(x["eccentricity"] for x in imp)):
        mine = sorted([x for x in imp if x["eccentricity"] == e], key=lambda x: x["dt"])
        ok = [x["dt"] for x in mine if x["outcome"] == "ok"]
        bad = [x["dt"] for x in mine if x["outcome"] == "solver-failure"]
        body.append([f"{e:.2f}", r.fmt(mine[0]["periapsis"], 3), r.fmt(mine[0]["omega_periapsis"], 3),
                     r.fmt(max(ok), 2) if ok else "none", r.fmt(min(bad), 2) if bad else "none",
                     r.fmt(max(x["min_separation"] / x["periapsis"] for x in mine if x["outcome"] != "ok"), 2)
                     if bad else "—"])
    out = [r.image(rel, "newton", "where implicit Euler's Newton fails"),
           r.table(["eccentricity", "true periapsis r_p", "ω_p = √(μ/r_p³) [1/s]", "largest dt that ran to the end [s]",
                    "smallest dt that failed [s]", "closest approach / r_p of the failed runs (largest)"], body)]
    sections = {"newton": "\n\n".join(out)}
    iterations = ""
    if os.path.exists(os.path.join(data_dir, "newton_iterations.csv")):
        sections["newton_iterations"] = r.image(rel, "newton_iterations",
                                                "Newton iterations per step against dt and stiffness")
        iterations = " ".join(w for w in (spring_iteration_words(sd.load(data_dir, "newton_iterations"), r),
                                          orbit_iteration_words(rows, r)) if w)
    facts = {"newton_words": failure_words(rows, r), "newton_iteration_words": iterations}
    facts.update(intro_facts(data_dir, r))
    return sections, facts
