#!/usr/bin/env bash
# Quick C7: three height maps (mesh x mesh) with heights in [0, 1] (c = (1 + V)/2
# with V over its analytic bound: a bound check of the kernel). Tables stay
# uniform: E_ks measured 0.0092..0.0115 at --quick over seeds 1..5; bound 0.02
# (a random table's mean D is 0.87/sqrt(512) = 0.038).
# Controllability: the optimised E_Con is below the unoptimised start's and r
# with the pattern is positive (measured 0.25..0.41 at --quick, seed 1).
set -euo pipefail
# shellcheck source=tests/tsv.sh
. "$(dirname "$0")/tsv.sh"
exp="$1" expect="$2" out="$3"
pat="$(cd "$(dirname "$0")/../data/patterns" && pwd)"
"$exp" --quick "${NOIMG[@]}" --threads 2 --out "$out" --patterns "$pat" >/dev/null
# The seed runs are nl_parallel_for items (nl_study_cheng_runs): one thread
# gives the same tables, timing columns aside (the check ignores them).
same_on_one_thread "$exp" "$out" --patterns "$pat"
"$expect" "$out/summary.tsv" rows=3 'E_ks<0.02' 'E_con>0' 'E_con<E_con_random' 'r_pattern>0' \
  'contrast>0' 'contrast<0.5' 'E_con_const>0' image:heightmaps.png
# the target patterns beside the height maps (64 x 64 control grid, D in [0, 1])
for p in flower x star; do "$expect" "$out/pattern_$p.tsv" rows=64 'c0>=0' 'c63<=1'; done
for p in flower x star; do
  "$expect" "$out/height_$p.tsv" rows=48 'c0>=0' 'c0<=1' 'c47>=0' 'c47<=1'
done
