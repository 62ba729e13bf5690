#!/usr/bin/env bash
# Quick Q3: the original plane is flat and uniformly lit; each added octave
# raises the mean bump (eq. 6 adds non-negative terms) and the shading varies.
set -euo pipefail
exp="$1" expect="$2" out="$3"
"$exp" --quick --out "$out" 2>/dev/null >/dev/null
"$expect" "$out/bumps.tsv" rows=6 'bump_mean>=0' 'bump_max>=bump_mean' 'shade_mean<=1' \
  file:bumps.png file:report.md
awk -F'\t' 'NR==2 && ($2!=0 || $5!=0) {exit 1}
            NR>2 && ($5<=0.01) {exit 1}
            NR>2 {if (NR>3 && $2<=prev) exit 1; prev=$2}' "$out/bumps.tsv"
set +e
"$exp" --quick --out "$out/bad" --set octaves=31 2>/dev/null; [ $? -eq 2 ] || exit 1
