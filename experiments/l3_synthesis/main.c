/* L3 - Lagae et al. 2010 sec. 5, Fig. 5-8: texture synthesis by analysis.
 * Procedural exemplars, each analysed and synthesised four ways: the paper's
 * method (PCA + histogram matching, steffen spline), without histogram
 * matching (Fig. 6b), in RGB without PCA (Fig. 5b), and with a
 * Fritsch-Carlson spline instead of steffen. Then the photographs of
 * data/exemplars (--exemplars DIR) with the paper's 10-quantile histogram,
 * with 33 quantiles at Gaussian knots, and calibrated (the `example` default:
 * gauss33 + band calibration at synthesis), per eq. 13 band against the photo. */
#include "byexample/nl_byexample.h"
#include "harness/nl_harness.h"
#include "study/nl_study.h"

#include <math.h>
#include <stdlib.h>

enum { NKIND = 4, NVAR = 5 };
static const char *kinds[NKIND] = {"wavelet", "clouds", "granite", "marble"};
static const char *variants[NVAR] = {"pca_hist", "pca_nohist", "rgb_hist", "pca_hist_fc", "pca_hist_gauss33"};
static const nl_byexample_options var_opt[NVAR] = {{1, 1, 0, 0, NL_HIST_PAPER, 0}, {1, 0, 0, 0, NL_HIST_PAPER, 0}, {0, 1, 0, 0, NL_HIST_PAPER, 0},
                                                   {1, 1, 0, 0, NL_HIST_PAPER, 0}, {1, 1, 0, 0, NL_HIST_GAUSS, 0}};

int main(int argc, char **argv)
{
  const char *exdir;
  nl_error err;
  if (nl_study_example_dir_parse(&argc, argv, &exdir, &err)) { fprintf(stderr, "l3_synthesis: %s\n", err.msg); return 2; }
  nl_harness *r = nl_harness_begin("l3_synthesis", "L3 - Texture synthesis by example: PCA colour and histogram matching", argc, argv);
  int quick = nl_harness_quick(r);
  int size = (int)nl_harness_param_int(r, "size", quick ? 128 : 512, 16, 4096,
                                       "side in pixels of the exemplar analysed and of the synthesised textures (quick 128)");
  int nphoto = (int)nl_harness_param_int(r, "photos", quick ? 2 : 16, 1, 16, "photographs of --exemplars DIR used, in name order (quick 2)");
  int psize = (int)nl_harness_param_int(r, "photo_size", quick ? 128 : 512, 16, 4096, "side of the syntheses of photographs (quick 128)");
  double min_share = nl_harness_param(r, "min_share", 0.02, 0, 1, "bands holding at least this share of the photo's power are checked");
  double max_ratio = nl_harness_param(r, "max_ratio", 1.3, 1, 100, "a checked band's synthesis/photo power ratio must lie in [1/max_ratio, max_ratio]");
  double max_ks = nl_harness_param(r, "max_ks", 0.03, 0, 1, "the KS distance of the luminance must be below this");
  nl_harness_params_done(r);
  int K = nl_harness_seeds(r);
  unsigned long seed0 = nl_harness_seed(r);
  char names[16][64];
  nl_image *photos[16];
  int np = nl_study_example_load(exdir, names, photos, nphoto, &err);   /* before any output */
  if (np <= 0) nl_harness_die(r, 2, "%s", err.msg);

  const char *kcols[] = {"kind", "variant", "ks_mean", "ks_sd", "ks_r", "ks_g", "ks_b", "corr_err", "params"};
  nl_table *kt = nl_table_alloc(9, kcols);
  const char *scols[] = {"kind", "max_abs_diff_fc_vs_steffen"};
  nl_table *ft = nl_table_alloc(2, scols);
  double *grey[3];
  for (int i = 0; i < 3; i++) grey[i] = malloc((size_t)size * size * sizeof *grey[i]);

  for (int k = 0; k < NKIND; k++) {
    nl_image *ex = nl_byexample_exemplar(kinds[k], size, nl_seed_stream(seed0, "l3.exemplar", (unsigned long)k));
    nl_image *first[NVAR];
    int nparams = 0;
    for (int v = 0; v < NVAR; v++) {
      nl_byexample_params p;
      if (nl_byexample_analyse(ex, &var_opt[v], &p, &err)) nl_harness_die(r, 1, "%s: %s", kinds[k], err.msg);
      nl_byexample_synth_options so = {1, 0, 0, v == 3 ? NL_SPLINE_FRITSCH_CARLSON : NL_SPLINE_STEFFEN};
      double *ks = malloc((size_t)K * 5 * sizeof *ks), *per = ks + K, *cs = per + 3 * K, acc[3] = {0}, m = 0, ss = 0, ce = 0;
      /* The K syntheses on the run's threads; sums in seed order after them. */
      first[v] = nl_study_example_synth_seeds(&p, &so, ex, size, K, seed0, nl_harness_threads(r), ks, per, cs, &err);
      if (!first[v]) nl_harness_die(r, 1, "%s: %s", kinds[k], err.msg);
      for (int s = 0; s < K; s++) {
        for (int c = 0; c < 3; c++) acc[c] += per[3 * s + c] / K;
        ce += cs[s] / K;
        m += ks[s] / K;
      }
      for (int s = 0; s < K; s++) ss += (ks[s] - m) * (ks[s] - m);
      nparams = nl_byexample_param_count(&p);
      nl_table_append(kt, "ssddddddi", kinds[k], variants[v], m, K > 1 ? sqrt(ss / (K - 1)) : 0.0,
                      acc[0], acc[1], acc[2], ce, nparams);
      free(ks);
      nl_harness_progress(r, (k * NVAR + v + 1.0) / (NKIND * NVAR), kinds[k]);
    }
    /* steffen vs Fritsch-Carlson on the same noise (seed0): pixel difference. */
    double dmax = 0;
    for (size_t i = 0; i < (size_t)size * size * 3; i++)
      dmax = fmax(dmax, fabs(first[0]->data[i] - first[3]->data[i]));
    nl_table_append(ft, "sd", kinds[k], dmax);

    /* Radial spectra of the luminance: exemplar, with and without histogram matching. */
    const nl_image *src[3] = {ex, first[0], first[1]};
    for (int i = 0; i < 3; i++) nl_byexample_luminance(src[i], grey[i]);
    nl_table *rt = nl_study_radial_table((const double *const *)grey,
                                         (const char *[]){"exemplar", "synthesis", "synthesis_nohist"}, 3, size, 1);
    char name[64];
    snprintf(name, sizeof name, "spectrum_%s.tsv", kinds[k]);
    nl_harness_write_table(r, rt, name);
    nl_table_free(rt);

    const nl_image *panels[6] = {ex, first[0], first[1], first[2], first[3], first[4]};
    const char *labels[6] = {"(a) exemplar", "(b) paper", "(c) no hist.", "(d) RGB", "(e) FC", "(f) gauss33"};
    char title[96];
    snprintf(title, sizeof title, "%s exemplar, %d x %d, seed %lu", kinds[k], size, size, seed0);
    snprintf(name, sizeof name, "synthesis_%s.png", kinds[k]);
    nl_study_montage(r, panels, labels, 6, 6, title, name);
    for (int v = 0; v < NVAR; v++) nl_image_free(first[v]);
    nl_image_free(ex);
  }
  nl_harness_write_table(r, kt, "ks.tsv");
  nl_harness_write_table(r, ft, "spline.tsv");
  nl_table *gt = nl_study_example_gauss_table((size_t)size * size, K, seed0, nl_harness_threads(r));
  nl_harness_write_table(r, gt, "gauss.tsv");
  nl_table *pt = nl_study_example_photos(r, names, photos, np, psize, K, seed0, min_share, max_ratio, max_ks);

  nl_harness_text(r, "Procedural exemplars are made at %d x %d: "
                  "`wavelet` (three multiresolution wavelet noises mixed by a correlated colour matrix: "
                  "the class the method models exactly), `clouds` (fBm of improved noise through a "
                  "sky ramp, clipped at both ends: a skewed histogram with spikes), `granite` "
                  "(turbulence through a 4-colour ramp), `marble` (sine stripes: anisotropic, expected "
                  "to fail like the paper's Fig. 9). Each is analysed once and synthesised with %d "
                  "seeds; KS = two-sample Kolmogorov-Smirnov distance between the exemplar's and the "
                  "synthesis' intensities per channel (mean over R, G, B, then mean +- sd over seeds); "
                  "corr_err = largest difference of the inter-channel correlations.", size, size, K);
  nl_harness_text(r, "Readings: the cumulative histogram is stored as the channel's quantiles at "
                  "p = j/9, j = 0..9 (min to max); synthesis maps noise by Phi(M / sigma_M) then a "
                  "monotone cubic through (p_j, q_j); sigma_M^2 = sigma_N^2 sum w_i^2 (the paper's "
                  "eq. 14 prints sum w_i, which cannot be a variance of a weighted sum). The paper "
                  "cites Fritsch-Carlson; we use GSL's steffen by default: both are monotone C1 "
                  "Hermite cubics, steffen's slopes are min(2|s_l|, 2|s_r|, |parabola slope|), FC "
                  "limits PCHIP's harmonic-mean slopes to alpha^2 + beta^2 <= 9. The largest pixel "
                  "difference between the two, same noise, is in the spline table. The paper counts "
                  "66 parameters for 512^2 RGB (9 matrix + 30 histogram + 27 weights); our count is "
                  "in the params column (we also store 3 means, sigma_N^2 and the tile period).");
  nl_harness_report_table(r, kt, "KS distance and colour-correlation error per exemplar and variant", 3);
  nl_harness_report_table(r, ft, "steffen vs Fritsch-Carlson: largest pixel difference (intensity units)", 4);
  for (int k = 0; k < NKIND; k++) {
    char file[64], cap[400];
    snprintf(file, sizeof file, "synthesis_%s.png", kinds[k]);
    snprintf(cap, sizeof cap, "Fig. 5-8 analogue, %s: (a) exemplar, (b) PCA + histogram matching (the paper's method), "
             "(c) without histogram matching (Fig. 6b), (d) independent RGB channels (Fig. 5b), (e) Fritsch-Carlson spline, "
             "(f) 33 quantiles at Gaussian knots (gauss33, not the paper's)", kinds[k]);
    nl_harness_figure(r, file, cap);
  }
  nl_harness_figure(r, "spectra.png", "Radially averaged power spectra (luminance) of exemplar and synthesis, per exemplar");
  nl_study_example_report(r, kt, gt, pt, K, psize, seed0, min_share, max_ratio, max_ks);
  for (int i = 0; i < np; i++) nl_image_free(photos[i]);
  nl_table_free(gt);
  nl_table_free(pt);

  nl_table_free(kt);
  nl_table_free(ft);
  for (int i = 0; i < 3; i++) free(grey[i]);
  nl_harness_check_measured(r, "*", 100);   /* measured tolerances (nl_harness.h) */
  return nl_harness_end(r);
}
