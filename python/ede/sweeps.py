"""Sweeps from Python: ede.sweep() runs a sweep file (docs/sweeps.md) with the ede-sweep program and returns
its two tables as numpy structured arrays; ede.sweep_tables() reads the tables of a sweep that ran.

It drives the ede-sweep program instead of binding its code: every run of a sweep is its own process anyway
(`ede-sweep SWEEP --child K`, so that one crashing run takes down neither the sweep nor the interpreter),
and the pool, the retries, the timeouts, the reuse of finished runs and MPI all live in that program; a
binding would still start the program once per run. The arrays are read from runs.csv and points.csv,
whose numbers ede-sweep writes with 17 significant digits, so they hold the row files' doubles exactly.
Rejected: binding tools/sweep into the module (threads waiting for children inside the interpreter, a
second Ctrl-C handling, no MPI) and pandas (not a dependency: `pandas.DataFrame(result.runs)` converts)."""
import csv
import os
import pathlib
import re
import shutil
import signal
import subprocess
import sys

import numpy as np

from ._errors import InvalidError
from .analysis import Report
from .run import _overrides

__all__ = ["sweep", "sweep_tables", "sweep_program"]

_PROGRESS = re.compile(r"^ede-sweep: (\d+)/(\d+) (\S+) (.*)$")


def sweep_program():
    """The ede-sweep program this module runs: $EDE_TOOLS_DIR/ede-sweep, else the build tree's (beside
    build/python), else the one on the PATH (the README's set-up installs it)."""
    candidates = []
    if os.environ.get("EDE_TOOLS_DIR"):
        candidates.append(pathlib.Path(os.environ["EDE_TOOLS_DIR"]) / "ede-sweep")
    candidates.append(pathlib.Path(__file__).resolve().parents[2] / "tools" / "ede-sweep")
    for c in candidates:
        if c.is_file() and os.access(c, os.X_OK):
            return str(c)
    found = shutil.which("ede-sweep")
    if found:
        return found
    raise FileNotFoundError("ede-sweep not found: install ede (cmake --install build) or set EDE_TOOLS_DIR to "
                            "the folder that holds it")


def _column(cells, kind):
    """One column of a table as a numpy array: kind "int" (empty: -1), "float" (empty: NaN), "text", or
    "value" (a parameter's TOML text: float64 when every cell is a number, else text)."""
    if kind == "value":
        try:
            return np.array([float(c) for c in cells], dtype=np.float64)
        except ValueError:
            kind = "text"
    if kind == "int":
        return np.array([int(c) if c != "" else -1 for c in cells], dtype=np.int64)
    if kind == "float":
        return np.array([float(c) if c != "" else np.nan for c in cells], dtype=np.float64)
    return np.array(cells, dtype="U%d" % max([1] + [len(c) for c in cells]))


def _table(path, kinds):
    """A CSV table as a numpy structured array; kinds(header) gives each column's kind."""
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    if not rows:
        raise InvalidError("%s: empty table" % path)
    header, body = rows[0], rows[1:]
    columns = [_column([r[k] for r in body], kind) for k, kind in enumerate(kinds(header))]
    out = np.empty(len(body), dtype=[(name, c.dtype) for name, c in zip(header, columns)])
    for name, c in zip(header, columns):
        out[name] = c
    return out


def _runs_kinds(header):
    seed = header.index("seed")
    status = header.index("status")
    kinds = {"run": "int", "seed": "int", "wall_seconds": "float"}
    return [kinds.get(h, "value" if 2 <= k < seed else "float" if seed < k < status else "text")
            for k, h in enumerate(header)]


def _points_kinds(header):
    runs = header.index("runs")
    return ["int" if h in ("point", "runs", "ok") and (k == 0 or k >= runs) else "value" if k < runs else "float"
            for k, h in enumerate(header)]


def sweep_tables(results):
    """The tables of a sweep that ran, from its results folder: a Report with `runs` (one row per run:
    run, name, the parameters, seed, the quantities, status, error, log, digest[, wall_seconds]) and
    `points` (one row per point: point, the parameters, runs, ok, Q_mean and Q_error per quantity), both
    numpy structured arrays whose fields are the CSV's columns. Numbers are float64 (an empty cell: NaN;
    an int column's: -1), a parameter whose values are not all numbers (a vector) is text."""
    results = pathlib.Path(results)
    return Report(runs=_table(results / "runs.csv", _runs_kinds),
                  points=_table(results / "points.csv", _points_kinds),
                  results=str(results))


class _Shown:
    """Progress of a sweep: ede-sweep's line per finished run on a terminal, one self-updating line in
    Jupyter, or the caller's function with {fraction, done, runs, name, status}."""

    def __init__(self, progress):
        from .progress import _in_jupyter
        self.call, self.handle = None, None
        if callable(progress) and progress is not True:
            self.call = progress
        elif progress is True and _in_jupyter():
            from IPython.display import display
            self.handle = display("ede.sweep: starting ...", display_id=True)
        elif progress not in (True, False, None):
            raise TypeError("progress: expected True, False or a callable, got %s" % type(progress).__name__)
        self.echo = progress is True and self.handle is None

    def line(self, text):
        m = _PROGRESS.match(text)
        if not m:
            return False
        if self.echo:
            sys.stderr.write(text + "\n")
            sys.stderr.flush()
        done, runs = int(m.group(1)), int(m.group(2))
        if self.handle is not None:
            self.handle.update("ede.sweep: %d/%d runs, last %s %s" % (done, runs, m.group(3), m.group(4)))
        if self.call is not None:
            self.call({"fraction": done / runs if runs else 1.0, "done": done, "runs": runs,
                       "name": m.group(3), "status": m.group(4)})
        return True


def sweep(path, workers=None, set=None, out_dir=None, timing=True, progress=True):
    """Runs the sweep file `path` with ede-sweep and returns its tables (see sweep_tables) with `status`
    (0: every run ok, 3: some not; the tables say which and why) and `summary` (the closing line).

    workers: runs at once (ede-sweep -j; default every core); set: overrides for every run (a dict
    {key: value} or a list of "key=value", as ede.run's); out_dir: the results folder (default: the sweep
    file's `results`); timing=False leaves wall_seconds out (the tables then depend on the sweep file
    alone); progress: True, False or a callable. Running the same sweep again reuses every finished run.
    A bad sweep file or base scene raises ede.InvalidError with ede-sweep's message; Ctrl-C stops the
    sweep (running runs keep resumable logs) and raises KeyboardInterrupt."""
    if not isinstance(path, (str, os.PathLike)):
        raise TypeError("path: expected a sweep file's path, got %s" % type(path).__name__)
    if workers is not None and (not isinstance(workers, int) or isinstance(workers, bool) or workers < 1):
        raise TypeError("workers: expected an int >= 1, got %r" % (workers,))
    shown = _Shown(progress)
    argv = [sweep_program(), os.fspath(path)]
    for o in _overrides(set):
        argv += ["--set", o]
    if workers is not None:
        argv += ["-j", str(workers)]
    if out_dir is not None:
        argv += ["--out-dir", os.fspath(out_dir)]
    if not timing:
        argv.append("--no-timing")
    proc = subprocess.Popen(argv, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    errors = []
    try:
        for text in proc.stderr:
            text = text.rstrip("\n")
            if not shown.line(text):
                errors.append(text)
        out = proc.stdout.read()
        status = proc.wait()
    except KeyboardInterrupt:
        proc.send_signal(signal.SIGINT)  # ede-sweep stops its runs (logs resumable) and writes the tables
        proc.wait()
        raise
    if status in (130, 143):
        raise KeyboardInterrupt("the sweep was interrupted; ede.sweep() again goes on from the finished runs")
    if status not in (0, 3):
        message = "\n".join(_message(e) for e in errors).strip()
        raise InvalidError(message or "ede-sweep exited with status %d" % status)
    lines = out.strip().splitlines()
    results = out_dir if out_dir is not None else _results_from(lines)
    tables = sweep_tables(results)
    tables["status"] = status
    tables["summary"] = lines[0] if lines else ""
    return tables


def _message(line):
    """ede-sweep's error line without "ede-sweep: " and "error: " (ede.Error's message is the tool's)."""
    for prefix in ("ede-sweep: ", "error: "):
        if line.startswith(prefix):
            line = line[len(prefix):]
    return line


def _results_from(lines):
    """The results folder from ede-sweep's closing lines ("runs.csv and points.csv in FOLDER")."""
    for line in lines:
        if line.startswith("runs.csv and points.csv in "):
            return line[len("runs.csv and points.csv in "):]
    raise InvalidError("ede-sweep did not say where its tables are: %s" % " / ".join(lines))
