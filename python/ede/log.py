"""Log: an event log (.ede) opened for reading -- states at any time, events, checks."""
import numbers
import os

from . import _ede
from ._toml import loads
from .state import State

__all__ = ["Log", "open"]

# The event kinds' names by number, as the library lists them (ede/events.hpp): "pair", "wall", "cell",
# "wrap", "action", "sample", "segment", "step", "thermostat".
EVENT_KINDS = tuple(_ede.EVENT_KINDS)


class Log:
    """An event log opened for reading (``ede.open(path)``), best used as a context manager::

        with ede.open("gas.ede") as log:
            s = log.state(0.5)

    Nothing in the file is trusted: a damaged or truncated log raises ede.CorruptLogError naming the
    file and the byte; a log whose run was killed reads up to its last complete record
    (``info["complete"]`` is False). States are rebuilt from the nearest keyframe with the engine's own
    functions: bit-identical to the run, and to ``ede-replay --at``.

    close() (or the end of the ``with`` block) frees the file at once; any later use raises ede.Error
    saying so. The arrays already returned stay valid. One Log may be shared by threads: their calls take
    turns (open the file once per thread to read in parallel). Ctrl-C stops a long state() or events() at
    its next chunk of events and raises KeyboardInterrupt; the Log stays usable. A request that cannot fit
    in memory raises MemoryError saying how much it needs, before anything is allocated.
    """

    def __init__(self, path):
        if not isinstance(path, (str, os.PathLike)):
            raise TypeError("ede.open: expected a path (str or os.PathLike), got %s" % type(path).__name__)
        self.path = os.fspath(path)
        self._log = _ede.Log(self.path)
        self._scene = None

    def close(self):
        """Frees the file (after calls in progress on other threads return). Idempotent."""
        self._log.close()

    @property
    def closed(self):
        return self._log.closed

    def __enter__(self):
        self._log.info()  # a closed Log raises here, as everywhere
        return self

    def __exit__(self, *exc):
        self.close()
        return False

    @property
    def info(self):
        """What the log holds: a dict (scene as a dict, seed, counts, time span, complete or not, ...)."""
        info = self._log.info()
        if self._scene is None:
            self._scene = loads(info["scene_text"])
        info["scene"] = self._scene
        return info

    @property
    def species(self):
        """The species: a list of (name, count)."""
        i = self.info
        return list(zip(i["species_names"], i["species_counts"]))

    @property
    def start_time(self):
        return self.info["start_time"]

    @property
    def end_time(self):
        return self.info["end_time"]

    def state(self, t=None, *, event=None, collisions_per_disk=None):
        """The state after every event with time <= t (a number, or a string as ede-replay --at reads it),
        or after the first `event` events, or right after the pair collision that brings the count to
        ceil(c N / 2) for collisions_per_disk=c (as [[actions]] collisions_per_disk counts); with none of
        them, the state at the end of the log."""
        if (t is not None) + (event is not None) + (collisions_per_disk is not None) > 1:
            raise TypeError("state: give one of a time t, event=n and collisions_per_disk=c, not both")
        if collisions_per_disk is not None:
            return State(self._log.state_at_event(self.events_after_collisions([collisions_per_disk])[0]))
        if event is not None:
            if isinstance(event, bool) or not hasattr(event, "__index__"):
                raise TypeError("state(event=n): expected an int, got %s" % type(event).__name__)
            return State(self._log.state_at_event(event.__index__()))
        if t is None:
            return State(self._log.state_at_end())
        return State(self._log.state_at(t))

    def events_after_collisions(self, collisions_per_disk):
        """For each c (ascending) the number of events after which the state is the one right after the
        pair collision that brings the count to ceil(c N / 2): state(event=n) of it is that snapshot.
        Read from the log's kind columns, without replaying."""
        values = list(collisions_per_disk)
        for c in values:
            if isinstance(c, bool) or not isinstance(c, numbers.Real):
                raise TypeError("collisions per disk: expected numbers, got %s" % type(c).__name__)
        return self._log.events_after_collisions([float(c) for c in values])

    def states(self, times):
        """The states at each of `times`, one after the other. Increasing times continue the replay from
        the previous state instead of seeking again from a keyframe."""
        for t in times:
            yield self.state(t)

    def events(self, t0=None, t1=None, *, first=None, last=None, positions=False, before=False, impulse=False,
               collision=False, out=None):
        """The logged events with t0 <= time <= t1 (and index in [first, last)) as a numpy structured
        array: index, time, kind (EVENT_KINDS[kind]), i, j, and the velocities after the event vix, viy,
        vjx, vjy; with positions=True also xi, yi, xj, yj (at the event), before=True the velocities just
        before (vix_before, ...), impulse=True the impulse on disk i (px, py = m_i (v_i' - v_i)).
        collision=True adds, in float64, the collision's statistics (docs/analysis.md): impulse (|m_i (v_i' - v_i)|),
        impact_parameter (b / (r_i + r_j), signed; pairs), relative_speed (|v_i - v_j| before; walls: |v_i|),
        normal_speed (the approach speed before; walls: |v_i . n|) and tangential_speed (signed; pairs);
        0 where an event has none (wraps, actions). Reals are otherwise in the log's scalar type. j is the
        partner (pair), the wall (wall) or the edge (wrap).

        out: an array returned by an earlier call with the same field arguments, long enough for this
        range: the rows are written into it (its first rows; the result is a view of them) instead of a
        new array, so reading a long log window by window (first/last) reuses one buffer's memory."""
        for name, v in (("first", first), ("last", last)):
            if v is not None and (isinstance(v, bool) or not hasattr(v, "__index__")):
                raise TypeError("events(%s=...): expected an int, got %s" % (name, type(v).__name__))
        return _ede.events(self._log, t0, t1, first, last, bool(positions), bool(before), bool(impulse),
                           bool(collision), out)

    def count_events(self):
        """Events by kind, from the log's kind columns (no replay)."""
        return self._log.count_events()

    def verify(self):
        """Reruns the logged scene and compares every event with the log (a dict; 'identical' says)."""
        return self._log.verify()

    def diff(self, other, full=False):
        """The first event at which this log and `other` part (a dict: identical, first_difference, text)."""
        if not isinstance(other, Log):
            raise TypeError("diff: expected an ede.Log, got %s" % type(other).__name__)
        return self._log.diff(other._log, full)

    def content_digest(self):
        """A digest of what the log says (scene, events, final state), independent of how it is stored."""
        return self._log.content_digest()

    def __repr__(self):
        if self.closed:
            return "<ede.Log %s (closed)>" % self.path
        i = self.info
        return "<ede.Log %s: %d disks, %d events, t in [%g, %g]%s>" % (
            self.path, i["disks"], i["events"], i["start_time"], i["end_time"],
            "" if i["complete"] else ", incomplete")


def open(path):
    """Opens an event log for reading."""
    return Log(path)
