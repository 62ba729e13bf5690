#!/usr/bin/env bash
# Quick Q4: six clouds and six Fig. 6 textures, each with spread; both
# montages written; same seed, same table.
set -euo pipefail
# shellcheck source=tests/tsv.sh
. "$(dirname "$0")/tsv.sh"   # tables by column name; refused
exp="$1" expect="$2" out="$3"
"$exp" --quick "${NOIMG[@]}" --out "$out" >/dev/null
"$expect" "$out/textures.tsv" rows=12 'sd>0.005' image:clouds.png image:textures.png file:report.md
"$expect" "$out/wood.tsv" rows=2 'perturb_rings_sd>0.05' 'perturb_rings_sd<1' \
  'ring_sd~0.353:0.01' image:wood.png
tsv_awk 'FNR > 1 {r = n("rings"); g = n("rings_geometry"); b = n("ramp_bands")
  if (r - g > 3 || g - r > 3 || b > r - 4) {printf "%s: rings %.2f, geometry %g, ramp bands %.2f\n", v("panel"), r, g, b; exit 1}}' "$out/wood.tsv"
grep -q 'RenderMan Companion' "$out/report.md"
# Verdict rows: Fig. 5 and Fig. 6, qualitative.
verdict_kinds "$out/verdicts.tsv" 0 2

if byte_reruns; then   # same seed, same tables (tsv.sh: release build only)
  "$exp" --quick --no-images --out "$out/again" >/dev/null
  cmp "$out/textures.tsv" "$out/again/textures.tsv"
  cmp "$out/wood.tsv" "$out/again/wood.tsv"
fi
set +e
refused "$exp" --quick --out "$out/bad" --set octaves=31
