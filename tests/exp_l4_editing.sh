#!/usr/bin/env bash
# L4 quick run. Editing: the 3 finest bands attenuated by 0.25 (power 0.0625).
# The FFT of a non-periodic image leaks ~1% of the strong coarse bands into
# every finer band (see the report), so the measured fine-band power ratio is
# 0.24-0.58 over seeds 1..5, not 0.0625, and moves with the seed; a bound on it
# could only be loose. What the method claims holds exactly on top of that
# leakage floor: a second run with edit factor 0 measures the floor r0 (power
# left when the bands are removed), and the edit scales the bands' own power by
# 0.0625, so ratio = r0 + 0.0625 (1 - r0). Measured at --quick over seeds 1..5
# (15 bands each): ratio - prediction has mean +0.002 and sd 0.008 (max 0.014)
# with histogram matching, mean -0.001 and sd 0.008 (max 0.020) without; the
# bound 0.03 is ~4 sd. Factor 0.5 instead of 0.25 would move the ratio by
# 0.19 (1 - r0) >= 0.08, no edit by (1 - r0) >= 0.4.
# Coarse bands (>= 4) are not edited: without histogram matching their ratio is
# 0.992-1.013 (sd 0.005; bound 1 +- 0.02, 4 sd); histogram matching of the
# edited image raises them to 1.034-1.114 (mean 1.068, sd 0.025; bound
# 1.07 +- 0.08, 3 sd).
# Solid slices keep the 2D channel distributions: KS 2D vs slice measured
# 0.065-0.321 (mean 0.157, sd 0.091, 15 channels): one seed's low bands have
# few independent samples at 128^2, so the bound is mean + 3 sd = 0.43 (0.25
# failed seed 5). The morph's matrix stays a rotation (det 1, orthogonal to
# rounding: measured |det - 1| and orth_err <= 9e-16; 1e-9 leaves room for
# any BLAS kernel).
set -euo pipefail
. "$(dirname "$0")/tsv.sh"   # tables by column name
"$1" --quick --out "$3"
"$1" --quick --out "$3/f0" --set edit_factor=0 >/dev/null
tsv_awk 'NR == 1 || n("band") < 3' "$3/editing.tsv" > "$3/editing_fine.tsv"
tsv_awk 'NR == 1 || n("band") >= 4' "$3/editing.tsv" > "$3/editing_coarse.tsv"
"$2" "$3/editing_fine.tsv" 'rows=3' 'ratio<0.7' 'ratio_nohist<0.7' 'expected==0.0625'
"$2" "$3/f0/editing.tsv" 'rows>=7'
# fine bands: ratio = r0 + 0.0625 (1 - r0) within 0.03 (columns ratio, ratio_nohist)
tsv_awk 'FNR == 1 {next}
  {k = n("band"); r = n("ratio"); rn = n("ratio_nohist")}
  NR == FNR {r0[k] = r; n0[k] = rn; next}
  k < 3 {
    p = r0[k] + 0.0625 * (1 - r0[k]); q = n0[k] + 0.0625 * (1 - n0[k]);
    if ((r0[k] == "") || (r - p > 0.03 || p - r > 0.03) || (rn - q > 0.03 || q - rn > 0.03)) {
      printf "band %d: ratio %.4f (predicted %.4f), ratio_nohist %.4f (predicted %.4f)\n", k, r, p, rn, q; bad = 1; exit 1 }
    cnt++ }
  END {if (bad || cnt != 3) {print "editing rows bad: " bad ", count " cnt " (wanted 3)"; exit 1}}' "$3/f0/editing.tsv" "$3/editing.tsv"
"$2" "$3/editing_coarse.tsv" 'rows>=2' 'ratio~1.07:0.08' 'ratio_nohist~1:0.02'
"$2" "$3/solid.tsv" 'rows=3' 'ks_2d_vs_slice<0.43'
"$2" "$3/morph.tsv" 'rows=5' 'det~1:1e-9' 'orth_err<1e-9' 'file:morph.png' 'file:editing.png'
test -s "$3/report.md" && test -s "$3/manifest.tsv"
