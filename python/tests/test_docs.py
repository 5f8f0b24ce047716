"""docs/python.md's worked example runs as written (its ```python blocks, in order, in a
temporary folder), and its API table names the parameters the functions have."""
import ast
import inspect
import os
import pathlib
import re

import fosssim
from fosssim import sweeps


def test_worked_example_runs(repo, tmp_path, monkeypatch):
    text = (repo / "docs" / "python.md").read_text()
    blocks = re.findall(r"```python\n(.*?)```", text, re.S)
    assert blocks, "docs/python.md has no python blocks"
    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv("FOSSSIM_REPO", str(repo))
    namespace = {"__name__": "__main__"}  # as when the example runs as a script
    for block in blocks:
        if "# docs: not run by the tests" in block:
            continue
        exec(compile(block, "docs/python.md", "exec"), namespace)
    # The example's charts were written.
    assert os.path.getsize(tmp_path / "energy_contacts.png") > 0


def test_api_table_names_the_real_parameters(repo):
    # The table once documented sim.step(n=1), whose keyword is count: every name in a call of the
    # table's left column must be a parameter of that function, in the module's type stubs (the
    # signatures as nanobind made them) or, for the Python part, its own signature.
    stub = pathlib.Path(fosssim.__file__).with_name("_fosssim.pyi")
    params = {}
    for node in ast.walk(ast.parse(stub.read_text())):
        if isinstance(node, ast.FunctionDef):
            a = node.args
            names = {x.arg for x in a.posonlyargs + a.args + a.kwonlyargs} - {"self"}
            params.setdefault(node.name, []).append(names)
        if isinstance(node, ast.ClassDef):  # Simulator(scene, ...): its __init__
            for f in node.body:
                if isinstance(f, ast.FunctionDef) and f.name == "__init__":
                    params.setdefault(node.name, []).append({x.arg for x in f.args.args} - {"self"})
    params["sweep"] = [set(inspect.signature(sweeps.sweep).parameters)]
    rows = [line for line in (repo / "docs" / "python.md").read_text().splitlines() if line.startswith("| `")]
    calls = [c for row in rows for c in re.findall(r"`(?:\w+\.)?(\w+)\(([^)`]*)\)", row.split("|")[1])]
    assert len(calls) > 20
    for name, args in calls:
        documented = {a.split("=")[0].strip() for a in args.split(",") if a.strip()}
        assert name in params, name
        assert any(documented <= p for p in params[name]), (name, sorted(documented), params[name])
