"""Scenes: loading, building in code, writing XML that loads back to the same scene."""
import math

import numpy as np
import pytest

import fosssim


def test_load_reads_the_file(assets):
    scene = fosssim.Scene.load(str(assets / "examples" / "projectile.xml"))
    assert scene.num_particles >= 1
    assert scene.integrator in fosssim.integrators()
    assert scene.num_steps == math.ceil(scene.duration / scene.dt)
    assert scene.positions.shape == (scene.num_particles, 2)


def test_every_asset_round_trips_through_xml(assets):
    files = sorted(assets.rglob("*.xml"))
    assert len(files) > 20
    for path in files:
        a = fosssim.Scene.load(str(path))
        b = fosssim.Scene.from_xml(a.to_xml(), name="copy.xml")
        assert b.to_xml() == a.to_xml(), path
        np.testing.assert_array_equal(a.positions, b.positions)
        np.testing.assert_array_equal(a.masses, b.masses)
        assert a.forces == b.forces
        assert a.collision == b.collision


def build_pendulum():
    s = fosssim.Scene()
    s.description = "a pendulum built in code"
    s.set_integrator("symplectic-euler", 0.001)
    s.duration = 0.5
    pivot = s.add_particle((0.0, 0.0), fixed=True, radius=0.05)
    bob = s.add_particle((1.0, 0.0), velocity=(0.0, 0.0), mass=2.0, radius=0.1)
    edge = s.add_edge(pivot, bob, radius=0.01)
    s.add_spring(edge, k=1e4, l0=1.0)
    s.add_gravity((0.0, -9.81))
    s.add_halfplane((0.0, -2.0), (0.0, 1.0))
    s.set_collision("hybrid", cor=0.5)
    return s


def test_built_scene_writes_and_loads_back(tmp_path):
    s = build_pendulum()
    # The penalty force of "hybrid" comes last, after the spring and gravity (the format's order).
    assert [f["type"] for f in s.forces] == ["springforce", "simplegravity", "collision penalty"]
    assert s.collision["k"] == 10.0 and s.collision["thickness"] == 0.1  # hybrid's defaults
    path = tmp_path / "pendulum.xml"
    s.write(str(path))
    t = fosssim.Scene.load(str(path))
    assert t.description == s.description
    assert t.forces == s.forces
    np.testing.assert_array_equal(t.positions, s.positions)
    assert list(t.fixed) == [True, False]
    assert t.edges == [(0, 1, 0.01)]


def test_forces_keep_the_format_order_whatever_the_call_order():
    s = fosssim.Scene()
    s.add_particle((0, 0))
    s.add_particle((1, 0))
    s.add_drag(0.1)
    s.add_gravity()
    s.add_vortex_force(0, 1, 1.0, 2.0)
    s.add_constant_force((1, 0))
    assert [f["type"] for f in s.forces] == ["simplegravity", "constantforce", "dragdamping", "vortexforce"]


def test_setters_validate():
    s = fosssim.Scene()
    s.add_particle((0, 0))
    s.add_particle((1, 0))
    with pytest.raises(fosssim.SceneError, match=r"expected an array of shape \(2, 2\)"):
        s.positions = np.zeros((3, 2))
    with pytest.raises(fosssim.SceneError, match="mass must be finite and > 0"):
        s.masses = np.array([1.0, -1.0])
    # A subnormal mass is > 0, but 1/m overflows: refused as the loader refuses m="1e-320".
    with pytest.raises(fosssim.SceneError, match="finite reciprocal"):
        s.masses = np.array([1.0, 1e-320])
    with pytest.raises(fosssim.SceneError, match="reciprocal is not finite"):
        s.add_particle((2, 0), mass=1e-320)
    with pytest.raises(fosssim.SceneError, match="particle 5 does not exist"):
        s.add_edge(0, 5)
    with pytest.raises(fosssim.SceneError, match=r"unknown collision type \"bogus\" \(valid: none, simple"):
        s.set_collision("bogus")
    with pytest.raises(fosssim.SceneError, match="unknown integrator"):
        s.set_integrator("rk4", 0.01)
    s.masses = np.array([3.0, 4.0])
    np.testing.assert_array_equal(s.masses, [3.0, 4.0])


def test_bad_file_raises_the_located_message(tmp_path):
    bad = tmp_path / "bad.xml"
    bad.write_text('<scene>\n  <duration time="1"/>\n  <integrator type="explicit-euler" dt="abc"/>\n</scene>\n')
    with pytest.raises(fosssim.SceneError) as info:
        fosssim.Scene.load(str(bad))
    # The same message as the command line: file, line, element, attribute.
    assert str(info.value).startswith(f"{bad}:3: <integrator> attribute 'dt'")
    assert isinstance(info.value, ValueError)
