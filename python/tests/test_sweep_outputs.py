"""fosssim-sweep's output files: a --csv or --chart where nothing can be written is refused before
the runs (exit 2), and a table or chart that fails to be written is reported (exit 1), the older
file of that name left as it was."""
import pytest

from fosssim import sweep_cli, sweeps

SCENE = "t2m2/ContinuousTimeTests/head_on_swap.xml"


@pytest.fixture
def no_runs(monkeypatch):
    """Fails the test if a run starts: the output checks come first."""
    def run_case(case):
        raise AssertionError("a run started before the output paths were checked")
    monkeypatch.setattr(sweeps, "run_case", run_case)


@pytest.mark.parametrize("option", ["--csv", "--chart"])
def test_unwritable_outputs_are_refused_before_any_run(assets, tmp_path, capsys, no_runs, option):
    folder = tmp_path / "folder"
    folder.mkdir()
    for path, why in ((tmp_path / "missing" / "x.out", "does not exist"), (folder, "is a directory"),
                      (str(tmp_path / "a") + "\0b", "embedded null byte")):
        with pytest.raises(SystemExit) as info:
            sweep_cli.main([str(assets / SCENE), "--serial", option, str(path)])
        assert info.value.code == 2
        err = capsys.readouterr().err
        assert option in err and why in err and "Traceback" not in err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["folder"]


def test_a_failed_chart_is_reported_and_the_older_chart_kept(assets, tmp_path, capsys, monkeypatch):
    csv, png = tmp_path / "s.csv", tmp_path / "c.png"
    png.write_bytes(b"older chart")

    def chart(table, path, *args):
        path.write(b"\x89PNG half a chart")
        raise OSError(28, "No space left on device")
    monkeypatch.setattr(sweeps, "chart", chart)
    code = sweep_cli.main([str(assets / SCENE), "--methods", "simple", "--serial", "--csv", str(csv), "--chart", str(png)])
    assert code == 1
    assert "--chart" in capsys.readouterr().err
    assert png.read_bytes() == b"older chart"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["c.png", "s.csv"]
