/* L2 - Lagae et al. 2010 sec. 4.3, Fig. 4: random weights -> noise ->
 * weights estimated by eq. 12-13 -> noise; beyond the paper, the weight
 * error against image size over seeds beside a leakage-corrected estimator
 * (transfer matrix measured on the noise, tapered DFT, NNLS;
 * byexample/nl_byexample_leak.h), and both on exemplar photographs. */
#include "claims.h"
#include "photos.h"
#include "report.h"
#include "sweep.h"
#include "study/nl_study.h"
#include "study/nl_study_exemplars.h"

#include <math.h>
#include <stdlib.h>

/* The 6 finest bands (periods 2-128 pixels) exist at every size from 64 up
 * and gain Fourier coefficients as the image grows; the coarsest band of
 * any image always holds the same ~8 coefficients. */
enum { FINE = 6, NE = NL_BYEXAMPLE_ESTIMATORS, MB = NL_WAVELET_MAX_BANDS };

int main(int argc, char **argv)
{
  const char *exdir;
  int nphotos;
  char **photos = l2_exemplars_option(&argc, argv, "l2_weights", &exdir, &nphotos);
  nl_harness *r = nl_harness_begin(
      "l2_weights", "L2 - Weights from an exemplar: the validation of Fig. 4", argc, argv);
  int quick = nl_harness_quick(r);
  int size = (int)nl_harness_param_fft_size(
      r, "size", quick ? 128 : 512, 16, 4096,
      "side in pixels of the noise whose weights are estimated (quick 128)");
  int maxsize =
      (int)nl_harness_param_fft_size(r, "max_size", quick ? 256 : 1024, 64, 4096,
                                "largest image side of the error-against-size sweep (quick 256)");
  int sweep_seeds =
      (int)nl_harness_param_int(r, "sweep_seeds", quick ? 3 : 20, 2, 1000,
                                "seeds per size in the error-against-size sweep (quick 3)");
  int tile = (int)nl_harness_param_int(r, "tile", NL_BYEXAMPLE_TILE, 8, 2048,
                                       "period in pixels of the wavelet-noise tile (even, >= 8)");
  int tseeds = (int)nl_harness_param_int(
      r, "transfer_seeds", quick ? 4 : 16, 1, 1000,
      "noises averaged into the band transfer matrix A, per size (quick 4)");
  int pmax = (int)nl_harness_param_int(
      r, "photo_max", quick ? 128 : 512, 16, 4096,
      "exemplar photographs are cropped about their centre to at most this side (quick 128)");
  int pseeds = (int)nl_harness_param_int(
      r, "photo_seeds", quick ? 2 : 8, 1, 1000,
      "syntheses averaged per estimator for a photograph's fit residual (quick 2)");
  double frac = nl_harness_param(r, "taper", 0.25, 0.01, 1,
                                 "fraction of each axis the corrected estimator's Tukey window "
                                 "tapers (1: Hann; 0.25 measured best)");
  nl_harness_params_done(r);
  nl_harness_note(r, "exemplars", "%s", exdir);
  unsigned long seed0 = nl_harness_seed(r);
  nl_wavelet_tile *t = nl_wavelet_tile_alloc(2, tile);
  if (!t) nl_harness_die(r, 2, "tile period %d must be even and >= 8", tile);
  nl_byexample_transfer T;

  /* Fig. 4 at one size and seed. */
  l2_fig4 fig = {
    .size = size, .nb = nl_byexample_band_count(size, size), .tile = tile, .seed = seed0
  };
  int nb = fig.nb;
  double truth[MB], est[NE * MB], est2[MB], f[NE];
  double *b_img = malloc((size_t)size * size * sizeof *b_img);
  double *d_img = malloc((size_t)size * size * sizeof *d_img);
  nl_error err;
  if (nl_byexample_transfer_measure(&T, tile, size, size, nb, frac, tseeds,
                                    nl_seed_stream(seed0, "l2.transfer", (unsigned long)size),
                                    nl_harness_threads(r), &err))
    nl_harness_die(r, 2, "--set size=%d: %s", size, err.msg);
  nl_byexample_trial(&T, t, seed0, FINE, truth, est, b_img, fig.e, f, fig.pw);
  nl_wavelet_bands b; /* (d): the estimated weights with new offsets */
  nl_wavelet_bands_init(&b, nb, est, tile, nl_seed_stream(seed0, "l2.new_offsets", 0), NULL);
  nl_wavelet_bands_grid(t, &b, size, size, 0, 1, d_img);
  nl_byexample_estimate(&T, NL_BYEXAMPLE_EQ12, d_img, est2);
  const char *wcols[] = { "band", "true", "est", "est_of_d", "corrected" };
  nl_table *wt = nl_table_alloc(5, wcols); /* est, est_of_d: eq. 12 */
  for (int k = 0; k < nb; k++)
    nl_table_append(wt, "idddd", k, truth[k], est[k], est2[k],
                    est[NL_BYEXAMPLE_CORRECTED * nb + k]);
  nl_harness_write_table(r, wt, "weights.tsv");
  double sd = 0;
  for (int k = 0; k < nb; k++) sd += truth[k] * truth[k];
  sd = sqrt(T.sigma2 * sd); /* eq. 14 with squares */
  nl_image *ib = nl_image_from_values(b_img, size, size, -3 * sd, 3 * sd);
  nl_image *id = nl_image_from_values(d_img, size, size, -3 * sd, 3 * sd);
  const nl_image *panels[] = { ib, id };
  const char *labels[] = { "(b) true weights", "(d) estimated weights" };
  nl_study_montage(r, panels, labels, 2, 2, "Fig. 4: validation of noise by example", "noise.png");

  /* Error against size, over seeds, per estimator; paired t-test of each against eq. 12. */
  l2_sweep sw = { .maxsize = maxsize,
                  .seeds = sweep_seeds,
                  .tseeds = tseeds,
                  .fine = FINE,
                  .frac = frac,
                  .p_last = 1,
                  .pf = 1 };
  nl_table *bt;
  nl_table *et = l2_size_sweep(r, tile, seed0, &sw, &bt);
  nl_harness_write_table(r, et, "estimators.tsv");
  nl_harness_write_table(r, bt, "bands.tsv");

  /* Photographs: true weights unknown; how well each estimator's weights
   * re-synthesise the band powers. */
  nl_table *pt = l2_exemplar_fits(r, photos, nphotos, pmax, tile, frac, tseeds, pseeds, seed0);
  if (nphotos) nl_harness_write_table(r, pt, "photos.tsv");

  nl_table *tt;
  nl_table *st = l2_claims(r, size, sw.err_all, sw.err_fine, sw.sizes, sw.nsizes, sw.seeds, FINE,
                           seed0, &tt);
  l2_report(r, &fig, &sw, wt, et, st, tt, pt, nphotos, exdir, pmax, pseeds);
  nl_table_free(st);
  nl_table_free(tt);
  free(sw.err_all);
  free(sw.err_fine);
  nl_image_free(ib);
  nl_image_free(id);
  nl_table_free(wt);
  nl_table_free(et);
  nl_table_free(bt);
  nl_table_free(pt);
  free(b_img);
  free(d_img);
  nl_study_paths_free(photos);
  nl_wavelet_tile_free(t);
  nl_harness_check_measured(r, "*", 100); /* measured tolerances (nl_harness.h) */
  return nl_harness_end(r);
}
