"""Exports read back by the programs they are for: extended XYZ by ASE, GSD by python3-gsd."""
import numpy as np
import pytest

import ede


def test_xyz_reads_back_in_ase_with_every_digit(gas_log, tmp_path):
    ase_io = pytest.importorskip("ase.io")
    log = ede.open(gas_log)
    times = [0.0, 0.25, 0.5]
    path = ede.export_xyz(log, tmp_path / "gas.xyz", times)
    frames = ase_io.read(path, index=":")
    assert len(frames) == 3
    for t, atoms in zip(times, frames):
        s = log.state(t)
        np.testing.assert_array_equal(atoms.positions[:, 0], s.x)
        np.testing.assert_array_equal(atoms.positions[:, 1], s.y)
        np.testing.assert_array_equal(atoms.get_masses(), s.mass)
        np.testing.assert_array_equal(atoms.arrays["vel"][:, 1], s.vy)
        np.testing.assert_array_equal(atoms.arrays["radius"], s.radius)
        assert list(atoms.arrays["ede_species"]) == [s.species_names[k] for k in s.species]
        assert float(atoms.info["Time"]) == float(s.time)
        np.testing.assert_array_equal(np.diag(atoms.cell.array)[:2], [s.lx, s.ly])


def test_gsd_reads_back_in_python3_gsd(periodic_log, tmp_path):
    gsd_hoomd = pytest.importorskip("gsd.hoomd")
    log = ede.open(periodic_log)
    path = ede.export_gsd(log, tmp_path / "gas.gsd", frames=4)
    times = ede.frame_times(log, frames=4)
    with gsd_hoomd.open(str(path), "rb") as traj:
        assert len(traj) == 4
        for t, frame in zip(times, traj):
            s = log.state(t)
            assert frame.configuration.dimensions == 2
            np.testing.assert_array_equal(frame.configuration.box[:2], np.float32([s.lx, s.ly]))
            np.testing.assert_array_equal(frame.particles.position[:, 0], np.float32(s.x - s.lx / 2))
            np.testing.assert_array_equal(frame.particles.velocity[:, 1], np.float32(s.vy))
            np.testing.assert_array_equal(frame.particles.diameter, np.float32(2 * s.radius))
            assert frame.particles.types == s.species_names
            np.testing.assert_array_equal(frame.log["ede/x"], s.x)  # the exact values ride along


def test_frame_times_cover_the_range(gas_log):
    log = ede.open(gas_log)
    t = ede.frame_times(log, frames=5)
    assert t[0] == log.start_time and t[-1] == log.end_time and len(t) == 5
    assert ede.frame_times(log) == [log.end_time]


def test_ede_replay_export_writes_the_modules_xyz_byte_for_byte(gas_log, tmp_path):
    from conftest import tool
    log = ede.open(gas_log)
    py_file = ede.export_xyz(log, tmp_path / "py.xyz", frames=3)
    tool("ede-replay", "export", gas_log, "-o", tmp_path / "cli.xyz", "--frames", 3)
    assert (tmp_path / "cli.xyz").read_text() == py_file.read_text()


def test_ede_replay_export_gsd_runs_the_module(periodic_log, tmp_path):
    gsd_hoomd = pytest.importorskip("gsd.hoomd")
    from conftest import tool
    tool("ede-replay", "export", periodic_log, "-o", tmp_path / "cli.gsd", "--at", "end")
    with gsd_hoomd.open(str(tmp_path / "cli.gsd"), "rb") as traj:
        assert len(traj) == 1
        np.testing.assert_array_equal(traj[0].log["ede/x"], ede.open(periodic_log).state().x)
    bad = tool("ede-replay", "export", periodic_log, "-o", tmp_path / "x.xyz", "--at", "1", "--frames", "3",
               check=False)
    assert bad.returncode == 2
