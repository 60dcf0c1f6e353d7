"""Closing: ede.open(...) as a context manager and close() free the log's file at once; any later use of the
Log raises ede.Error saying it was closed (never a crash, never data from a freed reader); the arrays it
returned stay valid. A closed ede.Simulation refuses to run or to give its state, and still describes how
it ended."""
import os

import numpy as np
import pytest

import ede
from conftest import SMALL_GAS

CLOSED = r"this ede.Log was closed \(close\(\), or the end of its `with` block\): open the file again"


def open_files_on(path):
    """How many of this process's file descriptors point at `path`."""
    fds = "/proc/self/fd"
    target = os.path.realpath(path)
    count = 0
    for fd in os.listdir(fds):
        try:
            count += os.path.realpath(os.readlink(os.path.join(fds, fd))) == target
        except OSError:
            pass
    return count


def test_with_block_closes_the_file_and_keeps_the_arrays(gas_log):
    before = open_files_on(gas_log)
    with ede.open(gas_log) as log:
        assert not log.closed
        assert open_files_on(gas_log) == before + 1
        s = log.state(0.25)
        ev = log.events(first=0, last=100)
    assert log.closed
    assert open_files_on(gas_log) == before
    fresh = ede.open(gas_log)
    np.testing.assert_array_equal(s.x, fresh.state(0.25).x)  # still the right numbers after close
    np.testing.assert_array_equal(ev, fresh.events(first=0, last=100))
    assert "closed" in repr(log)


def every_use(log, other):
    """Every public way to use a Log, each a thunk."""
    return {
        "info": lambda: log.info, "species": lambda: log.species, "start_time": lambda: log.start_time,
        "end_time": lambda: log.end_time, "state(t)": lambda: log.state(0.1), "state(event)": lambda: log.state(event=5),
        "state()": lambda: log.state(), "state(collisions_per_disk)": lambda: log.state(collisions_per_disk=1),
        "states": lambda: list(log.states([0.1, 0.2])), "events": lambda: log.events(),
        "events(out)": lambda: log.events(first=0, last=10, out=other.events(first=0, last=10)),
        "events_after_collisions": lambda: log.events_after_collisions([1]), "count_events": lambda: log.count_events(),
        "verify": lambda: log.verify(), "diff": lambda: log.diff(other), "diff from other": lambda: other.diff(log),
        "content_digest": lambda: log.content_digest(), "distribution": lambda: ede.distribution(log),
        "energy_series": lambda: ede.energy_series(log), "pressure": lambda: ede.pressure(log),
        "pair_correlation": lambda: ede.pair_correlation(log, 0.1), "msd": lambda: ede.msd(log, 0.1),
        "export_xyz": lambda: ede.export_xyz(log, os.devnull, frames=2), "with": lambda: log.__enter__(),
    }


def test_every_use_after_close_raises_naming_the_file(gas_log):
    log, other = ede.open(gas_log), ede.open(gas_log)
    log.close()
    log.close()  # idempotent
    for name, use in every_use(log, other).items():
        with pytest.raises(ede.InvalidError, match=CLOSED) as caught:
            use()
        assert str(gas_log) in str(caught.value), name
    assert other.state(0.1).events > 0  # another Log of the same file is untouched


def test_a_closed_log_is_an_error_the_python_way(gas_log):
    log = ede.open(gas_log)
    log.close()
    with pytest.raises(ValueError):  # ede.InvalidError is a ValueError, as for a closed Python file
        log.state()
    with pytest.raises(ede.Error):
        log.events()


def test_simulation_as_context_manager_and_after_close(tmp_path):
    path = tmp_path / "closed.ede"
    with ede.Simulation(SMALL_GAS, log=path) as sim:
        sim.advance_to(0.2)
        mid = sim.state
    assert sim.closed
    for name, use in {"run": sim.run, "advance_to": lambda: sim.advance_to(0.3), "state": lambda: sim.state,
                      "interrupt": sim.interrupt, "impulses": sim.impulses, "finish": sim.finish,
                      "write_state_csv": lambda: sim.write_state_csv(tmp_path / "s.csv")}.items():
        with pytest.raises(ede.InvalidError, match="this ede.Simulation was closed by close()") as caught:
            use()
        assert name.split("_")[0] in str(caught.value)
    assert not (tmp_path / "s.csv").exists()
    # What describes the run as it ended stays readable, and the log is what close() left.
    assert sim.time == 0.2 and sim.status == "running" and sim.counts["pair"] > 0
    assert sim.summary["disks"] == 200
    kept = sim.log_kept()
    assert kept["resumable"] and not kept["complete"]
    sim.close()  # idempotent
    with ede.open(path) as log:
        assert log.info["events"] == kept["events"] and not log.info["complete"]
    assert mid.time == 0.2
