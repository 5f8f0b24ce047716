"""Pictures and trajectory files."""
import re
import shutil
import threading
import time

import numpy as np
import pytest

import fosssim


@pytest.fixture
def billiards(assets):
    return fosssim.Scene.load(str(assets / "examples" / "billiards.xml"))


def test_svg_has_every_particle(billiards, tmp_path):
    sim = fosssim.Simulator(billiards)
    svg = sim.svg(320, 240)
    assert svg.count("<circle") == billiards.num_particles
    sim.save_svg(str(tmp_path / "frame.svg"), 320, 240)
    assert (tmp_path / "frame.svg").read_text() == svg


@pytest.mark.skipif(not fosssim.has_renderer, reason="built without the renderer")
def test_render_draws_the_background_and_the_particles(tmp_path):
    s = fosssim.Scene()
    s.add_particle((0.0, 0.0), radius=0.5)
    s.set_viewport(0.0, 0.0, 1.0)  # the disk fills the middle of the picture
    sim = fosssim.Simulator(s)
    image = sim.render(200, 100)
    assert image.shape == (100, 200, 3) and image.dtype == np.uint8
    assert tuple(image[95, 5]) == (255, 255, 255)  # the default white background (the time label is top left)
    # The centre is the default particle colour (0.65, 0.29, 0), to 8 bits.
    assert np.abs(image[50, 100].astype(int) - [166, 75, 0]).max() <= 1
    sim.save_png(str(tmp_path / "frame.png"), 200, 100)
    assert (tmp_path / "frame.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_trajectory_written_then_graded(assets, tmp_path):
    scene = fosssim.Scene.load(str(assets / "t2m2" / "ContinuousTimeTests" / "halfplane_cor05.xml"))
    path = tmp_path / "run.bin"
    assert fosssim.write_trajectory(scene, str(path), compat=True) == scene.num_steps
    passed, report = fosssim.grade_trajectory(scene, str(path), compat=True)
    assert passed and "Overall success: Passed." in report
    # A file of another run (the particle moved) fails.
    moved = scene.copy()
    p = moved.positions
    p[0, 0] += 0.01
    moved.positions = p
    fosssim.write_trajectory(moved, str(path), compat=True)
    passed, report = fosssim.grade_trajectory(scene, str(path), compat=True)
    assert not passed and "Overall success: Failed." in report


def test_negative_step_counts_raise_value_error(billiards, tmp_path):
    # write_trajectory(steps=-4) returned -4 and record_movie(steps=-3) wrote one frame: now
    # ValueError, before any file is made.
    with pytest.raises(ValueError, match="steps must be >= 0, got -4"):
        fosssim.write_trajectory(billiards, str(tmp_path / "run.bin"), steps=-4)
    if fosssim.has_renderer:  # without it, any movie raises SimulationError (no raster frames)
        sim = fosssim.Simulator(billiards)
        with pytest.raises(ValueError, match="steps must be >= 0, got -3"):
            sim.record_movie(str(tmp_path / "run.mp4"), steps=-3, width=32, height=32)
        with pytest.raises(ValueError, match="every must be >= 1, got 0"):
            sim.record_movie(str(tmp_path / "run.mp4"), steps=3, every=0, width=32, height=32)
        assert sim.steps_taken == 0
    assert list(tmp_path.iterdir()) == []
    assert fosssim.write_trajectory(billiards, str(tmp_path / "run.bin"), steps=0) == 0


def test_trajectory_of_a_scene_another_thread_changes(assets, tmp_path):
    # write_trajectory runs without the GIL: it read the Scene while this thread added particles
    # to it (and moved its vectors), and crashed. It runs a copy now: the file is the run of the
    # scene as it was at one moment, so exactly one of the scene's states grades it as passed.
    scene = fosssim.Scene.load(str(assets / "t2m2" / "HolisticTests" / "mixed_sizes.xml"))
    scene.duration = 10 * scene.duration
    path = str(tmp_path / "run.bin")
    states = [scene.copy()]
    writer = threading.Thread(target=fosssim.write_trajectory, args=(scene, path))
    writer.start()
    for k in range(20):
        scene.add_particle((100.0 + k, 100.0))
        states.append(scene.copy())
        time.sleep(0.005)
    writer.join()
    passed = [fosssim.grade_trajectory(state, path)[0] for state in states]
    assert passed.count(True) == 1


def test_unreadable_trajectory_raises_file_error(billiards, tmp_path):
    # No grade of nothing: the command line's error for -i, as the module's FileError.
    missing = str(tmp_path / "none.bin")
    with pytest.raises(fosssim.FileError, match="^" + re.escape(missing) + ": cannot open the trajectory file") as info:
        fosssim.grade_trajectory(billiards, missing)
    assert isinstance(info.value, OSError)
    with pytest.raises(fosssim.FileError, match="directory"):
        fosssim.grade_trajectory(billiards, str(tmp_path))


def test_grade_in_the_wrong_mode_says_which_mode_passes(assets, tmp_path):
    # Continuous-time handling differs with and without compat, and so do its files.
    scene = fosssim.Scene.load(str(assets / "t2m2" / "ContinuousTimeTests" / "halfplane_cor05.xml"))
    path = str(tmp_path / "run.bin")
    fosssim.write_trajectory(scene, path, compat=False)
    passed, report = fosssim.grade_trajectory(scene, path, compat=True)
    assert not passed and "this file looks made without --compat" in report
    fosssim.write_trajectory(scene, path, compat=True)
    passed, report = fosssim.grade_trajectory(scene, path, compat=False)
    assert not passed and "this file looks made with --compat" in report
    # A file that passes needs no hint.
    passed, report = fosssim.grade_trajectory(scene, path, compat=True)
    assert passed and "looks made" not in report


@pytest.mark.skipif(not fosssim.has_renderer or shutil.which("ffmpeg") is None, reason="needs the renderer and ffmpeg")
def test_movie_has_a_frame_per_state(billiards, tmp_path):
    sim = fosssim.Simulator(billiards)
    path = tmp_path / "run.mp4"
    frames = sim.record_movie(str(path), steps=6, every=2, width=64, height=48)
    assert frames == 1 + 3  # the current state, then after steps 2, 4 and 6
    assert sim.steps_taken == 6
    assert path.stat().st_size > 0


@pytest.mark.skipif(not fosssim.has_renderer, reason="built without the renderer")
def test_movie_names_that_are_no_movies_are_refused(billiards, tmp_path):
    # ffmpeg would write out.png as one picture and fail at the second frame: refused before it starts.
    sim = fosssim.Simulator(billiards)
    for name in ("out.png", "frame%03d.png", "out.txt", "movie"):
        with pytest.raises(fosssim.FileError, match=r"a movie's name ends in \.mp4, \.mov, \.mkv, \.webm, \.avi or \.gif"):
            sim.record_movie(str(tmp_path / name), steps=2, width=32, height=32)
    assert sim.steps_taken == 0
    assert list(tmp_path.iterdir()) == []
