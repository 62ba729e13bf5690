#!/usr/bin/env bash
# Quick C2: KS / chi-square / Kuiper objectives on two patterns; the chi-square
# objective gives the lowest chi2 (thesis sec. 4.2), CDF and histogram tables
# cover 512 angles and 500 bins.
set -euo pipefail
exp="$1" expect="$2" out="$3"
pat="$(cd "$(dirname "$0")/../data/patterns" && pwd)"
"$exp" --quick --out "$out" --patterns "$pat" >/dev/null
"$expect" "$out/summary.tsv" rows=6 'E_ks>=0' 'E_ks<0.06' 'V_kuiper>=E_ks' 'chi2>0' 'E_con>0' \
  'p_kuiper>=0' 'p_kuiper<=1' file:noise_flower.png file:noise_x.png
for p in flower x; do
  "$expect" "$out/cdf_$p.tsv" rows=512 'F>0' 'F<=1' 'u_ks>=0' 'u_ks<1' 'u_chisq<1' 'u_kuiper<1'
  "$expect" "$out/hist_$p.tsv" rows=500 'ks>=0' 'chisq>=0' 'kuiper>=0'
done
# chi-square objective: lowest chi2 of the three on each pattern (rows 2 and 5)
awk -F'\t' 'NR==2||NR==5{ks=$12} NR==3||NR==6{if(!($12<ks)){print "chi2 not lowest: " $0; exit 1}}' "$out/summary.tsv"
# same seed, same table
"$exp" --quick --out "$out/again" --patterns "$pat" >/dev/null
cmp "$out/summary.tsv" "$out/again/summary.tsv"
