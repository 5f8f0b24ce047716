"""FOSSSim as a Python module: 2D particles, capsule edges and half-planes, their forces,
integrators and collision handling, stepped by FOSSSim's C++ core.

    import fosssim
    scene = fosssim.Scene.load("assets/t2m2/ImpulsesTests/....xml")
    sim = fosssim.Simulator(scene)
    sim.run()
    df = sim.dataframe()          # one row per step: energies, momenta, contacts, costs

See docs/python.md for a worked example and fosssim.sweep for grids of runs on Dask.
"""

from ._fosssim import (  # noqa: F401  (the public names)
    FileError,
    Scene,
    SceneError,
    SimulationError,
    Simulator,
    collision_types,
    grade_trajectory,
    has_renderer,
    integrators,
    write_trajectory,
)

__version__ = "0.1.0"


def load(path):
    """Loads an XML scene file (the same as Scene.load)."""
    return Scene.load(str(path))


def sweep(*args, **kwargs):
    """Runs a grid of scenes x collision methods x dt x parameters; see fosssim.sweeps.sweep."""
    from .sweeps import sweep as _sweep

    return _sweep(*args, **kwargs)
