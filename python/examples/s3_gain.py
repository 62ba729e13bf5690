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


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("folder", nargs="?", default=os.path.join(ROOT, "results/quick/s3_fbm"))
    ap.add_argument("-o", "--out", help="write the five panels side by side to this PNG")
    a = ap.parse_args()
    r = nr.load(a.folder)
    par = dict(p.split("=", 1) for p in r.manifest["param"])
    size, extent, z = int(par["size"]), float(par["extent"]), float(par["z"])
    octaves, seed0 = int(par["octaves"]), r.manifest["seed"]
    table = r.tables["gain_seeds"]
    bad = 0
    panels = []
    for row in table:
        gain = float(row["setting"].split()[-1])
        v = nn.grid("fbm", size, extent=extent, z=z, seed=int(row["seed"]), octaves=octaves,
                    gain=gain, lacunarity=2.0)
        m, sd = ns.mean_sd(v.ravel())
        ok = m == row["mean"] and sd == row["sd"]
        bad += not ok
        print(f"{row['setting']:<16} seed {int(row['seed'])}: mean {m:+.6f} sd {sd:.6f}  "
              f"{'= table' if ok else 'DIFFERS from the table'}")
        if int(row["seed"]) == seed0:
            # grey levels as render maps them: the analytic bound to [0, 1]
            bound = nn.bound("fbm", octaves=octaves, gain=gain)
            panels.append((v / bound + 1) / 2)
    if a.out:
        gap = np.ones((size, 4))
        nb.write_image(np.hstack([x for p in panels for x in (p, gap)][:-1]), a.out, 8)
        print(f"wrote {a.out}")
    print(f"{len(table) - bad} of {len(table)} panels equal {a.folder}/gain_seeds.tsv")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
