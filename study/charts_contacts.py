"""Charts of the multi-contact problems (study/contact_problems.h), called by charts.py:

    contacts.png          energy, |momentum| and angular momentum over time per problem, the
                          default mode next to --compat
    contact_outcomes.png  the pile's mean height, failsafe share and rigid zones, and the slot's
                          escapes over time
"""
import math

import matplotlib.pyplot as plt

import study_data as sd
from charts import save


# One colour per mode, one line style per collision type, in both contact charts.
MODE_COLORS = {"default": "#1f77b4", "compat": "#d62728"}
TYPE_STYLES = {"continuous-time": "-", "hybrid": "--"}


def contact_runs(rows):
    """(mode, collision) pairs in first-seen order."""
    return sd.unique([{"k": (r["mode"], r["collision"])} for r in rows], "k")


def contact_line(ax, rows, mode, collision, y, **kw):
    mine = [r for r in rows if r["mode"] == mode and r["collision"] == collision]
    ax.plot([r["time"] for r in mine], [y(r, mine) for r in mine], color=MODE_COLORS[mode],
            ls=TYPE_STYLES[collision], lw=1.3 if mode == "default" else 1.0,
            label=f"{'default mode' if mode == 'default' else '--compat'}, {collision}", **kw)


def chart_contacts(data_dir):
    rows = sd.load(data_dir, "contacts_series")
    summary = sd.load(data_dir, "contacts_summary")
    problems = sd.unique(rows, "problem")
    titles = {r["problem"]: r["title"] for r in summary}
    quantities = [
        # E / E0, generalised to 1 + (E - E0) / |E0| (the same for E0 > 0; a gain still rises above
        # 1 where the start is negative: the clump's gravitational energy).
        ("energy relative to its start, 1 + (E - E0) / |E0|",
         lambda r, mine: 1 + (r["energy"] - mine[0]["energy"]) / abs(mine[0]["energy"])),
        ("|momentum| [kg m/s]", lambda r, mine: r["momentum"]),
        ("angular momentum about the origin [kg m²/s]", lambda r, mine: r["angular_momentum"]),
    ]
    fig, axes = plt.subplots(len(problems), len(quantities), figsize=(5.0 * len(quantities), 2.7 * len(problems)),
                             squeeze=False)
    for row, p in enumerate(problems):
        mine = [r for r in rows if r["problem"] == p]
        for col, (label, y) in enumerate(quantities):
            ax = axes[row][col]
            for mode, collision in contact_runs(mine):
                contact_line(ax, mine, mode, collision, y)
            ax.set_ylabel(label, fontsize=7.5)
            if col == 0:
                ax.set_title(titles.get(p, p), fontsize=8.5, loc="left")
            if row == len(problems) - 1:
                ax.set_xlabel("time [s]")
    handles, labels = axes[0][0].get_legend_handles_labels()
    fig.legend(handles, labels, loc="upper center", ncol=4, bbox_to_anchor=(0.5, 0.995))
    fig.suptitle("Multi-contact problems: energy, momentum and angular momentum over time, the default mode (blue) "
                 "next to --compat (red).\nWalls, floors, fixed edges and gravity exchange momentum with the "
                 "particles; only the rack, the cradle and the clump are isolated (both momenta should stay flat).",
                 y=1.025, fontsize=10)
    fig.tight_layout(rect=(0, 0, 1, 0.975))
    save(fig, data_dir, "contacts")


def chart_contact_outcomes(data_dir):
    rows = sd.load(data_dir, "contacts_series")
    summary = sd.load(data_dir, "contacts_summary")
    pile = [r for r in rows if r["problem"] == "pile"]
    pile_sum = [r for r in summary if r["problem"] == "pile"]
    fig, axes = plt.subplots(1, 4, figsize=(19, 4.4))
    ax = axes[0]
    for mode, collision in contact_runs(pile):
        contact_line(ax, pile, mode, collision, lambda r, mine: r["height"])
    if pile_sum:
        ax.axhline(pile_sum[0]["height_frozen"], color="0.3", ls=":", lw=1,
                   label="column stopped at its first contact")
        ax.axhline(pile_sum[0]["height_packed"], color="0.3", ls="-.", lw=1,
                   label=f"triangular lattice filling the V (packing π/(2√3) = {math.pi / (2 * math.sqrt(3)):.3f})")
    ax.set_ylabel("mean height of the disks' centres [m]")
    ax.set_title("Pile in a V: does it flow?")
    ax.legend(fontsize=6.5, loc="upper right")
    ax = axes[1]
    for mode, collision in contact_runs(pile):
        contact_line(ax, pile, mode, collision, lambda r, mine: 100 * r["zone_fraction"])
    ax.set_ylabel("disks in failsafe zones [%]")
    ax.set_ylim(-3, 103)
    ax.set_title("Pile in a V: the failsafe's share")
    ax = axes[2]
    slot = [r for r in rows if r["problem"] == "slot"]
    escapable = max((r["escapable"] for r in summary if r["problem"] == "slot"), default=math.nan)
    for mode, collision in contact_runs(slot):
        contact_line(ax, slot, mode, collision, lambda r, mine: r["escaped"])
    ax.set_ylabel(f"disks through an edge (of {escapable:.0f})")
    ax.set_title("Slot: disks escaped so far")
    ax = axes[3]
    for mode, collision in contact_runs(pile):
        contact_line(ax, pile, mode, collision, lambda r, mine: r["rigid_zones"])
    ax.set_ylabel("zones moved rigidly in the step")
    ax.set_title("Pile in a V: rigid zones (--compat: every zone)")
    for ax in axes:
        ax.set_xlabel("time [s]")
    handles, labels = axes[2].get_legend_handles_labels()
    fig.legend(handles, labels, loc="upper center", ncol=4, bbox_to_anchor=(0.5, 1.06))
    fig.tight_layout()
    save(fig, data_dir, "contact_outcomes")

