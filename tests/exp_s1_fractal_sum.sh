#!/usr/bin/env bash
# Quick S1: four settings, values inside the analytic bound, spectra written.
set -euo pipefail
# shellcheck source=tests/tsv.sh
. "$(dirname "$0")/tsv.sh"   # tables by column name; refused
exp="$1" expect="$2" out="$3"
"$exp" --quick "${NOIMG[@]}" --out "$out" >/dev/null
"$expect" "$out/fractal_distribution.tsv" rows=4 'max_abs<=bound' 'sd>0' 'octaves>=1' \
  'max_abs_over_bound<1' image:fractal_panels.png file:manifest.tsv file:report.md
"$expect" "$out/fractal_spectrum.tsv" rows=64 'freq>0'
# A second run with the same seed gives the same table, byte for byte.
if byte_reruns; then   # same seed, same tables (tsv.sh: release build only)
  "$exp" --quick --no-images --out "$out/again" >/dev/null
  cmp "$out/fractal_distribution.tsv" "$out/again/fractal_distribution.tsv"
fi
# Unknown parameters and bad values are refused with exit 2.
set +e
refused "$exp" --quick --out "$out/bad" --set nosuch=1
refused "$exp" --quick --out "$out/bad" --set size=abc
refused "$exp" --quick --out "$out/bad" --seed -4
[ ! -e "$out/bad/manifest.tsv" ]
