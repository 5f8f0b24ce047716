"""Checks on values given in code, where they are given and as what they are: text a scene file
cannot hold is refused by the setter that took it (not later by Simulator() or copy(), citing the
writer); a scene built without particles is named so (not "<particle> elements" of a file); a
value out of range is a ValueError whatever the call (set_collision with a huge maxiters was a
TypeError, render(0, 10) a SimulationError)."""
import pytest

import fosssim


@pytest.mark.parametrize("field", ["description", "tag"])
def test_text_a_scene_file_cannot_hold_is_refused_by_the_setter(field, one_disk_scene):
    s = one_disk_scene()
    setattr(s, field, "fine text, with\ttab and\nline end")
    with pytest.raises(fosssim.SceneError,
                       match=rf"^{field}: holds the control character U\+0001 \(a scene file is XML text"):
        setattr(s, field, "step\x01one")
    assert getattr(s, field) == "fine text, with\ttab and\nline end"  # the old text kept
    fosssim.Simulator(s)  # and the scene still writes, so it simulates


def test_a_scene_without_particles_is_named_as_built():
    s = fosssim.Scene()
    with pytest.raises(fosssim.SceneError, match=r"^Scene.copy: the scene has no particles; add at least one with "
                                                 r"add_particle$"):
        s.copy()
    with pytest.raises(fosssim.SceneError, match=r"^Simulator: the scene has no particles"):
        fosssim.Simulator(s)
    s.add_particle((0.0, 0.0))
    assert s.copy().num_particles == 1


@pytest.mark.parametrize("maxiters, shown", [(2**31, "2147483648"), (2**62, "4611686018427387904"),
                                             (10**30, "an integer beyond 2\\*\\*63")])
def test_maxiters_beyond_c_int_is_out_of_range_not_a_type_error(maxiters, shown, one_disk_scene):
    s = one_disk_scene()
    with pytest.raises(fosssim.SceneError, match=rf"set_collision: maxiters must be at most 10000, got {shown}"):
        s.set_collision("hybrid", maxiters=maxiters)
    s.set_collision("hybrid", maxiters=-(2**40))  # 0 or less: the failsafe at once, as the loader's -1
    assert s.collision["maxiters"] == -1
    with pytest.raises(TypeError):  # the wrong type stays a TypeError
        s.set_collision("hybrid", maxiters=1.5)


def test_render_sizes_out_of_range_are_value_errors_as_svg(one_disk_scene):
    sim = fosssim.Simulator(one_disk_scene())
    for call in (sim.svg, sim.render):
        with pytest.raises(fosssim.SceneError, match="picture size must be 1 .. 16384 pixels each way, got 0 x 10"):
            call(0, 10)
