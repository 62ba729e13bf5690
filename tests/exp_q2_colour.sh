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
tsv_awk -v ind=0 -v qual=1 'FNR > 1 { k[v("kind")]++
    if (v("kind") == "qualitative" && v("verdict") != "see figure") { print "bad: " $0; exit 1 } }
  END { if (k["independent"] != ind || k["qualitative"] != qual || NR - 1 != ind + qual) {
      printf "verdicts: %d independent, %d qualitative, %d rows\n", k["independent"],
        k["qualitative"], NR - 1; exit 1 } }' "$out/verdicts.tsv"
if byte_reruns; then   # same seed, same tables (tsv.sh: release build only)
  "$exp" --quick --no-images --out "$out/again" >/dev/null
  cmp "$out/values.tsv" "$out/again/values.tsv"
fi
