#!/usr/bin/env bash
# Quick C2: KS / chi-square / Kuiper objectives on two patterns (thesis sec. 4.2).
# Each objective wins on its own statistic: chi-square gives the lowest chi2,
# Kuiper the lowest V, KS a lower D than chi-square. Bounds measured at --quick
# over seeds 1..5 (values are means over 3 seeds per row, first-seed CDFs):
#  - every row passes KS and Kuiper at 5% (p_kuiper_min measured >= 0.85):
#    E_ks < 0.060 = 1.358 / sqrt(512), the critical
#    D (chi-square rows measured up to 0.026: KS is not what they optimise);
#  - the KS and Kuiper objectives reach E_ks 0.0077..0.0113 and V 0.0130..0.0217;
#    bounds 0.02 / 0.03 (about 1.8x the worst seed; a random table has mean
#    D = 0.87 / sqrt(512) = 0.038 and fails them);
#  - the first seed's empirical CDF stays within 0.02 of the uniform one for KS
#    and Kuiper (measured max 0.0123) and 0.06 for chi-square (measured 0.0385;
#    the KS critical value);
#  - Kuiper's V of the Kuiper objective is below the KS objective's V (measured
#    ratio 0.60..0.81) and the chi-square one's (0.42..0.52); KS objective's D
#    below the chi-square objective's (ratio 0.39..0.59). A margin of 0.9 on
#    each ratio keeps the check away from the noise of 3-seed means.
set -euo pipefail
# shellcheck source=tests/tsv.sh
. "$(dirname "$0")/tsv.sh"   # tables by column name
exp="$1" expect="$2" out="$3"
pat="$(cd "$(dirname "$0")/../data/patterns" && pwd)"
"$exp" --quick "${NOIMG[@]}" --threads 2 --out "$out" --patterns "$pat" >/dev/null
"$expect" "$out/summary.tsv" rows=6 'E_ks<0.06' 'chi2>0' 'E_con>0' 'p_kuiper_min>0.05' \
  image:noise_flower.png image:noise_x.png
awk -F'\t' 'NR == 1 {for (i = 1; i <= NF; i++) col[$i] = i} NR == 1 || $col["objective"] != "chisq"' \
  "$out/summary.tsv" > "$out/summary_ks_kuiper.tsv"
"$expect" "$out/summary_ks_kuiper.tsv" rows=4 'E_ks<0.02' 'V_kuiper<0.03'
for p in flower x; do
  "$expect" "$out/cdf_$p.tsv" rows=512 'u_ks~F:0.02' 'u_kuiper~F:0.02' 'u_chisq~F:0.06'
  # every histogram column counts all 512 angles
  awk -F'\t' 'NR==1{for(i=1;i<=NF;i++) col[$i]=i} NR>1{a+=$col["ks"]; b+=$col["chisq"]; c+=$col["kuiper"]} END{if(a!=512||b!=512||c!=512){print "histogram counts " a, b, c; exit 1}}' "$out/hist_$p.tsv"
  "$expect" "$out/hist_$p.tsv" rows=500
done
# rows per pattern: ks, chisq, kuiper (columns by name from the header)
awk -F'\t' 'NR==1{for(i=1;i<=NF;i++) col[$i]=i}
  NR>1{r=(NR-2)%3; d[r]=$col["E_ks"]; v[r]=$col["V_kuiper"]; c[r]=$col["chi2"]}
  NR>1 && r==2 {
    if(!(c[1] < c[0] && c[1] < c[2])) {print "chi2 not lowest for the chi-square objective: " $col["pattern"]; exit 1}
    if(!(v[2] < 0.9*v[0] && v[2] < 0.9*v[1])) {print "V not lowest for the Kuiper objective: " $col["pattern"]; exit 1}
    if(!(d[0] < 0.9*d[1])) {print "KS objective D not below chi-square objective D: " $col["pattern"]; exit 1}
  }' "$out/summary.tsv"
# same seed, same table, on one thread as on two (the seed runs are
# nl_parallel_for items, nl_study_cheng_runs)
if thread_identity; then
  "$exp" --quick --no-images --threads 1 --out "$out/again" --patterns "$pat" >/dev/null
  cmp "$out/summary.tsv" "$out/again/summary.tsv"
  "$(dirname "$exp")/../tools/noiselab-check" "$out/again" "$out" >/dev/null
fi
# The thesis's two claims per pattern as verdicts (Welch, alpha 0.05): the
# chi-square error is far lower under its own objective (measured p <= 0.001
# at --quick, 3 seeds), so that claim is reproduced for both patterns.
# "E_Con close in both" per pattern as an equivalence test (TOST against 5%
# of the mean E_Con, equiv.tsv): 6 verdict rows in all, every one of kind
# independent; the TOST rows decided by rule "p 0.05 0.2" (measured p 0.022
# and 0.046 at --quick seed 1: not checked, 3 seeds sit near the threshold).
tsv_awk 'NR > 1 && v("quantity") ~ /^chi2/ && v("verdict") != "reproduced" {
           print "verdict: " $0; exit 1 }
         NR > 1 && v("kind") != "independent" {print "kind: " $0; exit 1}
         NR > 1 && v("quantity") ~ /^E_Con close/ { tost++
           if (v("rule") != "p 0.05 0.2") {print "rule: " $0; exit 1} }
         END { if (NR != 7 || tost != 2) {
           print "verdicts: " NR - 1 " rows (" tost " TOST), wanted 6 (2)"; exit 1 } }' \
  "$out/verdicts.tsv"
"$expect" "$out/equiv.tsv" rows=2 'p_tost>=0' 'p_tost<=1' 'p_welch>=0' 'p_welch<=1' \
  'margin_frac==0.05' 'margin>0' 'seeds==3'
# a TOST p below 1/2 needs the difference inside the margin
tsv_awk 'NR > 1 && n("p_tost") < 0.5 {
    d = n("diff_pct") / (100 * n("margin_frac"))
    if (!(d < 1 && d > -1)) {print "TOST: " $0; exit 1} }' "$out/equiv.tsv"
# Between-objective Welch tests: 5 per pattern (E_con three pairs, E_ks, chi2);
# p in [0, 1]; chi2 chi-square vs KS objective differs (measured p <= 0.001 at
# --quick, as the verdicts above).
"$expect" "$out/tests.tsv" rows=10 'p_welch>=0' 'p_welch<=1' 'seeds==3'
tsv_awk 'NR > 1 && v("quantity") == "chi2" && !(n("p_welch") < 0.05) {print "chi2 test: " $0; exit 1}' "$out/tests.tsv"
