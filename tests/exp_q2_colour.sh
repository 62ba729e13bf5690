#!/usr/bin/env bash
# Quick Q2: six patterns (Perlin + five GCTBF), each with spread, the montage
# written; the GCTBF values stay inside their analytic bounds (F <= 2 sqrt 3).
set -euo pipefail
# shellcheck source=tests/tsv.sh
. "$(dirname "$0")/tsv.sh"   # byte_reruns
exp="$1" expect="$2" out="$3"
"$exp" --quick "${NOIMG[@]}" --out "$out" >/dev/null
"$expect" "$out/values.tsv" rows=6 'sd>0.01' 'max>min' 'max<=24.8' 'min>=-12' \
  image:colour.png file:report.md
# Verdict rows: Fig. 2, qualitative.
verdict_kinds "$out/verdicts.tsv" 0 1
if byte_reruns; then   # same seed, same tables (tsv.sh: release build only)
  "$exp" --quick --no-images --out "$out/again" >/dev/null
  cmp "$out/values.tsv" "$out/again/values.tsv"
fi
