/* L1 - Lagae et al. 2010 sec. 3 (Fig. 2, 3): wavelet noise (Cook & DeRose
 * 2005) as the band of a multiresolution noise; its band variance sigma_N^2
 * against the paper's 0.265, and how much of a band's power stays inside its
 * eq. 13 octave. */
#include "byexample/nl_byexample.h"
#include "harness/nl_harness.h"
#include "report.h"
#include "variance.h"
#include "study/nl_study.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#define SAMPLES 4 /* samples per unit and axis of a variance over the cell */
#define DECADES 4 /* of the log power spectrum images */
#define NFRAC   8 /* lattice shifts frac = i / NFRAC, i = 0..NFRAC */

int main(int argc, char **argv)
{
  nl_harness *r = nl_harness_begin("l1_wavelet",
                                   "L1 - Wavelet noise: band variance and band limits", argc, argv);
  int quick = nl_harness_quick(r);
  int size = (int)nl_harness_param_int(
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
    nl_byexample_band_leakage(t2, size, nb, nl_seed_replicate(seed0, s),
                              share + (size_t)s * nb * nb, var);
    ks[s] = l1_gauss_distance(t2, SAMPLES);
    l1_raw_tile_seed(r2, nl_seed_replicate(seed0, s));
    l1_raw_tile_seed(r3, nl_seed_replicate(seed0, s));
    rv2[s] = nl_wavelet_tile_variance(r2, SAMPLES);
    rv3[s] = nl_wavelet_tile_variance(r3, SAMPLES);
    rks[s] = l1_gauss_distance(r2, SAMPLES);
    nl_byexample_band_leakage(r2, size, nb, nl_seed_replicate(seed0, s),
                              rshare + (size_t)s * nb * nb, var);
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
  nl_wavelet_tile_seed(t2, seed0);
  nl_wavelet_tile_seed(t3, seed0);
  double w[NL_WAVELET_MAX_BANDS] = { 0 };
  w[band] = 1;
  nl_wavelet_bands b;
  nl_wavelet_bands_init(&b, band + 1, w, tile, seed0, NULL);
  double *img2 = malloc((size_t)size * size * sizeof *img2);
  double *img3 = malloc((size_t)size * size * sizeof *img3);
  nl_wavelet_bands_grid(t2, &b, size, size, 0, 1, img2);
  nl_wavelet_bands_init(&b, band + 1, w, tile3, seed0, NULL);
  nl_wavelet_bands_grid(t3, &b, size, size, 3.3, 1, img3);
  /* (b) and (d) show one period of the 3D tile at most: a wider window repeats it */
  int w3 = size < (tile3 << band) ? size : tile3 << band;
  double *win3 = l1_window(img3, size, w3);
  nl_image *im[4] = { nl_image_from_values(img2, size, size, -1.5, 1.5),
                      nl_image_from_values(win3, w3, w3, -1.5, 1.5),
                      nl_byexample_spectrum_image(img2, size, size, DECADES),
                      nl_byexample_spectrum_image(win3, w3, w3, DECADES) };
  free(win3);
  char lb[64];
  snprintf(lb, sizeof lb, w3 == tile3 << band ? "(b) 3D slice, one period" : "(b) 3D slice, %d px",
           w3);
  const char *labels[] = { "(a) 2D wavelet noise", lb, "(c) power spectrum of (a)",
                           "(d) power spectrum of (b)" };
  char title[96];
  snprintf(title, sizeof title, "One band (k = %d: 1/%d..1/%d cycles per pixel)", band, 4 << band,
           2 << band);
  nl_study_montage(r, (const nl_image *const *)im, labels, 4, 2, title, "noise.png");
  const double *imgs[2] = { img2, img3 };
  nl_table *rt = nl_study_radial_table(imgs, (const char *[]){ "power2d", "power3d" }, 2, size, 0);
  nl_harness_write_table(r, rt, "radial.tsv");
  const char *ecols[] = { "lo", "hi" };
  nl_table *et = nl_table_alloc(2, ecols);
  nl_table_append(et, "dd", ldexp(1.0, -(band + 2)), ldexp(1.0, -(band + 1)));
  nl_harness_write_table(r, et, "edges.tsv");
  nl_table_free(et);

  /* Summary against the literature. */
  double m2, s2, m3, s3;
  nl_stats_mean_sd(v2, K, NL_STATS_SUMMED, &m2, &s2);
  nl_stats_mean_sd(v3, K, NL_STATS_SUMMED, &m3, &s3);
  nl_table *rlt = l1_leakage_table(rshare, K, nb);
  /* summary.tsv: the paper's four claims, then the same quantities of the
   * control (rows + 4); se = sd / sqrt(seeds) for the equivalence tests */
  nl_table *st = nl_table_alloc(
      6, (const char *[]){ "quantity", "ours", "ours_sd", "ours_se", "seeds", "paper" });
  double sq = sqrt((double)K);
  const char *qn[4] = { "sigma_N^2 2D", "sigma_N^2 3D", "in-band share band 0",
                        "Kolmogorov distance to the normal law, 2D" };
  const double paper[4] = { L1_PAPER_SIGMA2_2D, L1_CD_SIGMA2_3D, 1.0, 0.0 };
  for (int c = 0; c < 2; c++) {
    const double *a[4] = { c ? rv2 : v2, c ? rv3 : v3, NULL, c ? rks : ks };
    const nl_table *l = c ? rlt : lt;
    for (int q = 0; q < 4; q++) {
      double m, sd;
      if (a[q])
        nl_stats_mean_sd(a[q], K, NL_STATS_SUMMED, &m, &sd);
      else {
        m = nl_table_value(l, 0, "inside");
        sd = nl_table_value(l, 0, "inside_sd");
      }
      char name[96];
      snprintf(name, sizeof name, "%s%s", qn[q], c ? ", raw coefficients" : "");
      nl_table_append(st, "sddddd", name, m, sd, sd / sq, (double)K, paper[q]);
    }
  }
  nl_harness_write_table(r, st, "summary.tsv");
  /* Equivalence margins: docs/experiments.md (printed precision for the
   * constants, 5% for eq. 7, one percent of the CDF for the normal law). */
  const char *rule[4] = { "equiv abs 0.0005 0.05 0.2", "equiv abs 0.0005 0.05 0.2",
                          "equiv rel 0.05 0.05 0.2", "equiv abs 0.01 0.05 0.2" };
  const char *what[4] = { "sigma_N^2 2D", "sigma_N^2 3D", "in-band share of band 0 (eq. 7)",
                          "Gaussian intensity distribution, Kolmogorov distance" };
  const char *note[4] = { "mean of N^2 over one period", "mean of N^2 over one period",
                          "the finest band's power inside its eq. 13 band",
                          "values of one period against the normal law" };
  for (size_t i = 0; i < 4; i++) {
    nl_harness_verdict_equiv(r, "summary.tsv", st, i, what[i], "paper", "ours", "ours_se", "seeds",
                             rule[i], "independent", note[i]);
    nl_harness_verdict_control(r, "the tile's coefficients without the band-pass", "summary.tsv",
                               st, i + 4);
  }
  nl_harness_text(
      r,
      "**Equivalence and controls:** sigma_N^2 is decided against the printed 0.265 (margin half "
      "a unit of its last digit, docs/experiments.md): ours %.4f, standard error %.2g. The same "
      "Gaussian coefficients without the band-pass (the control) have variance %.4f (2D), keep "
      "%.3f of band 0's power in its band against %.3f, and are as Gaussian (Kolmogorov distance "
      "%.4f against %.4f): the normal law comes from the coefficients, not from the wavelet "
      "construction, and is no evidence for it.\n",
      nl_table_value(st, 0, "ours"), nl_table_value(st, 0, "ours_se"), nl_table_value(st, 4, "ours"),
      nl_table_value(st, 6, "ours"), nl_table_value(st, 2, "ours"), nl_table_value(st, 7, "ours"),
      nl_table_value(st, 3, "ours"));
  nl_table *pt, *xt = l1_expected_table(tile, m2, s2, tile3, m3, s3, K, SAMPLES, &pt);
  nl_harness_write_table(r, xt, "expected.tsv");
  nl_harness_write_table(r, pt, "expected_period.tsv");
  l1_setting set = { tile, tile3, K, size, SAMPLES, DECADES, seed0, w3 };
  l1_report(r, &set, st, vr, ft, lt, xt, pt);
  nl_table_free(xt);
  nl_table_free(pt);

  for (int i = 0; i < 4; i++) nl_image_free(im[i]);
  nl_table_free(vt);
  nl_table_free(ft);
  nl_table_free(lt);
  nl_table_free(rt);
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
  free(img2);
  free(img3);
  nl_harness_check_measured(r, "*", 100); /* measured tolerances (nl_harness.h) */
  return nl_harness_end(r);
}
