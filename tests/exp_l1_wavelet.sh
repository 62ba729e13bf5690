#!/usr/bin/env bash
# L1 quick run: measured band variance (2D 0.275, 3D 0.195 within 0.02:
# the seed-to-seed sd is ~0.003), variance on shifted lattices larger in 2D
# than 3D, the two finest bands keeping > 75% of their power in-octave
# (measured 0.81-0.90), and every output present.
set -euo pipefail
# shellcheck source=tests/tsv.sh
. "$(dirname "$0")/tsv.sh"   # NOIMG
"$1" --quick "${NOIMG[@]}" --out "$3"
expect="$2"   # panels_oracle finds oracle_al beside it
# every panel against its caption (oracle_al.c), this run and the committed one
panels_oracle al l1 "$3" "$(dirname "$0")/../results/l1_wavelet"
"$2" "$3/summary.tsv" 'rows=8' 'ours>0' 'ours<1.0' 'ours_se>0' 'seeds==3' image:noise.png
"$2" "$3/variance.tsv" 'rows=3' 'var2d~0.275:0.02' 'var3d~0.195:0.02'
"$2" "$3/lattice.tsv" 'rows=9' 'var2d>var3d'
# every band keeps a share of its power in-octave: measured 0.21 (band 5, few
# coefficients) .. 0.90 over seeds 1..5
"$2" "$3/leakage.tsv" 'rows>=6' 'inside>0.15'
awk -F'\t' 'NR <= 3' "$3/leakage.tsv" > "$3/leakage_fine.tsv"   # bands 0 and 1
"$2" "$3/leakage_fine.tsv" 'rows=2' 'inside>0.75'
# Readings of the 3D variance against 0.210 (12 rows). Measured at --quick
# (period 32, seeds 1..3): the volume-like readings (ours, mean subtracted,
# random points, transposed copy, doubled period) 0.194-0.198, all within
# 0.005 of the volume reading (bound 0.01, ~3x their sd); the plane z = 0
# reads 0.223 (above 0.210 and above the volume by 0.026; bound: above by
# > 0.01), the plane z = 1/2 0.170 (below the volume by 0.027; bound 0.01).
"$2" "$3/variance_readings.tsv" 'rows=12' 'paper==0.21' 'var3d>0.1' 'var3d<0.3'
tsv_awk 'FNR > 1 {val[FNR - 2] = n("var3d")}
  END {
    for (i = 1; i <= 11; i++) if (i == 1 || i == 2 || i == 8 || i == 11)
      if (val[i] - val[0] > 0.01 || val[0] - val[i] > 0.01) {printf "volume-like reading %d: %.4f vs volume %.4f\n", i, val[i], val[0]; exit 1}
    if (!(val[4] > val[0] + 0.01 && val[5] < val[0] - 0.01)) {printf "planes z=0 %.4f, z=1/2 %.4f vs volume %.4f\n", val[4], val[5], val[0]; exit 1}
  }' "$3/variance_readings.tsv"
grep -q 'reading(s) lie within 2 sd over seeds of 0.210' "$3/report.md"
# The exact expectation (expect.h) beside the measurement: 2D 0.2703 and 3D
# 0.1959 on the 4-per-unit grid at every period >= 32 (0.1956 continuous);
# the quick run's means lie +0.07 and +1.47 standard errors from them
# (bound 4). Four verdict rows decided by equivalence, each with its
# control (the coefficients without the band-pass): the three that the
# control fails stay independent; the normal law, which the control also
# has, is by construction.
"$2" "$3/expected.tsv" 'rows=2' 'z<4' 'z>-4' 'seeds==3'
tsv_awk 'NR > 1 {e[n("dim")] = n("expected")}
  END {if (e[2] < 0.2698 || e[2] > 0.2708 || e[3] < 0.1954 || e[3] > 0.1964) {
         print "expected " e[2] " " e[3]; exit 1}}' \
  "$3/expected.tsv"
"$2" "$3/expected_period.tsv" 'rows=5' 'var3d_cont>0.195' 'var3d_cont<0.1965' 'var3d>var3d_cont'
"$2" "$3/verdicts.tsv" 'rows=4'
tsv_awk 'NR > 1 && v("rule") !~ /^equiv / {print "rule " v("rule"); exit 1}
  NR > 1 && v("quantity") ~ /Kolmogorov/ && v("kind") != "by construction" {print "normal law " v("kind"); exit 1}
  NR > 1 && v("quantity") !~ /Kolmogorov/ && (v("kind") != "independent" || v("control_verdict") != "not reproduced") {
    print v("quantity") ": " v("kind") ", control " v("control_verdict"); exit 1}' "$3/verdicts.tsv"
test -s "$3/report.md" && test -s "$3/manifest.tsv"
