#!/usr/bin/env bash
# Quick C7: three height maps (mesh x mesh) with heights in [0, 1].
set -euo pipefail
exp="$1" expect="$2" out="$3"
pat="$(cd "$(dirname "$0")/../data/patterns" && pwd)"
"$exp" --quick --out "$out" --patterns "$pat" >/dev/null
"$expect" "$out/summary.tsv" rows=3 'E_ks>=0' 'E_con>0' file:heightmaps.png
for p in flower x star; do
  "$expect" "$out/height_$p.tsv" rows=48 'c0>=0' 'c0<=1' 'c47>=0' 'c47<=1'
done
