"""Ctrl-C during a long noise call (points, grid): the extension runs it a block at a time
with the GIL released and checks for signals between blocks (_ext.c), so
SIGINT raises KeyboardInterrupt within a block's time, not when the call
ends. A child process starts a call that would take seconds; this process
sends SIGINT and the child says when KeyboardInterrupt reached Python
(CLOCK_MONOTONIC is the same clock in both processes)."""
import os
import signal
import subprocess
import sys
import time

import pytest

from conftest import BUILD, ROOT

CHILD = r"""
import math, sys, time, numpy as np, noiselab.noise as nn
noise, kw, seconds = sys.argv[1], eval(sys.argv[2]), float(sys.argv[3])
grid = kw.pop("grid", False)
r = np.random.default_rng(1)
x = r.uniform(-100, 100, (3, 2000))
t = time.thread_time()
nn.grid(noise, 40, **kw) if grid else nn.points(*x, noise, **kw)
per = (time.thread_time() - t) / (1600 if grid else x.shape[1])
n = int(seconds / per)   # a call of this many seconds of CPU, were it not stopped
if grid:
    size = int(math.sqrt(n))
    call = lambda: nn.grid(noise, size, **kw)
    n = size * size
else:
    x = r.uniform(-100, 100, (3, n))
    call = lambda: nn.points(*x, noise, **kw)
print("go", per * n, flush=True)
try:
    call()
    print("done", flush=True)
except KeyboardInterrupt:
    print("interrupted", time.monotonic(), flush=True)
"""


@pytest.mark.parametrize("noise,kw,seconds", [
    ("fbm", dict(basis="gctbf", octaves=8), 20.0),   # the library's point loops
    ("fbm", dict(octaves=30), 4.0),                   # the SIMD batch kernel
    ("fbm", dict(basis="gctbf", octaves=4, grid=True), 10.0),   # grid's rows
])
def test_ctrl_c_interrupts_a_long_call_within_0_2_s(noise, kw, seconds):
    env = dict(os.environ, NOISELAB_BUILD=BUILD,
               PYTHONPATH=os.path.join(ROOT, "python"), PYTHONDONTWRITEBYTECODE="1")
    p = subprocess.Popen([sys.executable, "-c", CHILD, noise, repr(kw), str(seconds)],
                         stdout=subprocess.PIPE, text=True, env=env)
    try:
        go = p.stdout.readline().split()
        assert go and go[0] == "go", go
        assert float(go[1]) > 1.0, "the call would not have been long"
        time.sleep(0.3)
        sent = time.monotonic()
        p.send_signal(signal.SIGINT)
        out = p.stdout.readline().split()
        p.wait(timeout=60)
    finally:
        if p.poll() is None:
            p.kill()
            p.wait()
    assert out and out[0] == "interrupted", out
    latency = float(out[1]) - sent
    print(f"{noise} {kw}: KeyboardInterrupt {latency * 1e3:.1f} ms after SIGINT, "
          f"load {os.getloadavg()[0]:.1f}")
    assert 0 <= latency < 0.2, latency
