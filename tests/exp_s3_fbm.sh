#!/usr/bin/env bash
# Quick S3: five gains and five lacunarities, values inside the bound.
set -euo pipefail
# shellcheck source=tests/tsv.sh
. "$(dirname "$0")/tsv.sh"   # NOIMG
exp="$1" expect="$2" out="$3"
"$exp" --quick "${NOIMG[@]}" --out "$out" >/dev/null
for k in gain lacunarity; do
  "$expect" "$out/${k}_distribution.tsv" rows=5 'max_abs<=bound' 'sd>0' 'octaves==6' \
    "image:${k}_panels.png"
  "$expect" "$out/${k}_spectrum.tsv" rows=64
done
# Parameters reach the program: 3 octaves.
"$exp" --quick --no-images --out "$out/three" --set octaves=3 >/dev/null
"$expect" "$out/three/gain_distribution.tsv" 'octaves==3'
