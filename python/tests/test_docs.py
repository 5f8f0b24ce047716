"""docs/python.md's worked example runs as written (its ```python blocks, in order, in a
temporary folder)."""
import os
import re


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
