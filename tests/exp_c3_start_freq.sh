#!/usr/bin/env bash
# Quick C3: f1 = 2, 4, 6, 8; lower f1 is smoother (roughness grows with f1).
# Tables stay uniform: E_ks measured 0.0082..0.030 at --quick over seeds 1..5
# (3-seed means; 0.011..0.034 at seed 1 on the domain [1, 2]^2); bound 0.05,
# under the KS 5% critical D 1.358/sqrt(512) = 0.060.
set -euo pipefail
# shellcheck source=tests/tsv.sh
. "$(dirname "$0")/tsv.sh"
exp="$1" expect="$2" out="$3"
pat="$(cd "$(dirname "$0")/../data/patterns" && pwd)"
"$exp" --quick "${NOIMG[@]}" --threads 2 --out "$out" --patterns "$pat" >/dev/null
# The seed runs are nl_parallel_for items (nl_study_cheng_runs): one thread
# gives the same tables, timing columns aside (the check ignores them).
same_on_one_thread "$exp" "$out" --patterns "$pat"
"$expect" "$out/summary.tsv" rows=4 'E_ks<0.05' 'E_con>0' 'roughness>0' 'roughness>f1*0.3' \
  image:panels.png
awk -F'\t' 'NR==1{for(i=1;i<=NF;i++) col[$i]=i; next}
  NR>2 && !($col["roughness"] > prev){print "roughness not increasing with f1 at row " NR; exit 1} {prev=$col["roughness"]}' "$out/summary.tsv"
# The trend test: Spearman's rho of roughness on f1 with a one-sided
# permutation p (9999 permutations, p in [1/10000, 1]), for the optimised
# tables (12 runs) and 10 random tables per f1 (40); measured rho 0.97 and
# 0.97, p = 0.0001 for both at --quick: every table's roughness rises with f1.
"$expect" "$out/trend_test.tsv" rows=2 'n_perm==9999' 'p_perm>=0.0001' 'p_perm<=0.01' 'rho>0.8' \
  'rho<=1' 'slope>0'
# Per f1: optimised against random roughness (measured ratio 0.993..1.007, no
# Welch p below 0.5 at --quick; 0.981..1.012, p 0.05..0.71 on [1, 2]^2); the
# ratio is the two means' quotient.
"$expect" "$out/trend.tsv" rows=4 'seeds==3' 'n_random==10' 'p_welch>=0' 'p_welch<=1' 'ratio>0.8' \
  'ratio<1.25'
tsv_awk 'NR > 1 {q = n("roughness") / n("roughness_random")
                 d = q - n("ratio")
                 if (d > 1e-9 || d < -1e-9) {print "ratio: " $0; exit 1}}' \
  "$out/trend.tsv"
# Three verdicts decided by p: the trend (its control, the random tables'
# trend, passes as well: by construction, measured rho 0.97 both) and the
# lowest f1's control of the pattern (r, E_Con), each with a control.
"$expect" "$out/verdicts.tsv" rows=3
tsv_awk 'NR > 1 && (v("rule") != "p 0.01 0.05" || v("control_verdict") == "-") {print; exit 1}
         NR == 2 && v("kind") != "by construction" {print "trend: " $0; exit 1}' \
  "$out/verdicts.tsv"
"$expect" "$out/control.tsv" rows=1 'f1==2' 'n_random==99' 'p_random>=0.01' 'p_random<=1'
"$expect" "$out/baselines.tsv" rows=2 'r_pattern<0.1' 'r_pattern>-0.1'
# Seams per f1: the first seed's table and its start table on [1, 2]^2, then
# the first seed's table on [0, 1]^2 (origin 0).
"$expect" "$out/seams.tsv" rows=12 'tables==1' 'seam_ratio>1' 'border_outward>=-1' \
  'border_outward<=1'
# The figures against their captions (tests/oracle_cheng.c): every panel
# recomputed from the run's tables.tsv through the noise's point call, and
# the pattern panels from the pattern PNGs, compared to 8 bits.
NL_PATTERNS="$pat" panels_oracle cheng c3 "$out" "$(dirname "$0")/../results/c3_start_freq"
