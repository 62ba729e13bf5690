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
  'n_ok<=seeds' 'BIC>AIC' 'paper_samples==1000'
"$expect" "$out/original.tsv" rows=4 'E_ks>0' 'E_ks<0.05' 'E_con>0' 'E_R_pool_max_gap>=0' 'E_R_pool_best<=E_R_pool_median'
"$expect" "$out/pool_runs.tsv" rows=24 'E_best<=E_start' 'kept==20'
"$expect" "$out/aic_path.tsv" rows\>=8 'BIC>AIC' 'iterations>=1' 'converged==1'
"$expect" "$out/cutoff_k.tsv" rows=192 'K>=1' 'K<=100'
"$expect" "$out/assess.tsv" rows=9 'ks_median>0' 'ks_median<1' 'ks_reject>=0' 'ks_reject<=1' 'n_held==20' \
  file:aic_path.tsv
# columns by name: `named` prefixes an awk program with col[NAME] = index from the header
named() { printf 'NR==1{for(i=1;i<=NF;i++) col[$i]=i; next} %s' "$1"; }
# drops the named columns (timings) from a table, header included
drop() { local f="$1"; shift
  awk -F'\t' -v OFS='\t' -v drop="$*" 'NR==1{split(drop, d, " "); for(j in d) x[d[j]]=1; for(i=1;i<=NF;i++) if(!($i in x)) k[++n]=i}
    {s=$k[1]; for(j=2;j<=n;j++) s=s OFS $k[j]; print s}' "$f"; }
# thesis cutoffs with level-1 entries: one cluster
awk -F'\t' "$(named '$col["low_levels"]==1 && $col["cutoff_rule"]=="thesis" && ($col["K_initial"]!=1 || $col["status"]!="one_cluster"){print "thesis cutoff row: " $0; exit 1}')" "$out/gmm.tsv"
# matched cutoff: exactly the thesis's initial K on every seed
awk -F'\t' "$(named '$col["cutoff_rule"]=="matched_K0" && ($col["K_initial"]!=$col["paper_K_initial"] || $col["K_initial_sd"]!=0){print "matched row: " $0; exit 1}')" "$out/gmm.tsv"
# K never grows with the cutoff
awk -F'\t' "$(named '{key=$col["texture"]"/"$col["low_levels"]; if (key==prev && $col["K"]>k){print "K grows: " $0; exit 1} prev=key; k=$col["K"]}')" "$out/cutoff_k.tsv"
grep -q '^pool_bytes_erosion_low1' "$out/manifest.tsv"
grep -q '^cluster_bytes_cloud_low1' "$out/manifest.tsv"
# one thread: same pool, same models (timing columns dropped)
"$exp" --quick --out "$out/one" --patterns "$pat" --set threads=1 >/dev/null
cmp <(drop "$out/gmm.tsv" seconds_gmm) <(drop "$out/one/gmm.tsv" seconds_gmm)
cmp <(drop "$out/pool_runs.tsv" seconds) <(drop "$out/one/pool_runs.tsv" seconds)
cmp "$out/assess.tsv" "$out/one/assess.tsv"
