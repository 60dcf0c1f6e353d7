"""Lees-Edwards shear in Python: the log says its box is sheared, its crossings of the sliding edges come
through as `shear` events whose state after holds the new x and vx, and the analyses that do not follow the
sliding images yet refuse the log with the reason."""
import numpy as np
import pytest

import ede

SHEARED = """
seed = 3
[box]
size = [4.0, 4.0]
boundary = "lees-edwards"
shear_rate = 1.0
[physics]
restitution = 0.9
[[species]]
name = "gas"
count = 100
radius = 0.05
[species.velocity]
kind = "maxwell"
temperature = 0.5
[stop]
time = 4.0
"""


def test_a_sheared_log_names_its_box_and_its_crossings(tmp_path):
    scene = tmp_path / "shear.toml"
    scene.write_text(SHEARED)
    log = tmp_path / "shear.ede"
    ede.run(scene, log=log, progress=False)
    lg = ede.open(log)
    assert lg.info["format_version"] == 3
    assert lg.info["lees_edwards"] is True
    assert lg.info["boundary"] == "periodic"
    counts = lg.count_events()
    assert counts["shear"] > 10
    ev = lg.events()
    kinds = np.array([ede.EVENT_KINDS[k] for k in ev["kind"]])
    crossings = ev[kinds == "shear"]
    assert len(crossings) == counts["shear"]
    first = crossings[0]
    before = lg.state(event=int(first["index"]))
    after = lg.state(event=int(first["index"]) + 1)
    i = int(first["i"])
    # The image's velocity: vx moves by -+ shear_rate * Ly = 4 (up through the top: minus).
    assert abs(abs(after.vx[i] - before.vx[i]) - 4.0) < 1e-12
    assert after.vy[i] == before.vy[i]
    with pytest.raises(Exception, match="Lees-Edwards"):
        ede.msd(lg, max_lag=0.5, lag_step=0.1)
    # The images' offset at a state's time, as the engine computes it; g(r) pairs through the sliding image.
    assert lg.info["shear_rate"] == 1.0
    st = lg.state(t=2.5)
    assert st.shear_offset == (1.0 * 4.0 * float(st.time)) % 4.0
    g = ede.pair_correlation(lg, 1.0, bins=20, t0=2.5)
    assert g["count"].sum() > 0


def test_an_unsheared_log_says_so(gas_log):
    assert ede.open(gas_log).info["lees_edwards"] is False


THERMOSTATTED = """
seed = 4
[box]
size = [20.0, 20.0]
boundary = "lees-edwards"
shear_rate = RATE
[thermostat]
temperature = 1.0
rate = 0.05
[[species]]
name = "gas"
count = 100
radius = 0.5
[species.velocity]
kind = "maxwell"
temperature = 1.0
[stop]
time = 600.0
"""


def test_the_viscosity_of_sheared_runs_and_its_zero_shear_limit(tmp_path, gas_log):
    runs = []
    for rate in (0.05, 0.1):
        scene = tmp_path / ("s%g.toml" % rate)
        scene.write_text(THERMOSTATTED.replace("RATE", repr(rate)))
        log = tmp_path / ("s%g.ede" % rate)
        ede.run(scene, log=log, progress=False)
        v = ede.sheared_viscosity(ede.open(log), t0=100.0, blocks=5)
        assert v["shear_rate"] == rate
        assert v["shear_stress"] < 0
        assert v["viscosity"] == pytest.approx(-v["shear_stress"] / rate, rel=1e-12)
        assert v["reduced_rate"] == pytest.approx(rate / np.sqrt(v["kT"]), rel=1e-12)  # sigma = m = 1
        assert len(v["block_kT"]) == 5 and v["thermostat_events"] > 1000
        assert np.isfinite(v["enskog"]) and 0.5 < v["viscosity"] / v["enskog"] < 1.5
        runs.append(v)
    fit = ede.zero_shear_viscosity(runs)
    assert fit["points"] == 2
    assert fit["packing_fraction"] == pytest.approx(100 * np.pi * 0.25 / 400, rel=1e-12)
    assert fit["reduced_viscosity_error"] > 0
    with pytest.raises(Exception, match="not sheared"):
        ede.sheared_viscosity(ede.open(gas_log))
