"""Fixtures for the Python module's tests: small logs written once per session, and the command-line tools
(their directory from EDE_TOOLS_DIR, set by ctest) to compare with."""
import os
import pathlib
import subprocess

import pytest

import ede

ROOT = pathlib.Path(__file__).resolve().parents[2]
TOOLS = pathlib.Path(os.environ.get("EDE_TOOLS_DIR", ROOT / "build" / "tools"))

SMALL_GAS = """
seed = 7
[box]
size = [1.0, 1.0]
boundary = "walls"
[[species]]
name = "light"
count = 150
radius = 0.01
mass = 1.0
[species.velocity]
kind = "speed"
speed = 1.0
[[species]]
name = "heavy"
count = 50
radius = 0.01
mass = 4.0
[species.velocity]
kind = "speed"
speed = 0.5
[stop]
collisions_per_particle = 20
[log]
keyframe_interval = 1000
chunk_events = 256
"""


def tool(name, *args, check=True):
    """Runs a tool; returns the CompletedProcess (text)."""
    return subprocess.run([str(TOOLS / name), *map(str, args)], capture_output=True, text=True, check=check)


@pytest.fixture(scope="session")
def gas_scene(tmp_path_factory):
    p = tmp_path_factory.mktemp("scene") / "small-gas.toml"
    p.write_text(SMALL_GAS)
    return p


@pytest.fixture(scope="session")
def gas_log(gas_scene, tmp_path_factory):
    path = tmp_path_factory.mktemp("logs") / "gas.ede"
    ede.run(gas_scene, log=path, progress=False)
    return path


@pytest.fixture(scope="session")
def periodic_log(tmp_path_factory):
    path = tmp_path_factory.mktemp("logs") / "periodic.ede"
    ede.run(ROOT / "examples" / "scenes" / "periodic.toml", log=path, progress=False,
            set={"stop.collisions_per_particle": 5})
    return path
