#!/usr/bin/env bash
# Quick Q4: six clouds and six Fig. 6 textures, each with spread; both
# montages written; same seed, same table.
set -euo pipefail
# shellcheck source=tests/tsv.sh
. "$(dirname "$0")/tsv.sh"   # tables by column name; refused
exp="$1" expect="$2" out="$3"
"$exp" --quick "${NOIMG[@]}" --out "$out" >/dev/null
# Every panel against its caption, recomputed point by point
# (tests/oracle_sq.c): this run's when it wrote images, and the committed
# paper-scale figures the report shows.
panels_oracle sq q4 "$out" "$(dirname "$0")/../results/q4_textures"
"$expect" "$out/textures.tsv" rows=12 'sd>0.005' image:clouds.png image:textures.png file:report.md
"$expect" "$out/wood.tsv" rows=2 'perturb_rings_sd>0.05' 'perturb_rings_sd<1' \
  'ring_sd~0.353:0.01' image:wood.png
tsv_awk 'FNR > 1 {r = n("rings"); g = n("rings_geometry"); b = n("ramp_bands")
  if (r - g > 3 || g - r > 3 || b > r - 4) {printf "%s: rings %.2f, geometry %g, ramp bands %.2f\n", v("panel"), r, g, b; exit 1}}' "$out/wood.tsv"
grep -q 'RenderMan Companion' "$out/report.md"
# rings.tsv: per panel the ramp's bands, the wood shader's and the shader's
# without the GCTBF (its geometry alone, sd 0), copied from wood.tsv.
"$expect" "$out/rings.tsv" rows=6 'bands>=0' 'bands_sd>=0' 'seeds==3'
# Verdict rows: per wood panel "ramp below wood shader", whose control (the
# shader without the GCTBF) passes too: by construction, the rings are the
# shader's; Fig. 5 and Fig. 6, qualitative.
tsv_awk 'FNR > 1 { k[v("kind")]++
    if (v("kind") == "by construction" && v("control_verdict") != "reproduced") { print "wood: " $0; exit 1 }
    if (v("kind") == "qualitative" && v("verdict") != "see figure") { print "figure: " $0; exit 1 } }
  END { if (k["by construction"] != 2 || k["qualitative"] != 2 || NR != 5) {
      print "verdicts: " NR - 1 " rows"; exit 1 } }' "$out/verdicts.tsv"

if byte_reruns; then   # same seed, same tables (tsv.sh: release build only)
  "$exp" --quick --no-images --out "$out/again" >/dev/null
  cmp "$out/textures.tsv" "$out/again/textures.tsv"
  cmp "$out/wood.tsv" "$out/again/wood.tsv"
fi
set +e
refused "$exp" --quick --out "$out/bad" --set octaves=31
