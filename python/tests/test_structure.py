"""Structure and transport from Python give the numbers ede-stats gr, msd and vacf give (the same library
functions, CSV with exact digits), and refuse what the library refuses."""
import csv
import math

import numpy as np
import pytest

import ede
from conftest import tool


def table(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return {k: np.array([float(r[k]) if r[k] != "" else np.nan for r in rows]) for k in rows[0]}


def test_pair_correlation_equals_ede_stats_gr(gas_log, tmp_path):
    out = tmp_path / "gr.csv"
    tool("ede-stats", "gr", gas_log, "--r-max", 0.2, "--bins", 40, "--species", "light", "-o", out)
    ref = table(out)
    g = ede.pair_correlation(ede.open(gas_log), 0.2, bins=40, species="light")
    np.testing.assert_array_equal(g.g, ref["g"])
    np.testing.assert_array_equal(g["count"], ref["count"])
    assert g.n_a == 150 and g.frames == 1
    with pytest.raises(ValueError, match="no species"):
        ede.pair_correlation(ede.open(gas_log), 0.2, species="nope")


def test_msd_and_vacf_equal_ede_stats(gas_log, tmp_path):
    log = ede.open(gas_log)
    t_end = float(log.info["end_time"])
    out = tmp_path / "vacf.csv"
    tool("ede-stats", "vacf", gas_log, "--max-lag", t_end / 4, "-o", out)
    v = ede.vacf(log, t_end / 4)
    np.testing.assert_array_equal(v.c, table(out)["c"])
    out = tmp_path / "msd.csv"
    tool("ede-stats", "msd", gas_log, "--max-lag", t_end / 4, "-o", out)
    m = ede.msd(log, t_end / 4)
    np.testing.assert_array_equal(m.msd, table(out)["msd"])
    assert m.diffusion > 0
    with pytest.raises(ede.Error, match="max lag"):
        ede.msd(log, 2 * t_end)


def test_bond_order_and_structure_factor_shapes(gas_log):
    log = ede.open(gas_log)
    b = ede.bond_order(log, 0.2, bins=20)
    assert b.psi6.dtype == np.complex128 and b.psi6.shape == (200,)
    assert 0 <= b["global"] <= 1
    s = ede.structure_factor(log, 200.0, shells=10)
    assert s.kx.shape == s.s.shape and np.all(s.s >= 0)
    assert ede.henderson_contact(0.0) == 1.0
    assert abs(ede.kolafa_rottner_z(0.5) / ((1 + 0.5 ** 2 / 8) / 0.25) - 1) < 0.005
    assert ede.kolafa_rottner_contact(0.0) == 1.0
    assert math.isnan(ede.kolafa_rottner_z(0.72))
