#!/usr/bin/env bash
# Quick S4: u in [0, 1] with the arcsine law's mean 1/2, sd 1/(2 sqrt 2)
# and distribution.
set -euo pipefail
# shellcheck source=tests/tsv.sh
. "$(dirname "$0")/tsv.sh"   # NOIMG
exp="$1" expect="$2" out="$3"
"$exp" --quick "${NOIMG[@]}" --out "$out" >/dev/null
# Every panel against its caption, recomputed point by point
# (tests/oracle_sq.c): this run's when it wrote images, and the committed
# paper-scale figures the report shows.
panels_oracle sq s4 "$out" "$(dirname "$0")/../results/s4_marble"
"$expect" "$out/distribution.tsv" rows=4 'u_mean~0.5:0.05' 'u_sd~0.35355:0.02' image:panels.png
"$expect" "$out/u_density.tsv" rows=20 'u>0' 'u<1'
# The density itself. With the phase 2 pi stripes (y + a F(p)) uniform mod
# 2 pi, u = (1 + sin(phase)) / 2 has the arcsine law, CDF A(u) = (2 / pi)
# asin(sqrt(u)), density 1 / (pi sqrt(u (1 - u))); the displacement moves
# the stripes, not the law (the experiment's report). u_density.tsv holds
# each of the 20 bins' density (width 0.05) per amplitude a: summed to a
# bin's upper edge, the measured CDF there. Each column must sum to 1 (every
# sample lands in a bin) and stay within 0.05 of A at every edge (the
# Kolmogorov distance seen at the edges). Tolerance: over seeds 1-9 at quick
# scale the largest distance of an a > 0 column was 0.033 (a = 1, seed 8),
# their mean 0.014; a = 0 is the unperturbed stripes sampled at 32 rows per
# period (128 pixels over 4 units), 32 values of u, off by up to
# 1/32 = 0.031 on every seed. A uniform u would be 0.10 away.
tsv_awk 'function A(x) { return 2 / pi * atan2(sqrt(x), sqrt(1 - x)) }
  BEGIN { pi = atan2(0, -1); w = 0.05; tol = 0.05 }
  FNR == 1 { for (i = 1; i <= NF; i++) if (i != col("u")) name[i] = $i
    next }
  { edge = n("u") + w / 2
    if (edge > 1) edge = 1
    for (i in name) {
      cdf[i] += $i * w
      d = cdf[i] - A(edge)
      if (d < 0) d = -d
      if (d > gap[i]) { gap[i] = d; at[i] = edge } } }
  END { for (i in name) {
      if (gap[i] > tol) {
        printf "%s: CDF %.4f from the arcsine law at u = %g\n", name[i], gap[i], at[i]
        bad = 1 }
      if (cdf[i] < 1 - 1e-9 || cdf[i] > 1 + 1e-9) {
        printf "%s: densities sum to %.12g\n", name[i], cdf[i] / w
        bad = 1 } }
    exit bad }' "$out/u_density.tsv"
# The same distance computed by the program (cdf_gap of distribution.tsv):
# within 0.05 for every a > 0 (0.004-0.026 at seed 1).
tsv_awk 'FNR > 1 && n("a") > 0 && !(n("cdf_gap") >= 0 && n("cdf_gap") <= 0.05) {
  print "a = " n("a") ": cdf_gap " n("cdf_gap"); exit 1 }' "$out/distribution.tsv"
# The bend (bend.tsv): the share of u's squared neighbour differences along
# x is 0 for the straight stripes (a = 0, exactly), grows with a (0.103,
# 0.246, 0.382 at seed 1, quick) and stays below an isotropic field's 1/2;
# the control, each row displaced by one value of the sum, is 0 exactly.
"$expect" "$out/bend.tsv" rows=7 'gx_share>=0' 'gx_share<0.5' 'seeds==3'
tsv_awk 'FNR > 1 && (v("displacement") == "row'"'"'s first pixel" || n("a") == 0) && n("gx_share") != 0 {
    print "straight stripes bent: " $0; exit 1 }
  FNR > 1 && v("displacement") == "fractal sum" && n("a") > 0 {
    if (!(n("gx_share") > last)) { print "bend does not grow with a: " $0; exit 1 }
    last = n("gx_share") }' "$out/bend.tsv"
# Verdict rows: the bend at a = 0.25 against a = 0 (independent; reproduced,
# Welch p = 0.0004 over 3 seeds), its control not reproduced; the panels.
verdict_kinds "$out/verdicts.tsv" 1 1
tsv_awk 'FNR > 1 && v("kind") == "independent" && (v("verdict") != "reproduced" \
    || v("control_verdict") != "not reproduced") { print "verdict: " $0; exit 1 }' "$out/verdicts.tsv"
