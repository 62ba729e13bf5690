#!/usr/bin/python3
"""S3 from Python: fBm at gain 0, 0.25, 0.5, 0.75, 1 (six octaves of improved
noise, lacunarity 2), the slides' "fBm varying gain" panels, and the mean and
sd of every panel checked against the committed table of the same run.

  PYTHONPATH=python /usr/bin/python3 python/examples/s3_gain.py [RESULTS_DIR] [-o PANELS.png]

RESULTS_DIR is an S3 folder (default results/quick/s3_fbm); its manifest
gives the window (size, extent, z) and seeds, so the check redoes exactly
that run. Exit 1 if a number differs from the table.
"""
import argparse
import os
import sys

import numpy as np

import noiselab.byexample as nb
import noiselab.noise as nn
import noiselab.results as nr
import noiselab.stats as ns

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def panels(folder):
    """Redoes the S3 run in folder: one row a seed and gain of gain_seeds.tsv,
    (setting, seed, mean, sd, equal to the table), and the panels of the
    run's first seed as grey levels in [0, 1] (render's mapping)."""
    r = nr.load(folder)
    par = dict(p.split("=", 1) for p in r.manifest["param"])
    size, extent, z = int(par["size"]), float(par["extent"]), float(par["z"])
    octaves, seed0 = int(par["octaves"]), r.manifest["seed"]
    rows, grey = [], []
    for row in r.tables["gain_seeds"]:
        gain = float(row["setting"].split()[-1])
        v = nn.grid("fbm", size, extent=extent, z=z, seed=int(row["seed"]), octaves=octaves,
                    gain=gain, lacunarity=2.0)
        m, sd = ns.mean_sd(v.ravel())
        rows.append((row["setting"], int(row["seed"]), m, sd, m == row["mean"] and sd == row["sd"]))
        if int(row["seed"]) == seed0:
            # grey levels as render maps them: the analytic bound to [0, 1]
            bound = nn.bound("fbm", octaves=octaves, gain=gain)
            grey.append((v / bound + 1) / 2)
    return rows, grey


def side_by_side(grey):
    """The panels in one image, 4 white columns between them."""
    gap = np.ones((grey[0].shape[0], 4))
    return np.hstack([x for p in grey for x in (p, gap)][:-1])


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("folder", nargs="?", default=os.path.join(ROOT, "results/quick/s3_fbm"))
    ap.add_argument("-o", "--out", help="write the five panels side by side to this PNG")
    a = ap.parse_args()
    rows, grey = panels(a.folder)
    for setting, seed, m, sd, ok in rows:
        print(f"{setting:<16} seed {seed}: mean {m:+.6f} sd {sd:.6f}  "
              f"{'= table' if ok else 'DIFFERS from the table'}")
    if a.out:
        nb.write_image(side_by_side(grey), a.out, 8)
        print(f"wrote {a.out}")
    good = sum(ok for *_, ok in rows)
    print(f"{good} of {len(rows)} panels equal {a.folder}/gain_seeds.tsv")
    return 0 if good == len(rows) else 1


if __name__ == "__main__":
    sys.exit(main())
