"""The example a reader runs: python/examples/s3_gain.py regenerates S3's gain
panels and finds every panel's mean and sd equal to the committed table."""
import os
import subprocess
import sys

import numpy as np

from conftest import ROOT, s3_copy_with_one_sd_changed
import noiselab.byexample as nb

SCRIPT = os.path.join(ROOT, "python", "examples", "s3_gain.py")


def run(*args):
    env = dict(os.environ, PYTHONPATH=os.path.join(ROOT, "python"))
    return subprocess.run([sys.executable, SCRIPT, *map(str, args)], env=env,
                          capture_output=True, text=True)


def test_s3_gain_example(tmp_path):
    r = run("-o", tmp_path / "panels.png")
    assert r.returncode == 0, r.stdout + r.stderr
    assert "15 of 15 panels equal" in r.stdout
    img = nb.read_image(tmp_path / "panels.png")
    assert img.shape[0] == 128 and img.shape[1] == 5 * 128 + 4 * 4
    # rougher with gain: the mean |horizontal step| over the sd grows panel by panel
    panels = [img[:, k * 132:k * 132 + 128, 0].astype(float) for k in range(5)]
    rough = [np.abs(np.diff(p, axis=1)).mean() / p.std() for p in panels]
    assert rough == sorted(rough), rough


def test_s3_gain_example_fails_on_a_changed_table(tmp_path):
    """The check can fail: one sd changed in a copy of the folder is found."""
    s3_copy_with_one_sd_changed(tmp_path)
    r = run(tmp_path)
    assert r.returncode == 1 and "14 of 15 panels equal" in r.stdout, r.stdout + r.stderr
