"""Stepped potentials from Python: a square-well run's step events flow through the event kinds (names from
the library's one list), its log is format version 3, and the summary carries the potential energy."""
import numpy as np

import ede
from conftest import SMALL_GAS

WELLS = SMALL_GAS + """
[[physics.steps]]
radius = [0.03]
energy = [-1.0]
"""


def test_event_kinds_follow_the_library():
    assert ede.EVENT_KINDS[:6] == ("pair", "wall", "cell", "wrap", "action", "sample")
    assert ede.EVENT_KINDS[6] == "segment"
    assert ede.EVENT_KINDS[7] == "step"


def test_a_square_well_run_logs_step_events(tmp_path):
    path = tmp_path / "wells.ede"
    sim = ede.Simulation(WELLS, log=path)
    sim.run(max_events=20000)
    steps = sim.counts["step"]
    assert steps > 0
    summary = sim.summary
    sim.close()
    assert summary["potential_final"] <= 0
    log = ede.open(path)
    assert log.info["format_version"] == 3
    ev = log.events()
    kinds = np.array([ede.EVENT_KINDS[k] for k in ev["kind"]])
    assert int(np.count_nonzero(kinds == "step")) == steps
    assert log.count_events()["step"] == steps
    assert log.verify()["identical"]
