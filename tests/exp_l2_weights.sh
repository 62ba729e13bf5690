#!/usr/bin/env bash
# L2 quick run (128^2, 7 bands, band 0 finest; size sweep 64..256, 3 seeds per
# size). Bounds are |mean| + 3 sd of the error measured at --quick over seeds
# 1..20 (not one seed's draw), rounded up:
#  - per band, est - true: band 0 mean +0.012 sd 0.061 (bound 0.2); bands 1-3
#    sd 0.084, 0.095, 0.120 (bound 0.37). Leakage between octaves (L1) moves
#    power between neighbours, so a 0.1 next to weights near 1 comes out near
#    0.5 in the coarser bands; bands 4-6 have too few coefficients at 128^2
#    (sd 0.17, 0.20, 0.28: 3 sd exceeds the weight range [0.1, 1]), so they are
#    checked only through the total power below. The old single 0.45 failed
#    band 6 on seeds 2 and 5 and accepted 0.45 on the fine bands.
#  - re-estimating from the noise of the estimated weights (est_of_d) repeats
#    the estimate: bands 0-2 sd 0.045 (bound 0.17), band 3 sd 0.062 (0.21);
#  - total power sum w_est^2 / sum w^2 (a wrong sigma_N^2 or Parseval factor
#    moves it by 2x or more): 3-seed means 0.79..1.18, sd 0.053..0.083 per size,
#    bound 1 +- 0.25 (the old 0.15 failed seeds with 0.79 and 1.18);
#  - relative RMS error of the weight vector shrinks with size: per size
#    err_mean 0.284 / 0.258 / 0.218 (sd 0.055 / 0.064 / 0.043; bounds 0.45 /
#    0.45 / 0.35), fine-band error at 256 below 0.9x that at 64 (measured ratio
#    0.36..0.86).
set -euo pipefail
. "$(dirname "$0")/tsv.sh"   # tables by column name
"$1" --quick --out "$3"
"$2" "$3/weights.tsv" 'rows=7' 'file:noise.png'
tsv_awk 'NR == 1 || n("band") == 0' "$3/weights.tsv" > "$3/weights_b0.tsv"
tsv_awk 'NR == 1 || (n("band") >= 1 && n("band") <= 2)' "$3/weights.tsv" > "$3/weights_b12.tsv"
tsv_awk 'NR == 1 || n("band") == 3' "$3/weights.tsv" > "$3/weights_b3.tsv"
"$2" "$3/weights_b0.tsv" 'rows=1' 'est~true:0.2' 'est_of_d~est:0.17'
"$2" "$3/weights_b12.tsv" 'rows=2' 'est~true:0.37' 'est_of_d~est:0.17'
"$2" "$3/weights_b3.tsv" 'rows=1' 'est~true:0.37' 'est_of_d~est:0.21'
"$2" "$3/error_vs_size.tsv" 'rows=3' 'err_mean>0' 'err_mean<0.45' 'err_sd>=0' 'power_ratio~1:0.25'
tsv_awk 'NR == 4 && n("err_mean") >= 0.35 {print "err_mean at 256: " n("err_mean"); exit 1}
            NR == 2 {e64 = n("err_fine_mean")} NR == 4 {e256 = n("err_fine_mean")}
            END {if (!(e256 < 0.9 * e64)) {print "fine error does not shrink with size: " e64 " -> " e256; exit 1}}' \
  "$3/error_vs_size.tsv"
test -s "$3/report.md" && test -s "$3/manifest.tsv"
