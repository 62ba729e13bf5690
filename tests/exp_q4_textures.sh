#!/usr/bin/env bash
# Quick Q4: six clouds and six Fig. 6 textures, each with spread; both
# montages written; same seed, same table.
set -euo pipefail
exp="$1" expect="$2" out="$3"
"$exp" --quick --out "$out" 2>/dev/null >/dev/null
"$expect" "$out/textures.tsv" rows=12 'sd>0.005' file:clouds.png file:textures.png file:report.md
"$exp" --quick --out "$out/again" 2>/dev/null >/dev/null
cmp "$out/textures.tsv" "$out/again/textures.tsv"
set +e
"$exp" --quick --out "$out/bad" --set octaves=31 2>/dev/null; [ $? -eq 2 ] || exit 1
