"""Sweeps: the table's rows follow the grid, metrics say what the physics says, and a run on a
local Dask cluster of two worker processes gives the same table as a serial run."""
import math

import pandas as pd
import pytest

import fosssim
from fosssim import sweep_cli, sweeps

SCENE = "t2m2/ContinuousTimeTests/head_on_swap.xml"


def test_grid_and_metrics(assets):
    table = fosssim.sweep([str(assets / SCENE)], methods=["none", "continuous-time"], dts=[0.01, 0.005],
                          params={"cor": [1.0, 0.5]}, serial=True)
    assert len(table) == 2 * 2 * 2
    assert set(table["method"]) == {"none", "continuous-time"}
    assert (table["error"] == "").all()
    ct = table[(table["method"] == "continuous-time") & (table["cor"] == 1.0)]
    # Elastic, equal masses, no forces: energy and momentum kept, one contact, no overlap left.
    assert (ct["energy_drift"].abs() < 1e-12).all()
    assert (ct["momentum_drift"] < 1e-12).all()
    assert (ct["contacts"] == 1).all()
    assert (ct["max_interpenetration"] == 0).all()
    # Without collision handling the balls pass through each other: they overlap at some step.
    none = table[table["method"] == "none"]
    assert (none["contacts"] == 0).all()
    assert (none["max_interpenetration"] > 0).any()
    # COR 0.5 loses energy.
    inelastic = table[(table["method"] == "continuous-time") & (table["cor"] == 0.5)]
    assert (inelastic["energy_drift"] < -0.1).all()
    steps = table.set_index(["method", "dt", "cor"])["steps"]
    assert steps[("none", 0.01, 1.0)] == math.ceil(0.25 / 0.01)
    assert steps[("none", 0.005, 1.0)] == math.ceil(0.25 / 0.005)


def test_bad_parameter_is_a_row_error(assets):
    table = fosssim.sweep([str(assets / SCENE)], methods=["hybrid"], dts=[0.01], params={"cor": [2.0]}, serial=True)
    assert "cor must lie in [0, 1]" in table["error"][0]


def test_values_of_the_wrong_type_are_row_errors(assets):
    # A setter's TypeError used to end the whole sweep; now only the cases with the bad value fail.
    table = fosssim.sweep([str(assets / SCENE)], methods=["hybrid"], dts=[0.01],
                          params={"maxiters": [1.5, 20], "cor": ["abc", 0.5]}, serial=True)
    assert len(table) == 4
    errors = {(row.maxiters, row.cor): row.error for row in table.itertuples()}
    assert errors[(20, 0.5)] == ""
    assert errors[(1.5, 0.5)] == "sweep: parameter maxiters: expected an integer, got 1.5"
    assert errors[(20, "abc")] == "sweep: parameter cor: expected a number, got 'abc'"
    assert errors[(1.5, "abc")].startswith("sweep: parameter ")
    assert (table.loc[table["error"] != "", "steps"] == 0).all()
    assert table.loc[table["error"] == "", "steps"].item() == math.ceil(0.25 / 0.01)


def test_a_single_string_is_one_value(assets):
    # "hybrid" is one method, not six one-letter ones; so is a single parameter value or dt.
    table = fosssim.sweep(str(assets / SCENE), methods="hybrid", dts=0.01, params={"failsafe": "rigid", "cor": 0.5},
                          serial=True)
    assert len(table) == 1
    row = table.iloc[0]
    assert (row["method"], row["dt"], row["failsafe"], row["cor"], row["error"]) == ("hybrid", 0.01, "rigid", 0.5, "")


def test_workers_must_be_positive(assets):
    # workers=-1 made a LocalCluster that waited forever for workers it never started.
    for workers in (-1, 0, 1.5, True):
        with pytest.raises(ValueError, match="workers must be a positive integer"):
            fosssim.sweep(str(assets / SCENE), methods="none", dts=0.01, workers=workers)


def test_local_cluster_gives_the_serial_table(assets):
    pytest.importorskip("dask.distributed")
    scenes = [str(assets / SCENE), str(assets / "t2m2/GeometricTests/stack.xml")]
    kwargs = dict(methods=["continuous-time", "hybrid", "penalty"], dts=[0.01, 0.005])
    serial = fosssim.sweep(scenes, serial=True, **kwargs)
    parallel = fosssim.sweep(scenes, workers=2, **kwargs)
    drop = list(sweeps.TIMING_COLUMNS)
    pd.testing.assert_frame_equal(serial.drop(columns=drop), parallel.drop(columns=drop), check_exact=True)
    assert len(serial) == 2 * 3 * 2


def test_command_line(assets, tmp_path):
    csv, png = tmp_path / "s.csv", tmp_path / "s.png"
    code = sweep_cli.main([str(assets / SCENE), "--methods", "simple,continuous-time", "--dt", "0.01,0.02", "--serial",
                        "--csv", str(csv), "--chart", str(png)])
    assert code == 0
    table = pd.read_csv(csv, keep_default_na=False)
    assert len(table) == 4
    assert png.read_bytes()[:4] == b"\x89PNG"
    with pytest.raises(SystemExit):
        sweep_cli.main([str(assets / SCENE), "--methods", "bogus"])


def test_command_line_fails_when_no_run_was_measured(assets, tmp_path, capsys):
    csv = tmp_path / "s.csv"
    # Every run fails (cor out of range): the table is written, the exit status says so.
    code = sweep_cli.main([str(assets / SCENE), "--methods", "simple,hybrid", "--param", "cor=2", "--serial",
                        "--csv", str(csv)])
    assert code == 1
    assert "no run was measured (2 failed)" in capsys.readouterr().err
    assert (pd.read_csv(csv, keep_default_na=False)["error"] != "").all()
    # One run measured of two: success, the failed one printed.
    code = sweep_cli.main([str(assets / SCENE), "--methods", "hybrid", "--param", "cor=2,1", "--serial",
                        "--csv", str(csv)])
    assert code == 0
    assert "cor must lie in [0, 1]" in capsys.readouterr().err
    # An unknown parameter, or a worker count that is not positive, is refused before any run.
    with pytest.raises(SystemExit, match="--param foo: unknown parameter"):
        sweep_cli.main([str(assets / SCENE), "--param", "foo=1", "--serial", "--csv", str(csv)])
    with pytest.raises(SystemExit) as info:
        sweep_cli.main([str(assets / SCENE), "--workers", "0", "--csv", str(csv)])
    assert info.value.code == 2


def test_values_out_of_range_or_of_the_wrong_type_fail_their_runs_only(assets):
    # maxiters beyond C's int (2**31) and a method that is no name raised the setters' TypeError,
    # which ended the whole sweep and lost every good row.
    table = fosssim.sweep([str(assets / SCENE)], methods=["hybrid", 1], dts=[0.01],
                          params={"maxiters": [20, 50000, 2**31, 10**400]}, serial=True)
    assert len(table) == 2 * 4
    errors = {(row.method, row.maxiters): row.error for row in table.itertuples()}
    assert errors[("hybrid", 20)] == ""
    for big in (50000, 2**31):
        assert f"set_collision: maxiters must be at most 10000, got {big}" in errors[("hybrid", big)]
    assert "maxiters must be at most 10000, got an integer beyond 2**63" in errors[("hybrid", 10**400)]
    for maxiters in (20, 50000, 2**31, 10**400):
        assert errors[(1, maxiters)] == "sweep: method: expected a name, got 1"
    assert (table.loc[table["error"] != "", "steps"] == 0).all()


@pytest.mark.parametrize("kwargs, named", [
    (dict(params={"k": [1.0, 1000.0], "cor": []}), "parameter cor"),
    (dict(methods=[]), "methods"),
    (dict(dts=[]), "dts"),
])
def test_an_empty_value_list_is_refused_naming_it(assets, kwargs, named):
    # An empty list made the grid empty, which was replaced by one case without any parameter:
    # every other parameter's values were silently dropped.
    args = dict(methods="hybrid", dts=0.01, serial=True)
    args.update(kwargs)
    with pytest.raises(ValueError, match=rf"^sweep: {named}: no values given"):
        fosssim.sweep(str(assets / SCENE), **args)


def test_command_line_refuses_no_methods_and_non_integers_without_a_traceback(assets, tmp_path, capsys):
    csv = tmp_path / "s.csv"
    # "--methods ," ended in a KeyError traceback (dropping 'error' of an empty table).
    with pytest.raises(SystemExit) as info:
        sweep_cli.main([str(assets / SCENE), "--methods", ",", "--dt", "0.01", "--serial", "--csv", str(csv)])
    assert info.value.code == 2
    assert "--methods: no method given in ','" in capsys.readouterr().err
    # "1e3" was "not a number".
    with pytest.raises(SystemExit, match=r"--param maxiters: expected an integer, got '1e3'"):
        sweep_cli.main([str(assets / SCENE), "--param", "maxiters=1e3", "--serial", "--csv", str(csv)])
    assert not csv.exists()
    # Beyond C's int: each run's error (it was a TypeError traceback), and no run measured.
    code = sweep_cli.main([str(assets / SCENE), "--methods", "hybrid", "--dt", "0.01", "--param", "maxiters=99999999999",
                        "--serial", "--csv", str(csv)])
    assert code == 1
    err = capsys.readouterr().err
    assert "maxiters must be at most 10000, got 99999999999" in err
    assert "no run was measured (1 failed)" in err
    assert "Traceback" not in err
