#!/usr/bin/env bash
# Quick C9: fixed vs optimised octave amplitudes (default and wide bounds),
# 6 cases x 3 (3 seeds per row), and per case the negative control, gains
# fixed at random within the same bounds (baselines.tsv, baselines_parts.tsv).
# What can fail, bounded by measurements at --quick over seeds 1..5:
#  - the fixed-amplitude rows are C1's rescaled rows for the same texture and
#    pattern, bit for bit (same seeds, same setting: amp_vary = 0 changes
#    nothing), compared with results/quick/c1_textures/summary.tsv;
#  - the optimised gains stay within their bounds ([1/4, 4], and [1/R, R]
#    with R = 64 for the wide rows) and every case moved them (some octave's
#    mean gain differs from 1);
#  - E_Con's parts (parts.tsv) add up to E_Con (means of a sum: rounding
#    only, 1e-9 relative); one verdict row per case on E_Con (summary.tsv)
#    and one on the scale-free shape 1 - r (parts.tsv one_minus_r = 1 -
#    r_pattern), each with the random-gains control: kind independent with a
#    control that is not reproduced, or by construction when the control
#    passes (quick seed 1: erosion/disc's E_Con, random gains 756.5 against
#    fixed 775.5);
#  - both conditions optimise: E_Con below the unoptimised start table's in
#    every row, tables stay uniform (E_ks < 0.025: measured 0.0088..0.0173 optimised, 0.0096..0.0122 fixed; E_Con / E_Con_random <= 0.898);
#  - Welch p-values in [0, 1], 12 rows per case (5 quantities and E_Con's 3
#    parts optimised vs fixed, 4 wide vs default bounds).
set -euo pipefail
# shellcheck source=tests/tsv.sh
. "$(dirname "$0")/tsv.sh"   # tables by column name
exp="$1" expect="$2" out="$3"
root="$(cd "$(dirname "$0")/.." && pwd)"
pat="$root/data/patterns"
"$exp" --quick "${NOIMG[@]}" --threads 2 --out "$out" --patterns "$pat" >/dev/null
# The seed runs are nl_parallel_for items (nl_study_cheng_runs): one thread
# gives the same tables, timing columns aside (the check ignores them).
same_on_one_thread "$exp" "$out" --patterns "$pat"
# every panel against its caption (tests/oracle_chengb.c: the first seed
# rerun, the value point by point), this run's and the committed one's
panels_oracle chengb c9 "$out" "$(dirname "$0")/../results/c9_amplitudes"
"$expect" "$out/summary.tsv" rows=18 'seeds==3' 'E_ks>0' 'E_ks<0.025' 'E_con<E_con_random' \
  'contrast>0' image:values.png
"$expect" "$out/gains.tsv" rows=48 'gain<=R' 'at_bound>=0' 'at_bound<=1'
tsv_awk 'NR > 1 { a = v("amplitudes")
    r = a == "optimised" ? 4 : a == "optimised_wide" ? 64 : 0
    if (n("R") != r || !(n("gain") * r >= 1 - 1e-12)) { print "bounds: " $0; exit 1 } }' \
  "$out/gains.tsv"
"$expect" "$out/tests.tsv" rows=72 'p_welch>=0' 'p_welch<=1' 'seeds==3'
"$expect" "$out/timing.tsv" rows=18
# its times, in times.tsv (not tracked)
tsv_awk 'v("table") == "timing.tsv" && v("column") == "seconds_per_run" { k++; if (!(n("value") > 0)) exit 1 }
         END { exit !(k == 18) }' "$out/times.tsv" || { echo "times.tsv: timing's seconds_per_run"; exit 1; }
"$expect" "$out/parts.tsv" rows=18 'seeds==3' 'E_con_offset>=0' 'E_con_contrast>=0' 'E_con_shape>=0'
tsv_awk 'NR > 1 { d = n("E_con_offset") + n("E_con_contrast") + n("E_con_shape") - n("E_con")
    if (d * d > (1e-9 * n("E_con")) ^ 2) { print "parts: " $0; exit 1 } }' "$out/parts.tsv"
tsv_awk 'NR > 1 { k = v("kind"); cv = v("control_verdict")
    if (!(k == "independent" && cv != "reproduced" && cv != "-" || k == "by construction" && cv == "reproduced")) {
      print "kind and control: " $0; exit 1 }
    if (v("control") !~ /^gains fixed at random/) { print "control: " $0; exit 1 }
    if (v("quantity") !~ /shape 1 - r/) { con++; next }
    sh++
    if (v("source") != "parts.tsv:one_minus_r") { print $0; exit 1 } }
  END { if (sh != 6 || con != 6) { print "verdicts: " con " E_Con, " sh " shape"; exit 1 } }' \
  "$out/verdicts.tsv"
"$expect" "$out/baselines.tsv" rows=12 'seeds==3' 'E_con<E_con_random'
"$expect" "$out/baselines_parts.tsv" rows=12 'seeds==3' 'one_minus_r>=0' 'one_minus_r<=2'
# the controls' fixed rows are the summary's fixed rows; the shape statistic
# is 1 - r_pattern of the same runs
tsv_awk 'FNR == 1 { f++ } FNR > 1 && v("amplitudes") == "fixed" { k = v("texture") "/" v("pattern")
    if (f == 1) e[k] = v("E_con"); else if (v("E_con") != e[k]) { print "fixed row differs: " k; exit 1 } }' \
  "$out/summary.tsv" "$out/baselines.tsv"
tsv_awk 'FNR == 1 { f++ } FNR > 1 { k = v("texture") "/" v("pattern") "/" v("amplitudes")
    if (f == 1) r[k] = n("r_pattern"); else if ((n("one_minus_r") - 1 + r[k]) ^ 2 > 1e-24) { print "1 - r: " k; exit 1 } }' \
  "$out/summary.tsv" "$out/parts.tsv"
tsv_awk 'NR > 1 {c = v("texture") "/" v("pattern"); if (n("gain") != 1) moved[c] = 1; seen[c] = 1}
  END {for (c in seen) if (!(c in moved)) {print "gains not moved: " c; exit 1}}' "$out/gains.tsv"
# fixed rows == C1's rescaled rows (every summary column the reference has,
# as text: a column added since the reference was written is not compared)
ref="$root/results/quick/c1_textures/summary.tsv"
awk -F'\t' 'FNR == 1 {for (i = 1; i <= NF; i++) {col[FILENAME, $i] = i; if (FILENAME == ARGV[2]) hdr[i] = $i}; nf[FILENAME] = NF; next}
  FILENAME == ARGV[1] && $col[ARGV[1], "formula"] == "rescaled" {row[$col[ARGV[1], "texture"] "/" $col[ARGV[1], "pattern"]] = $0}
  FILENAME == ARGV[2] && $col[ARGV[2], "amplitudes"] == "fixed" {
    k = $col[ARGV[2], "texture"] "/" $col[ARGV[2], "pattern"]
    if (!(k in row)) {print "no C1 row for " k; bad = 1; exit 1}
    split(row[k], a, "\t"); n++
    for (i = col[ARGV[2], "seeds"]; i <= nf[ARGV[2]]; i++)
      if (((ARGV[1], hdr[i]) in col) && a[col[ARGV[1], hdr[i]]] != $i) {
        print "fixed " k " " hdr[i] ": " $i " vs C1 " a[col[ARGV[1], hdr[i]]]; bad = 1; exit 1}
  }
  END {if (!bad && n != 6) {print "fixed rows compared with C1: " n ", wanted 6"; exit 1}}' "$ref" "$out/summary.tsv"
refused "$exp" --quick --out "$out.bad" --patterns "$pat" --set amp_range=0.5
refused "$exp" --quick --out "$out.bad" --patterns "$pat" --set cases=7
