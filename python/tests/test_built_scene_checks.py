"""Checks on values given in code, where they are given and as what they are: text a scene file
cannot hold is refused by the setter that took it (not later by Simulator() or copy(), citing the
writer); a scene built without particles is named so (not "<particle> elements" of a file); a
value out of range is a ValueError whatever the call (set_collision with a huge maxiters was a
TypeError, render(0, 10) a SimulationError); and a movie's frame rate has the command line's
limits, checked before a step is taken."""
import math
import subprocess
import sys

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


@pytest.mark.skipif(not fosssim.has_renderer, reason="built without the renderer")
def test_a_frame_too_large_for_the_memory_names_the_calls_arguments(assets):
    # The advice was the command line's "try a smaller --frame-size", an option Python has not.
    scene = str(assets / "t2m2" / "ContinuousTimeTests" / "head_on_swap.xml")
    # An address-space limit 300 MiB above what the process maps: room for the 6000x6000 frame's
    # own buffer (144 MB), not for what OSMesa needs besides (over 500 MB).
    code = ("import os, resource, fosssim\n"
            f"sim = fosssim.Simulator(fosssim.Scene.load({scene!r}))\n"
            "mapped = int(open('/proc/self/statm').read().split()[0]) * os.sysconf('SC_PAGESIZE')\n"
            "resource.setrlimit(resource.RLIMIT_AS, (mapped + (300 << 20),) * 2)\n"
            "try:\n    sim.render(6000, 6000)\nexcept fosssim.SimulationError as e:\n    print(e)\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=300).stdout
    assert "out of memory for 6000x6000 frames" in out
    assert "try a smaller width and height" in out and "--frame-size" not in out


@pytest.mark.parametrize("fps", [math.inf, math.nan, 1e-300, 0.0, -5.0, 1000.5])
def test_record_movie_takes_the_command_lines_frame_rates(fps, one_disk_scene, tmp_path):
    sim = fosssim.Simulator(one_disk_scene())
    with pytest.raises(ValueError, match=r"fps must be from 0.01 to 1000 \(frames a second, as --fps\), got "):
        sim.record_movie(str(tmp_path / "m.mp4"), steps=5, fps=fps, width=32, height=32)
    assert sim.steps_taken == 0
    assert list(tmp_path.iterdir()) == []  # no movie, no partial file


@pytest.mark.skipif(not fosssim.has_renderer, reason="built without the renderer")
def test_a_movie_that_made_no_file_names_no_partial_file(one_disk_scene, tmp_path, monkeypatch):
    # An ffmpeg that fails before writing anything: the message named "m.partial.mp4" as holding
    # the movie so far, a file that was never made.
    bin_dir = tmp_path / "bin"
    bin_dir.mkdir()
    fake = bin_dir / "ffmpeg"
    fake.write_text("#!/bin/sh\nexit 1\n")
    fake.chmod(0o755)
    monkeypatch.setenv("PATH", f"{bin_dir}:/usr/bin:/bin")
    out = tmp_path / "m.mp4"
    sim = fosssim.Simulator(one_disk_scene())
    with pytest.raises(fosssim.FileError) as info:
        sim.record_movie(str(out), steps=3, width=32, height=32)
    assert not (tmp_path / "m.partial.mp4").exists()
    assert "nothing was written (no partial file was made" in str(info.value)
    assert "is in" not in str(info.value)
