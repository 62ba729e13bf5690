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
#include "l3.h"
#include "photos.h"
#include "study/nl_study.h"
#include "synthesis.h"
#include "verdicts.h"

#include <stdlib.h>

enum { NKIND = 4, NVAR = L3_NVAR };
static const char *kinds[NKIND] = {"wavelet", "clouds", "granite", "marble"};

int main(int argc, char **argv)
{
  const char *exdir;
  nl_error err;
  if (l3_photos_dir_parse(&argc, argv, &exdir, &err)) {
    fprintf(stderr, "l3_synthesis: %s\n", err.msg);
    return 2;
  }
  nl_harness *r = nl_harness_begin(
      "l3_synthesis", "L3 - Texture synthesis by example: PCA colour and histogram matching", argc,
      argv);
  int quick = nl_harness_quick(r);
  int size = (int)nl_harness_param_fft_size(r, "size", quick ? 128 : 512, 16, 4096,
                                       "side in pixels of the exemplar analysed and of the "
                                       "synthesised textures (quick 128)");
  int nphoto = (int)nl_harness_param_int(r, "photos", quick ? 2 : 16, 1, 16,
                                         "photographs of --exemplars DIR used, in name order "
                                         "(quick 2)");
  int psize = (int)nl_harness_param_fft_size(r, "photo_size", quick ? 128 : 512, 16, 4096,
                                        "side of the syntheses of photographs (quick 128)");
  double min_share = nl_harness_param(r, "min_share", 0.02, 0, 1,
                                      "bands holding at least this share of the photo's power "
                                      "are checked");
  double max_ratio = nl_harness_param(r, "max_ratio", 1.3, 1, 100,
                                      "a checked band's synthesis/photo power ratio must lie in "
                                      "[1/max_ratio, max_ratio]");
  double max_ks = nl_harness_param(r, "max_ks", 0.03, 0, 1,
                                   "the KS distance of the luminance must be below this");
  nl_harness_params_done(r);
  nl_harness_note(r, "exemplars", "%s", exdir); /* the photographs' folder, for a figure's reader */
  int K = nl_harness_seeds(r);
  unsigned long seed0 = nl_harness_seed(r);
  char names[16][64];
  nl_image *photos[16];
  int np = l3_photos_load(exdir, names, photos, nphoto, &err); /* before any output */
  if (np <= 0) nl_harness_die(r, 2, "%s", err.msg);

  const char *kcols[] = {"kind", "variant", "ks_mean",  "ks_sd",      "ks_r", "ks_g",
                         "ks_b", "corr_err", "params", "corr_err_sd", "seeds"};
  nl_table *kt = nl_table_alloc(11, kcols);
  const char *scols[] = {"kind", "max_abs_diff_fc_vs_steffen"};
  nl_table *ft = nl_table_alloc(2, scols);

  /* One progress bar: the synthetic exemplars, then the photographs. */
  nl_harness_stage(r, 0.0, 0.5, "exemplars");
  for (int k = 0; k < NKIND; k++) {
    unsigned long xseed = nl_seed_stream(seed0, "l3.exemplar", (unsigned long)k);
    nl_image *ex = nl_byexample_exemplar(kinds[k], size, xseed);
    nl_image *first[NVAR];
    for (int v = 0; v < NVAR; v++) {
      first[v] = l3_variant(r, kt, kinds[k], v, ex, size);
      nl_harness_progress(r, (k * NVAR + v + 1.0) / (NKIND * NVAR), kinds[k]);
    }
    /* steffen vs Fritsch-Carlson on the same noise (seed0): pixel difference. */
    nl_table_append(ft, "sd", kinds[k], l3_max_abs_diff(first[0], first[3]));
    char name[64];
    snprintf(name, sizeof name, "spectrum_%s.tsv", kinds[k]);
    l3_write_spectra(r, name, ex, first[0], first[1]);

    const nl_image *panels[6] = {ex, first[0], first[1], first[2], first[3], first[4]};
    const char *labels[6] = {"(a) exemplar", "(b) paper", "(c) no hist.",
                             "(d) RGB",      "(e) FC",    "(f) gauss33"};
    char title[96];
    snprintf(title, sizeof title, "%s exemplar, %d x %d, seed %lu", kinds[k], size, size, seed0);
    snprintf(name, sizeof name, "synthesis_%s.png", kinds[k]);
    nl_study_montage(r, panels, labels, 6, 6, title, name);
    for (int v = 0; v < NVAR; v++) nl_image_free(first[v]);
    nl_image_free(ex);
    /* Fig. 5's control: the exemplar with each channel from another seed,
     * so that its channels are independent and RGB synthesis loses no
     * correlation; PCA and RGB syntheses of it. */
    nl_image *ix = NULL;
    for (int c = 0; c < 3; c++) {
      nl_image *e = nl_byexample_exemplar(kinds[k], size, nl_seed_stream(xseed, "l3.channel", c));
      if (!ix) ix = nl_image_alloc(e->width, e->height, 3);
      for (size_t q = 0; q < (size_t)e->width * e->height; q++)
        ix->data[3 * q + c] = e->data[q * e->channels + (e->channels == 3 ? c : 0)];
      nl_image_free(e);
    }
    snprintf(name, sizeof name, "%s, channels independent", kinds[k]);
    for (int v = 0; v <= 2; v += 2) /* pca_hist, rgb_hist */
      nl_image_free(l3_variant(r, kt, name, v, ix, size));
    nl_image_free(ix);
  }
  nl_harness_write_table(r, kt, "ks.tsv");
  nl_harness_write_table(r, ft, "spline.tsv");
  nl_table *gt = l3_gauss_table((size_t)size * size, K, seed0, nl_harness_threads(r));
  nl_harness_write_table(r, gt, "gauss.tsv");
  nl_harness_stage(r, 0.5, 1.0, "photographs");
  nl_table *pt = l3_photos(r, names, photos, np, psize, K, seed0, min_share, max_ratio, max_ks);
  nl_table *ct = l3_verdicts(r, pt, psize, photos, names, np, min_share, max_ratio, max_ks);
  l3_figure_verdicts(r, kt, kinds, NKIND);

  l3_report_exemplars(r, kt, ft, kinds, NKIND, size, K);
  l3_report_photos(r, kt, gt, pt, ct, K, psize, seed0, min_share, max_ratio, max_ks);
  nl_table_free(ct);
  for (int i = 0; i < np; i++) nl_image_free(photos[i]);
  nl_table_free(gt);
  nl_table_free(pt);
  nl_table_free(kt);
  nl_table_free(ft);
  nl_harness_check_measured(r, "*", 100); /* measured tolerances (nl_harness.h) */
  return nl_harness_end(r);
}
