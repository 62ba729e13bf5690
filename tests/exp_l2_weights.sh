#!/usr/bin/env bash
# L2 quick run (128^2, 7 bands, band 0 finest; size sweep 64..256, 3 seeds per
# size, transfer matrix from 4 noises; one exemplar, a 96^2 fBm rendered here
# by noiselab-render). Bounds are from the quick run over seeds 1..20, not
# one seed's draw (the per-band eq. 12 bounds were measured with another
# random stream of true weights; the same kind of spread):
#  - per band, eq. 12's est - true: band 0 mean +0.012 sd 0.061 (bound 0.2);
#    bands 1-3 sd 0.084, 0.095, 0.120 (bound 0.37). Leakage between octaves
#    (L1) moves power between neighbours; bands 4-6 have too few coefficients
#    at 128^2 (sd 0.17-0.28) and are checked only through the total power.
#  - re-estimating from the noise of the estimated weights (est_of_d) repeats
#    the estimate: bands 0-2 sd 0.045 (bound 0.17), band 3 sd 0.062 (0.21);
#  - eq. 12's total power sum w_est^2 / sum w^2: 3-seed means 0.79..1.18,
#    bound 1 +- 0.25; its relative RMS error per size below 0.45 (0.40 at
#    256; measured 0.183..0.370), its 6-finest-band error at 256 below 0.9x
#    that at 64 (ratio 0.53..0.84);
#  - NNLS weights are square roots of a non-negative solution: corrected >= 0
#    in weights.tsv, and every estimator's error finite and > 0;
#  - the transfer matrix + NNLS (nnls_raw) removes the spill between
#    neighbouring octaves: summed RMS error of bands 1-3 at 256 below 0.75x
#    eq. 12's (ratio 0.09..0.61);
#  - the corrected estimator (matrix + Tukey 1/4 taper + NNLS, the default
#    taper) too: bands 1-3 below 0.8x eq. 12's at 256 (ratio 0.11..0.57) and
#    below 1.0x at 128 (ratio 0.19..0.93). Not at 64 (ratio up to
#    2.1: bands 1-3 hold few coefficients there), and not over all bands:
#    the two coarsest bands (8 and 24 coefficients) come out worse when
#    unmixed, and they dominate the relative error (all-band error below
#    eq. 12's on 6 of 12 seeds at 256), so neither is a bound. With the Hann
#    window (--set taper=1) bands 1-3 at 256 were below eq. 12 on 10 of 12
#    seeds only: Hann keeps an effective quarter of the samples;
#  - on an fBm exemplar (steep spectrum, not periodic) the corrected weights
#    re-synthesise the tapered band powers better: resid_taper below 0.75x
#    eq. 12's (ratio 0.05..0.51 over the seeds and two fBm exemplars).
#  - verdict rows: "very similar" from eq. 12's error at the Fig. 4 side
#    (similar.tsv, paper 0; measured 0.226 at quick), the error's trend with
#    the side over seeds (trend.tsv: p-values in [0, 1]; the 6 finest bands'
#    slope negative, measured -0.051 per doubling, as the ratio above says;
#    its log2 slope against the -1 of halving, measured -0.40), and the same
#    for random weights (the control); four verdict rows, all independent,
#    each with a control that fails.
set -euo pipefail
# shellcheck source=tests/tsv.sh
. "$(dirname "$0")/tsv.sh"   # tables by column name; refused
exp="$1" out="$3"
mkdir -p "$out/exemplars"
"$(dirname "$exp")/../tools/noiselab-render" fbm --size 96 --seed 5 -o "$out/exemplars/fbm96.png" > /dev/null
# The main run reads the shipped photographs, as reproduce does, so that the
# sanitizer check can compare this very run with results/quick; the fBm
# exemplar gets a run of its own (no size sweep: max_size 64, 2 seeds).
exemplars="$(cd "$(dirname "$0")/.." && pwd)/data/exemplars"
"$exp" --quick "${NOIMG[@]}" --threads 2 --exemplars "$exemplars" --out "$out"
expect="$2"   # panels_oracle finds oracle_al beside it
# every panel against its caption (oracle_al.c), this run and the committed one
panels_oracle al l2 "$out" "$(dirname "$0")/../results/l2_weights"
# The photographs' fits are nl_parallel_for items (l2_exemplar_fits): one
# thread gives the same photos.tsv byte for byte (the size sweep, which does
# not enter it, cut to 64 pixels and 2 seeds).
# The transfer measurement's (replicate, band) renders and the size sweep's
# trials are nl_parallel_for items too (nl_byexample_leak.h): Fig. 4's
# weights as on two threads, and the fBm run's sweep (same sizes and seeds,
# two threads; the sweep does not read the exemplars) as the one-thread run's.
# The fBm run, another exemplar, runs in both builds; the one-thread run is a
# thread-identity rerun (tsv.sh): release build only.
"$exp" --quick --no-images --threads 2 --exemplars "$out/exemplars" --set max_size=64 --set sweep_seeds=2 --out "$out/fbm" > /dev/null
if thread_identity; then
  "$exp" --quick --no-images --threads 1 --exemplars "$exemplars" --set max_size=64 \
    --set sweep_seeds=2 --out "$out.t1" > /dev/null
  cmp "$out/photos.tsv" "$out.t1/photos.tsv"
  cmp "$out/weights.tsv" "$out.t1/weights.tsv"
  for t in estimators bands; do cmp "$out.t1/$t.tsv" "$out/fbm/$t.tsv"; done
fi
"$2" "$out/weights.tsv" 'rows=7' image:noise.png 'corrected>=0'
tsv_awk 'NR == 1 || n("band") == 0' "$out/weights.tsv" > "$out/weights_b0.tsv"
tsv_awk 'NR == 1 || (n("band") >= 1 && n("band") <= 2)' "$out/weights.tsv" > "$out/weights_b12.tsv"
tsv_awk 'NR == 1 || n("band") == 3' "$out/weights.tsv" > "$out/weights_b3.tsv"
"$2" "$out/weights_b0.tsv" 'rows=1' 'est~true:0.2' 'est_of_d~est:0.17'
"$2" "$out/weights_b12.tsv" 'rows=2' 'est~true:0.37' 'est_of_d~est:0.17'
"$2" "$out/weights_b3.tsv" 'rows=1' 'est~true:0.37' 'est_of_d~est:0.21'
"$2" "$out/estimators.tsv" 'rows=12' 'err_mean>0' 'err_sd>=0' 'p_vs_eq12>=0' 'p_vs_eq12<=1' 'p_fine_vs_eq12>=0' 'p_fine_vs_eq12<=1'
tsv_awk 'NR == 1 || v("estimator") == "eq12"' "$out/estimators.tsv" > "$out/eq12.tsv"
"$2" "$out/eq12.tsv" 'rows=3' 'err_mean<0.45' 'power_ratio~1:0.25'
tsv_awk 'NR > 1 && n("size") == 256 && n("err_mean") >= 0.40 {print "eq12 err_mean at 256: " n("err_mean"); exit 1}
         NR > 1 && n("size") == 64 {e64 = n("err_fine_mean")} NR > 1 && n("size") == 256 {e256 = n("err_fine_mean")}
         END {if (!(e256 < 0.9 * e64)) {print "eq12 fine error does not shrink with size: " e64 " -> " e256; exit 1}}' \
  "$out/eq12.tsv"
"$2" "$out/similar.tsv" 'rows=2' 'paper==0' 'ours>0' 'ours<1' 'ours_se>0' 'seeds==3'
"$2" "$out/trend.tsv" 'rows=4' 'p_falls>=0' 'p_falls<=1' 'slope_sd>0' 'sizes==3' \
  'paper_log_slope==-1' 'log_slope_se>0'
tsv_awk 'NR > 1 && v("bands") == "6 finest" && !(n("slope_mean") < 0) {print "fine slope " n("slope_mean"); exit 1}' "$out/trend.tsv"
"$2" "$out/verdicts.tsv" 'rows=4'
tsv_awk 'NR > 1 && (v("kind") != "independent" || v("control_verdict") != "not reproduced") {
  print v("quantity") ": " v("kind") ", control " v("control_verdict"); exit 1}' "$out/verdicts.tsv"
"$2" "$out/bands.tsv" 'rows=84' 'rmse>=0'
tsv_awk 'NR > 1 && n("band") >= 1 && n("band") <= 3 {s[n("size") " " v("estimator")] += n("rmse")}
         function below(what, size, f) {
           if (!(s[size " " what] < f * s[size " eq12"])) {print "bands 1-3 at " size ": " what " " s[size " " what] " vs eq12 " s[size " eq12"]; bad = 1}
         }
         END {below("nnls_raw", 256, 0.75); below("corrected", 256, 0.8); below("corrected", 128, 1.0); exit bad}' \
  "$out/bands.tsv"
"$2" "$out/fbm/photos.tsv" 'rows=4' 'resid_raw>0' 'resid_taper>0'
tsv_awk 'NR > 1 {r[v("estimator")] = n("resid_taper")}
         END {if (!(r["corrected"] < 0.75 * r["eq12"])) {print "fBm exemplar: corrected " r["corrected"] " vs eq12 " r["eq12"]; exit 1}}' \
  "$out/fbm/photos.tsv"
"$2" "$out/photos.tsv" 'rows>=4' 'resid_raw>0' 'resid_taper>0'   # the shipped photographs
grep -q 'No exemplar photographs' "$out/report.md" && { echo "photographs not reported"; exit 1; }
test -s "$out/report.md" && test -s "$out/manifest.tsv"
refused "$exp" --quick --out "$out/bad" --exemplars
refused "$exp" --quick --out "$out/bad" --exemplars "$out/weights.tsv"
