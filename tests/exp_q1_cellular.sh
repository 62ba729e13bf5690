#!/usr/bin/env bash
# Quick Q1: inverse-CDF counts pass chi-square against Poisson(4) and F1 passes
# KS against the nearest-neighbour law on every seed (alpha = 0.01); the
# paper's closest-p rule fails both on every seed (smaller m on ties); with the
# larger m on ties its mean count is near 4.2 and chi-square still rejects it;
# bad lambda / M refused.
set -euo pipefail
# shellcheck source=tests/tsv.sh
. "$(dirname "$0")/tsv.sh"   # tables by column name
exp="$1" expect="$2" out="$3"
"$exp" --quick "${NOIMG[@]}" --out "$out" >/dev/null
# Every panel against its caption, recomputed point by point
# (tests/oracle_sq.c): this run's when it wrote images, and the committed
# paper-scale figures the report shows.
panels_oracle sq q1 "$out" "$(dirname "$0")/../results/q1_cellular"
"$expect" "$out/summary.tsv" rows=3 'mean_f1_theory>0.34' 'mean_f1_theory<0.36' image:planes.png
tsv_awk 'v("rule")=="inverse-cdf" && (n("chi2_rejects")!=0 || n("ks_rejects")!=0 || n("mean_count")<3.8 || n("mean_count")>4.2) {print "row " NR " (" v("rule") ") out of range: " $0; exit 1}
            v("rule")=="closest" && (n("chi2_rejects")!=n("seeds") || n("ks_rejects")!=n("seeds")) {print "row " NR " (" v("rule") ") out of range: " $0; exit 1}
            v("rule")=="closest-last" && (n("chi2_rejects")!=n("seeds") || n("mean_count")<4.1 || n("mean_count")>4.3) {print "row " NR " (" v("rule") ") out of range: " $0; exit 1}' "$out/summary.tsv"
tsv_awk 'NR>1 && v("rule")=="inverse-cdf" && (n("chi2_p")<0.01 || n("ks_p")<0.01) {print "row " NR " (" v("rule") ") out of range: " $0; exit 1}' "$out/tests.tsv"
"$expect" "$out/tests.tsv" rows=9 'chi2>0' 'ks_d>0' 'df>=8'
"$expect" "$out/counts.tsv" rows=21 'poisson>0' 'closest>=0' 'inverse_cdf>=0' 'closest_last>=0'
# The verdict: the paper's rule (closest p(m), 16-bit cube seeds) against
# Poisson(4), every seed's cubes pooled: rejected (chi-square 3.1e4, p = 0).
# Its negative control, row 5: every cube with 4 points (no count law),
# rejected too (chi-square 5.1e4): the test tells a law from no law.
"$expect" "$out/count_law.tsv" rows=5 'p>=0' 'p<=1' 'chi2>0' 'cubes==12288'
tsv_awk 'v("rule") == "closest" && n("p") > 1e-6 { print "closest: p " n("p"); exit 1 }
  v("seeding") == "full hash" && n("p") < 0.01 { print "full hash pooled: p " n("p"); exit 1 }' \
  "$out/count_law.tsv"
tsv_awk 'FNR > 1 && v("quantity") == "count law of the paper'"'"'s rule" { rows++
    if (v("kind") != "independent" || v("verdict") != "not reproduced" \
        || v("rule") != "fit 0.01 0.001" || v("control_verdict") != "not reproduced") {
      print "verdict: " $0; exit 1 } }
  FNR > 1 && v("quantity") == "faces where some F_i jumps, paper'"'"'s rule" { rows++
    if (v("kind") != "independent" || v("verdict") != "reproduced" \
        || v("control_verdict") != "not reproduced") { print "verdict: " $0; exit 1 } }
  END { if (rows != 2 || NR != 3) { print "verdicts: " NR - 1 " rows"; exit 1 } }' "$out/verdicts.tsv"
# Continuity (sec. 3.1) across cube faces, where the 27 cubes searched
# change: F1..F4 at both sides of 1000 x 3 random faces, 1e-7 apart, never
# jump under the paper's rule (largest |dF| / step 0.99999: a distance is
# 1-Lipschitz); searching x's own cube alone they jump at every face.
"$expect" "$out/continuity.tsv" rows=2 'faces==3000' 'paper_jumps==0'
tsv_awk 'v("search") == "27 cubes" && (n("jumps") != 0 || n("max_ratio") > 1.000001) { print; exit 1 }
  v("search") == "own cube only" && n("jump_frac") < 0.9 { print; exit 1 }' "$out/continuity.tsv"
# The check: inverse-CDF counts with r from a full hash of (seed, i, j, k)
# pass on every seed (p 0.13-0.72 at seeds 1-3; paper scale: 0 of 10
# rejected, pooled p = 0.24).
"$expect" "$out/hash_check.tsv" rows=3 'chi2_p>=0.01' 'mean_count~4:0.1'
# The fixed set of 2^16 first draws every table shares: the same for any
# permutation (mean count 3.981201171875 = 260911 / 65536), and the
# chi-square it adds to a table of n cubes, n sum (q - p)^2 / p, is
# n / 65536 times its own (pooled bins aside): 0.60 at 4096 cubes (own 13.0).
"$expect" "$out/fixed_set.tsv" rows=1 'cube_seeds==65536' 'mean_count~3.981201171875:1e-12' \
  'chi2_added>0' 'chi2_added<chi2'
if byte_reruns; then   # same seed, same tables (tsv.sh: release build only)
  "$exp" --quick --no-images --out "$out/again" >/dev/null
  cmp "$out/tests.tsv" "$out/again/tests.tsv"
fi
set +e
refused "$exp" --quick --out "$out/bad" --set lambda=-1
refused "$exp" --quick --out "$out/bad" --set M=0
[ ! -e "$out/bad/manifest.tsv" ]
