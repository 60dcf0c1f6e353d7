"""The Andersen thermostat in Python: its events come through with their kind's name, their disk and the
new velocity (the state after the event has it), and the counts by kind name them."""
import csv
import io

import numpy as np

import ede
from conftest import SMALL_GAS, tool


def test_thermostat_events_have_their_name_disk_and_velocity(tmp_path):
    log = tmp_path / "thermo.ede"
    ede.run(SMALL_GAS, log=log, set={"thermostat.temperature": 1.0, "thermostat.rate": 2.0}, progress=False)
    lg = ede.open(log)
    assert lg.info["format_version"] == 3
    counts = lg.count_events()
    assert counts["thermostat"] > 100
    ev = lg.events()
    kinds = [ede.EVENT_KINDS[k] for k in ev["kind"]]
    redraws = ev[np.array([k == "thermostat" for k in kinds])]
    assert len(redraws) == counts["thermostat"]
    assert np.all(redraws["j"] == -1)
    first = redraws[0]
    after = lg.state(event=int(first["index"]) + 1)
    assert after.vx[first["i"]] == first["vix"] and after.vy[first["i"]] == first["viy"]
    rows = list(csv.DictReader(io.StringIO(tool("ede-replay", "events", log, "--from-event", int(first["index"]),
                                                "--to-event", int(first["index"])).stdout)))
    assert rows[0]["kind"] == "thermostat" and int(rows[0]["i"]) == first["i"]
