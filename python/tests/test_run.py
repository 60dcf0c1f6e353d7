"""ede.run / ede.Simulation: the same logs as ede-sim, overrides, errors, pausing, progress, Ctrl-C."""
import os
import signal
import subprocess
import sys
import textwrap
import time

import numpy as np
import pytest

import ede
from conftest import ROOT, SMALL_GAS, tool


def test_run_writes_the_log_ede_sim_writes_byte_for_byte(gas_scene, tmp_path):
    a, b = tmp_path / "py.ede", tmp_path / "cli.ede"
    summary = ede.run(str(gas_scene), log=a, set={"physics.restitution": 0.9}, progress=False)
    tool("ede-sim", gas_scene, "-q", "-o", b, "--set", "physics.restitution=0.9")
    assert a.read_bytes() == b.read_bytes()
    assert summary["disks"] == 200
    assert summary["status"] == "reached stop.collisions_per_particle"


def test_scene_as_text_and_as_dict_run_the_same_physics(tmp_path):
    import tomllib
    text_log, dict_log = tmp_path / "text.ede", tmp_path / "dict.ede"
    ede.run(SMALL_GAS, log=text_log, progress=False)
    ede.run(tomllib.loads(SMALL_GAS), log=dict_log, progress=False)
    a, b = ede.open(text_log), ede.open(dict_log)
    assert a.info["events"] == b.info["events"]
    np.testing.assert_array_equal(a.state().vx, b.state().vx)
    assert a.info["scene"] == b.info["scene"]


def test_a_bad_scene_raises_the_message_ede_sim_prints(tmp_path):
    bad = tmp_path / "bad.toml"
    bad.write_text(SMALL_GAS.replace("radius = 0.01\nmass = 4.0", "radius = -0.01\nmass = 4.0"))
    with pytest.raises(ede.InvalidError) as caught:
        ede.run(str(bad), progress=False)
    cli = tool("ede-sim", bad, "-q", "-o", tmp_path / "x.ede", check=False)
    assert cli.returncode != 0
    assert str(caught.value) in cli.stderr
    assert "species[1].radius" in str(caught.value)
    with pytest.raises(ede.InvalidError, match="physics.restitution"):
        ede.run(SMALL_GAS, set={"physics.restitution": 1.5}, progress=False)
    with pytest.raises(TypeError, match="scene: expected"):
        ede.run(3.14)
    with pytest.raises(TypeError, match="set: expected"):
        ede.run(SMALL_GAS, set=5)


def test_pausing_changes_nothing_and_the_state_matches_the_log(tmp_path):
    path = tmp_path / "paused.ede"
    with ede.Simulation(SMALL_GAS, log=path) as sim:
        assert sim.advance_to(0.2) == "running"
        mid = sim.state
        assert mid.time == 0.2
        sim.run(max_events=500)
        assert sim.run() == "reached stop.collisions_per_particle"
        end = sim.state
    log = ede.open(path)
    np.testing.assert_array_equal(log.state(0.2).x, mid.x)
    np.testing.assert_array_equal(log.state().vx, end.vx)
    straight = tmp_path / "straight.ede"
    ede.run(SMALL_GAS, log=straight, progress=False)
    assert straight.read_bytes() == path.read_bytes()


def test_progress_callback_sees_the_run_and_its_exceptions_stop_it(tmp_path):
    scene = SMALL_GAS.replace("collisions_per_particle = 20", "collisions_per_particle = 4000")
    seen = []
    sim = ede.Simulation(scene, log=tmp_path / "p.ede")
    sim.run(max_events=600_000, progress=seen.append)
    assert seen and all(0 <= p["fraction"] <= 1 for p in seen)
    assert seen[-1]["events"] > seen[0]["events"]
    assert seen[-1]["time"] == sim.time and seen[-1]["fraction"] < 1  # paused at max_events: a last report

    done = []
    ede.Simulation(SMALL_GAS).run(progress=done.append)
    assert done[-1]["fraction"] == 1.0  # the stop reached: the display ends at 100 %

    def stop(p):
        raise RuntimeError("enough")

    with pytest.raises(RuntimeError, match="enough"):
        sim.run(progress=stop)
    assert sim.status == "running"
    sim.close()
    assert ede.open(tmp_path / "p.ede").info["events"] > 0


def test_ctrl_c_leaves_a_readable_resumable_log(tmp_path):
    path = tmp_path / "long.ede"
    scene = tmp_path / "long.toml"
    scene.write_text(SMALL_GAS.replace("collisions_per_particle = 20", "collisions_per_particle = 1e7"))
    code = textwrap.dedent("""
        import sys, ede
        print("started", flush=True)
        ede.run(sys.argv[1], log=sys.argv[2], progress=False)
    """)
    env = dict(os.environ)
    p = subprocess.Popen([sys.executable, "-c", code, str(scene), str(path)], stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE, text=True, env=env)
    assert p.stdout.readline().strip() == "started"
    time.sleep(1.5)
    p.send_signal(signal.SIGINT)
    out, err = p.communicate(timeout=60)
    assert p.returncode != 0
    assert "KeyboardInterrupt" in err
    assert "interrupted: " in err and "resumable" in err
    log = ede.open(path)
    assert not log.info["complete"]
    assert log.info["events"] > 0
    log.state(event=log.info["events"])  # every kept event reads


def test_resume_finishes_a_killed_run_byte_identically(tmp_path):
    scene = SMALL_GAS.replace("collisions_per_particle = 20", "collisions_per_particle = 60")
    whole, cut = tmp_path / "whole.ede", tmp_path / "cut.ede"
    ede.run(scene, log=whole, progress=False)
    sim = ede.Simulation(scene, log=cut)
    sim.run(max_events=30_000)
    sim.close()
    assert sim.log_kept()["resumable"]
    ede.resume(cut, progress=False)
    assert cut.read_bytes() == whole.read_bytes()


def test_load_scene_gives_the_effective_scene():
    s = ede.load_scene(SMALL_GAS, set={"physics.restitution": 0.8, "species[0].count": 10})
    assert s["physics"]["restitution"] == 0.8
    assert s["species"][0]["count"] == 10
