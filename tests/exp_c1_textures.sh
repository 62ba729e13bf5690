#!/usr/bin/env bash
# Quick C1: four textures x three patterns, every table uniform-looking by KS
# and better than a random table on the control term (E_Con < pixels / 4).
set -euo pipefail
exp="$1" expect="$2" out="$3"
pat="$(cd "$(dirname "$0")/../data/patterns" && pwd)"
"$exp" --quick --out "$out" --patterns "$pat" >/dev/null
"$expect" "$out/summary.tsv" rows=12 'seeds==3' 'E_ks>0' 'E_ks<0.06' 'E_con>0' 'rms_con<0.5' \
  'p_ks>=0' 'p_ks<=1' 'roughness>0' file:cloud.png file:marble.png file:erosion.png file:fire.png
