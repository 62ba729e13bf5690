#!/usr/bin/env bash
# Quick A2: at every octave count the bounded image equals the plain one
# (0 8-bit levels apart), the bounded march evaluates fewer octaves (from
# N = 1 on, at least 1.3x fewer at N = 10), plain evaluates terms per
# sample. Timings are written but not checked.
set -euo pipefail
. "$(dirname "$0")/tsv.sh"   # tables by column name
exp="$1" expect="$2" out="$3"
"$exp" --quick --out "$out" >/dev/null
"$expect" "$out/timing.tsv" rows=6 'max_diff_levels==0' 'bounded_evals<plain_evals' \
  'eval_ratio>1' 'terms>octaves' 'max_noise<=1.2247448713915890' 'plain_ms>0' \
  file:balls.png file:ball.png file:bounds.png file:report.md
# The gain grows with the number of octaves (last row against the second).
tsv_awk 'NR==3{a=n("eval_ratio")} NR==7{b=n("eval_ratio")} END{exit !(b > a && b > 1.3)}' "$out/timing.tsv"
grep -q "differ by 0 levels" "$out/report.md"
set +e
refused "$exp" --quick --out "$out/bad" --set slope=1
