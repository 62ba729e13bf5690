/* L2 - Lagae et al. 2010 sec. 4.3, Fig. 4: random weights -> noise ->
 * weights estimated by eq. 12-13 -> noise; beyond the paper, the weight
 * error against image size over seeds beside a leakage-corrected estimator
 * (transfer matrix measured on the noise, tapered DFT, NNLS;
 * byexample/nl_byexample_leak.h), and both on exemplar photographs. */
#include "byexample/nl_byexample_leak.h"
#include "harness/nl_harness.h"
#include "study/nl_study.h"
#include "study/nl_study_exemplars.h"

#include <math.h>
#include <stdlib.h>

/* The 6 finest bands (periods 2-128 pixels) exist at every size from 64 up
 * and gain Fourier coefficients as the image grows; the coarsest band of
 * any image always holds the same ~8 coefficients. */
enum { FINE = 6, NE = NL_BYEX_ESTIMATORS, MB = NL_WAVELET_MAX_BANDS };

int main(int argc, char **argv)
{
  const char *exdir;
  int nphotos;
  char **photos = nl_study_exemplars_option(&argc, argv, "l2_weights", &exdir, &nphotos);
  nl_harness *r = nl_harness_begin("l2_weights", "L2 - Weights from an exemplar: the validation of Fig. 4", argc, argv);
  int quick = nl_harness_quick(r);
  int size = (int)nl_harness_param_int(r, "size", quick ? 128 : 512, 16, 4096,
                                       "side in pixels of the noise whose weights are estimated (quick 128)");
  int maxsize = (int)nl_harness_param_int(r, "max_size", quick ? 256 : 1024, 64, 4096,
                                          "largest image side of the error-against-size sweep (quick 256)");
  int sweep_seeds = (int)nl_harness_param_int(r, "sweep_seeds", quick ? 3 : 20, 2, 1000,
                                              "seeds per size in the error-against-size sweep (quick 3)");
  int tile = (int)nl_harness_param_int(r, "tile", NL_EXAMPLE_TILE, 8, 2048,
                                       "period in pixels of the wavelet-noise tile (even, >= 8)");
  int tseeds = (int)nl_harness_param_int(r, "transfer_seeds", quick ? 4 : 16, 1, 1000,
                                         "noises averaged into the band transfer matrix A, per size (quick 4)");
  int pmax = (int)nl_harness_param_int(r, "photo_max", quick ? 128 : 512, 16, 4096,
                                       "exemplar photographs are cropped about their centre to at most this side (quick 128)");
  int pseeds = (int)nl_harness_param_int(r, "photo_seeds", quick ? 2 : 8, 1, 1000,
                                         "syntheses averaged per estimator for a photograph's fit residual (quick 2)");
  double frac = nl_harness_param(r, "taper", 0.25, 0.01, 1, "fraction of each axis the corrected estimator's Tukey window tapers (1: Hann; 0.25 measured best)");
  nl_harness_params_done(r);
  nl_harness_note(r, "exemplars", "%s", exdir);
  unsigned long seed0 = nl_harness_seed(r);
  nl_wavelet_tile *t = nl_wavelet_tile_alloc(2, tile);
  if (!t) nl_harness_die(r, 2, "tile period %d must be even and >= 8", tile);
  nl_byexample_transfer T;

  /* Fig. 4 at one size and seed. */
  int nb = nl_byexample_band_count(size, size);
  double truth[MB], est[NE * MB], est2[MB], e[NE], f[NE], pw[NE];
  double *b_img = malloc((size_t)size * size * sizeof *b_img), *d_img = malloc((size_t)size * size * sizeof *d_img);
  nl_byexample_transfer_measure(&T, tile, size, size, nb, frac, tseeds, nl_seed_stream(seed0, "l2.transfer", (unsigned long)size), nl_harness_threads(r));
  nl_byexample_trial(&T, t, seed0, FINE, truth, est, b_img, e, f, pw);
  nl_wavelet_bands b;
  nl_wavelet_bands_init(&b, nb, est, tile, nl_seed_stream(seed0, "l2.new_offsets", 0), NULL);   /* (d): new offsets */
  nl_wavelet_bands_grid(t, &b, size, size, 0, 1, d_img);
  nl_byexample_estimate(&T, NL_BYEX_EQ12, d_img, est2);
  const char *wcols[] = {"band", "true", "est", "est_of_d", "corrected"};
  nl_table *wt = nl_table_alloc(5, wcols);   /* est, est_of_d: eq. 12 */
  for (int k = 0; k < nb; k++) nl_table_append(wt, "idddd", k, truth[k], est[k], est2[k], est[NL_BYEX_CORRECTED * nb + k]);
  nl_harness_write_table(r, wt, "weights.tsv");
  double sd = 0;
  for (int k = 0; k < nb; k++) sd += truth[k] * truth[k];
  sd = sqrt(T.sigma2 * sd);   /* eq. 14 with squares */
  nl_image *ib = nl_image_from_values(b_img, size, size, -3 * sd, 3 * sd);
  nl_image *id = nl_image_from_values(d_img, size, size, -3 * sd, 3 * sd);
  const nl_image *panels[] = {ib, id};
  const char *labels[] = {"(b) true weights", "(d) estimated weights"};
  nl_study_montage(r, panels, labels, 2, 2, "Fig. 4: validation of noise by example", "noise.png");

  /* Error against size, over seeds, per estimator; paired t-test of each against eq. 12. */
  const char *ecols[] = {"size", "bands", "estimator", "err_mean", "err_sd", "err_fine_mean", "err_fine_sd",
                         "power_ratio", "p_vs_eq12", "p_fine_vs_eq12", "seeds"};
  const char *bcols[] = {"size", "band", "estimator", "rmse", "bias"};
  nl_table *et = nl_table_alloc(11, ecols), *bt = nl_table_alloc(5, bcols);
  int nsizes = 0, below = 0, bbelow = 0;
  for (int s = 64; s <= maxsize; s *= 2) nsizes++;
  double *E = malloc((size_t)3 * NE * sweep_seeds * sizeof *E), m[3][NE], v[3][NE], pmax_p = 0, p_last = 1, pf = 1;
  double rms[NE * MB], bias[NE * MB];
  unsigned long *seeds = malloc((size_t)sweep_seeds * sizeof *seeds);
  for (int k = 0; k < sweep_seeds; k++) seeds[k] = nl_seed_stream(seed0, "l2.size_trial", (unsigned long)k);
  for (int s = 64, done = 0; s <= maxsize; s *= 2, done++) {
    int n = nl_byexample_band_count(s, s);
    nl_byexample_transfer_measure(&T, tile, s, s, n, frac, tseeds, nl_seed_stream(seed0, "l2.transfer", (unsigned long)s), nl_harness_threads(r));
    nl_byexample_trials(&T, seeds, sweep_seeds, FINE, E, rms, bias, nl_harness_threads(r));   /* on the run's threads */
    for (int q = 0; q < NE; q++)
      for (int k = 0; k < n; k++) nl_table_append(bt, "iisdd", s, k, nl_byexample_estimator_names[q], rms[q * n + k], bias[q * n + k]);
    for (int k = 0; k < n && s == maxsize; k++) bbelow += rms[NL_BYEX_CORRECTED * n + k] < rms[k];
    for (int q = 0; q < NE; q++) {
      for (int c = 0; c < 3; c++) nl_study_mean_sd(E + (c * NE + q) * sweep_seeds, sweep_seeds, &m[c][q], &v[c][q]);
      double p = q ? nl_byexample_paired_p(E + q * sweep_seeds, E, sweep_seeds) : 1;   /* paired by seed */
      pf = q ? nl_byexample_paired_p(E + (NE + q) * sweep_seeds, E + NE * sweep_seeds, sweep_seeds) : 1;
      nl_table_append(et, "iisdddddddi", s, n, nl_byexample_estimator_names[q], m[0][q], v[0][q], m[1][q], v[1][q],
                      m[2][q], p, pf, sweep_seeds);
      if (q == NL_BYEX_CORRECTED) { below += m[0][q] < m[0][0]; pmax_p = fmax(pmax_p, p); p_last = p; }
    }
    nl_harness_progress(r, (done + 1.0) / nsizes, "size sweep");
  }
  nl_harness_write_table(r, et, "estimators.tsv");
  nl_harness_write_table(r, bt, "bands.tsv");

  /* Photographs: true weights unknown; how well each estimator's weights re-synthesise the band powers. */
  nl_table *pt = nl_study_exemplar_fits(r, photos, nphotos, pmax, tile, frac, tseeds, pseeds, seed0);
  if (nphotos) nl_harness_write_table(r, pt, "photos.tsv");

  nl_harness_text(r, "Fig. 4 at %d x %d (%d bands, seed %lu): random weights uniform in [0.1, 1] "
                  "(the paper does not say how it draws them), a 2D wavelet-noise sum with them (b), "
                  "weights estimated by eq. 12-13 with our measured sigma_N^2 = %.4f (paper: 0.265), "
                  "and a noise with the estimated weights and new band offsets (d). Relative RMS weight "
                  "error |w_est - w| / |w| = %.3f (corrected estimator: %.3f); total power sum w_est^2 / sum w^2 = %.3f. "
                  "The paper says only that the two sets are \"very similar\" and converge with sample size; the sweep measures it.",
                  size, size, nb, seed0, nl_byexample_sigma2(tile), e[0], e[NL_BYEX_CORRECTED], pw[0]);
  nl_harness_text(r, "Beyond the paper: eq. 12 reads each band from its own power, but each wavelet band spills "
                  "into its neighbour octaves (L1) and the DFT of the non-periodic image leaks edge power into "
                  "finer bands. The corrected estimator measures the band-to-band transfer matrix on the noise "
                  "(%d noises per size), tapers the image (taper fraction %.2g; 1 = Hann) and solves non-negative least squares "
                  "for w^2; eq12_taper (taper only) and nnls_raw (matrix only) separate the two. Its mean error is "
                  "below eq. 12's at %d of %d sizes; at %d pixels, %.3f (sd %.3f) against %.3f (sd %.3f), paired t-test over "
                  "%d seeds p = %.2g (largest p over sizes %.2g).",
                  tseeds, frac, below, nsizes, maxsize, m[0][NL_BYEX_CORRECTED], v[0][NL_BYEX_CORRECTED], m[0][0], v[0][0],
                  sweep_seeds, p_last, pmax_p);
  nl_harness_text(r, "Where: over the %d finest bands the corrected error at %d pixels is %.3f (sd %.3f) against eq. 12's %.3f "
                  "(sd %.3f), paired t-test p = %.2g; per band, its RMS error is below eq. 12's in %d of %d bands (bands.tsv).", FINE,
                  maxsize, m[1][NL_BYEX_CORRECTED], v[1][NL_BYEX_CORRECTED], m[1][0], v[1][0], pf, bbelow, nl_byexample_band_count(maxsize, maxsize));
  nl_harness_report_table(r, wt, "Fig. 4 (a, c): true and estimated weights (band 0 finest); est_of_d re-estimates from (d) by eq. 12; corrected: NNLS + taper", 3);
  nl_harness_figure(r, "weights.png", "Fig. 4 (a, c): true vs estimated weights");
  nl_harness_figure(r, "noise.png", "Fig. 4 (b, d): noise of the true and of the estimated weights");
  nl_harness_report_table(r, et, "Relative RMS weight error vs image size per estimator (mean and sd over seeds); power_ratio = mean sum w_est^2 / sum w^2; p_vs_eq12, p_fine_vs_eq12: paired t-tests against eq. 12 over seeds (all bands; 6 finest)", 4);
  nl_harness_figure(r, "error.png", "Weight error vs image size per estimator, error bars one sd over seeds");
  nl_harness_figure(r, "bands.png", "RMS weight error per band at the largest size, per estimator (bands.tsv)");
  if (nphotos) {
    nl_harness_text(r, "Exemplar photographs (%d in %s, luminance, cropped to at most %d pixels): the true weights are "
                    "unknown, so each estimator's weights are re-synthesised (%d noises) and their band powers compared "
                    "with the photograph's, raw and tapered: RMS over bands of the relative power error. Mean over "
                    "photographs (raw, tapered): eq12 %.3f, %.3f; corrected %.3f, %.3f.", nphotos, exdir, pmax, pseeds,
                    nl_study_mean_where(pt, "estimator", "eq12", "resid_raw", NULL, 0, NULL),
                    nl_study_mean_where(pt, "estimator", "eq12", "resid_taper", NULL, 0, NULL),
                    nl_study_mean_where(pt, "estimator", "corrected", "resid_raw", NULL, 0, NULL),
                    nl_study_mean_where(pt, "estimator", "corrected", "resid_taper", NULL, 0, NULL));
    nl_harness_report_table(r, pt, "Photographs: band-power fit residual of each estimator's re-synthesis", 4);
  } else nl_harness_text(r, "No exemplar photographs in %s (--exemplars DIR): the photograph comparison was not run.", exdir);

  nl_image_free(ib); nl_image_free(id);
  nl_table_free(wt); nl_table_free(et); nl_table_free(bt); nl_table_free(pt);
  free(b_img); free(d_img); free(E); free(seeds);
  nl_study_paths_free(photos);
  nl_wavelet_tile_free(t);
  nl_harness_check_measured(r, "*", 100);   /* measured tolerances (nl_harness.h) */
  return nl_harness_end(r);
}
