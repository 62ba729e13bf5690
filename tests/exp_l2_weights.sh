#!/usr/bin/env bash
# L2 quick run. Per band, leakage between octaves (L1) lets a weight of 0.1
# next to weights near 1 come out near 0.5, so the per-band check is loose
# (0.45) and the sharp one is the total power: sum w_est^2 / sum w^2 within
# 15% of 1 (a wrong sigma_N^2 or Parseval factor moves it by much more).
set -euo pipefail
"$1" --quick --out "$3"
"$2" "$3/weights.tsv" 'rows=7' 'est~true:0.45' 'est_of_d~est:0.45' 'est>=0' 'file:noise.png'
"$2" "$3/error_vs_size.tsv" 'rows=3' 'err_mean>0' 'err_mean<0.5' 'err_sd>=0' 'power_ratio~1:0.15'
test -s "$3/report.md" && test -s "$3/manifest.tsv"
