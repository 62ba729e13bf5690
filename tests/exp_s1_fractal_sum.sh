#!/usr/bin/env bash
# Quick S1: four settings, values inside the analytic bound, and the
# spectrum's slope that the slides' octaves imply.
set -euo pipefail
# shellcheck source=tests/tsv.sh
. "$(dirname "$0")/tsv.sh"   # tables by column name; refused
exp="$1" expect="$2" out="$3"
"$exp" --quick "${NOIMG[@]}" --out "$out" >/dev/null
"$expect" "$out/fractal_distribution.tsv" rows=4 'max_abs<=bound' 'sd>0' 'octaves>=1' \
  'max_abs_over_bound<1' image:fractal_panels.png file:manifest.tsv file:report.md
"$expect" "$out/fractal_spectrum.tsv" rows=64 'freq>0'
# Each octave has half the amplitude and twice the frequency of the one before
# (the slides): fBm with gain 2^-H, H = 1. Its variance falls 4-fold per
# octave and spreads over a ring of 4 times the area, so the radially averaged
# 2D power (this table: |F|^2 averaged over each ring) falls as f^-(2H+2) =
# f^-4; a 1D profile's spectrum would fall as f^-(2H+1). Fitted over 1 to 8
# cycles per unit (octaves 0 to 3 at quick scale; above, octaves past the
# Nyquist frequency of 16 fold back) the 8-octave column reads -3.74 (seed
# 1), -3.61 to -3.78 over seeds 1-9, -3.72 at paper scale: shallower than -4
# by a systematic 0.2 to 0.4 (the lowest octave's own tail: one octave alone
# falls only as f^-3.35 over that band, column (a)). The check holds the
# slope in [-4.2, -3.5]: 0.2 below the law, as for the gains where the law
# is met (exp_s3_fbm.sh), and 0.1 above the shallowest seed; a spectrum that
# lost its upper octaves falls as the lone octave's -3.35 and fails.
tsv_slopes "$out/fractal_spectrum.tsv" 1 8 >"$out/fractal_slopes.tsv"
"$expect" "$out/fractal_slopes.tsv" '(d) 8 octaves>=-4.2' '(d) 8 octaves<=-3.5'
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
