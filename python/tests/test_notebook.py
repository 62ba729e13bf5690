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
    env = {"NOISELAB_LIBRARY": os.path.abspath(os.path.join(BUILD, "libnoiselab.so")),
           "PYDEVD_DISABLE_FILE_VALIDATION": "1"}   # ipykernel's debugger note on stderr
    if folder:
        env["NOISELAB_S3_FOLDER"] = str(folder)
    old = {k: os.environ.get(k) for k in env}
    os.environ.update(env)   # the kernel inherits the environment
    try:
        client = nbclient.NotebookClient(nb, timeout=600, kernel_name="python3",
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


def test_notebook_fails_on_a_changed_table(tmp_path):
    """Its check can fail: one sd changed in a copy of the folder stops it."""
    s3_copy_with_one_sd_changed(tmp_path)
    with pytest.raises(nbclient.exceptions.CellExecutionError) as e:
        execute(tmp_path)
    assert "1 panels differ" in str(e.value)
