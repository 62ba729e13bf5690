"""The build under test: NOISELAB_BUILD (the meson test sets it), else ../../build."""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
BUILD = os.environ.get("NOISELAB_BUILD", os.path.join(ROOT, "build"))
os.environ.setdefault("NOISELAB_LIBRARY", os.path.join(BUILD, "libnoiselab.so"))
sys.path.insert(0, os.path.join(ROOT, "python"))


def s3_copy_with_one_sd_changed(folder):
    """S3's committed quick tables copied into folder, one sd of gain_seeds.tsv
    changed in its 12th digit: the examples' checks must find that panel."""
    src = os.path.join(ROOT, "results", "quick", "s3_fbm")
    for f in os.listdir(src):
        if f.endswith(".tsv"):
            with open(os.path.join(src, f), encoding="utf-8") as fh:
                text = fh.read()
            if f == "gain_seeds.tsv":
                text = text.replace("0.28279196913397137", "0.282791969134", 1)
            with open(os.path.join(str(folder), f), "w", encoding="utf-8") as fh:
                fh.write(text)
