/* L1 - Lagae et al. 2010 sec. 3 (Fig. 2, 3): wavelet noise (Cook & DeRose
 * 2005) as the band of a multiresolution noise; its band variance sigma_N^2
 * against the paper's 0.265, and how much of a band's power stays inside its
 * eq. 13 octave. */
#include "byexample/nl_byexample.h"
#include "harness/nl_harness.h"
#include "report.h"
#include "variance.h"
#include "study/nl_study.h"

#include <stdlib.h>

#define SAMPLES 4 /* samples per unit and axis of a variance over the cell */
#define DECADES 4 /* of the log power spectrum images */
#define NFRAC   8 /* lattice shifts frac = i / NFRAC, i = 0..NFRAC */

int main(int argc, char **argv)
{
  nl_harness *r = nl_harness_begin("l1_wavelet",
                                   "L1 - Wavelet noise: band variance and band limits", argc, argv);
  int quick = nl_harness_quick(r);
  int size = (int)nl_harness_param_fft_size(
      r, "size", quick ? 128 : 512, 32, 4096,
      "side in pixels of the wavelet-noise images and spectra (quick 128)");
  int tile =
      (int)nl_harness_param_int(r, "tile", NL_BYEXAMPLE_TILE, 8, 2048,
                                "period in pixels of the 2D wavelet-noise tile (even, >= 8)");
  int tile3 =
      (int)nl_harness_param_int(r, "tile3", quick ? 32 : NL_BYEXAMPLE_TILE3, 8, 256,
                                "period of the 3D wavelet-noise tile (even, >= 8; quick 32)");
  int band =
      (int)nl_harness_param_int(r, "band", 2, 0, 8, "the band shown in the images (0 = finest)");
  nl_harness_params_done(r);
  int K = nl_harness_seeds(r);
  int nb = nl_byexample_band_count(size, size);
  unsigned long seed0 = nl_harness_seed(r);
  l1_setting set = { tile, tile3, K, size, SAMPLES, DECADES, seed0, 0 };

  /* Band variance per seed, 2D tile and 3D tile. */
  const char *vcols[] = { "seed", "var2d", "var3d" };
  nl_table *vt = nl_table_alloc(3, vcols);
  double *v2 = calloc((size_t)K, sizeof *v2);
  double *v3 = calloc((size_t)K, sizeof *v3);
  double *share = calloc((size_t)K * nb * nb, sizeof *share);
  double *var = calloc((size_t)nb, sizeof *var);
  nl_wavelet_tile *t2 = nl_wavelet_tile_alloc(2, tile);
  nl_wavelet_tile *t3 = nl_wavelet_tile_alloc(3, tile3);
  if (!t2 || !t3) nl_harness_die(r, 2, "tile periods must be even and >= 8");
  /* The control: the same coefficients without the band-pass (variance.h);
   * and the Kolmogorov distance of each to the normal law. */
  nl_wavelet_tile *r2 = nl_wavelet_tile_alloc(2, tile), *r3 = nl_wavelet_tile_alloc(3, tile3);
  double *rv2 = calloc((size_t)K, sizeof *rv2), *rv3 = calloc((size_t)K, sizeof *rv3);
  double *ks = calloc((size_t)K, sizeof *ks), *rks = calloc((size_t)K, sizeof *rks);
  double *rshare = calloc((size_t)K * nb * nb, sizeof *rshare);
  for (int s = 0; s < K; s++) {
    nl_wavelet_tile_seed(t2, nl_seed_replicate(seed0, s));
    nl_wavelet_tile_seed(t3, nl_seed_replicate(seed0, s));
    v2[s] = nl_wavelet_tile_variance(t2, SAMPLES);
    v3[s] = nl_wavelet_tile_variance(t3, SAMPLES);
    nl_table_append(vt, "idd", (int)(nl_seed_replicate(seed0, s)), v2[s], v3[s]);
    nl_error err;
    if (nl_byexample_band_leakage(t2, size, nb, nl_seed_replicate(seed0, s),
                                  share + (size_t)s * nb * nb, var, &err))
      nl_harness_die(r, 2, "--set size=%d: %s", size, err.msg);
    ks[s] = l1_gauss_distance(t2, SAMPLES);
    l1_raw_tile_seed(r2, nl_seed_replicate(seed0, s));
    l1_raw_tile_seed(r3, nl_seed_replicate(seed0, s));
    rv2[s] = nl_wavelet_tile_variance(r2, SAMPLES);
    rv3[s] = nl_wavelet_tile_variance(r3, SAMPLES);
    rks[s] = l1_gauss_distance(r2, SAMPLES);
    if (nl_byexample_band_leakage(r2, size, nb, nl_seed_replicate(seed0, s),
                                  rshare + (size_t)s * nb * nb, var, &err))
      nl_harness_die(r, 2, "--set size=%d: %s", size, err.msg);
    nl_harness_progress(r, (s + 1.0) / K, "seeds");
  }
  nl_harness_write_table(r, vt, "variance.tsv");

  /* Non-stationarity: variance on lattices shifted by frac (last seed). */
  const char *fcols[] = { "frac", "var2d", "var3d" };
  nl_table *ft = nl_table_alloc(3, fcols);
  for (int i = 0; i <= NFRAC; i++)
    nl_table_append(ft, "ddd", (double)i / NFRAC,
                    nl_wavelet_lattice_variance(t2, (double)i / NFRAC),
                    nl_wavelet_lattice_variance(t3, (double)i / NFRAC));
  nl_harness_write_table(r, ft, "lattice.tsv");
  nl_table *lt = l1_leakage_table(share, K, nb); /* mean share of band k's power in band j */
  nl_harness_write_table(r, lt, "leakage.tsv");

  /* The 3D gap: sigma_N^2 read in the ways Cook & DeRose's 0.210 could have been measured. */
  nl_table *vr = l1_variance_readings(tile3, K, seed0, L1_CD_SIGMA2_3D);
  nl_harness_write_table(r, vr, "variance_readings.tsv");

  /* Images of one band in 2D and a slice of 3D, their spectra, and radial
   * power profiles (frequency in cycles per pixel). */
  set.window3 = l1_band_figure(r, t2, t3, &set, band);

  /* Summary against the literature: the claims, their controls and verdicts. */
  double m2, s2, m3, s3;
  nl_stats_mean_sd(v2, K, NL_STATS_SUMMED, &m2, &s2);
  nl_stats_mean_sd(v3, K, NL_STATS_SUMMED, &m3, &s3);
  nl_table *rlt = l1_leakage_table(rshare, K, nb);
  l1_per_seed ps = { K, v2, v3, rv2, rv3, ks, rks };
  nl_table *st = l1_verdicts(r, &ps, lt, rlt);
  nl_table *pt, *xt = l1_expected_table(tile, m2, s2, tile3, m3, s3, K, SAMPLES, &pt);
  nl_harness_write_table(r, xt, "expected.tsv");
  nl_harness_write_table(r, pt, "expected_period.tsv");
  l1_report(r, &set, st, vr, ft, lt, xt, pt);
  nl_table_free(xt);
  nl_table_free(pt);

  nl_table_free(vt);
  nl_table_free(ft);
  nl_table_free(lt);
  nl_table_free(st);
  nl_table_free(rlt);
  nl_wavelet_tile_free(r2);
  nl_wavelet_tile_free(r3);
  free(rv2);
  free(rv3);
  free(ks);
  free(rks);
  free(rshare);
  nl_table_free(vr);
  nl_wavelet_tile_free(t2);
  nl_wavelet_tile_free(t3);
  free(v2);
  free(v3);
  free(share);
  free(var);
  nl_harness_check_measured(r, "*", 100); /* measured tolerances (nl_harness.h) */
  return nl_harness_end(r);
}
