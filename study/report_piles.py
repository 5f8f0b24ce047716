"""The facts of docs/study.md about the settling pile (section 4), the default mode against
`--compat`, and the "What to pick" advice that depends on what was measured."""
import math

import study_data as sd
import report_contacts as contacts
from report_format import fmt, join, problem_name


def failsafe_share(r):
    """Share of the steps that used the failsafe (the CSV fills it for the hybrid only)."""
    if sd.finite(r["failsafe_fraction"]):
        return r["failsafe_fraction"]
    if r["collision"] in ("continuous-time", "hybrid") and r["steps"] > 0:
        return r["failsafe_steps"] / r["steps"]
    return math.nan


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
        # Consecutive maxiters with the same largest part as one range: "the failsafe's zone
        # solves at maxiters 0-20, the narrow phase at 50-100".
        groups = []
        for r, t in zip(runs, top):
            if groups and groups[-1][0] == t:
                groups[-1][2] = int(r["maxiters"])
            else:
                groups.append([t, int(r["maxiters"]), int(r["maxiters"])])
        spans = [f"{names[t]} at maxiters {a}" + (f"-{b}" if b != a else "") for t, a, b in groups]
        where = "the largest share of the step goes to " + ", ".join(spans)
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
        "whatever touches a wall; the default mode welds a jammed contact's particles into one body for the rest of "
        "a step, which slides along the walls it is locked against (it stops them only if they move across their "
        "kick by at most a kick).\n" if found else "")


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
