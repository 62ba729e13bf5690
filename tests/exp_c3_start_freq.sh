#!/usr/bin/env bash
# Quick C3: f1 = 2, 4, 6, 8; lower f1 is smoother (roughness grows with f1).
# Tables stay uniform: E_ks measured 0.0082..0.030 at --quick over seeds 1..5
# (3-seed means); bound 0.05, under the KS 5% critical D 1.358/sqrt(512) = 0.060.
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
