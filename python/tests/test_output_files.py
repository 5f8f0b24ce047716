"""Output files under hostile conditions: a write that fails leaves the file of that name as it
was (the data so far in NAME.partial.EXT, named in the exception), the scene file is never written
over, and a path with a NUL byte is refused rather than cut short.

A failing write is injected with RLIMIT_FSIZE in a child process (writes past the limit fail with
EFBIG, SIGXFSZ ignored): no device is written to, and nothing large is made."""
import os
import pathlib
import shutil
import subprocess
import sys
import textwrap

import pytest

import fosssim

BLOWS_UP = """<scene>
  <duration time="1"/>
  <integrator type="symplectic-euler" dt="0.01"/>
  <particle m="1" px="0" py="1" vx="0" vy="0" fixed="0" radius="0.1"/>
  <particle m="1" px="0.5" py="1" vx="0" vy="0" fixed="0" radius="0.1"/>
  <edge i="0" j="1"/>
  <springforce edge="0" k="1e7" l0="1"/>
</scene>
"""
OLD = b"an older file that must survive\n"


@pytest.fixture
def billiards_path(assets):
    return assets / "examples" / "billiards.xml"


def with_file_size_limit(code, limit=200):
    """Runs `code` (fosssim imported, `path` etc. from its text) in a child whose files may not grow
    past `limit` bytes; returns its stdout (it prints the exception it expects)."""
    prelude = textwrap.dedent(f"""
        import resource, signal, fosssim
        signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
        resource.setrlimit(resource.RLIMIT_FSIZE, ({limit}, resource.getrlimit(resource.RLIMIT_FSIZE)[1]))
        """)
    done = subprocess.run([sys.executable, "-c", prelude + textwrap.dedent(code)], capture_output=True, text=True,
                          timeout=120)
    assert done.returncode == 0, done.stderr
    return done.stdout


@pytest.mark.skipif(not fosssim.has_renderer, reason="built without the renderer")
def test_failed_png_write_keeps_the_old_file_and_its_link(billiards_path, tmp_path):
    # libpng removes the file it fails to write: that was the target itself (a device node, through
    # a link, was deleted). Now it writes a partial file, and the target is never touched.
    target = tmp_path / "old.png"
    target.write_bytes(OLD)
    link = tmp_path / "link.png"
    link.symlink_to(target)
    out = with_file_size_limit(f"""
        sim = fosssim.Simulator(fosssim.Scene.load({str(billiards_path)!r}))
        for p in ({str(target)!r}, {str(link)!r}):
            try:
                sim.save_png(p)
            except fosssim.FileError as e:
                print(e)
        """)
    assert out.count("was not written") == 2, out
    assert target.read_bytes() == OLD
    assert link.is_symlink() and link.read_bytes() == OLD
    assert sorted(p.name for p in tmp_path.iterdir()) == ["link.png", "old.png"]


@pytest.mark.skipif(not fosssim.has_renderer, reason="built without the renderer")
def test_png_through_a_link_replaces_the_file_it_points_at(billiards, tmp_path):
    target = tmp_path / "old.png"
    target.write_bytes(OLD)
    os.chmod(target, 0o640)
    link = tmp_path / "link.png"
    link.symlink_to(target)
    fosssim.Simulator(billiards).save_png(str(link), 32, 32)
    assert link.is_symlink() and target.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert target.stat().st_mode & 0o777 == 0o640  # the old file's permissions
    assert sorted(p.name for p in tmp_path.iterdir()) == ["link.png", "old.png"]


@pytest.mark.skipif(not fosssim.has_renderer, reason="built without the renderer")
def test_png_onto_a_directory_is_refused_and_the_directory_kept(billiards, tmp_path):
    folder = tmp_path / "empty"
    folder.mkdir()
    with pytest.raises(fosssim.FileError, match="is a directory"):
        fosssim.Simulator(billiards).save_png(str(folder), 32, 32)
    assert folder.is_dir()


@pytest.fixture
def billiards(billiards_path):
    return fosssim.Scene.load(str(billiards_path))


def test_trajectory_over_its_own_scene_file_is_refused(billiards_path, tmp_path):
    scene_file = tmp_path / "victim.xml"
    shutil.copy(billiards_path, scene_file)
    before = scene_file.read_bytes()
    scene = fosssim.Scene.load(str(scene_file))
    link = tmp_path / "link.bin"
    link.symlink_to(scene_file)
    for path in (scene_file, link):
        with pytest.raises(fosssim.FileError, match=r"is the same file as the scene file the Scene was loaded from "
                                                    r"\(\".*victim.xml\"\): FOSSSim never writes over its input"):
            fosssim.write_trajectory(scene, str(path), steps=1)
    assert scene_file.read_bytes() == before
    sim = fosssim.Simulator(scene)
    with pytest.raises(fosssim.FileError, match="same file as the scene file"):
        sim.save_svg(str(scene_file))
    assert scene_file.read_bytes() == before
    assert sorted(p.name for p in tmp_path.iterdir()) == ["link.bin", "victim.xml"]


def test_failed_run_keeps_the_older_trajectory_and_names_the_partial_file(tmp_path):
    out = tmp_path / "good_old.bin"
    out.write_bytes(OLD)
    scene = fosssim.Scene.from_xml(BLOWS_UP, "blow.xml")
    with pytest.raises(fosssim.SimulationError) as failed:
        fosssim.write_trajectory(scene, str(out))
    partial = tmp_path / "good_old.partial.bin"
    assert f'the trajectory so far is in "{partial}"' in str(failed.value)
    assert "the older file of that name is as it was" in str(failed.value)
    assert out.read_bytes() == OLD
    assert partial.stat().st_size > 0
    # A later complete run replaces both: the stale partial file goes, the final name gets the run.
    fosssim.write_trajectory(scene, str(out), steps=0)  # the initial record only: the run fails at step 1
    assert out.read_bytes() != OLD and out.stat().st_size > 0
    assert not partial.exists()


def test_scene_write_on_a_full_disk_keeps_the_older_scene(billiards_path, tmp_path):
    target = tmp_path / "scene.xml"
    target.write_bytes(OLD)
    out = with_file_size_limit(f"""
        scene = fosssim.Scene.load({str(billiards_path)!r})
        try:
            scene.write({str(target)!r})
        except fosssim.FileError as e:
            print(e)
        """)
    assert "the scene so far is in" in out and "scene.partial.xml" in out, out
    assert target.read_bytes() == OLD
    # And a write that completes is the whole scene.
    fosssim.Scene.load(str(billiards_path)).write(str(target))
    assert fosssim.Scene.load(str(target)).num_particles == fosssim.Scene.load(str(billiards_path)).num_particles
    assert not (tmp_path / "scene.partial.xml").exists()


@pytest.mark.skipif(not fosssim.has_renderer or shutil.which("ffmpeg") is None, reason="needs the renderer and ffmpeg")
def test_failed_movie_keeps_the_older_movie_and_names_the_partial_file(tmp_path):
    out = tmp_path / "run.mp4"
    out.write_bytes(OLD)
    sim = fosssim.Simulator(fosssim.Scene.from_xml(BLOWS_UP, "blow.xml"))
    with pytest.raises(fosssim.SimulationError) as failed:
        sim.record_movie(str(out), width=32, height=32)
    assert f'the movie so far is in "{tmp_path / "run.partial.mp4"}"' in str(failed.value)
    assert out.read_bytes() == OLD


PATH_TAKERS = {
    "Scene.load": lambda s, p: fosssim.Scene.load(p),
    "Scene.write": lambda s, p: s.write(p),
    "write_trajectory": lambda s, p: fosssim.write_trajectory(s, p, steps=1),
    "grade_trajectory": lambda s, p: fosssim.grade_trajectory(s, p),
    "save_svg": lambda s, p: fosssim.Simulator(s).save_svg(p, 16, 16),
    "save_png": lambda s, p: fosssim.Simulator(s).save_png(p, 16, 16),
    "record_movie": lambda s, p: fosssim.Simulator(s).record_movie(p, steps=1, width=16, height=16),
    "sweep": lambda s, p: fosssim.sweep([p], methods="none", serial=True),
}


@pytest.mark.parametrize("name", PATH_TAKERS)
def test_a_nul_byte_in_a_path_is_refused(billiards, tmp_path, name):
    if name in ("save_png", "record_movie") and not fosssim.has_renderer:
        pytest.skip("built without the renderer")
    (tmp_path / "a.xml").write_bytes(pathlib.Path(billiards.path).read_bytes())
    with pytest.raises(ValueError, match="embedded null byte"):
        PATH_TAKERS[name](billiards, str(tmp_path / "a.xml") + "\0.bin")
    assert [p.name for p in tmp_path.iterdir()] == ["a.xml"]  # nothing written under the cut name
