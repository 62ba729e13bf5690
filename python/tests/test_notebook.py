"""The notebook a reader runs: python/examples/s3_gain.ipynb, executed as
Jupyter would (nbclient, an ipykernel kernel), regenerates S3's gain panels
and checks them against the committed table."""
import os

import pytest

from conftest import BUILD, ROOT, s3_copy_with_one_sd_changed

nbclient = pytest.importorskip(
    "nbclient", reason="Debian's python3-nbclient is not installed (scripts/noiselab setup "
    "installs it with python3-nbformat and python3-ipykernel)")
nbformat = pytest.importorskip("nbformat", reason="Debian's python3-nbformat is not installed")
pytest.importorskip("ipykernel", reason="Debian's python3-ipykernel is not installed")

NOTEBOOK = os.path.join(ROOT, "python", "examples", "s3_gain.ipynb")


def execute(folder=None):
    """The notebook run in its folder, as Jupyter runs it; its output text."""
    nb = nbformat.read(NOTEBOOK, as_version=4)
    for cell in nb.cells:   # what was committed is what this run must give again
        if cell.cell_type == "code":
            cell.outputs, cell.execution_count = [], None
    env = {"NOISELAB_LIBRARY": os.path.abspath(os.path.join(BUILD, "libnoiselab.so")),
           "PYDEVD_DISABLE_FILE_VALIDATION": "1"}   # ipykernel's debugger note on stderr
    if folder:
        env["NOISELAB_S3_FOLDER"] = str(folder)
    old = {k: os.environ.get(k) for k in env}
    os.environ.update(env)   # the kernel inherits the environment
    try:
        client = nbclient.NotebookClient(nb, timeout=600, kernel_name="python3",
                                         record_timing=False,
                                         resources={"metadata": {"path": os.path.dirname(
                                             NOTEBOOK)}})
        client.execute()
    finally:
        for k, v in old.items():
            if v is None:
                os.environ.pop(k, None)
            else:
                os.environ[k] = v
    text = []
    for cell in nb.cells:
        for out in cell.get("outputs", []):
            text.append(out.get("text", ""))
    return nb, "".join(text)


def test_notebook_regenerates_s3_gain():
    nb, text = execute()
    assert "15 of 15 panels equal" in text, text
    pictures = [o for c in nb.cells for o in c.get("outputs", [])
                if "image/png" in o.get("data", {})]
    assert len(pictures) == 1


def outputs(nb):
    """Each code cell's outputs: their kind, text and PNG bytes, the count."""
    return [(c.execution_count, [(o.output_type, o.get("text", ""), o.get("data", {}).get("image/png"))
                                 for o in c.outputs])
            for c in nb.cells if c.cell_type == "code"]


def test_committed_notebook_shows_this_run():
    """The notebook is committed with its outputs, so a reader on GitHub sees
    the panels and the check; they are the ones this run makes (the text,
    the PNG's bytes). NOISELAB_NOTEBOOK_WRITE=1 writes this run's outputs
    into python/examples/s3_gain.ipynb after a change."""
    nb, _ = execute()
    if os.environ.get("NOISELAB_NOTEBOOK_WRITE") == "1":
        nbformat.write(nb, NOTEBOOK)
    committed = nbformat.read(NOTEBOOK, as_version=4)
    assert any(c.get("outputs") for c in committed.cells), "committed without outputs"
    assert outputs(committed) == outputs(nb), "the committed outputs are not this run's " \
        "(NOISELAB_NOTEBOOK_WRITE=1 pytest tests/test_notebook.py rewrites them)"


def test_notebook_fails_on_a_changed_table(tmp_path):
    """Its check can fail: one sd changed in a copy of the folder stops it."""
    s3_copy_with_one_sd_changed(tmp_path)
    with pytest.raises(nbclient.exceptions.CellExecutionError) as e:
        execute(tmp_path)
    assert "1 panels differ" in str(e.value)
