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
"$expect" "$out/summary.tsv" rows=3 'mean_f1_theory>0.34' 'mean_f1_theory<0.36' image:planes.png
tsv_awk 'v("rule")=="inverse-cdf" && (n("chi2_rejects")!=0 || n("ks_rejects")!=0 || n("mean_count")<3.8 || n("mean_count")>4.2) {print "row " NR " (" v("rule") ") out of range: " $0; exit 1}
            v("rule")=="closest" && (n("chi2_rejects")!=n("seeds") || n("ks_rejects")!=n("seeds")) {print "row " NR " (" v("rule") ") out of range: " $0; exit 1}
            v("rule")=="closest-last" && (n("chi2_rejects")!=n("seeds") || n("mean_count")<4.1 || n("mean_count")>4.3) {print "row " NR " (" v("rule") ") out of range: " $0; exit 1}' "$out/summary.tsv"
tsv_awk 'NR>1 && v("rule")=="inverse-cdf" && (n("chi2_p")<0.01 || n("ks_p")<0.01) {print "row " NR " (" v("rule") ") out of range: " $0; exit 1}' "$out/tests.tsv"
"$expect" "$out/tests.tsv" rows=9 'chi2>0' 'ks_d>0' 'df>=8'
"$expect" "$out/counts.tsv" rows=21 'poisson>0' 'closest>=0' 'inverse_cdf>=0' 'closest_last>=0'
if byte_reruns; then   # same seed, same tables (tsv.sh: release build only)
  "$exp" --quick --no-images --out "$out/again" >/dev/null
  cmp "$out/tests.tsv" "$out/again/tests.tsv"
fi
set +e
refused "$exp" --quick --out "$out/bad" --set lambda=-1
refused "$exp" --quick --out "$out/bad" --set M=0
[ ! -e "$out/bad/manifest.tsv" ]
