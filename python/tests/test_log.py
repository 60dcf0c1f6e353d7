"""ede.open: info, states and events, compared bit for bit with ede-replay."""
import csv
import io

import numpy as np
import pytest

import ede
from conftest import tool


def replay_csv(*args):
    rows = list(csv.DictReader(io.StringIO(tool("ede-replay", *args).stdout)))
    return {k: [r[k] for r in rows] for k in rows[0]}


def test_info_describes_the_run(gas_log):
    log = ede.open(gas_log)
    i = log.info
    assert i["disks"] == 200
    assert i["complete"] and not i["damaged"]
    assert i["events"] > 2000
    assert i["scalar"] == "double"
    assert i["scene"]["species"][1]["name"] == "heavy"
    assert log.species == [("light", 150), ("heavy", 50)]
    assert i["seed"] == 7
    assert i["end_time"] > 0 and i["start_time"] == 0


@pytest.mark.parametrize("t", [0.0, 0.123456789, "0.3", 0.5])
def test_state_at_time_is_bit_identical_to_ede_replay(gas_log, t):
    s = ede.open(gas_log).state(t)
    ref = replay_csv("state", gas_log, "--at", repr(t) if isinstance(t, float) else t)
    for k in ("x", "y", "vx", "vy", "radius", "mass"):
        col = getattr(s, k)
        assert col.dtype == np.float64
        np.testing.assert_array_equal(col, np.array([float(v) for v in ref[k]]), err_msg=k)
    assert list(s.id) == [int(v) for v in ref["id"]]
    assert [s.species_names[k] for k in s.species] == ref["species"]


def test_state_after_n_events_is_bit_identical_to_ede_replay(gas_log):
    s = ede.open(gas_log).state(event=777)
    assert s.events == 777
    ref = replay_csv("state", gas_log, "--event", 777)
    np.testing.assert_array_equal(s.vx, np.array([float(v) for v in ref["vx"]]))
    np.testing.assert_array_equal(s.x, np.array([float(v) for v in ref["x"]]))


def test_states_over_a_grid_equal_single_seeks(gas_log):
    times = np.linspace(0.0, 0.4, 9)
    log = ede.open(gas_log)
    seq = list(log.states(times))
    for t, s in zip(times, seq):
        single = ede.open(gas_log).state(t)
        np.testing.assert_array_equal(s.x, single.x)
        np.testing.assert_array_equal(s.vy, single.vy)
        assert s.events == single.events


def test_state_arrays_are_views_that_outlive_the_log(gas_log):
    s = ede.open(gas_log).state(0.25)
    x = s.x
    del s
    assert np.isfinite(x).all() and len(x) == 200
    with pytest.raises(ValueError):
        x[0] = 1.0  # read-only: it is the library's buffer


def test_events_are_the_rows_of_ede_replay_events(gas_log):
    log = ede.open(gas_log)
    ev = log.events(0.1, 0.2, positions=True, before=True, collision=True)
    ref = replay_csv("events", gas_log, "--from", 0.1, "--to", 0.2, "--full")
    for k in ("impulse", "impact_parameter", "relative_speed", "normal_speed", "tangential_speed"):
        assert k in ev.dtype.names and k in ref  # compared below, bit for bit, with the CLI's columns
    assert len(ev) == len(ref["index"]) > 50
    np.testing.assert_array_equal(ev["index"], np.array([int(v) for v in ref["index"]]))
    np.testing.assert_array_equal(ev["time"], np.array([float(v) for v in ref["time"]]))
    assert [ede.EVENT_KINDS[k] for k in ev["kind"]] == ref["kind"]
    for k in ("i", "j"):
        np.testing.assert_array_equal(ev[k], np.array([int(v) for v in ref[k]]))
    for k in ref:
        if k in ev.dtype.names and k not in ("index", "time", "kind", "i", "j"):
            np.testing.assert_array_equal(ev[k], np.array([float(v) if v else 0.0 for v in ref[k]]), err_msg=k)


def test_events_by_index_and_all_events(gas_log):
    log = ede.open(gas_log)
    every = log.events()
    assert len(every) == log.info["events"]
    part = log.events(first=100, last=200)
    np.testing.assert_array_equal(part, every[100:200])
    assert np.all(np.diff(every["time"]) >= 0)


def test_events_into_a_reused_array_window_by_window(gas_log):
    log = ede.open(gas_log)
    every = log.events(before=True)
    window = 250
    buf = log.events(first=0, last=window, before=True)
    address = buf.__array_interface__["data"][0]
    pieces = []
    for first in range(0, len(every), window):
        rows = log.events(first=first, last=first + window, before=True, out=buf)
        assert rows.__array_interface__["data"][0] == address  # written into buf, not a new array
        pieces.append(rows.copy())
    np.testing.assert_array_equal(np.concatenate(pieces), every)
    with pytest.raises(ValueError, match="holds 500 events, the array 250 rows"):
        log.events(first=0, last=500, before=True, out=buf)
    with pytest.raises(TypeError, match="is not the one these arguments give"):
        log.events(first=0, last=10, out=buf)  # buf has the velocities before; these rows do not
    with pytest.raises(TypeError, match="expected a numpy array"):
        log.events(first=0, last=10, out=[1, 2, 3])
    with pytest.raises(ValueError, match="contiguous 1-D"):
        log.events(first=0, last=10, before=True, out=buf[::2])


def test_impulses_conserve_momentum_in_pair_collisions(gas_log):
    log = ede.open(gas_log)
    ev = log.events(impulse=True, before=True)
    mass = log.state(0.0).mass
    pairs = ev[ev["kind"] == 0]
    pj = mass[pairs["j"]] * (pairs["vjx"] - pairs["vjx_before"])
    np.testing.assert_allclose(pairs["px"], -pj, rtol=0, atol=1e-12)
    walls = ev[ev["kind"] == 1]
    np.testing.assert_array_equal(walls["px"], mass[walls["i"]] * (walls["vix"] - walls["vix_before"]))


def test_collision_fields_are_the_impulse_and_geometry_of_each_collision(gas_log):
    log = ede.open(gas_log)
    ev = log.events(impulse=True, collision=True)
    pairs = ev[ev["kind"] == 0]
    assert len(pairs) > 100
    np.testing.assert_allclose(pairs["impulse"], np.hypot(pairs["px"], pairs["py"]), rtol=1e-12)
    assert np.all(np.abs(pairs["impact_parameter"]) <= 1 + 1e-12)
    assert np.all(pairs["normal_speed"] > 0)
    np.testing.assert_allclose(pairs["normal_speed"] ** 2 + pairs["tangential_speed"] ** 2,
                               pairs["relative_speed"] ** 2, rtol=1e-9)
    # Smooth elastic collisions: |J| = 2 mu g_n, mu = m_i m_j / (m_i + m_j) (masses 1 and 4 here).
    mass = log.state(0.0).mass
    mi, mj = mass[pairs["i"]], mass[pairs["j"]]
    np.testing.assert_allclose(pairs["impulse"], 2 * mi * mj / (mi + mj) * pairs["normal_speed"], rtol=1e-9)


def test_wrong_argument_types_raise_type_errors(gas_log):
    log = ede.open(gas_log)
    with pytest.raises(TypeError, match="expected a path"):
        ede.open(42)
    with pytest.raises(TypeError, match="expected an int"):
        log.state(event=1.5)
    with pytest.raises(TypeError, match="expected a time"):
        log.state([0.1])
    with pytest.raises(TypeError, match="not both"):
        log.state(0.1, event=3)
    with pytest.raises(ede.InvalidError):
        log.state("soon")


def test_a_time_outside_the_log_is_an_error_naming_the_file(gas_log):
    with pytest.raises(ede.Error, match="gas.ede"):
        ede.open(gas_log).state(1e9)


def test_not_a_log_raises_naming_the_file(tmp_path):
    p = tmp_path / "notes.ede"
    p.write_bytes(b"this is not an event log" * 10)
    with pytest.raises(ede.CorruptLogError, match="notes.ede"):
        ede.open(p)
    with pytest.raises(ede.IoError, match="missing.ede"):
        ede.open(tmp_path / "missing.ede")


def test_damaged_logs_raise_and_never_crash(gas_log, tmp_path):
    data = bytearray(gas_log.read_bytes())
    rng = np.random.default_rng(3)
    for trial in range(40):
        bad = bytearray(data)
        if trial % 2:
            bad = bad[: int(rng.integers(1, len(bad)))]  # cut short
        else:
            pos = int(rng.integers(0, len(bad)))
            bad[pos] ^= 1 << int(rng.integers(0, 8))  # one bit flipped
        p = tmp_path / ("bad%d.ede" % trial)
        p.write_bytes(bytes(bad))
        try:
            log = ede.open(p)
            log.state(event=log.info["events"])
            log.events()
        except ede.Error as e:
            assert "bad%d.ede" % trial in str(e)


def test_state_by_collisions_per_disk_is_the_state_after_that_collision(gas_log):
    log = ede.open(gas_log)
    n = log.events_after_collisions([0, 1, 2])
    assert n[0] == 0 and 0 < n[1] < n[2]
    ev = log.events(last=n[2])
    assert (ev["kind"] == 0).sum() == int(np.ceil(2 * log.info["disks"] / 2)) and ev["kind"][-1] == 0
    a, b = log.state(collisions_per_disk=1), log.state(event=n[1])
    np.testing.assert_array_equal(a.x, b.x)
    np.testing.assert_array_equal(a.vx, b.vx)
    with pytest.raises(TypeError):
        log.state(0.5, collisions_per_disk=1)
