#!/usr/bin/env bash
# Quick A1: the analytic bound and every incremental interval hold on every
# random point; observed extremes are positive and below the bound.
set -euo pipefail
exp="$1" expect="$2" out="$3"
"$exp" --quick --out "$out" 2>/dev/null >/dev/null
"$expect" "$out/bounds.tsv" rows=8 'over_bound==0' 'over_bound_incremental==0' \
  'max_abs<=bound' 'max_abs>0.5' 'max_noise<=1.2247448713915890' 'S<2' 'S>=1' \
  file:manifest.tsv file:report.md
"$exp" --quick --out "$out/again" 2>/dev/null >/dev/null
cmp "$out/bounds.tsv" "$out/again/bounds.tsv"
set +e
"$exp" --quick --out "$out/bad" --set octaves=31 2>/dev/null; [ $? -eq 2 ] || exit 1
[ ! -e "$out/bad/manifest.tsv" ]
