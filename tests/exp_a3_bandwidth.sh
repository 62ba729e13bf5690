#!/usr/bin/env bash
# Quick A3: three signals with a band inside (0, Nyquist), F_inf < F_sup,
# the second octave higher than the first, the RMS reading of sigma on the
# first bin; the sweep table is complete.
set -euo pipefail
. "$(dirname "$0")/tsv.sh"   # tables by column name; refused
exp="$1" expect="$2" out="$3"
"$exp" --quick --out "$out" >/dev/null
"$expect" "$out/bandwidth.tsv" rows=3 'f_inf<f_sup' 'f_inf>0' 'f_sup<8' 'sigma>0' \
  'f_inf_rms<=f_inf' 'f_inf_rms~0.0078125:1e-12' 'f_sup_bins>100'
"$expect" "$out/sweep.tsv" rows=8 'oct1_f_sup<oct2_f_sup' 'oct1_f_inf<oct1_f_sup' 'sum_f_sup>=oct1_f_sup'
"$expect" "$out/psd.tsv" 'rows>=500' 'gamma_oct1>=0' file:manifest.tsv
"$exp" --quick --out "$out/again" >/dev/null
cmp "$out/bandwidth.tsv" "$out/again/bandwidth.tsv"
set +e
refused "$exp" --quick --out "$out/bad" --set rate=0
