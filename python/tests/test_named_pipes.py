"""Outputs that are named pipes, as FOSSSim treats them: a pipe that nothing reads is refused at
once (opening it for writing would block for ever, deaf to Ctrl-C), and a pipe that a process
reads gets the whole output and then its end (the reader is not left waiting).

Each test that could hang if a pipe were opened blindly arms a rescuer: a process that opens the
pipe for reading after RESCUE seconds, so that a blocked writer returns and the test fails
instead of hanging the suite."""
import os
import subprocess
import sys

import pytest

import fosssim
from fosssim import sweep_cli, sweeps

RESCUE = 20.0
SCENE = "t2m2/ContinuousTimeTests/head_on_swap.xml"

# The pipes' other ends run in child processes: the module's writers hold the GIL, so a thread of
# this process could neither rescue a writer blocked in open() nor drain a full pipe.
RESCUER = """
import sys, time
time.sleep(float(sys.argv[2]))
with open(sys.argv[1], "rb") as f:
    f.read()
"""
READER = """
import os, select, sys, time
fd = os.open(sys.argv[1], os.O_RDONLY | os.O_NONBLOCK)  # a reader, without waiting for a writer
print("ready", flush=True)
chunks = []
while True:
    select.select([fd], [], [], 0.05)
    try:
        chunk = os.read(fd, 65536)
    except BlockingIOError:  # a writer is there, nothing written yet
        continue
    if chunk:
        chunks.append(chunk)
    elif chunks:  # every writer closed, after the data: the end
        break
    else:  # no writer came yet: that is not the end of the output
        time.sleep(0.01)
with open(sys.argv[2], "wb") as out:
    out.write(b"".join(chunks))
"""


@pytest.fixture
def pipe(tmp_path):
    path = tmp_path / "pipe"
    os.mkfifo(path)
    return path


class Rescuer:
    """Opens `path` for reading after RESCUE seconds (and drains it), unless the test ends first;
    `came` tells whether it had to."""

    def __init__(self, path):
        self.path = path
        self.came = False

    def __enter__(self):
        self.process = subprocess.Popen([sys.executable, "-c", RESCUER, str(self.path), str(RESCUE)])
        return self

    def __exit__(self, *exc):
        self.came = self.process.poll() is not None
        self.process.kill()
        self.process.wait()


class Reader:
    """Reads `path` to its end, into `out`, as a consumer such as `cat` does; `ended` tells whether
    it saw the end of its input."""

    def __init__(self, path, out):
        self.path, self.out = path, out
        self.ended = False

    def __enter__(self):
        self.process = subprocess.Popen([sys.executable, "-c", READER, str(self.path), str(self.out)],
                                        stdout=subprocess.PIPE, text=True)
        assert self.process.stdout.readline() == "ready\n"
        return self

    def __exit__(self, *exc):
        try:
            self.process.wait(RESCUE)
            self.ended = True
        except subprocess.TimeoutExpired:
            self.process.kill()
            self.process.wait()
        self.process.stdout.close()


WRITERS = {
    "Scene.write": lambda scene, path: scene.write(str(path)),
    "write_trajectory": lambda scene, path: fosssim.write_trajectory(scene, str(path)),
    "save_svg": lambda scene, path: fosssim.Simulator(scene).save_svg(str(path)),
}


@pytest.mark.parametrize("name", sorted(WRITERS))
def test_a_pipe_that_nothing_reads_is_refused(one_disk_scene, pipe, name):
    with Rescuer(pipe) as rescuer:
        with pytest.raises(fosssim.FileError, match="named pipe that nothing reads"):
            WRITERS[name](one_disk_scene(), pipe)
    assert not rescuer.came, "the writer blocked on the pipe until the rescuer read it"


@pytest.mark.parametrize("name", sorted(WRITERS))
def test_a_pipe_that_a_process_reads_gets_the_whole_output_and_its_end(one_disk_scene, tmp_path, pipe, name):
    scene = one_disk_scene()
    WRITERS[name](scene, tmp_path / "file")  # the same output into a file, to compare
    with Reader(pipe, tmp_path / "read") as reader:
        WRITERS[name](scene, pipe)
    assert reader.ended, "the reader saw no end of its input"
    assert (tmp_path / "read").read_bytes() == (tmp_path / "file").read_bytes()


def test_sweep_refuses_a_pipe_that_nothing_reads_before_the_runs(assets, pipe, capsys, monkeypatch):
    monkeypatch.setattr(sweeps, "run_case", lambda case: pytest.fail("a run started before the outputs were checked"))
    with Rescuer(pipe) as rescuer:
        with pytest.raises(SystemExit) as info:
            sweep_cli.main([str(assets / SCENE), "--serial", "--csv", str(pipe)])
    assert info.value.code == 2 and not rescuer.came
    assert "named pipe that nothing reads" in capsys.readouterr().err


def test_sweep_writes_its_table_into_a_pipe_that_a_process_reads(assets, pipe, tmp_path):
    arguments = [str(assets / SCENE), "--methods", "simple", "--dt", "0.01", "--serial"]
    assert sweep_cli.main(arguments + ["--csv", str(tmp_path / "table.csv")]) == 0
    with Reader(pipe, tmp_path / "read") as reader:
        assert sweep_cli.main(arguments + ["--csv", str(pipe)]) == 0
    assert reader.ended, "the reader saw no end of its input"
    table = (tmp_path / "table.csv").read_bytes().splitlines()
    piped = (tmp_path / "read").read_bytes().splitlines()
    # The timing column differs from run to run; the header and the row count do not.
    assert piped[0] == table[0] and len(piped) == len(table)
