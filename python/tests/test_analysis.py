"""The analyses give the numbers the tools give (their CSV tables, written with exact digits)."""
import csv

import numpy as np
import pytest

import ede
from conftest import ROOT, tool


def table(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return {k: np.array([float(r[k]) if r[k] != "" else np.nan for r in rows]) for k in rows[0]
            if k not in ("species", "label")}


def test_distribution_equals_ede_stats_hist(gas_log, tmp_path):
    out = tmp_path / "h.csv"
    tool("ede-stats", "hist", gas_log, "--at", 0.3, "-o", out)
    ref = table(out)
    d = ede.distribution(ede.open(gas_log), 0.3)
    np.testing.assert_array_equal(d.edges[:-1], ref["bin_left"])
    np.testing.assert_array_equal(d.density, ref["density"])
    np.testing.assert_array_equal(d["count"], ref["count"])
    np.testing.assert_array_equal(d.law_density, ref["mb_density"])
    assert d.disks == 200 and 0 <= d.ks.p_value <= 1
    heavy = ede.distribution(ede.open(gas_log), 0.3, species="heavy")
    assert heavy.disks == 50
    with pytest.raises(ede.Error, match="no species"):
        ede.distribution(ede.open(gas_log), 0.3, species="medium")


def test_energy_series_equals_ede_stats_energy(gas_log, tmp_path):
    out = tmp_path / "e.csv"
    tool("ede-stats", "energy", gas_log, "--points", 11, "-o", out)
    ref = table(out)
    e = ede.energy_series(ede.open(gas_log), points=11)
    np.testing.assert_array_equal(e.time, ref["time"])
    np.testing.assert_array_equal(e.kinetic_energy, ref["kinetic_energy"])
    heavy = e.species_energy["heavy"] / 50
    np.testing.assert_array_equal(heavy, ref["mean_kinetic_energy:heavy"])
    assert e.max_drift < 1e-13  # elastic: energy conserved to rounding


def test_collision_series_equals_ede_stats_collisions(gas_log, tmp_path):
    out = tmp_path / "c.csv"
    tool("ede-stats", "collisions", gas_log, "--every", 0.1, "-o", out)
    ref = table(out)
    c = ede.collision_series(ede.open(gas_log), ref["time"])
    np.testing.assert_array_equal(c.pair_collisions, ref["pair_collisions"])
    np.testing.assert_array_equal(c.rate[1:], ref["collision_rate"][1:])
    np.testing.assert_array_equal(c.fast_percent, ref["fast_percent"])


def test_impacts_equal_ede_stats_impacts(gas_log, tmp_path):
    out = tmp_path / "i.csv"
    tool("ede-stats", "impacts", gas_log, "--from", 0.5, "--bins", 12, "-o", out)
    ref = table(out)
    i = ede.impacts(ede.open(gas_log), t0=0.5, bins=12)
    np.testing.assert_array_equal(i.impact_edges[:-1], ref["b_left"])
    np.testing.assert_array_equal(i.impact_density, ref["b_density"])
    np.testing.assert_array_equal(i.speed_edges[1:], ref["g_right"])
    np.testing.assert_array_equal(i.speed_density, ref["g_density"])
    np.testing.assert_array_equal(i.speed_law, ref["g_law"])
    assert i.pair_collisions == i.impact_count.sum() > 100
    assert 0 <= i.impact_ks.p_value <= 1 and 0 <= i.speed_ks.p_value <= 1


def test_species_stats_equal_ede_stats_species(gas_log, tmp_path):
    out = tmp_path / "s.csv"
    tool("ede-stats", "species", gas_log, "--at", 0.4, "-o", out)
    ref = table(out)
    rows = ede.species_stats(ede.open(gas_log), [0.4])
    assert [r.species for r in rows] == ["light", "heavy", "all"]
    np.testing.assert_array_equal([r.mean_speed for r in rows], ref["mean_speed"])
    np.testing.assert_array_equal([r.kT for r in rows], ref["kT"])


def test_pressure_equals_ede_stats_pressure(gas_log, tmp_path):
    out = tmp_path / "p.csv"
    tool("ede-stats", "pressure", gas_log, "-o", out)
    ref = table(out)
    p = ede.pressure(ede.open(gas_log))
    np.testing.assert_array_equal(p.virial.blocks, ref["P_virial"])
    np.testing.assert_array_equal(p.wall.blocks, ref["P_wall"])
    assert p.z_virial.mean > 1  # a dense-enough gas pushes harder than an ideal one


def test_crater_equals_ede_crater_measure(tmp_path):
    log_path, out = tmp_path / "crater.ede", tmp_path / "crater.csv"
    ede.run(ROOT / "examples" / "crater.toml", log=log_path, progress=False, set={"stop.time": 0.05})
    tool("ede-crater", "measure", log_path, "-o", out)
    ref = table(out)
    c = ede.crater(ede.open(log_path))
    np.testing.assert_array_equal(c.height_after, ref["h_after"])
    np.testing.assert_array_equal(c.height_before, ref["h_before"])
    assert c.depth == pytest.approx(np.max(ref["h_before"] - ref["h_after"]), rel=0, abs=0)
    assert c.count > 0


def test_crater_metrics_equal_ede_crater_scans(tmp_path):
    """Every metric of ede.crater, with the time and source it chose, against ede-crater scan's CSV (each row
    the measurement `ede-crater LOG` makes of that run's log, 17 digits), one run collapsing (tc = 0)."""
    out = tmp_path / "scan"
    tool("ede-crater", "scan", ROOT / "examples" / "crater.toml", "--param", "physics.tc", "--values", "0,1e-6",
         "--set", "species.projectile.radius=0.07", "--set", "species.bed.count=100",
         "--set", "species.projectile.mass=125", "-q", "-j", 2, "--out-dir", out)
    with open(out / "scan.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    assert [r["suspect"] for r in rows] == ["1", "0"]  # tc = 0 collapses: measured at its log's end
    for row in rows:
        c = ede.crater(ede.open(out / row["log"]))
        assert c.source == row["time_source"]
        for key in ["time", "energy_fraction"] + ["count", "depth", "width", "area", "depth_below_mean",
                                                  "deepest_x", "removed_area", "raised_area", "detached"]:
            assert c[key] == float(row[key]), key
