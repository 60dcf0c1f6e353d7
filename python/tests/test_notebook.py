"""The notebook examples/python/jupyter.ipynb executed headless, as Jupyter would run it (nbclient with an
ipykernel kernel: Debian's python3-nbclient and python3-ipykernel): ede.run's progress line and
ede.sweep's appear under their cells as display output, and the run's log is there and complete.
Skipped (pytest's skip) where nbclient, nbformat or ipykernel is missing."""
import os

import pytest

import ede
from conftest import ROOT

nbclient = pytest.importorskip("nbclient")
nbformat = pytest.importorskip("nbformat")
pytest.importorskip("ipykernel")


def test_notebook_shows_progress_and_writes_the_log(tmp_path, monkeypatch):
    nb = nbformat.read(str(ROOT / "examples" / "python" / "jupyter.ipynb"), as_version=4)
    monkeypatch.setenv("EDE_NOTEBOOK_OUT", str(tmp_path))
    monkeypatch.setenv("EDE_NOTEBOOK_QUICK", "1")
    monkeypatch.setenv("PYDEVD_DISABLE_FILE_VALIDATION", "1")  # ipykernel's debugger warning, not ours
    client = nbclient.NotebookClient(nb, timeout=300, kernel_name="python3",
                                     resources={"metadata": {"path": str(ROOT / "examples" / "python")}})
    client.execute()
    shown = [o["data"].get("text/plain", "") for c in nb.cells if c.cell_type == "code" for o in c.outputs
             if o["output_type"] in ("display_data", "update_display_data")]
    printed = "".join(o.get("text", "") for c in nb.cells if c.cell_type == "code" for o in c.outputs
                      if o["output_type"] == "stream" and o["name"] == "stdout")
    assert any("events" in s and "M events/s" in s and "%" in s for s in shown), shown  # ede.run's line
    assert any("ede.sweep: 9/9 runs" in s for s in shown), shown                       # ede.sweep's line
    log_path = tmp_path / "notebook-gas.ede"
    assert ede.open(log_path).info["complete"]
    assert "the log: %s" % log_path in printed
    assert "9 runs: 9 ok" in printed
