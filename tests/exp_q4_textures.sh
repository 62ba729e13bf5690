#!/usr/bin/env bash
# Quick Q4: six clouds and six Fig. 6 textures, each with spread; both
# montages written; same seed, same table.
set -euo pipefail
. "$(dirname "$0")/tsv.sh"   # tables by column name; refused
exp="$1" expect="$2" out="$3"
"$exp" --quick --out "$out" >/dev/null
"$expect" "$out/textures.tsv" rows=12 'sd>0.005' file:clouds.png file:textures.png file:report.md
"$exp" --quick --out "$out/again" >/dev/null
cmp "$out/textures.tsv" "$out/again/textures.tsv"
set +e
refused "$exp" --quick --out "$out/bad" --set octaves=31
