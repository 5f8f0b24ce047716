"""The side-by-side table of scripts/bench --piles, from the block CSV that fosssim-bench and
fosssim-box2d-pile append to (bench/block_table.h). One row per scene, N and seed: each engine's
mean ms/step over the steps that all engines ran (runs may stop at the time limit at different
steps), its first and last block, and the shares in zones and at rest after its last block.

    python3 bench/piles_table.py blocks.csv
    python3 bench/piles_table.py --blocks blocks.csv   # also every block, engines side by side

With --blocks, each run's blocks follow its row: ms/step per block and engine, each engine's
block over its first, which is what a cost that creeps as a pile forms shows (the engines' own
ratio to their first block), and the pairs of disks touching after the block where the CSV has
them: a cost that grows with the scene's contacts, in every engine, is told apart from one that
grows with the method.
"""
import csv
import sys
from collections import OrderedDict


def block_rows(by_engine, engines, common):
    """Every block up to `common` steps, engines side by side, and each block over the first."""
    print("  %-11s" % "steps" + "".join(" | %-35s" % (e + ", touching") for e in engines if e in by_engine))
    firsts = {e: float(rows[0]["ms_per_step"]) for e, rows in by_engine.items()}
    for k, row in enumerate(next(iter(by_engine.values()))):
        if int(row["last_step"]) > common:
            break
        line = "  %-11s" % ("%s-%s" % (row["first_step"], row["last_step"]))
        for e in engines:
            rows = by_engine.get(e)
            if rows is None:
                continue
            if k >= len(rows):
                line += " | %-35s" % "-"
                continue
            ms = float(rows[k]["ms_per_step"])
            touching = rows[k].get("touching_pairs") or "-"  # older CSVs have no such column
            line += " | %-35s" % ("%9.2f (%5.1f x first) %9s" % (ms, ms / firsts[e] if firsts[e] > 0 else float("nan"),
                                                                touching))
        print(line)


def main(path, blocks=False):
    runs = OrderedDict()  # (scene, n, seed) -> engine -> [rows]
    engines = []
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            key = (row["scene"], int(row["n"]), int(row["seed"]))
            runs.setdefault(key, OrderedDict()).setdefault(row["engine"], []).append(row)
            if row["engine"] not in engines:
                engines.append(row["engine"])
    if not runs:
        print("no runs in " + path)
        return 1
    default = next((e for e in engines if e == "FOSSSim"), engines[0])
    box2d = next((e for e in engines if e.startswith("Box2D")), None)
    print("mean ms/step over the steps every engine ran (first block -> last block); "
          "shares after each engine's last block")
    head = "%-17s %6s %4s %6s" % ("scene", "N", "seed", "steps")
    for e in engines:
        head += " | %-26s" % e
    if box2d and default != box2d:
        head += " | %9s" % ("Box2D/" + default)
    head += " | %s" % "in zones (FOSSSim, mean) / at rest at the end, per engine"
    print(head)
    for (scene, n, seed), by_engine in runs.items():
        common = min(int(rows[-1]["last_step"]) for rows in by_engine.values())
        line = "%-17s %6d %4d %6d" % (scene, n, seed, common)
        means = {}
        for e in engines:
            rows = by_engine.get(e)
            if not rows:
                line += " | %-26s" % "-"
                continue
            inside = [r for r in rows if int(r["last_step"]) <= common]
            steps = sum(int(r["last_step"]) - int(r["first_step"]) + 1 for r in inside)
            means[e] = sum(float(r["ms_per_step"]) * (int(r["last_step"]) - int(r["first_step"]) + 1)
                           for r in inside) / steps
            line += " | %-26s" % ("%8.2f (%.2f -> %.2f)" % (means[e], float(rows[0]["ms_per_step"]),
                                                             float(rows[-1]["ms_per_step"])))
        if box2d and default != box2d:
            ratio = means[box2d] / means[default] if box2d in means and default in means else None
            line += " | %9s" % ("%.2f" % ratio if ratio else "-")
        shares = []
        rows = by_engine.get(default)
        if rows:
            zone = [float(r["zone_share"]) for r in rows if r["zone_share"]]
            shares.append("zones %.0f%%" % (100 * sum(zone) / len(zone)) if zone else "zones -")
        for e in engines:
            if e in by_engine:
                shares.append("%.0f%%" % (100 * float(by_engine[e][-1]["rest_share"])))
        line += " | " + " / ".join(shares)
        print(line)
        if blocks:
            block_rows(by_engine, engines, common)
    return 0


if __name__ == "__main__":
    args = sys.argv[1:]
    per_block = "--blocks" in args
    args = [a for a in args if a != "--blocks"]
    if len(args) != 1:
        sys.exit("usage: python3 bench/piles_table.py [--blocks] blocks.csv")
    sys.exit(main(args[0], per_block))
