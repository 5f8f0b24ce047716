"""The fosssim-sweep command: fosssim.sweeps.sweep over the scenes given, the table written as CSV
and, if asked, charted. Output paths are checked before the runs (which may take hours), and
outputs are written as FOSSSim writes its own: under a partial name, renamed when complete."""
import argparse
import errno
import io
import os
import stat
import sys

from . import sweeps

# Descriptors open for writing on the named pipes the outputs go to (see _output_problem), closed
# when main returns.
_pipe_probes = []


def _output_problem(path):
    """Why `path` cannot be written, or None: checked before the runs, which may take hours, so that
    a typo in --csv or --chart is not found only when the table is done. What FOSSSim refuses is
    refused here too: a named pipe that nothing reads (the write would block for ever), a socket,
    a block device. A pipe that a process reads keeps a probe open for writing until the output is
    written: closed before, it would be the pipe's last writer, and a reader such as `cat` would
    take that for the end of its input and leave."""
    if "\0" in path:
        return "embedded null byte"
    if os.path.isdir(path):
        return "is a directory"
    parent = os.path.dirname(path) or "."
    if not os.path.isdir(parent):
        return f"the directory {parent!r} does not exist"
    if os.path.exists(path):
        mode = os.stat(path).st_mode
        if stat.S_ISFIFO(mode):
            try:  # without blocking, opening for writing fails (ENXIO) when no process reads
                _pipe_probes.append(os.open(path, os.O_WRONLY | os.O_NONBLOCK | os.O_CLOEXEC))
            except OSError:
                return "is a named pipe that nothing reads"
            return None
        if stat.S_ISSOCK(mode) or stat.S_ISBLK(mode):
            return "is a socket" if stat.S_ISSOCK(mode) else "is a block device"
        if not os.access(path, os.W_OK):
            return "the file is not writable"
    elif not os.access(parent, os.W_OK | os.X_OK):
        return f"the directory {parent!r} is not writable"
    return None


def _write_output(path, write):
    """Writes a regular file under NAME.partial.EXT and renames it over `path` when complete, as
    FOSSSim -o does: a failed write leaves an older file of that name as it was. A device or a pipe
    is written directly. write(file) writes the content into an open binary file."""
    if os.path.exists(path) and not os.path.isfile(path):
        # A pipe is opened without blocking: if its reader left during the runs, open() would wait
        # for another for ever; it fails instead (ENXIO).
        pipe = stat.S_ISFIFO(os.stat(path).st_mode)
        try:
            fd = os.open(path, os.O_WRONLY | (os.O_NONBLOCK if pipe else 0) | os.O_CLOEXEC)
        except OSError as e:
            if pipe and e.errno == errno.ENXIO:
                raise OSError(e.errno, "nothing reads the named pipe any more") from None
            raise
        os.set_blocking(fd, True)
        with open(fd, "wb") as f:
            write(f)
        return
    target = os.path.realpath(path)  # a symbolic link keeps pointing at the new file
    stem, ending = os.path.splitext(target)
    partial = stem + ".partial" + ending
    try:
        with open(partial, "wb") as f:
            write(f)
    except BaseException:
        try:
            os.remove(partial)
        except OSError:
            pass
        raise
    os.replace(partial, target)


def _positive(text):
    try:
        value = int(text)
    except ValueError:
        value = 0
    if value < 1:
        raise argparse.ArgumentTypeError(f"expected a positive integer, got {text!r}")
    return value


def _parse_params(items):
    params = {}
    for item in items or []:
        name, _, values = item.partition("=")
        if not values:
            raise SystemExit(f"fosssim-sweep: --param {item}: expected NAME=V1,V2,...")
        if name not in sweeps.PARAMETERS:
            raise SystemExit(f"fosssim-sweep: --param {name}: unknown parameter (valid: {', '.join(sweeps.PARAMETERS)})")
        parsed = []
        for v in values.split(","):
            try:
                parsed.append(int(v) if name == "maxiters" else float(v) if name not in ("integrator", "failsafe") else v)
            except ValueError:
                kind = "an integer" if name == "maxiters" else "a number"
                raise SystemExit(f"fosssim-sweep: --param {name}: expected {kind}, got {v!r}")
        params[name] = parsed
    return params


def main(argv=None):
    """fosssim-sweep with `argv` (default: sys.argv[1:]); returns the exit status."""
    try:
        return _main(argv)
    finally:
        while _pipe_probes:
            os.close(_pipe_probes.pop())


def _main(argv):
    parser = argparse.ArgumentParser(
        prog="fosssim-sweep", description=sweeps.__doc__.split("\n\n")[0],
        epilog="Exit status: 0 when at least one run was measured (the failed ones are the table's error column, "
               "and are printed), 1 when every run failed, the scenes do not load, a --param is wrong or the table or "
               "chart could not be written (the older file of that name is left as it was), 2 a bad command line "
               "(--csv and --chart where nothing can be written are found before the runs).")
    parser.add_argument("scenes", nargs="+", help="scene files")
    parser.add_argument("--methods", default=",".join(sweeps.METHODS), help="collision methods, comma separated")
    parser.add_argument("--dt", default=None, help="time steps, comma separated (default: each scene's)")
    parser.add_argument("--param", action="append", metavar="NAME=V1,V2",
                        help="a parameter to vary: " + ", ".join(sweeps.PARAMETERS))
    parser.add_argument("--compat", action="store_true", help="the course's formulas (FOSSSim --compat)")
    parser.add_argument("--scheduler", metavar="ADDRESS", help="an existing Dask scheduler (tcp://host:8786)")
    parser.add_argument("--workers", type=_positive, help="local worker processes (default: every core)")
    parser.add_argument("--serial", action="store_true", help="no Dask: run the tasks here, one by one")
    parser.add_argument("--csv", default="sweep.csv", help="the table (default sweep.csv)")
    parser.add_argument("--chart", default=None, help="a PNG chart of the table")
    args = parser.parse_args(argv)
    import fosssim

    try:
        dts = [float(v) for v in args.dt.split(",")] if args.dt else None
    except ValueError:
        parser.error(f"--dt: expected numbers, got {args.dt!r}")
    methods = [m for m in args.methods.split(",") if m]
    if not methods:
        parser.error(f"--methods: no method given in {args.methods!r} (valid: {', '.join(fosssim.collision_types())})")
    bad = [m for m in methods if m not in fosssim.collision_types()]
    if bad:
        parser.error(f"--methods: unknown {bad} (valid: {', '.join(fosssim.collision_types())})")
    for option, path in (("--csv", args.csv), ("--chart", args.chart)):
        problem = path is not None and _output_problem(path)
        if problem:
            parser.error(f"{option} {path!r}: cannot write there: {problem}")
    try:
        table = sweeps.sweep(args.scenes, methods=methods, dts=dts, params=_parse_params(args.param), compat=args.compat,
                      scheduler=args.scheduler, workers=args.workers, serial=args.serial)
    except ValueError as e:  # SceneError, or a list of no values
        print(f"fosssim-sweep: error: {e}", file=sys.stderr)
        return 1
    written = True
    try:
        _write_output(args.csv, lambda f: table.to_csv(f, index=False))
    except OSError as e:
        print(f"fosssim-sweep: error: --csv {args.csv!r}: the table was not written: {e}", file=sys.stderr)
        written = False
    if args.chart:
        try:
            # Into memory first: the file's own write errors (a full disk) then reach here.
            buffer = io.BytesIO()
            sweeps.chart(table, buffer)
            _write_output(args.chart, lambda f: f.write(buffer.getvalue()))
        except OSError as e:
            print(f"fosssim-sweep: error: --chart {args.chart!r}: the chart was not written: {e}", file=sys.stderr)
            written = False
    print(table.drop(columns=["error"]).to_string(index=False))
    failed = table[table["error"] != ""]
    for _, row in failed.iterrows():
        print(f"fosssim-sweep: {row['scene']} {row['method']} dt={row['dt']}: {row['error']}", file=sys.stderr)
    # Some runs failing is a result (an integrator that blows up at large dt); all of them failing
    # is a sweep that measured nothing, which a script must not take for success.
    if len(failed) == len(table):
        print(f"fosssim-sweep: error: no run was measured ({len(failed)} failed)", file=sys.stderr)
        return 1
    return 0 if written else 1


if __name__ == "__main__":
    sys.exit(main())
