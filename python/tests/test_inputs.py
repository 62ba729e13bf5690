"""Damaged inputs refused as the tools refuse them: an image file cut short,
a Cheng control pattern with values outside [0, 1]."""
import numpy as np
import pytest

import conftest  # noqa: F401  (puts the build's package on the path)
import noiselab.byexample as nb
import noiselab.cheng as nc


@pytest.mark.parametrize("name,bits", [("cut.tif", 8), ("cut.png", 8), ("cut.exr", 16)])
def test_truncated_image_raises(tmp_path, name, bits):
    rng = np.random.default_rng(3)
    path = tmp_path / name
    nb.write_image(rng.random((96, 128, 3)), path, bits)
    data = path.read_bytes()
    path.write_bytes(data[: len(data) * 3 // 10])   # as `head -c` 30% leaves it
    with pytest.raises(ValueError, match=str(path)):
        nb.read_image(path)


@pytest.mark.parametrize("value", [1.5, -0.25])
def test_pattern_outside_unit_interval_raises(value):
    pattern = np.zeros((16, 16, 4))
    pattern[..., 3] = 1
    pattern[5, 7, 0] = value
    rng = np.random.default_rng(0)
    table = (rng.uniform(0, 2 * np.pi, 512), rng.permutation(512))
    with pytest.raises(ValueError, match=r"pixel \(7, 5\)"):
        nc.evaluate(table, pattern, grid=8, octaves=2)
