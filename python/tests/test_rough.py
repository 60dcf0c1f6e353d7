"""Rough disks in Python: state() carries omega and inertia (bit-identical to ede-replay --at's CSV),
smooth states carry None, and the rotational energy of an elastic rough run adds to a constant total."""
import numpy as np

import ede
from conftest import SMALL_GAS, tool


def test_rough_state_has_omega_and_inertia_and_matches_the_csv(tmp_path):
    log = tmp_path / "rough.ede"
    ede.run(SMALL_GAS, log=log, set={"physics.roughness": 1.0, "species[0].spin_temperature": 0.5}, progress=False)
    lg = ede.open(log)
    start, end = lg.state(0.0), lg.state()
    assert start.omega is not None and end.omega is not None
    assert np.all(start.inertia > 0)
    # Perfectly rough and elastic: translation + rotation is constant, and energy moved between them.
    e0 = start.kinetic_energy.sum() + start.rotational_energy.sum()
    e1 = end.kinetic_energy.sum() + end.rotational_energy.sum()
    assert abs(e1 / e0 - 1) < 1e-12
    assert abs(end.rotational_energy.sum() / start.rotational_energy.sum() - 1) > 1e-3
    csv = tmp_path / "end.csv"
    tool("ede-replay", log, "--at", "end", "-o", csv)
    rows = np.genfromtxt(csv, delimiter=",", names=True, dtype=None, encoding=None)
    assert np.array_equal(rows["omega"], end.omega)
    assert np.array_equal(rows["inertia"], end.inertia)


def test_smooth_state_has_no_omega(tmp_path):
    log = tmp_path / "smooth.ede"
    ede.run(SMALL_GAS, log=log, progress=False)
    s = ede.open(log).state()
    assert s.omega is None and s.inertia is None
    assert np.all(s.rotational_energy == 0)
    assert "omega" not in s.to_dict()


def test_rough_events_carry_spins_that_conserve_each_collisions_energy(tmp_path):
    log = tmp_path / "rough-events.ede"
    ede.run(SMALL_GAS, log=log, set={"physics.roughness": 1.0, "species[0].spin_temperature": 0.5}, progress=False)
    lg = ede.open(log)
    ev = lg.events(before=True)
    for name in ("omega_i", "omega_j", "omega_i_before", "omega_j_before"):
        assert name in ev.dtype.names
    start = lg.state(0.0)
    m, inertia = start.mass, start.inertia
    pairs = ev[ev["kind"] == 0]
    assert len(pairs) > 100 and np.any(pairs["omega_i"] != pairs["omega_i_before"])
    i, j = pairs["i"], pairs["j"]

    def energy(suffix):
        v = lambda k: pairs[k + suffix]  # noqa: E731
        return (0.5 * m[i] * (v("vix") ** 2 + v("viy") ** 2) + 0.5 * m[j] * (v("vjx") ** 2 + v("vjy") ** 2) +
                0.5 * inertia[i] * v("omega_i") ** 2 + 0.5 * inertia[j] * v("omega_j") ** 2)

    # beta = 1, xi = 1: each collision moves energy between translation and rotation and loses none.
    np.testing.assert_allclose(energy(""), energy("_before"), rtol=1e-12)
    # The last spin logged for each disk is its spin at the end.
    end = lg.state()
    last = {}
    for row in ev:
        last[row["i"]] = row["omega_i"]
        if row["kind"] == 0:
            last[row["j"]] = row["omega_j"]
    assert last and all(end.omega[k] == w for k, w in last.items())


def test_smooth_events_have_no_spin_columns(tmp_path):
    log = tmp_path / "smooth-events.ede"
    ede.run(SMALL_GAS, log=log, progress=False)
    names = ede.open(log).events(before=True).dtype.names
    assert "omega_i" not in names and "vix_before" in names
