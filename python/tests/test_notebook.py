"""The example notebook executes from start to end (nbclient), so it cannot
rot."""

from pathlib import Path

import pytest

nbformat = pytest.importorskip("nbformat")
nbclient = pytest.importorskip("nbclient")

HERE = Path(__file__).resolve().parent
NOTEBOOK = HERE.parent / "examples" / "quickstart.ipynb"


def test_quickstart_notebook_executes(monkeypatch):
    # The kernel draws inline (images in the outputs) unless told otherwise.
    monkeypatch.delenv("MPLBACKEND", raising=False)
    nb = nbformat.read(NOTEBOOK, as_version=4)
    client = nbclient.NotebookClient(
        nb, timeout=600, kernel_name="python3", resources={"metadata": {"path": str(NOTEBOOK.parent)}}
    )
    client.execute()
    outputs = [o for cell in nb.cells if cell.cell_type == "code" for o in cell.get("outputs", [])]
    assert not [o for o in outputs if o.get("output_type") == "error"]
    # The plots were drawn.
    assert any("image/png" in o.get("data", {}) for o in outputs)
