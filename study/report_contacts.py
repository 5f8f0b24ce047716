"""The multi-contact section of docs/study.md (contacts_summary.csv, contacts_series.csv): the
outcome table, and the numbers its prose quotes (report_text.CONTACTS_WORDS). Every number and
every comparative word ("kept", "escaped", "frozen", "the same in both modes") is decided here
from the data; the words around them are report_text.py's.
"""
import math
import os
import re

import study_data as sd


def title_cor(title):
    """The COR a problem's title states ("... (COR 1)" -> "COR 1"): the scene's own, not retyped."""
    m = re.search(r"COR [0-9.]+", title)
    return m.group(0) if m else "its COR"


def percent(fmt, x, digits=2):
    if not sd.finite(x):
        return "—"
    return f"{100 * x:.0f} %" if 100 * x >= 10 else fmt(100 * x, digits) + " %"


def near_one(values, fmt):
    """How close ratios that should be 1 came: "exactly" or "to within 3e-16"."""
    dev = max(abs(v - 1) for v in values) if values else math.nan
    if not sd.finite(dev):
        return "(not measured)"
    return "exactly" if dev == 0 else f"to within {fmt(dev, 1)}"


def rows_of(data_dir):
    """The contacts summary, or None when this run did not include the experiment."""
    if not os.path.exists(os.path.join(data_dir, "contacts_summary.csv")):
        return None
    return sd.load(data_dir, "contacts_summary")




def section(data_dir, rel, rep):
    """The charts and the outcome table; `rep` is report.py (its fmt, table and image)."""
    fmt, table, image = rep.fmt, rep.table, rep.image
    pct = lambda x, digits=2: percent(fmt, x, digits)  # noqa: E731
    rows = rows_of(data_dir)
    if rows is None:
        return ""
    out = [image(rel, "contacts", "energy, momentum and angular momentum over time, default mode and --compat"),
           image(rel, "contact_outcomes", "pile height, failsafe share, rigid zones and slot escapes over time")]
    body, last = [], None
    for r in rows:
        title = r["title"] if r["problem"] != last else ""
        last = r["problem"]
        escaped = f"{int(r['escaped'])} of {int(r['escapable'])}" if r["escapable"] > 0 else "—"
        if r["shots"] > 1 and r["escapable"] > 0:
            escaped += f" ({int(r['shots_escaped'])} of {int(r['shots'])} shots)"
        speed = fmt(r["speed_ratio"], 3) if sd.finite(r["speed_ratio"]) else "—"
        if r["frozen"] == 1:
            rest = f"**frozen** at {r['stopped_time']:g} s"
        elif r["stopped"] == 1:
            rest = f"at rest from {r['stopped_time']:g} s"
        else:
            rest = "moving"
        zones = f"{pct(r['zone_fraction_mean'])} / {pct(r['zone_fraction_max'])}" if r["zone_fraction_max"] > 0 else "0"
        body.append([title, "default" if r["mode"] == "default" else "--compat", r["collision"], fmt(r["energy_gain"], 3),
                     fmt(r["energy_end"], 3), escaped, speed, rest, zones, f"{int(r['rigid_zone_steps'])} of {int(r['steps'])}",
                     fmt(r["max_overlap"], 2)])
    out.append(table(["problem", "mode", "type", "largest E / E0", "E_end / E0", "escaped", "speed ratio (below)",
                      "motion at the end", "disks in zones: mean / most", "steps with rigid zones",
                      "deepest overlap [m]"], body))
    labels = [f"{r['title'].split(':')[0]}: {r['speed_label']}" for r in rows
              if isinstance(r["speed_label"], str) and r["mode"] == "default" and r["collision"] == "hybrid"]
    out.append("Speed ratios: " + "; ".join(labels) + ".")
    if any(r["problem"] == "clump" for r in rows):
        out.append("E / E0 is 1 + (E - E0) / |E0| throughout, the same where E0 is positive; the clump's "
                   "gravitational energy makes its E0 negative, and a gain still reads above 1.")
    return "\n\n".join(out)



def facts(data_dir, rep):
    """Sentences with this run's numbers for report_text.CONTACTS_WORDS (empty without the data)."""
    rows = rows_of(data_dir)
    if rows is None:
        return {"contacts_words": ""}
    series = sd.load(data_dir, "contacts_series")
    fmt = rep.fmt
    pct = lambda x, digits=2: percent(fmt, x, digits)  # noqa: E731
    by = {(r["problem"], r["mode"], r["collision"]): r for r in rows}
    types = ("continuous-time", "hybrid")

    def get(problem, mode, collision):
        return by.get((problem, mode, collision))

    def both(problem, mode, key):
        """The value of `key` for both types: one number if they agree to 3 digits, else a pair."""
        a, b = (get(problem, mode, t) for t in types)
        if not a or not b:
            return "—"
        fa, fb = fmt(a[key], 3), fmt(b[key], 3)
        return fa if fa == fb else f"{fa} (continuous-time) and {fb} (hybrid)"

    def worst(problem, mode, key, transform=lambda x: x):
        vals = [transform(get(problem, mode, t)[key]) for t in types if get(problem, mode, t)]
        vals = [v for v in vals if sd.finite(v)]
        return max(vals) if vals else math.nan

    def first_contacts(problem, mode, collision):
        """Contacts counted in the first step that had any."""
        for r in series:
            if r["problem"] == problem and r["mode"] == mode and r["collision"] == collision and r["contacts"] > 0:
                return int(r["contacts"])
        return 0

    def first_escape(problem, mode, collision):
        for r in series:
            if r["problem"] == problem and r["mode"] == mode and r["collision"] == collision and r["escaped"] > 0:
                return r["time"]
        return math.nan

    f = {}
    # Joint drop.
    jd, jc, jh = get("joint-drop", "default", "hybrid"), get("joint-drop", "compat", "continuous-time"), \
        get("joint-drop", "compat", "hybrid")
    if jd and jc and jh:
        f["joint_default_ratio"] = near_one([get("joint-drop", "default", t)["speed_ratio"] for t in types], fmt)
        f["joint_default_gain"] = both("joint-drop", "default", "energy_gain")
        f["joint_compat_contacts"] = first_contacts("joint-drop", "compat", "hybrid")
        f["joint_compat_ratio"] = fmt(jh["speed_ratio"], 3)
        f["joint_compat_gain"] = fmt(jh["energy_gain"], 3)
        f["joint_compat_ct_ratio"] = fmt(jc["speed_ratio"], 3)
        f["joint_compat_ct_gain"] = fmt(jc["energy_gain"], 3)
    # Touching rack.
    dev = worst("touching-rack", "default", "energy_end", lambda x: abs(x - 1))
    f["rack_default_energy"] = "nothing (to the last bit)" if dev == 0 else f"{fmt(dev, 2)} (relative)"
    f["rack_default_momentum"] = fmt(worst("touching-rack", "default", "momentum_drift"), 2)
    f["rack_default_angular"] = fmt(worst("touching-rack", "default", "angular_drift"), 2)
    f["rack_compat_gain"] = both("touching-rack", "compat", "energy_gain")
    # Corridor.
    cd = [get("corridor", "default", t) for t in types]
    f["corridor_default_escapes"] = "none" if all(r and r["escaped"] == 0 for r in cd) else "some"
    f["corridor_default_speed"] = near_one([r["speed_ratio"] for r in cd if r], fmt)
    f["corridor_default_bounces"] = fmt(min(r["contacts"] / r["steps"] for r in cd if r), 3)
    cc, ch = get("corridor", "compat", "continuous-time"), get("corridor", "compat", "hybrid")
    if cc and ch:
        f["corridor_compat_ct"] = (f"goes through a wall at t = {first_escape('corridor', 'compat', 'continuous-time'):g} s "
                                   f"and ends {fmt(abs(cc['height_end']), 3)} m from the corridor's middle line"
                                   if cc["escaped"] > 0 else "stays inside")
        f["corridor_compat_hybrid"] = (f"stops dead at t = {ch['stopped_time']:g} s (speed ratio {fmt(ch['speed_ratio'], 2)})"
                                       if ch["frozen"] == 1 else f"keeps {fmt(ch['speed_ratio'], 3)} of its speed")
    # Slot.
    sd_rows = [get("slot", "default", t) for t in types]
    sc, sh = get("slot", "compat", "continuous-time"), get("slot", "compat", "hybrid")
    if all(sd_rows) and sc and sh:
        f["slot_disks"] = int(sd_rows[0]["escapable"])
        f["slot_shots"] = int(sd_rows[0]["shots"])
        f["slot_default_escaped"] = " and ".join(str(int(r["escaped"])) for r in sd_rows) \
            if sd_rows[0]["escaped"] != sd_rows[1]["escaped"] else str(int(sd_rows[0]["escaped"]))
        loss = [1 - r["energy_end"] for r in sd_rows]
        f["slot_loss"] = (f"which removes {pct(loss[0])} (continuous-time) and {pct(loss[1])} (hybrid) of the kinetic "
                          f"energy that {title_cor(sd_rows[0]['title'])} would keep: the price of never tunnelling"
                          if min(loss) > 1e-9 else
                          f"which kept the kinetic energy to {fmt(max(abs(x) for x in loss), 1)}")
        f["slot_zones"] = f"{pct(sd_rows[0]['zone_fraction_max'])} and {pct(sd_rows[1]['zone_fraction_max'])}"
        per_step = max(r["contacts"] for r in series if r["problem"] == "slot" and r["mode"] == "default")
        f["slot_contacts"] = fmt(per_step / sd_rows[0]["shots"], 3)
        f["slot_compat_ct"] = f"{int(sc['escaped'])} of {int(sc['escapable'])} disks ({int(sc['shots_escaped'])} of {int(sc['shots'])} shots)"
        f["slot_compat_hybrid"] = (f"keeps them all in by stopping every disk (kinetic energy zero from t = {sh['stopped_time']:g} s)"
                                   if sh["frozen"] == 1 else f"lets {int(sh['escaped'])} through")
    # Newton's cradle.
    cr = [r for r in rows if r["problem"] == "cradle"]
    if cr:
        lo, hi = min(r["speed_ratio"] for r in cr), max(r["speed_ratio"] for r in cr)
        others = max(r["others_speed"] for r in cr)
        same = all(abs(r["speed_ratio"] - 1) < 1e-9 and r["others_speed"] < 1e-9 for r in cr)
        f["cradle_words"] = (
            f"both modes, both types, pass the velocity on: the last ball leaves at the first ball's speed "
            f"{near_one([lo, hi], fmt)} and the first four keep at most {fmt(others, 2)} of it: a row of "
            "touching balls, each pushed by one neighbour at a time, is not where the course's summed impulses "
            "fail; several contacts on one body in the same pass (the joint, the rack) are." if same else
            f"The last ball leaves at {fmt(lo, 4)} to {fmt(hi, 4)} times the first ball's speed over the four runs, "
            f"and the first four keep up to {fmt(others, 2)} of it (see the table for which run).")
    # Pile in a V.
    pdr = [get("pile", "default", t) for t in types]
    pc, ph = get("pile", "compat", "continuous-time"), get("pile", "compat", "hybrid")
    if all(pdr) and pc and ph:
        d = pdr[1]
        f["pile_disks"] = int(d["particles"])
        f["pile_zone_mean"] = " and ".join(pct(r["zone_fraction_mean"]) for r in pdr)
        f["pile_zone_max"] = " and ".join(pct(r["zone_fraction_max"]) for r in pdr)
        f["pile_steps"] = int(d["steps"])
        f["pile_rigid"] = ("no zone had to fall back to rigid motion in any of the "
                           f"{int(d['steps'])} steps" if all(r["rigid_zone_steps"] == 0 for r in pdr) else
                           "a zone fell back to rigid motion (it touched nothing) in " +
                           " and ".join(f"{int(r['rigid_zone_steps'])}" for r in pdr) + f" of the {int(d['steps'])} steps")
        f["pile_default_height"] = " and ".join(fmt(r["height_end"], 3) for r in pdr)
        f["pile_lattice"] = fmt(d["height_packed"], 3)
        f["pile_frozen_height"] = fmt(d["height_frozen"], 3)
        f["pile_default_packing"] = " and ".join(fmt(r["packing_end"], 2) for r in pdr)
        flows = all(r["frozen"] == 0 for r in pdr)
        f["pile_default_flow"] = "neither default run froze" if flows else "a default run froze (see the table)"
        f["pile_flows"] = "The pile flows" if flows else "The pile does not flow everywhere"
        f["pile_compat_hybrid"] = (
            f"comes to rest at t = {ph['stopped_time']:g} s with its mean height at {fmt(ph['height_end'], 3)} m "
            f"(packing {fmt(ph['packing_end'], 2)}): frozen, every zone rigid ({int(ph['rigid_zone_steps'])} of "
            f"{int(ph['steps'])} steps had one) and the zones against the walls held still"
            if ph["frozen"] == 1 else
            f"ends at a mean height of {fmt(ph['height_end'], 3)} m (packing {fmt(ph['packing_end'], 2)}), not frozen")
        f["pile_compat_ct"] = (f"has no failsafe: disks sink into each other by up to {fmt(pc['max_overlap'], 2)} m "
                               f"and the mean height falls to "
                               f"{fmt(pc['height_end'], 3)} m, against {fmt(d['height_packed'], 3)} m for the lattice "
                               "filling")
        total = sum(r["wall_s"] for r in rows)
        f["contacts_cost"] = (f"The experiment steps for {fmt(total, 2)} s in all; the default mode's pile costs "
                              f"{fmt(1e3 * pdr[0]['wall_s'] / pdr[0]['steps'], 2)} and "
                              f"{fmt(1e3 * pdr[1]['wall_s'] / pdr[1]['steps'], 2)} ms per step (continuous-time, "
                              f"hybrid) against {fmt(1e3 * ph['wall_s'] / ph['steps'], 2)} ms for --compat's hybrid.")
    # Clump.
    kd = [get("clump", "default", t) for t in types]
    kc, kh = get("clump", "compat", "continuous-time"), get("clump", "compat", "hybrid")
    if all(kd) and kc and kh:
        f["clump_disks"] = int(kd[0]["particles"])
        f["clump_default_momentum"] = fmt(worst("clump", "default", "momentum_drift"), 2)
        f["clump_default_angular"] = fmt(worst("clump", "default", "angular_drift"), 2)
        f["clump_zone_mean"] = " and ".join(pct(r["zone_fraction_mean"]) for r in kd)
        f["clump_steps"] = int(kd[0]["steps"])
        f["clump_rigid"] = " and ".join(str(int(r["rigid_zone_steps"])) for r in kd)
        f["clump_compat_ct"] = (f"moves angular momentum by {fmt(kc['angular_drift'], 2)} of its scale and its energy "
                                f"peaks at {fmt(kc['energy_gain'], 3)} times its start")
        f["clump_compat_hybrid"] = f"moves angular momentum by {fmt(kh['angular_drift'], 2)}"
    try:
        from report_text import CONTACTS_WORDS
        f["contacts_words"] = CONTACTS_WORDS.format(**f)
    except KeyError:  # a quick run without some problem: the table alone
        f["contacts_words"] = ""
    return f
