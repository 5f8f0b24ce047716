"""Sweeps: one scene or several, run for every collision method, time step and parameter value,
measured for error and cost, serially or on a Dask cluster.

    table = fosssim.sweep(["assets/t2m2/HolisticTests/v_pile.xml"],
                          methods=fosssim.sweeps.METHODS, dts=[0.01, 0.005, 0.0025])

Each run is one task: it loads the scene from its XML text, applies the method, dt and
parameters, runs the scene's duration and returns one row. Rows depend only on the task (the
simulator is deterministic and single-threaded per task), so a run on a cluster gives the same
table as a serial one except for the wall-time column.

Columns: scene, method, dt, one column per parameter, steps, energy_drift (E_end - E_0, relative
to the energy scale max(|E_0|, max kinetic energy)), energy_gain (the largest E(t) - E_0, same
scale: energy that collision handling or the integrator created), momentum_drift (|p_end - p_0|
relative to max |p|; gravity and walls change momentum honestly, so compare methods on one scene),
contacts (impulses over the run), max_interpenetration (the deepest overlap of two disks, a disk
and an edge or a disk and a half-plane at the end of any step, relative to the smaller radius;
NaN above 2,000 particles), failsafe_zone_steps (steps that ended with impact zones),
wall_per_sim_second (the steps' wall time, as timed inside the simulator, per simulated second:
the cost; the sweep's own measuring is not counted), error (empty, or the message of a run that
failed).
"""

import itertools
import math
import numbers
import os
import sys
from collections.abc import Iterable

import numpy as np

#: The five collision methods of the scene format.
METHODS = ("none", "simple", "continuous-time", "penalty", "hybrid")

#: Columns that measure the machine rather than the physics (they differ between runs).
TIMING_COLUMNS = ("wall_per_sim_second",)

#: Parameters a sweep may vary, and how each applies to a scene.
PARAMETERS = ("cor", "maxiters", "k", "thickness", "integrator", "failsafe", "duration")


def _value(name, value):
    """A parameter's value as the scene's setters take it. A value of the wrong type is the case's
    error (SceneError, its row's `error`), not a TypeError from a setter that ends the sweep."""
    import fosssim

    if name in ("integrator", "failsafe"):
        if isinstance(value, str):
            return value
        kind = "a name"
    elif isinstance(value, numbers.Real) and not isinstance(value, (bool, np.bool_)):
        if name != "maxiters":
            return float(value)
        # Any integer, 2**31 too, is the setter's to judge (its range error is the row's); float()
        # of a huge one would raise OverflowError here.
        if isinstance(value, numbers.Integral):
            return int(value)
        if math.isfinite(value) and float(value).is_integer():  # 20.0 is 20 (a CSV's integers may come back as floats)
            return int(value)
        kind = "an integer"
    else:
        kind = "an integer" if name == "maxiters" else "a number"
    raise fosssim.SceneError(f"sweep: parameter {name}: expected {kind}, got {value!r}")


def _apply(scene, method, dt, params):
    import fosssim

    # A method or dt of the wrong type fails its runs, as a parameter's does, not the setter's TypeError.
    if not isinstance(method, str):
        raise fosssim.SceneError(f"sweep: method: expected a name, got {method!r}")
    if not isinstance(dt, numbers.Real) or isinstance(dt, (bool, np.bool_)):
        raise fosssim.SceneError(f"sweep: dt: expected a number, got {dt!r}")
    unknown = set(params) - set(PARAMETERS)
    if unknown:
        raise fosssim.SceneError(f"sweep: unknown parameter(s) {sorted(unknown)} (valid: {', '.join(PARAMETERS)})")
    params = {name: _value(name, value) for name, value in params.items()}
    c = scene.collision
    settings = dict(cor=c["cor"], maxiters=c["maxiters"], failsafe=c["failsafe"])
    # k and thickness: the scene's own when it has the same kind of penalty force, else the method's defaults.
    if c["type"] == method:
        settings.update(k=c["k"], thickness=c["thickness"])
    for key in ("cor", "maxiters", "failsafe", "k", "thickness"):
        if key in params:
            settings[key] = params[key]
    scene.set_collision(method, **settings)
    scene.set_integrator(params.get("integrator", scene.integrator), dt)
    if "duration" in params:
        scene.duration = params["duration"]
    return scene


def _overlap(scene, x, radii, fixed, edges, planes, limit=2000):
    """The deepest overlap at positions x, relative to the smaller radius (0 when none)."""
    n = len(radii)
    if n > limit:
        return math.nan
    worst = 0.0
    joined = {(min(i, j), max(i, j)) for i, j, _ in edges}
    if n > 1:
        d = np.sqrt(((x[:, None, :] - x[None, :, :]) ** 2).sum(-1))
        depth = (radii[:, None] + radii[None, :] - d) / np.minimum(radii[:, None], radii[None, :])
        iu = np.triu_indices(n, 1)
        dep = depth[iu]
        both_fixed = fixed[iu[0]] & fixed[iu[1]]
        dep = np.where(both_fixed, 0.0, dep)
        for k in np.argsort(dep)[::-1][:8]:  # the deepest pairs not joined by an edge
            if dep[k] <= 0:
                break
            if (iu[0][k], iu[1][k]) not in joined:
                worst = max(worst, dep[k])
                break
    for p, nrm in planes:
        nrm = np.asarray(nrm) / np.linalg.norm(nrm)
        dist = (x - np.asarray(p)) @ nrm
        dep = np.where(fixed, 0.0, (radii - dist) / radii)
        worst = max(worst, dep.max(initial=0.0))
    for i, j, r in edges:
        a, b = x[i], x[j]
        ab = b - a
        t = np.clip(((x - a) @ ab) / max(ab @ ab, 1e-300), 0.0, 1.0)
        dist = np.linalg.norm(x - (a + t[:, None] * ab), axis=1)
        dep = (radii + r - dist) / np.minimum(radii, r)
        dep[[i, j]] = 0.0
        if fixed[i] and fixed[j]:
            dep = np.where(fixed, 0.0, dep)
        worst = max(worst, dep.max(initial=0.0))
    return float(worst)


def run_case(case):
    """One task: case = dict(name, xml, method, dt, params, compat). Returns one row (a dict)."""
    import fosssim

    row = dict(scene=case["name"], method=case["method"], dt=case["dt"], **case["params"])
    try:
        scene = _apply(fosssim.Scene.from_xml(case["xml"], case["name"]), case["method"], case["dt"], case["params"])
        sim = fosssim.Simulator(scene, compat=case.get("compat", False))
        radii = scene.radii
        fixed = np.asarray(scene.fixed, dtype=bool)
        edges, planes = scene.edges, scene.halfplanes
        worst = [_overlap(scene, sim.positions, radii, fixed, edges, planes)]

        def look(s):
            worst.append(_overlap(scene, s.positions, radii, fixed, edges, planes))

        sim.run(every=1, callback=look)
        d = sim.diagnostics()
        wall = float(d["cost_total"].sum())  # the steps' own wall time, not this loop's Python
        energy = d["energy"]
        scale = max(abs(energy[0]), d["kinetic"].max(), 1e-300)
        p = np.stack([d["momentum_x"], d["momentum_y"]], axis=1)
        pscale = max(np.linalg.norm(p, axis=1).max(), 1e-300)
        row.update(
            steps=sim.steps_taken,
            energy_drift=(energy[-1] - energy[0]) / scale,
            energy_gain=max((energy - energy[0]).max(), 0.0) / scale,
            momentum_drift=float(np.linalg.norm(p[-1] - p[0]) / pscale),
            contacts=int(d["contacts"].sum()),
            max_interpenetration=max(worst),
            failsafe_zone_steps=int((d["failsafe_zones"] > 0).sum()),
            wall_per_sim_second=wall / max(sim.time, 1e-300),
            error="",
        )
    except (ValueError, TypeError, OverflowError, fosssim.SimulationError) as e:
        # Bad values of every kind (SceneError is a ValueError; a setter's TypeError or OverflowError
        # for a value that slipped past _value) fail this run only: the other rows stand.
        row.update(steps=0, error=str(e))
    return row


def _cases(scenes, methods, dts, params, compat):
    names = []
    texts = []
    import fosssim

    for s in scenes:
        if isinstance(s, fosssim.Scene):
            names.append(s.path or s.description or "scene")
            texts.append(s.to_xml())
        else:
            names.append(os.path.basename(str(s)))
            texts.append(fosssim.Scene.load(str(s)).to_xml())
    keys = list(params)
    grid = list(itertools.product(*(params[k] for k in keys)))  # one empty tuple when there are no parameters
    cases = []
    for (name, xml), method, dt, values in itertools.product(zip(names, texts), methods, dts, grid):
        # A dt that is no number stays as given: _apply makes it the run's error.
        number = isinstance(dt, numbers.Real) and not isinstance(dt, (bool, np.bool_))
        cases.append(dict(name=name, xml=xml, method=method, dt=float(dt) if number else dt,
                          params=dict(zip(keys, values)), compat=compat))
    return cases


def _listed(values):
    """values as a list; a single value (a str, which would otherwise be split into its
    characters, or a number) is a list of one."""
    if isinstance(values, (str, bytes, os.PathLike)) or not isinstance(values, Iterable):
        return [values]
    return list(values)


def sweep(scenes, methods=METHODS, dts=None, params=None, compat=False, scheduler=None, workers=None,
          serial=False, client=None):
    """Runs every scene x method x dt x parameter combination; returns a pandas DataFrame.

    scenes: paths or fosssim.Scene objects. dts: time steps (default: each scene's own).
    params: {name: [values]} for name in PARAMETERS. A single scene, method, dt or parameter value
    needs no list ("hybrid" is one method, not six). serial: run here, one after the other.
    Otherwise on Dask: `client` if given, else the scheduler at `scheduler` ("tcp://host:8786"),
    else a LocalCluster of `workers` processes (a positive integer; default: every core), closed
    afterwards.
    """
    import pandas as pd

    if workers is not None and (isinstance(workers, bool) or not isinstance(workers, numbers.Integral) or workers < 1):
        # LocalCluster(n_workers=-1) waits forever for workers it never starts.
        raise ValueError(f"sweep: workers must be a positive integer (None: one per core), got {workers!r}")
    scenes = _listed(scenes)
    methods = _listed(methods)
    if dts is not None:
        dts = _listed(dts)
    params = {name: _listed(values) for name, values in (params or {}).items()}
    # An empty list makes the grid empty: no run at all, or (as it once did) silently none of the
    # parameters. Named here, before any run.
    lists = [("scenes", scenes), ("methods", methods)] + ([("dts", dts)] if dts is not None else [])
    for what, values in lists + [(f"parameter {name}", values) for name, values in params.items()]:
        if not values:
            raise ValueError(f"sweep: {what}: no values given (an empty list would make no runs)")
    if dts is None:
        import fosssim

        dts = sorted({(s if isinstance(s, fosssim.Scene) else fosssim.Scene.load(str(s))).dt for s in scenes})
    cases = _cases(scenes, methods, dts, params, compat)
    if serial:
        rows = [run_case(c) for c in cases]
    else:
        rows = _on_dask(cases, scheduler, workers, client)
    return pd.DataFrame(rows)


def _on_dask(cases, scheduler, workers, client):
    from dask.distributed import Client, LocalCluster

    own_cluster = own_client = None
    try:
        if client is None:
            if scheduler:
                client = own_client = Client(scheduler)
            else:
                own_cluster = LocalCluster(n_workers=workers or os.cpu_count() or 1, threads_per_worker=1,
                                           processes=True, dashboard_address=None)
                client = own_client = Client(own_cluster)
        futures = client.map(run_case, cases, pure=False)
        return client.gather(futures)
    finally:
        if own_client is not None:
            own_client.close()
        if own_cluster is not None:
            own_cluster.close()


def chart(table, path, metrics=("energy_drift", "max_interpenetration", "wall_per_sim_second")):
    """One row of panels per scene: each metric against dt, one line per method (log scales)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    scenes = list(dict.fromkeys(table["scene"]))
    fig, axes = plt.subplots(len(scenes), len(metrics), figsize=(4.2 * len(metrics), 3.4 * len(scenes)),
                             squeeze=False)
    for r, name in enumerate(scenes):
        part = table[(table["scene"] == name) & (table["error"] == "")]
        for c, metric in enumerate(metrics):
            ax = axes[r][c]
            for method, rows in part.groupby("method", sort=False):
                rows = rows.sort_values("dt")
                ax.plot(rows["dt"], rows[metric].abs().clip(lower=1e-17), marker="o", label=method)
            ax.set_xscale("log")
            ax.set_yscale("log")
            ax.set_xlabel("dt (s)")
            ax.set_title(f"{name}: |{metric}|", fontsize=9)
            ax.grid(True, which="both", alpha=0.3)
    axes[0][0].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=90)
    plt.close(fig)


def main(argv=None):
    """The fosssim-sweep command (fosssim.sweep_cli.main)."""
    from .sweep_cli import main as cli_main

    return cli_main(argv)


if __name__ == "__main__":
    sys.exit(main())
