"""ede.sweep(): a sweep file run from Python gives ede-sweep's tables (the same CSV bytes) as numpy
structured arrays holding the row files' exact doubles; bad input raises with ede-sweep's message."""
import csv
import json
import math

import numpy as np
import pytest

import ede
from conftest import ROOT, tool

SMALL = ROOT / "tests" / "tools" / "sweep" / "small.sweep.toml"


def test_sweep_tables_are_ede_sweeps(tmp_path):
    seen = []
    got = ede.sweep(SMALL, workers=2, out_dir=tmp_path / "py", timing=False, progress=seen.append)
    tool("ede-sweep", SMALL, "--out-dir", tmp_path / "cli", "-j", 1, "--no-timing", "-q")
    for name in ("runs.csv", "points.csv"):
        assert (tmp_path / "py" / name).read_bytes() == (tmp_path / "cli" / name).read_bytes()
    assert got.status == 0 and got.summary.startswith("8 runs: 8 ok")
    assert sorted(p["done"] for p in seen) == list(range(1, 9)) and seen[-1]["runs"] == 8

    runs, points = got.runs, got.points
    assert len(runs) == 8 and len(points) == 4
    assert runs.dtype["physics.restitution"] == np.float64 and runs.dtype["seed"] == np.int64
    # Every cell of the CLI's table, number for number.
    with open(tmp_path / "cli" / "runs.csv", newline="") as f:
        for rec, row in zip(runs, csv.DictReader(f)):
            for key, cell in row.items():
                v = rec[key]
                if isinstance(v, (np.floating, float)):
                    assert (math.isnan(v) and cell == "") or v == float(cell), (key, cell, v)
                elif isinstance(v, (np.integer, int)):
                    assert v == int(cell)
                else:
                    assert v == cell
    # The arrays hold the doubles the runs' processes measured (their row files), exactly.
    for rec in runs:
        row = json.loads((tmp_path / "py" / "runs" / (rec["name"] + ".json")).read_text())
        for q, v in zip(row["collect"], row["values"]):
            assert rec[q] == v
    with open(tmp_path / "cli" / "points.csv", newline="") as f:
        for rec, row in zip(points, csv.DictReader(f)):
            assert rec["ok"] == int(row["ok"]) == 2
            assert rec["energy@0.25_mean"] == float(row["energy@0.25_mean"])
            assert rec["energy@0.25_error"] == float(row["energy@0.25_error"])

    again = ede.sweep(SMALL, out_dir=tmp_path / "py", progress=False, timing=False)
    assert "(0 run now, 8 reused)" in again.summary
    same = ede.sweep_tables(tmp_path / "py")
    assert same.runs.tobytes() == runs.tobytes()


def test_sweep_overrides_and_bad_input(tmp_path):
    got = ede.sweep(SMALL, out_dir=tmp_path / "set", progress=False, set={"stop.time": 0.6})
    assert got.status == 0
    assert list(got.runs["status"]) == ["ok"] * 8
    bad = tmp_path / "typo.sweep.toml"
    bad.write_text('scene = "%s"\ncolect = []\n' % (ROOT / "examples" / "cooling.toml"))
    with pytest.raises(ede.InvalidError, match="typo.sweep.toml:2: unknown key 'colect'. Fix:"):
        ede.sweep(bad, progress=False)
    with pytest.raises(ede.InvalidError, match="physics.restitution: must be in"):
        ede.sweep(SMALL, out_dir=tmp_path / "bad", progress=False, set={"physics.restitution": 2})
    with pytest.raises(TypeError, match="workers"):
        ede.sweep(SMALL, workers="two")
    with pytest.raises(TypeError, match="path"):
        ede.sweep(3)
