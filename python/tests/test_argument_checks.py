"""Arguments checked where they are given, with the loader's limits and wording: a bad value is
refused by the call that took it, naming it, not later by Simulator() citing a line of XML the user
never wrote; and no value is quietly taken for another (k = -1 was "the default")."""
import math

import pytest

import fosssim


@pytest.mark.parametrize("call, message", [
    (lambda s: s.add_gravity((math.nan, 0.0)), r"add_gravity: g\[0\] must be finite, got nan"),
    (lambda s: s.add_gravity((0.0, -math.inf)), r"add_gravity: g\[1\] must be finite, got -inf"),
    (lambda s: s.add_constant_force((math.inf, 0.0)), r"add_constant_force: f\[0\] must be finite, got inf"),
    (lambda s: s.set_collision("hybrid", maxiters=100000), r"set_collision: maxiters must be at most 10000, got 100000"),
    (lambda s: s.set_collision("penalty", k=-1.0), r"set_collision: k must be >= 0, got -1"),
    (lambda s: s.set_collision("hybrid", thickness=-1.0), r"set_collision: thickness must be >= 0, got -1"),
    (lambda s: s.set_collision("penalty", k=math.nan), r"set_collision: k must be finite, got nan"),
])
def test_builder_refuses_at_the_call(call, message, one_disk_scene):
    s = one_disk_scene()
    before = s.to_xml()
    with pytest.raises(fosssim.SceneError, match=message):
        call(s)
    assert s.to_xml() == before  # nothing half-applied


def test_duration_and_dt_may_not_ask_for_more_steps_than_the_loader_allows(one_disk_scene):
    s = one_disk_scene()
    with pytest.raises(fosssim.SceneError, match=r"duration: duration / dt = 1e\+308 / 0.01 asks for .* steps; at most 1e\+12"):
        s.duration = 1e308
    s.duration = 1e9  # 1e11 steps: allowed, as in a file
    with pytest.raises(fosssim.SceneError, match=r"set_integrator: duration / dt = 1e\+09 / 1e-06 .* at most 1e\+12"):
        s.set_integrator("symplectic-euler", 1e-6)
    assert s.dt == 0.01 and s.duration == 1e9


def test_penalty_settings_default_only_when_not_given(one_disk_scene):
    s = one_disk_scene()
    s.set_collision("penalty")
    assert s.collision["k"] == 100 and s.collision["thickness"] == 0.01  # the type's defaults
    s.set_collision("penalty", k=0.0, thickness=0.0)  # 0 is a value (>= 0, as in a file), not the default
    assert s.collision["k"] == 0 and s.collision["thickness"] == 0


def test_sweep_values_are_refused_naming_the_setter(assets):
    scene = str(assets / "t2m2" / "ContinuousTimeTests" / "head_on_swap.xml")
    table = fosssim.sweep([scene], methods="penalty", dts=0.01, params={"k": [-1.0]}, serial=True)
    assert "set_collision: k must be >= 0, got -1" in table["error"][0]
    table = fosssim.sweep([scene], methods="none", dts=0.01, params={"duration": [1e308]}, serial=True)
    assert table["error"][0].startswith("duration: duration / dt = 1e+308")
    assert ".xml:" not in table["error"][0]  # no line of the base scene: the sweep set the value
