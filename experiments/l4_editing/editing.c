/* editing.c - L4's loop over seeds (Lagae et al. 2010 Fig. 10c, d):
 * frequency-based editing measured on the luminance band power (eq. 13),
 * its floor, the band leakage behind the floor, and solid extrapolation. */
#include "editing.h"
#include "study/nl_study.h"

#include <math.h>
#include <stdlib.h>

static nl_image *synth(const nl_byexample_params *p, int size, unsigned long seed, int solid,
                       nl_error *err)
{
  nl_image *im = NULL;
  nl_byexample_synth_options so = { 1, solid, 0.0, NL_SPLINE_STEFFEN };
  return nl_byexample_synthesize(p, size, size, seed, &so, &im, err) ? NULL : im;
}

static nl_status luminance_power(const nl_image *im, int nb, double *power, nl_error *err)
{
  double *v = nl_xmalloc((size_t)im->width * im->height * sizeof *v);
  nl_byexample_luminance(im, v);
  nl_status st = nl_byexample_band_power(v, im->width, im->height, nb, power, err);
  free(v);
  return st;
}

nl_status l4_edit_replicate(const nl_image *ex, int nfine, double factor, unsigned long seed,
                            l4_edit *out, nl_error *err)
{
  int size = ex->width;
  /* [0] histogram matching, [1] without */
  nl_byexample_options opt[2] = { { 1, 1, 0, 0, NL_HIST_PAPER, 0 },
                                  { 1, 0, 0, 0, NL_HIST_PAPER, 0 } };
  nl_byexample_params p[2];
  for (int h = 0; h < 2; h++) {
    nl_byexample_params pe, p0;
    if (nl_byexample_analyse(ex, &opt[h], &p[h], err)) return NL_EINVAL;
    pe = p0 = p[h];
    nl_byexample_attenuate(&pe, nfine, factor); /* the edit */
    nl_byexample_attenuate(&p0, nfine, 0.0);    /* the bands removed: what is left is the floor */
    nl_image *b = synth(&p[h], size, seed, 0, err);
    nl_image *c = synth(&pe, size, seed, 0, err);
    nl_image *z = synth(&p0, size, seed, 0, err);
    if (!b || !c || !z) {
      nl_image_free(b);
      nl_image_free(c);
      nl_image_free(z);
      return NL_EINVAL;
    }
    double pc[NL_WAVELET_MAX_BANDS], pz[NL_WAVELET_MAX_BANDS];
    out->nbands = p[h].nbands;
    nl_status st = luminance_power(b, out->nbands, out->power[h], err);
    if (!st) st = luminance_power(c, out->nbands, pc, err);
    if (!st) st = luminance_power(z, out->nbands, pz, err);
    nl_image_free(c);
    nl_image_free(z);
    c = z = NULL;
    if (st) {
      nl_image_free(b);
      return st;
    }
    for (int k = 0; k < out->nbands; k++) {
      out->ratio[h][k] = pc[k] / out->power[h][k];
      out->floor[h][k] = pz[k] / out->power[h][k];
    }
    /* Fig. 10d: a slice of the solid texture against the 2D synthesis and the exemplar */
    if (h == 0) {
      nl_image *s = synth(&p[h], size, seed, 1, err);
      if (!s) {
        nl_image_free(b);
        nl_image_free(c);
        nl_image_free(z);
        return NL_EINVAL;
      }
      nl_study_ks_channels(b, s, out->ks_slice);
      nl_study_ks_channels(b, ex, out->ks_exemplar);
      nl_image_free(s);
    }
    nl_image_free(b);
    nl_image_free(c);
    nl_image_free(z);
  }
  /* Single bands of the same wavelet noise (2D tile of the synthesis):
   * the share of band k's power that eq. 13 puts in the nfine finest bands. */
  int nb = out->nbands;
  nl_wavelet_tile *t = nl_wavelet_tile_alloc(2, p[0].tile);
  if (!t) return nl_fail(err, NL_EINVAL, "tile period %d: not a valid wavelet tile", p[0].tile);
  nl_wavelet_tile_seed(t, nl_seed_stream(seed, "l4.leakage", 0));
  double *share = nl_xmalloc((size_t)nb * nb * sizeof *share);
  double var[NL_WAVELET_MAX_BANDS];
  nl_status st = nl_byexample_band_leakage(t, size, nb, nl_seed_stream(seed, "l4.leakage", 1), share, var, err);
  if (st) {
    free(share);
    nl_wavelet_tile_free(t);
    return st;
  }
  for (int k = 0; k < nb; k++) {
    out->leak[k] = 0;
    for (int j = 0; j < nfine && j < nb; j++) out->leak[k] += share[(size_t)k * nb + j];
  }
  free(share);
  nl_wavelet_tile_free(t);
  return NL_OK;
}

static void mean_sd(const l4_edit *rep, int K, size_t offset, double *m, double *sd)
{
  double *v = nl_xmalloc((size_t)K * sizeof *v);
  for (int s = 0; s < K; s++) v[s] = *(const double *)((const char *)&rep[s] + offset);
  nl_stats_mean_sd(v, K, NL_STATS_SUMMED, m, sd);
  free(v);
}
#define MEAN_SD(field, m, sd)                                                                      \
  mean_sd(rep, K, (size_t)((const char *)&rep[0].field - (const char *)&rep[0]), m, sd)

nl_table *l4_edit_tables(const l4_edit *rep, int K, int nfine, double factor, nl_table **solid,
                         nl_table **summary)
{
  const char *ecols[] = { "band",         "power_b",          "ratio",     "ratio_sd",
                          "ratio_nohist", "ratio_nohist_sd",  "floor",     "floor_nohist",
                          "predicted",    "predicted_nohist", "leak_fine", "expected" };
  nl_table *et = nl_table_alloc(12, ecols);
  int nb = rep[0].nbands;
  double f2 = factor * factor;
  /* over the edited bands: ratio and floor ranges, largest ratio sd and |ratio - predicted| */
  double rmin = INFINITY, rmax = -INFINITY, flo = INFINITY, fhi = -INFINITY, sdmax = 0, dev = 0;
  /* band powers (no histogram matching): edited, unedited, their leakage, the floor; p0, pmax */
  double pfine = 0, pcoarse = 0, pleak = 0, pfloor = 0, p0 = 0, pmax = 0;
  for (int k = 0; k < nb; k++) {
    double pb, pn, r, rsd, rn, rnsd, fl, fln, lk, sd;
    MEAN_SD(power[0][k], &pb, &sd);
    MEAN_SD(power[1][k], &pn, &sd);
    MEAN_SD(ratio[0][k], &r, &rsd);
    MEAN_SD(ratio[1][k], &rn, &rnsd);
    MEAN_SD(floor[0][k], &fl, &sd);
    MEAN_SD(floor[1][k], &fln, &sd);
    MEAN_SD(leak[k], &lk, &sd);
    int edited = k < nfine;
    nl_table_append(et, "iddddddddddd", k, pb, r, rsd, rn, rnsd, fl, fln, fl + f2 * (1 - fl),
                    fln + f2 * (1 - fln), lk, edited ? f2 : 1.0);
    if (k == 0) p0 = pb;
    if (pb > pmax) pmax = pb;
    if (edited) {
      rmin = fmin(rmin, fmin(r, rn));
      rmax = fmax(rmax, fmax(r, rn));
      flo = fmin(flo, fmin(fl, fln));
      fhi = fmax(fhi, fmax(fl, fln));
      sdmax = fmax(sdmax, fmax(rsd, rnsd));
      pfine += pn;
      pfloor += fln * pn;
      /* the edit on top of the floor, per seed: r = r0 + f^2 (1 - r0) */
      for (int s = 0; s < K; s++)
        for (int h = 0; h < 2; h++) {
          double r0 = rep[s].floor[h][k];
          dev = fmax(dev, fabs(rep[s].ratio[h][k] - (r0 + f2 * (1 - r0))));
        }
    } else {
      pcoarse += pn;
      pleak += lk * pn;
    }
  }
  const char *scols[] = { "channel", "ks_2d_vs_slice", "ks_2d_vs_slice_sd", "ks_2d_vs_exemplar",
                          "ks_2d_vs_exemplar_sd" };
  *solid = nl_table_alloc(5, scols);
  for (int c = 0; c < 3; c++) {
    double a, asd, b, bsd;
    MEAN_SD(ks_slice[c], &a, &asd);
    MEAN_SD(ks_exemplar[c], &b, &bsd);
    nl_table_append(*solid, "idddd", c, a, asd, b, bsd);
  }
  const char *names[] = { "ratio_fine_min",         "ratio_fine_max",    "ratio_fine_sd_max",
                          "floor_fine_min",         "floor_fine_max",    "edit_dev_max",
                          "coarse_over_fine_power", "floor_fine_nohist", "floor_from_leakage",
                          "peak_over_finest_power" };
  *summary = nl_table_alloc(10, names); /* one row, addressed by column name */
  nl_table_append(*summary, "dddddddddd", rmin, rmax, sdmax, flo, fhi, dev, pcoarse / pfine,
                  pfloor / pfine, pleak / pfine, pmax / p0);
  return et;
}
