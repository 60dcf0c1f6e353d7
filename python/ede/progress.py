"""Progress of a run: one line on a terminal, or a line that updates itself in Jupyter.

Rejected: tqdm and ipywidgets (not every installation has them; a self-updating display handle needs
only IPython, which every Jupyter kernel has)."""
import sys
import time

__all__ = ["make_progress"]


def _in_jupyter():
    ip = sys.modules.get("IPython")
    if ip is None:
        return False
    try:
        shell = ip.get_ipython()
    except Exception:
        return False
    return shell is not None and type(shell).__name__ == "ZMQInteractiveShell"


def _line(p):
    return "%5.1f %%  t = %-12.6g %12d events  %.3g M events/s" % (
        100.0 * p["fraction"], p["time"], p["events"],
        p["events"] / p["wall_seconds"] / 1e6 if p["wall_seconds"] > 0 else 0.0)


class _Terminal:
    def __init__(self, stream):
        self.stream, self.last = stream, 0.0

    def __call__(self, p):
        now = time.monotonic()
        if now - self.last < 0.2:
            return
        self.last = now
        self.stream.write("\r" + _line(p))
        self.stream.flush()

    def done(self):
        if self.last:
            self.stream.write("\n")
            self.stream.flush()


class _Jupyter:
    def __init__(self):
        from IPython.display import display
        self.handle = display("starting ...", display_id=True)

    def __call__(self, p):
        self.handle.update(_line(p))

    def done(self):
        pass


def make_progress(progress):
    """progress: True (a terminal line or a Jupyter display), False/None (nothing) or a callable taking a
    dict (fraction, events, time, wall_seconds). Returns (callback, done)."""
    if progress is None or progress is False:
        return None, lambda: None
    if callable(progress):
        return progress, lambda: None
    if progress is True:
        shown = _Jupyter() if _in_jupyter() else _Terminal(sys.stderr)
        return shown, shown.done
    raise TypeError("progress: expected True, False or a callable, got %s" % type(progress).__name__)
