"""Running scenes from Python: ede.run(), ede.Simulation, ede.resume(), ede.load_scene()."""
import json
import os
import sys

from . import _ede, _toml
from ._errors import InvalidError
from .progress import make_progress
from .state import State

__all__ = ["Simulation", "run", "resume", "load_scene"]


def _overrides(set):
    if set is None:
        return []
    if isinstance(set, dict):
        return ["%s=%s" % (k, _toml.value_text(v)) for k, v in set.items()]
    if isinstance(set, (list, tuple)) and all(isinstance(x, str) for x in set):
        return list(set)  # already "key=value", as ede-sim --set takes them
    raise TypeError("set: expected a dict {key: value} or a list of 'key=value' strings, got %s"
                    % type(set).__name__)


def _scene_source(scene):
    """(text or path, is_file, source name) for a path, a TOML string or a dict."""
    if isinstance(scene, os.PathLike):
        return os.fspath(scene), True, os.fspath(scene)
    if isinstance(scene, dict):
        return _toml.dumps(scene), False, "<dict>"
    if isinstance(scene, str):
        # TOML text has a newline or an '='; a file name has neither.
        if "\n" in scene or "=" in scene:
            return scene, False, "<text>"
        return scene, True, scene
    raise TypeError("scene: expected a path, a TOML string or a dict, got %s" % type(scene).__name__)


def load_scene(scene, set=None):
    """The effective scene (after `set` overrides) as a dict, checked by the same loader as ede-sim: a bad
    scene raises ede.InvalidError with ede-sim's message."""
    text, is_file, name = _scene_source(scene)
    return _toml.loads(_ede.check_scene(text, is_file, name, _overrides(set)))


class Simulation:
    """A scene run by the engine, step by step if wished.

    >>> sim = ede.Simulation("examples/gas.toml", log="gas.ede", set={"physics.restitution": 0.9})
    >>> sim.advance_to(1.0); s = sim.state          # the disks at t = 1
    >>> sim.run(); print(sim.summary["status"]); sim.close()

    finish() ends a run early with a complete log (ede.open reads it as finished, verify() re-runs it to
    that time); with impulses=True, impulses() gives running sums of the impulses on the walls and the
    pair virial, whose differences between two times are the pressure over that window (ede.pressure's).

    Pausing never changes what happens: the events (and the log) are the same bit for bit whatever the
    slices. Ctrl-C during run() or advance_to() stops the run at its next check and raises
    KeyboardInterrupt; the log keeps every complete record (close() it, or go on running).

    As a context manager (``with ede.Simulation(...) as sim:``) it is closed at the end of the block.
    After close() or finish(), what describes the run as it ended (summary, status, time, counts, message,
    scene_text, log_kept()) stays readable; running it, its state, write_state_csv() and impulses() raise
    ede.Error saying it was closed.
    """

    def __init__(self, scene, log=None, set=None, *, impulses=False, _resume=None):
        self._impulses = bool(impulses)
        self._closed_by = None  # "close()" or "finish()" once closed
        if _resume is not None:
            self._sim = _ede.Simulation(os.fspath(_resume))
            return
        if log is not None and not isinstance(log, (str, os.PathLike)):
            raise TypeError("log: expected a path or None, got %s" % type(log).__name__)
        text, is_file, name = _scene_source(scene)
        self._sim = _ede.Simulation(text, is_file, name, _overrides(set), os.fspath(log) if log else "",
                                    self._impulses)

    def _check_open(self, what):
        if self._closed_by:
            raise InvalidError("%s: this ede.Simulation was closed by %s: a closed run cannot go on or be read; "
                               "its log can: ede.open(path), or ede.resume(path) if it was not finished"
                               % (what, self._closed_by))

    @property
    def closed(self):
        return self._closed_by is not None

    def run(self, max_events=None, progress=False):
        """Runs to the scene's stop condition (or `max_events` more events); returns the status."""
        self._check_open("run()")
        callback, done = make_progress(progress)
        try:
            return self._sim.run(max_events, callback)
        finally:
            done()

    def advance_to(self, t, progress=False):
        """Processes every event up to time t and leaves the state at t; returns the status."""
        self._check_open("advance_to()")
        callback, done = make_progress(progress)
        try:
            return self._sim.advance_to(t, callback)
        finally:
            done()

    def interrupt(self):
        self._check_open("interrupt()")
        self._sim.interrupt()

    @property
    def state(self):
        self._check_open("state")
        return State(self._sim.state())

    @property
    def time(self):
        return self._sim.time()

    @property
    def status(self):
        return self._sim.status()

    @property
    def counts(self):
        return self._sim.counts()

    @property
    def summary(self):
        """The run summary (the same fields as ede-sim --json)."""
        return json.loads(self._sim.summary_json())

    @property
    def message(self):
        """Why the run stalled or came to rest, and what to do; else ''."""
        return self._sim.message()

    @property
    def scene_text(self):
        return self._sim.scene_text()

    def write_state_csv(self, path):
        self._check_open("write_state_csv()")
        self._sim.write_state_csv(os.fspath(path))

    def finish(self):
        """Ends the run here, as if a stop condition held now: the events still due at exactly this time are
        processed, then the log is closed complete at this time (every tool reads it as a finished run,
        Log.verify() re-runs it to this time, its end state is this state). The log cannot be resumed
        afterwards (close() keeps an unfinished run resumable instead). Then as close(). Idempotent; after
        close() it raises ede.Error (the log was closed resumable, not finished)."""
        if self._closed_by == "finish()":
            return
        self._check_open("finish()")
        self._closed_by = "finish()"  # closed even if finishing fails (the error says why)
        self._sim.finish()

    def impulses(self):
        """The running sums since the run began (Simulation(..., impulses=True)): a dict with time, wall
        (sum of |dp_n| per wall: left, right, bottom, top, a numpy array), virial (W = sum of r_ij . dp_i
        over pair collisions), pair_collisions and wall_collisions. The pressure over (t0, t1] comes from
        two of them, d = at t1 - at t0 (as ede.pressure and ede-stats pressure compute it):
        walls P = d wall.sum() / (2 (Lx + Ly) (t1 - t0)); virial P = (N kT + d virial / (2 (t1 - t0))) / A."""
        self._check_open("impulses()")
        if not self._impulses:
            raise ValueError("impulses(): this Simulation keeps no impulse sums; make it with "
                             "ede.Simulation(scene, ..., impulses=True)")
        return self._sim.impulses()

    def close(self):
        """Closes the log (a finished run's log gets its index). Idempotent."""
        self._closed_by = self._closed_by or "close()"
        self._sim.close()

    def log_kept(self):
        """What the log on disk holds after close(): events, complete, resumable, ..."""
        return self._sim.log_kept()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()
        return False


def _report_interrupt(sim, log):
    if not log:
        return
    k = sim.log_kept()
    where = "complete" if k["complete"] else (
        "resumable from event %d: ede.resume(%r) or ede-sim --resume %s" % (k["resume_event"], k["path"], k["path"])
        if k["resumable"] else "not resumable")
    sys.stderr.write("interrupted: %s keeps %d events (%s)\n" % (k["path"], k["events"], where))


def run(scene, log=None, set=None, progress=True, max_events=None):
    """Runs a scene (a path, a TOML string or a dict) to its stop condition and returns the run summary
    (a dict, as ede-sim --json). With `log`, every event is recorded there. Ctrl-C stops the run, keeps
    a readable log and raises KeyboardInterrupt."""
    sim = Simulation(scene, log=log, set=set)
    try:
        sim.run(max_events=max_events, progress=progress)
    except BaseException:
        sim.close()
        _report_interrupt(sim, log)
        raise
    sim.close()
    return sim.summary


def resume(path, progress=True):
    """Continues a killed run from its log, in place; returns the summary. The finished log is
    byte-identical to an uninterrupted run's."""
    sim = Simulation(None, _resume=path)
    try:
        sim.run(progress=progress)
    except BaseException:
        sim.close()
        _report_interrupt(sim, os.fspath(path))
        raise
    sim.close()
    return sim.summary
