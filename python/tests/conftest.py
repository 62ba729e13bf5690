"""The build under test: NOISELAB_BUILD (the meson test sets it), else ../../build."""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
BUILD = os.environ.get("NOISELAB_BUILD", os.path.join(ROOT, "build"))
os.environ.setdefault("NOISELAB_LIBRARY", os.path.join(BUILD, "libnoiselab.so"))
sys.path.insert(0, os.path.join(ROOT, "python"))
