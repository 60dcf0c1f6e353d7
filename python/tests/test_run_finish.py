"""ede.Simulation.finish() and .impulses(): a run ended early has a complete log that ede.open reads as
finished, that verifies and that ends at exactly the state the run stopped at; the impulse sums taken at
two times give ede.pressure's wall and virial pressures over that window (to 1e-9: the same sums in the
same order, only the division differs) and count its collisions."""
import numpy as np
import pytest

import ede
from conftest import SMALL_GAS


def same_state(a, b):
    for column in ("x", "y", "vx", "vy"):
        np.testing.assert_array_equal(getattr(a, column), getattr(b, column))


@pytest.mark.parametrize("stop", ["advance_to", "run"])
def test_finish_early_gives_a_complete_log_that_verifies_and_ends_at_the_stop_state(tmp_path, stop):
    path = tmp_path / "early.ede"
    sim = ede.Simulation(SMALL_GAS, log=path)
    if stop == "advance_to":
        sim.advance_to(0.3)
    else:
        sim.run(max_events=2345)
    stopped, events = sim.state, sim.counts
    assert sim.status == "running"
    sim.finish()
    sim.finish()  # idempotent
    log = ede.open(path)
    assert log.info["complete"]
    assert log.end_time == stopped.time
    if stop == "advance_to":
        assert log.end_time == 0.3
    same_state(log.state(), stopped)
    assert log.count_events()["pair"] == events["pair"]
    report = log.verify()
    assert report["identical"], report


def test_a_finished_run_runs_no_more(tmp_path):
    path = tmp_path / "done.ede"
    sim = ede.Simulation(SMALL_GAS, log=path)
    sim.advance_to(0.2)
    sim.finish()
    with pytest.raises(ede.InvalidError, match=r"run\(\): this ede.Simulation was closed by finish\(\)"):
        sim.run()
    assert sim.time == 0.2
    assert ede.open(path).end_time == 0.2


def pressures(scene_set, tmp_path, t0, t1):
    path = tmp_path / "p.ede"
    sim = ede.Simulation(SMALL_GAS, log=path, set=scene_set, impulses=True)
    start = sim.impulses()
    assert start["time"] == 0 and start["wall"].sum() == 0 and start["virial"] == 0
    sim.advance_to(t0)
    a = sim.impulses()
    sim.advance_to(t1)
    b = sim.impulses()
    sim.finish()
    assert a["time"] == t0 and b["time"] == t1
    log = ede.open(path)
    return a, b, ede.pressure(log, t0=t0, t1=t1, blocks=4), log


def test_impulses_give_the_walls_pressure_of_ede_pressure(tmp_path):
    t0, t1 = 0.3, 1.5
    a, b, report, log = pressures(None, tmp_path, t0, t1)
    lx = ly = 1.0
    p_wall = (b["wall"].sum() - a["wall"].sum()) / (2 * (lx + ly) * (t1 - t0))
    assert p_wall == pytest.approx(report.wall["mean"], rel=1e-9)
    events = log.events(t0, t1)
    in_window = events[events["time"] > t0]  # (t0, t1]
    for kind in ("wall", "pair"):
        logged = int(np.count_nonzero(in_window["kind"] == ede.EVENT_KINDS.index(kind)))
        assert b[kind + "_collisions"] - a[kind + "_collisions"] == logged > 0


def test_impulses_give_the_virial_pressure_of_ede_pressure_in_a_periodic_box(tmp_path):
    t0, t1 = 0.3, 1.5
    a, b, report, log = pressures({"box.boundary": "periodic"}, tmp_path, t0, t1)
    n, area = 200, 1.0
    kT = report.kT["mean"]  # elastic: K is constant, the window's mean is its value
    p_virial = (n * kT + (b["virial"] - a["virial"]) / (2 * (t1 - t0))) / area
    assert p_virial == pytest.approx(report.virial["mean"], rel=1e-9)
    assert b["wall"].sum() == 0 and b["virial"] > a["virial"] > 0


def test_impulses_need_the_option():
    sim = ede.Simulation(SMALL_GAS)
    with pytest.raises(ValueError, match="impulses=True"):
        sim.impulses()
