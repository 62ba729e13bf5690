#!/usr/bin/env bash
# Quick C6: reproductions of erosion, marble and cloud from their mixtures.
# Reproductions stay uniform (no KS rejection), near the original's control
# error, and far faster than an optimisation; montages and CDF tables exist;
# same seed, same numbers. Reproductions vs original (two-sample KS of the
# angles): ks2_D measured 0.0078..0.0273 at --quick over seeds 1..5 (mean 0.0151,
# sd 0.0043, 240 reproductions; 0.0098..0.0215 at seed 1 on the domain
# [1, 2]^2); bound 0.035 (~1.3x the largest, mean + 4.5 sd).
# Timing columns are not checked (a time's only bound, >= 0, cannot fail).
set -euo pipefail
# shellcheck source=tests/tsv.sh
. "$(dirname "$0")/tsv.sh"
exp="$1" expect="$2" out="$3"
pat="$(cd "$(dirname "$0")/../data/patterns" && pwd)"
"$exp" --quick "${NOIMG[@]}" --threads 2 --out "$out" --patterns "$pat" >/dev/null
"$expect" "$out/summary.tsv" rows=9 'E_ks>0' 'E_ks<0.05' 'p_ks_min>0.05' 'E_con>0' 'below_ks<=1' 'below_con<=1' \
  'K>=20' image:textures_erosion.png image:textures_marble.png \
    image:textures_cloud.png
# the times, in times.tsv (not tracked): a reproduction with its texture is
# no slower than one optimisation, on each of the 9 rows (0: the originals)
tsv_awk 'v("table") == "summary.tsv" && v("column") == "ms_texture" { t[n("row")] = n("value") }
         v("table") == "summary.tsv" && v("column") == "seconds_opt" { o[n("row")] = n("value") }
         END { for (q in t) { k++; if (!(t[q] >= 0 && t[q] <= o[q] * 1000)) exit 1 }; exit !(k == 9) }' "$out/times.tsv" \
  || { echo "times.tsv: summary's ms_texture against seconds_opt"; exit 1; }
"$expect" "$out/reproductions.tsv" rows=48 'E_ks>0' 'p_ks>0.05' 'ks2_D>0' 'ks2_D<0.035'
for t in erosion marble cloud; do
  "$expect" "$out/cdf_$t.tsv" rows=512 'F>0' 'F<=1' 'u_original>=0' 'u_original<1' 'u_r8<1'
done
# reproductions keep E_Con within 20% of the original's (sec. 4.4: "close")
awk -F'\t' 'NR==1{for(i=1;i<=NF;i++) col[$i]=i; next} $col["kind"]=="original"{o=$col["E_con"]}
  $col["kind"]!="original" && ($col["E_con"]>1.2*o || $col["E_con"]<0.8*o){print "E_Con far from original: " $0; exit 1}' "$out/summary.tsv"
# Same seed, same numbers - and on one thread as on two: the originals, the
# pool runs and the reproductions' evaluations are nl_parallel_for items
# (c6_reproduce_cases; the draws stay in order on one thread).
if thread_identity; then
  "$exp" --quick --no-images --threads 1 --out "$out/again" --patterns "$pat" >/dev/null
  # timing columns dropped by name
  drop() { awk -F'\t' -v OFS='\t' 'NR==1{for(i=1;i<=NF;i++) if($i!="ms_reproduce" && $i!="ms_texture" && $i!="seconds_opt") k[++n]=i}
    {s=$k[1]; for(j=2;j<=n;j++) s=s OFS $k[j]; print s}' "$1"; }
  cmp <(drop "$out/reproductions.tsv") <(drop "$out/again/reproductions.tsv")
  cmp <(drop "$out/summary.tsv") <(drop "$out/again/summary.tsv")
  for t in erosion marble cloud; do cmp "$out/cdf_$t.tsv" "$out/again/cdf_$t.tsv"; done
fi
# "Often below the original's" as a sign test (below.tsv): per texture, swap
# and error a row whose p_sign is P(X <= below), X ~ Binomial(n, 1/2),
# recomputed here from the exact sum to 1e-9; verdicts: one per texture and
# error for the thesis's swap (kind independent, rule fit 0.05 0.01) and four
# qualitative rows for the figures (3 montages, cdf.png).
"$expect" "$out/below.tsv" rows=12 'n==8' 'below>=0' 'below<=n' 'p_sign>0' 'p_sign<=1'
tsv_awk 'NR > 1 { k = n("below"); m = n("n"); c = 1; s = 0
    for (i = 0; i <= k; i++) { s += c; c = c * (m - i) / (i + 1) }
    e = s / 2 ^ m; if (k >= m) e = 1
    if ((n("p_sign") - e) ^ 2 > (1e-9 * e) ^ 2) { print "sign p: " $0 " wanted " e; exit 1 } }' \
  "$out/below.tsv"
tsv_awk 'NR > 1 && v("kind") == "independent" { ind++
    if (v("rule") != "fit 0.05 0.01" || v("source") !~ /^below.tsv/) {
      print "sign verdict: " $0; exit 1 } }
  NR > 1 && v("kind") == "qualitative" { fig++
    if (v("verdict") != "see figure") { print $0; exit 1 } }
  END { if (ind != 6 || fig != 4) {
    print "verdicts: " ind " independent, " fig " qualitative"; exit 1 } }' \
  <(tsv_awk 'NR == 1 || v("quantity") !~ /(uniform|frame|pool E_R)/' "$out/verdicts.tsv")
# The controls and the other claims' rows (controls.h): random tables in
# place of reproductions (never below the original: measured 0 of 8), the
# reproductions' uniformity against w1 = 0, a reproduced table against one
# frame at 30 Hz (an optimisation as the control), the pool's E_R against
# the original's (the runs' random starts as the control: never below).
"$expect" "$out/below_ctl.tsv" rows=6 'n==8' 'below==0'
"$expect" "$out/uniform.tsv" rows=6 'p_uniform>0' 'p_uniform<=1'
"$expect" "$out/speed.tsv" rows=9 'ms>0' 'n>=1'
"$expect" "$out/pool_er.tsv" rows=6 'n==6' 'p_below>0' 'p_below<=1' 'e_original>0'
tsv_awk 'NR > 1 && v("runs") ~ /random starts/ && n("below") != 0 {print "a random start below the original: " $0; exit 1}' \
  "$out/pool_er.tsv"
tsv_awk 'NR > 1 && v("kind") != "qualitative" && v("control_verdict") == "-" {print "no control: " $0; exit 1}' \
  "$out/verdicts.tsv"
# The figures against their captions (tests/oracle_cheng.c): every panel
# recomputed from the run's tables.tsv through the noise's point call, and
# the pattern panels from the pattern PNGs, compared to 8 bits.
NL_PATTERNS="$pat" panels_oracle cheng c6 "$out" "$(dirname "$0")/../results/c6_reproduce"
