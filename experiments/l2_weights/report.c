/* L2's report (report.h): Fig. 4's validation, the estimators against image
 * size and the photographs, every number formatted from the run. */
#include "report.h"
#include "study/nl_study.h"

#include "claims.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* The verdict rows (claims.tsv): how "very similar" was read, and whether
 * the error falls with the side. */
static void report_claims(nl_harness *r, const l2_sweep *s, const nl_table *et,
                          const nl_table *st, const nl_table *tt)
{
  char means[256] = ""; /* eq. 12's all-band error by side */
  size_t ml = 0;
  double prev = INFINITY;
  int rises = 0; /* sides whose mean error is above the one before */
  for (size_t i = 0; i < et->nrows && ml < sizeof means - 32; i++)
    if (!strcmp(nl_table_text(et, i, "estimator"), nl_byexample_estimator_names[0])) {
      double e = nl_table_value(et, i, "err_mean");
      rises += e > prev;
      prev = e;
      ml += (size_t)snprintf(means + ml, sizeof means - ml, "%s%d px %.3f", ml ? ", " : "",
                             (int)nl_table_value(et, i, "size"), e);
    }
  int all_falls = nl_table_value(tt, 0, "p_falls") <= 0.05;
  int fine_falls = nl_table_value(tt, 1, "p_falls") <= 0.05;
  char similar[160] = "the Fig. 4 side is not in the sweep";
  if (st->nrows)
    snprintf(similar, sizeof similar, "%s %.3f (sd %.3f over %d seeds)",
             nl_table_text(st, 0, "quantity"), nl_table_value(st, 0, "ours"),
             nl_table_value(st, 0, "ours_sd"), s->seeds);
  nl_harness_text(
      r,
      "**Verdicts.** \"Very similar\" is read, before the run, as eq. 12's relative RMS weight "
      "error within a tenth of 0, shown by two one-sided tests (rule %s): "
      "%s. The paper explains the remaining difference by the band "
      "power converging with sample size; tested by each seed's least-squares slope of the error "
      "on log2(side) over the sweep's %d sides (%d to %d pixels) and a one-sided t-test of mean "
      "slope < 0: all bands %+.4f per doubling (sd %.4f, p = %.2g), the %d finest bands, which "
      "exist at every side, %+.4f (sd %.4f, p = %.2g). All-band means by side: %s (%d of %d "
      "steps up). At the 5%% level the all-band error %s and the finest bands' error %s. A "
      "falling slope is what any improvement gives; the paper's explanation, sampling error of "
      "the band powers, predicts more: a band of fixed frequency holds 4x the coefficients per "
      "doubling of the side, so its error halves, slope -1 of log2 error on log2 side. The finest "
      "bands' slope is %+.3f (sd %.3f over seeds): the error falls by %.2fx per doubling, not "
      "2x. Random weights (the control) give %+.3f.%s",
      L2_SIMILAR_RULE, similar, s->nsizes, s->sizes[0], s->sizes[s->nsizes - 1],
      nl_table_value(tt, 0, "slope_mean"), nl_table_value(tt, 0, "slope_sd"),
      nl_table_value(tt, 0, "p_falls"), s->fine, nl_table_value(tt, 1, "slope_mean"),
      nl_table_value(tt, 1, "slope_sd"), nl_table_value(tt, 1, "p_falls"), means, rises,
      s->nsizes - 1, all_falls ? "falls" : "does not fall", fine_falls ? "falls" : "does not fall",
      nl_table_value(tt, 1, "log_slope_mean"), nl_table_value(tt, 1, "log_slope_sd"),
      exp2(-nl_table_value(tt, 1, "log_slope_mean")), nl_table_value(tt, 3, "log_slope_mean"),
      fine_falls && !all_falls
          ? " What does not fall is the coarse end: each doubling of the side adds a coarser "
            "eq. 13 band, and the coarsest band holds the same few Fourier coefficients at every "
            "side."
          : "");
}

void l2_report(nl_harness *r, const l2_fig4 *f, const l2_sweep *s, const nl_table *wt,
               const nl_table *et, const nl_table *st, const nl_table *tt, const nl_table *pt,
               int nphotos, const char *exdir, int pmax, int pseeds)
{
  nl_harness_text(r,
                  "Fig. 4 at %d x %d (%d bands, seed %lu): random weights uniform in [%g, %g] (the "
                  "paper does not say how it draws them), a 2D wavelet-noise sum with them (b), "
                  "weights estimated by eq. 12-13 with our measured sigma_N^2 = %.4f (paper: %g), "
                  "and a noise with the estimated weights and new band offsets (d). Relative RMS "
                  "weight error |w_est - w| / |w| = %.3f (corrected estimator: %.3f); total power "
                  "sum w_est^2 / sum w^2 = %.3f. The paper says only that the two sets are \"very "
                  "similar\" and converge with sample size; the sweep measures it.",
                  f->size, f->size, f->nb, f->seed, NL_BYEXAMPLE_TRUE_WEIGHT_MIN,
                  NL_BYEXAMPLE_TRUE_WEIGHT_MAX, nl_byexample_sigma2(f->tile), L2_PAPER_SIGMA2,
                  f->e[0], f->e[NL_BYEXAMPLE_CORRECTED], f->pw[0]);
  report_claims(r, s, et, st, tt);
  nl_harness_text(
      r,
      "Beyond the paper: eq. 12 reads each band from its own power, but each wavelet band spills "
      "into its neighbour octaves (L1) and the DFT of the non-periodic image leaks edge power into "
      "finer bands. The corrected estimator measures the band-to-band transfer matrix on the noise "
      "(%d noises per size), tapers the image (taper fraction %.2g; 1 = Hann) and solves "
      "non-negative least squares for w^2; eq12_taper (taper only) and nnls_raw (matrix only) "
      "separate the two. Its mean error is below eq. 12's at %d of %d sizes; at %d pixels, %.3f "
      "(sd %.3f) against %.3f (sd %.3f), paired t-test over %d seeds p = %.2g (largest p over "
      "sizes %.2g).",
      s->tseeds, s->frac, s->below, s->nsizes, s->maxsize, s->m[0][NL_BYEXAMPLE_CORRECTED],
      s->v[0][NL_BYEXAMPLE_CORRECTED], s->m[0][0], s->v[0][0], s->seeds, s->p_last, s->pmax);
  nl_harness_text(r,
                  "Where: over the %d finest bands the corrected error at %d pixels is %.3f (sd "
                  "%.3f) against eq. 12's %.3f (sd %.3f), paired t-test p = %.2g; per band, its "
                  "RMS error is below eq. 12's in %d of %d bands (bands.tsv).",
                  s->fine, s->maxsize, s->m[1][NL_BYEXAMPLE_CORRECTED],
                  s->v[1][NL_BYEXAMPLE_CORRECTED],
                  s->m[1][0], s->v[1][0], s->pf, s->bbelow,
                  nl_byexample_band_count(s->maxsize, s->maxsize));
  nl_harness_report_table(r, wt,
                          "Fig. 4 (a, c): true and estimated weights (band 0 finest); est_of_d "
                          "re-estimates from (d) by eq. 12; corrected: NNLS + taper",
                          3);
  nl_harness_figure(r, "weights.png", "Fig. 4 (a, c): true vs estimated weights");
  nl_harness_figure(r, "noise.png",
                    "Fig. 4 (b, d): noise of the true and of the estimated weights");
  char cap[320];
  snprintf(cap, sizeof cap,
           "Relative RMS weight error vs image size per estimator (mean and sd over seeds); "
           "power_ratio = mean sum w_est^2 / sum w^2; p_vs_eq12, p_fine_vs_eq12: paired t-tests "
           "against eq. 12 over seeds (all bands; %d finest)",
           s->fine);
  nl_harness_report_table(r, et, cap, 4);
  nl_harness_figure(r, "error.png",
                    "Weight error vs image size per estimator, error bars one sd over seeds");
  nl_harness_figure(r, "bands.png",
                    "RMS weight error per band at the largest size, per estimator (bands.tsv)");
  if (nphotos) {
    nl_harness_text(
        r,
        "Exemplar photographs (%d in %s, luminance, cropped to at most %d pixels): the true "
        "weights are unknown, so each estimator's weights are re-synthesised (%d noises) and their "
        "band powers compared with the photograph's, raw and tapered: RMS over bands of the "
        "relative power error. Mean over photographs (raw, tapered): eq12 %.3f, %.3f; corrected "
        "%.3f, %.3f.",
        nphotos, exdir, pmax, pseeds,
        nl_study_mean_where(pt, "estimator", "eq12", "resid_raw", NULL, 0, NULL),
        nl_study_mean_where(pt, "estimator", "eq12", "resid_taper", NULL, 0, NULL),
        nl_study_mean_where(pt, "estimator", "corrected", "resid_raw", NULL, 0, NULL),
        nl_study_mean_where(pt, "estimator", "corrected", "resid_taper", NULL, 0, NULL));
    nl_harness_report_table(
        r, pt, "Photographs: band-power fit residual of each estimator's re-synthesis", 4);
  } else
    nl_harness_text(
        r,
        "No exemplar photographs in %s (--exemplars DIR): the photograph comparison was not run.",
        exdir);
}
