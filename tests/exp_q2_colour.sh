#!/usr/bin/env bash
# Quick Q2: six patterns (Perlin + five GCTBF), each with spread, the montage
# written; the GCTBF values stay inside their analytic bounds (F <= 2 sqrt 3).
set -euo pipefail
# shellcheck source=tests/tsv.sh
. "$(dirname "$0")/tsv.sh"   # byte_reruns
exp="$1" expect="$2" out="$3"
"$exp" --quick "${NOIMG[@]}" --out "$out" >/dev/null
# Every panel against its caption, recomputed point by point
# (tests/oracle_sq.c): this run's when it wrote images, and the committed
# paper-scale figures the report shows.
panels_oracle sq q2 "$out" "$(dirname "$0")/../results/q2_colour"
"$expect" "$out/values.tsv" rows=6 'sd>0.01' 'max>min' 'max<=24.8' 'min>=-12' \
  image:colour.png file:report.md
# What eq. 4 makes of each pattern (spline_use.tsv): the clamped share and
# the colour-index entropy over the spline's 10 segments (at most log2 10 =
# 3.32 bits). Worley's linear patterns are never clamped (F1, F2 - F1 >= 0
# and below 1 here); F2 - F1 - F1F1 is negative on about half the plane
# (0.54 at seed 1, quick; 0.57 at paper scale).
"$expect" "$out/spline_use.tsv" rows=9 'entropy>0' 'entropy<=3.3220' 'clamped>=0' 'clamped<=1' \
  'seeds==3'
tsv_awk 'v("pattern") == "linear" && n("clamped") != 0 { print "linear clamped: " $0; exit 1 }
  v("pattern") == "F2 - F1 - F1F1" && !(n("clamped") > 0.3 && n("clamped") < 0.8) {
    print "F2 - F1 - F1F1 clamped: " $0; exit 1 }' "$out/spline_use.tsv"
# Verdict rows: the entropy of the linear patterns below the non-linear ones
# (independent; not reproduced: 2.10 vs 1.97 bits at quick scale, 2.02 vs
# 1.93 at paper scale), its control never reproduced; Fig. 2, qualitative.
verdict_kinds "$out/verdicts.tsv" 1 1
tsv_awk 'FNR > 1 && v("kind") == "independent" && v("control_verdict") !~ /^(partly|not reproduced)$/ {
  print "control: " $0; exit 1 }' "$out/verdicts.tsv"
if byte_reruns; then   # same seed, same tables (tsv.sh: release build only)
  "$exp" --quick --no-images --out "$out/again" >/dev/null
  cmp "$out/values.tsv" "$out/again/values.tsv"
fi
