/* The per-band comparison of a photograph with its synthesis (Lagae et al.
 * 2010 sec. 5 on real exemplars), shared by the `example` command and L3's
 * photographs. See nl_study.h. */
#include "study/nl_study.h"
#include "byexample/nl_byexample.h"
#include "spectrum/nl_spectrum.h"
#include "stats/nl_stats.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static double ks2(const double *x, size_t n, const double *y, size_t m)
{
  nl_stats_ks_result res;
  nl_stats_ks2_test(x, n, y, m, &res, NULL);
  return res.d;
}

nl_table *nl_study_example_band_table(void)
{
  static const char *cols[] = { "exemplar", "representation", "replicate",   "band",
                                "freq_lo",  "freq_hi",        "power_photo", "power_synth",
                                "ratio",    "share",          "checked" };
  return nl_table_alloc(11, cols);
}

nl_table *nl_study_example_summary_table(void)
{
  static const char *cols[] = { "exemplar",    "representation", "replicate",
                                "width",       "height",         "ks",
                                "ks_rgb",      "tail_photo",     "tail_synth",
                                "speckle",     "bands_checked",  "worst_band",
                                "worst_ratio", "pass",           "ks_grad" };
  return nl_table_alloc(15, cols);
}

/* |grad L| by forward differences over the (w - 1) x (h - 1) interior: edges
 * and joints, the structure band power and histogram do not describe. */
static size_t grad_mag(const double *l, int w, int h, double *g)
{
  size_t k = 0;
  for (int y = 0; y + 1 < h; y++)
    for (int x = 0; x + 1 < w; x++) {
      double dx = l[(size_t)y * w + x + 1] - l[(size_t)y * w + x];
      double dy = l[(size_t)(y + 1) * w + x] - l[(size_t)y * w + x];
      g[k++] = sqrt(dx * dx + dy * dy);
    }
  return k;
}

nl_status nl_study_example_compare(const nl_image *ex, const nl_image *syn, const char *name,
                                   const char *rep, int replicate, double min_share, double max_ratio,
                                   double max_ks, nl_table *bands, nl_table *sum, nl_error *err)
{
  /* Both images are Fourier-transformed (eq. 13 band powers). */
  const nl_image *im[2] = {ex, syn};
  for (int i = 0; i < 2; i++)
    if (nl_spectrum_check_size(im[i]->width, im[i]->height, err)) {
      char msg[NL_ERROR_LEN];
      snprintf(msg, sizeof msg, "%s", err ? err->msg : "");
      return nl_fail(err, NL_EINVAL, "%s: %s", i ? rep : name, msg);
    }
  size_t n = (size_t)ex->width * ex->height, m = (size_t)syn->width * syn->height;
  double *le = nl_xmalloc(n * sizeof *le), *ls = nl_xmalloc(m * sizeof *ls);
  nl_byexample_luminance(ex, le);
  nl_byexample_luminance(syn, ls);
  /* Eq. 13 bands of the photograph's luminance (Parseval-normalised: power
   * per pixel, comparable across sizes); the synthesis' extra coarse bands
   * hold what its larger size adds and are not compared. */
  double pe[NL_WAVELET_MAX_BANDS], ps[NL_WAVELET_MAX_BANDS], total = 0, worst = 1;
  int nbe = nl_byexample_band_count(ex->width, ex->height);
  /* a smaller synthesis lacks the coarsest bands */
  int nb = nl_byexample_band_count(syn->width, syn->height);
  if (nb > nbe) nb = nbe;
  if (nl_byexample_band_power(le, ex->width, ex->height, nbe, pe, err) ||
      nl_byexample_band_power(ls, syn->width, syn->height, nb, ps, err)) {   /* checked above */
    free(le);
    free(ls);
    return NL_EINVAL;
  }
  for (int k = 0; k < nbe; k++) total += pe[k];
  int checked = 0, worst_k = -1;
  for (int k = 0; k < nb; k++) {
    double share = total > 0 ? pe[k] / total : 0, ratio = pe[k] > 0 ? ps[k] / pe[k] : 0;
    int use = share >= min_share;
    if (use && (worst_k < 0 || fabs(log(ratio)) > fabs(log(worst)))) {
      worst = ratio;
      worst_k = k;
    }
    checked += use;
    /* band k: max(|f_x|, |f_y|) in (2^-(k+2), 2^-(k+1)] cycles per pixel */
    if (bands)
      nl_table_append(bands, "ssiiddddddi", name, rep, replicate, k, ldexp(1.0, -(k + 2)),
                      ldexp(1.0, -(k + 1)), pe[k], ps[k], ratio, share, use);
  }
  double ks = ks2(le, n, ls, m), per[3] = { 0 }, ks_rgb = ks;
  if (ex->channels >= 3 && syn->channels >= 3) ks_rgb = nl_study_ks_channels(ex, syn, per);
  double tp = nl_byexample_tail_mass(le, n, le, n, 2.5),
         tsy = nl_byexample_tail_mass(ls, m, le, n, 2.5);
  int pass = worst_k >= 0 && worst <= max_ratio && worst >= 1 / max_ratio && ks < max_ks;
  double *ge = nl_xmalloc(n * sizeof *ge), *gs = nl_xmalloc(m * sizeof *gs);
  size_t nge = grad_mag(le, ex->width, ex->height, ge),
         ngs = grad_mag(ls, syn->width, syn->height, gs);
  double ksg = nge && ngs ? ks2(ge, nge, gs, ngs) : NAN;
  nl_table_append(sum, "ssiiidddddiidid", name, rep, replicate, ex->width, ex->height, ks, ks_rgb,
                  tp, tsy, nl_byexample_speckle(ex, syn), checked, worst_k, worst, pass, ksg);
  free(ge);
  free(gs);
  free(le);
  free(ls);
  return NL_OK;
}
