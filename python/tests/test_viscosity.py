"""ede.viscosity gives the numbers ede-stats viscosity gives (the same library function; CSV with exact
digits), with Enskog's reference, and refuses a walled box as the library does."""
import csv
import math

import numpy as np
import pytest

import ede
from conftest import tool

GAS = """
seed = 5
[box]
size = [1.0, 1.0]
boundary = "periodic"
[[species]]
name = "gas"
count = 200
radius = 0.0126
[species.velocity]
kind = "maxwell"
temperature = 1.0
[stop]
time = 20.0
"""


@pytest.fixture(scope="module")
def gas(tmp_path_factory):
    d = tmp_path_factory.mktemp("viscosity")
    (d / "gas.toml").write_text(GAS)
    ede.run(d / "gas.toml", log=d / "gas.ede", progress=False)
    return d / "gas.ede"


def table(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return {k: np.array([float(r[k]) for r in rows]) for k in rows[0]}


def test_viscosity_equals_ede_stats(gas, tmp_path):
    out = tmp_path / "viscosity.csv"
    tool("ede-stats", "viscosity", gas, "--from", 1, "--max-lag", 0.3, "--lag-step", 0.01, "-o", out)
    ref = table(out)
    v = ede.viscosity(ede.open(gas), 0.3, lag_step=0.01, t0=1)
    for column in ("lag", "eta", "error", "eta_xy", "eta_normal", "green_kubo", "green_kubo_error", "acf"):
        np.testing.assert_array_equal(v[column], ref[column])
    assert v.lag.shape == (30,) and v.disks == 200 and v.blocks == 10
    assert math.isclose(v.packing_fraction, 200 * math.pi * 0.0126**2, rel_tol=1e-12)
    assert v.enskog == ref["enskog"][0]
    assert v.enskog == pytest.approx(ede.enskog_viscosity(v.packing_fraction, 0.0252, v.g_contact, v.kT, 1.0), rel=1e-15)
    # A short run: only the order of magnitude against Enskog (the C++ tests hold the statistical checks).
    assert 0.5 < v.viscosity / v.enskog < 2


def test_viscosity_refuses_walls(gas_log):
    with pytest.raises(ede.Error, match="periodic"):
        ede.viscosity(ede.open(gas_log), 0.01)
