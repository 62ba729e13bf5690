#!/usr/bin/env bash
# Quick C2: KS / chi-square (Cramer's V and raw, eq. 3.4 as printed) / Kuiper
# objectives on two patterns (thesis sec. 4.2).
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
# every panel against its caption (tests/oracle_chengb.c: the first seed
# rerun, the value point by point), this run's and the committed one's
panels_oracle chengb c2 "$out" "$(dirname "$0")/../results/c2_ks_vs_chisq"
"$expect" "$out/summary.tsv" rows=8 'E_ks<0.06' 'chi2>0' 'E_con>0' 'p_kuiper_min>0.05' \
  image:noise_flower.png image:noise_x.png
awk -F'\t' 'NR == 1 {for (i = 1; i <= NF; i++) col[$i] = i} NR == 1 || $col["objective"] == "ks" || $col["objective"] == "kuiper"' \
  "$out/summary.tsv" > "$out/summary_ks_kuiper.tsv"
"$expect" "$out/summary_ks_kuiper.tsv" rows=4 'E_ks<0.02' 'V_kuiper<0.03'
for p in flower x; do
  "$expect" "$out/cdf_$p.tsv" rows=512 'u_ks~F:0.02' 'u_kuiper~F:0.02' 'u_chisq~F:0.06' \
    'u_chisq_raw~F:0.06'
  # every histogram column counts all 512 angles
  awk -F'\t' 'NR==1{for(i=1;i<=NF;i++) col[$i]=i} NR>1{a+=$col["ks"]; b+=$col["chisq"]; c+=$col["kuiper"]; d+=$col["chisq_raw"]} END{if(a!=512||b!=512||c!=512||d!=512){print "histogram counts " a, b, c, d; exit 1}}' "$out/hist_$p.tsv"
  "$expect" "$out/hist_$p.tsv" rows=500
done
# rows per pattern: ks, chisq, kuiper, chisq_raw (columns by name from the header)
awk -F'\t' 'NR==1{for(i=1;i<=NF;i++) col[$i]=i}
  NR>1{r=(NR-2)%4; d[r]=$col["E_ks"]; v[r]=$col["V_kuiper"]; c[r]=$col["chi2"]}
  NR>1 && r==3 {
    if(!(c[3] < c[0])) {print "chi2 not below the KS objective'"'"'s under the raw term: " $col["pattern"]; exit 1}
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
# The thesis's three claims per pattern. "KS CDF closer" and "chi2 lower
# under its objective" compare an objective with another on its own
# statistic (own.tsv); their control is the Kuiper objective on V against the
# same other objective: when it passes too, the harness turns the row into
# "by construction" (quick seed 1: E_KS rows by construction, control p <=
# 0.01; chi2 rows independent, control partly at 3 seeds). "E_Con close" is
# TOST (rule equiv abs M 0.05 0.2, M one pooled seed-to-seed sd of E_Con,
# docs/experiments.md) for the Cramer's V and the raw chi-square reading,
# control the KS objective against its random start tables (measured 15.5%
# and 19.2% apart at quick: never equivalent). 8 verdict rows.
tsv_awk 'NR > 1 { k = v("kind"); cv = v("control_verdict")
    if (cv == "-" || cv == "") { print "no control: " $0; exit 1 }
    if (!(k == "independent" && cv != "reproduced" || k == "by construction" && cv == "reproduced")) {
      print "kind and control: " $0; exit 1 } }
  NR > 1 && v("quantity") ~ /^chi2/ && v("ours") !~ / vs / { print "chi2 row: " $0; exit 1 }
  NR > 1 && v("quantity") ~ /^(E_KS|chi2),/ { own++; if (v("source") != "own.tsv:value") { print "source: " $0; exit 1 } }
  NR > 1 && v("quantity") ~ /^E_Con close/ { tost++
    if (v("rule") !~ /^equiv abs [0-9.e+-]+ 0.05 0.2$/) {print "rule: " $0; exit 1}
    if (v("control_verdict") != "not reproduced") {print "TOST control: " $0; exit 1} }
  END { if (NR != 9 || tost != 4 || own != 4) {
    print "verdicts: " NR - 1 " rows (" tost " TOST, " own " own), wanted 8 (4, 4)"; exit 1 } }' \
  "$out/verdicts.tsv"
"$expect" "$out/own.tsv" rows=14 'seeds==3' 'value>0' 'value_sd>=0'
# per pattern: Cramer's V, then its control, then raw, then its control;
# the margin is the pooled sd of the pair's E_Con and the control shares it
"$expect" "$out/equiv.tsv" rows=8 'p_tost>=0' 'p_tost<=1' 'p_welch>=0' 'p_welch<=1' \
  'margin>0' 'seeds==3' 'se>0' 'n_eff>=3' 'no_diff==0'
tsv_awk 'NR > 1 { d = n("diff") - (n("mean_b") - n("mean_a")); if (d * d > 1e-18) { print "diff: " $0; exit 1 } }
  NR > 1 && v("b") != "random" { m = n("margin") }
  NR > 1 && v("b") == "random" && n("margin") != m { print "control margin: " $0; exit 1 }
  NR > 1 && n("p_tost") < 0.5 && !(n("diff") < n("margin") && n("diff") > -n("margin")) { print "TOST: " $0; exit 1 }' \
  "$out/equiv.tsv"
# the margin is the pooled sd of the pair's E_Con (summary.tsv)
tsv_awk 'FNR == 1 { f++ } f == 1 && FNR > 1 { sd[v("pattern") "/" v("objective")] = n("E_con_sd") }
  f == 2 && FNR > 1 && v("b") != "random" {
    m = sqrt((sd[v("pattern") "/ks"] ^ 2 + sd[v("pattern") "/" v("b")] ^ 2) / 2)
    if ((m - n("margin")) ^ 2 > 1e-18 * m * m) { print "margin rule: " $0; exit 1 } }' \
  "$out/summary.tsv" "$out/equiv.tsv"
# Between-objective Welch tests: 8 per pattern (E_con four pairs, E_ks and
# chi2 for each chi-square reading); p in [0, 1]; chi2 chi-square vs KS
# objective differs (measured p <= 0.001 at --quick).
"$expect" "$out/tests.tsv" rows=16 'p_welch>=0' 'p_welch<=1' 'seeds==3'
tsv_awk 'NR > 1 && v("quantity") == "chi2" && !(n("p_welch") < 0.05) {print "chi2 test: " $0; exit 1}' "$out/tests.tsv"
