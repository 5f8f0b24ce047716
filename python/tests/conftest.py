import pathlib

import pytest

import fosssim

REPO = pathlib.Path(__file__).resolve().parents[2]
ASSETS = REPO / "assets"


@pytest.fixture
def repo():
    return REPO


@pytest.fixture
def assets():
    return ASSETS


def _one_disk_scene():
    s = fosssim.Scene()
    s.add_particle((0.0, 0.0), (0.0, 0.0), 1.0, 0.1, False)
    s.set_integrator("symplectic-euler", 0.01)
    s.duration = 0.1
    return s


@pytest.fixture
def one_disk_scene():
    """A factory of fresh scenes of one disk at rest (symplectic Euler, dt 0.01, 0.1 s)."""
    return _one_disk_scene
