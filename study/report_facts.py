"""The numbers docs/study.md's prose quotes, from the study's CSV files (report_text.py holds the
words around them): accuracy, collisions, robustness and the profile. The pile's and the modes'
facts are in report_piles.py."""
import math

import study_data as sd
import report_text as text
import report_limits as limits
import report_format
from report_format import fmt, median, problem_name, join
from report_piles import hybrid_pile_facts


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
    limits.energy_facts(acc, report_format, f)
    limits.comparison_facts(acc, report_format, f)

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
