#!/usr/bin/env bash
# Quick C5: pools, clustering and AIC selection for erosion, marble, cloud and
# erosion with the two-level split. Checks the table's invariants, the
# thesis-cutoff rows (no (cos, sin) distance reaches the thesis's cutoffs, so
# one cluster), the matched rows (the thesis's K0 exactly), the pool rule,
# and that the pool does not depend on the number of threads.
set -euo pipefail
exp="$1" expect="$2" out="$3"
pat="$(cd "$(dirname "$0")/../data/patterns" && pwd)"
"$exp" --quick --out "$out" --patterns "$pat" >/dev/null
"$expect" "$out/gmm.tsv" rows=8 'K_initial>=1' 'K_final>=K_initial' 'input_samples<=pool' 'seeds==3' \
  'n_ok<=seeds' 'BIC>AIC' 'thesis_samples==1000'
"$expect" "$out/original.tsv" rows=4 'E_ks>0' 'E_ks<0.05' 'E_con>0' 'E_R_pool_max_gap>=0' 'E_R_pool_best<=E_R_pool_median'
"$expect" "$out/pool_runs.tsv" rows=24 'E_best<=E_start' 'kept==20'
"$expect" "$out/aic_path.tsv" rows\>=8 'BIC>AIC' 'iterations>=1' 'converged==1'
"$expect" "$out/cutoff_k.tsv" rows=192 'K>=1' 'K<=100'
"$expect" "$out/assess.tsv" rows=9 'ks_median>0' 'ks_median<1' 'ks_reject>=0' 'ks_reject<=1' 'n_held==20' \
  file:aic_path.tsv
# thesis cutoffs with level-1 entries: one cluster (status text in column 21)
awk -F'\t' 'NR>1 && $2==1 && $3=="thesis" && ($10!=1 || $21!="one_cluster"){print "thesis cutoff row: " $0; exit 1}' "$out/gmm.tsv"
# matched cutoff: exactly the thesis's initial K on every seed
awk -F'\t' 'NR>1 && $3=="matched_K0" && ($10!=$24 || $11!=0){print "matched row: " $0; exit 1}' "$out/gmm.tsv"
# K never grows with the cutoff
awk -F'\t' 'NR>1{key=$1"/"$2; if (key==prev && $4>k){print "K grows: " $0; exit 1} prev=key; k=$4}' "$out/cutoff_k.tsv"
grep -q '^pool_bytes_erosion_low1' "$out/manifest.tsv"
grep -q '^cluster_bytes_cloud_low1' "$out/manifest.tsv"
# one thread: same pool, same models (timing columns dropped)
"$exp" --quick --out "$out/one" --patterns "$pat" --set threads=1 >/dev/null
cmp <(cut -f1-21 "$out/gmm.tsv") <(cut -f1-21 "$out/one/gmm.tsv")
cmp <(cut -f1-6 "$out/pool_runs.tsv") <(cut -f1-6 "$out/one/pool_runs.tsv")
cmp "$out/assess.tsv" "$out/one/assess.tsv"
