/* L2's exemplar photographs (photos.h): the --exemplars option and every
 * photograph's fit by every estimator. */
#include "spectrum/nl_spectrum.h"
#include "photos.h"
#include "byexample/nl_byexample_leak.h"
#include "base/nl_parallel.h"
#include "study/nl_study_exemplars.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The luminance (nl_byexample_luminance) of the image at path, cropped about
 * its centre to at most max x max pixels: *w x *h doubles, caller frees. */
static nl_status exemplar_luminance(const char *path, int max, double **out, int *w, int *h,
                                    nl_error *err)
{
  nl_image *im;
  nl_status s = nl_image_read(path, &im, err);
  if (s) return s;
  int W = im->width, H = im->height;
  double *lum = nl_xmalloc((size_t)W * H * sizeof *lum);
  nl_byexample_luminance(im, lum);
  nl_image_free(im);
  *w = W < max ? W : max;
  *h = H < max ? H : max;
  int x0 = (W - *w) / 2, y0 = (H - *h) / 2;
  *out = nl_xmalloc((size_t)*w * *h * sizeof **out);
  for (int y = 0; y < *h; y++)
    memcpy(*out + (size_t)y * *w, lum + (size_t)(y + y0) * W + x0, (size_t)*w * sizeof **out);
  free(lum);
  return NL_OK;
}

char **l2_exemplars_option(int *argc, char **argv, const char *prog, const char **dir, int *n)
{
  nl_error err;
  char **paths = NULL;
  if (nl_study_dir_option(argc, argv, "--exemplars", "data/exemplars", dir, &err) ||
      nl_study_pngs(*dir, &paths, n, &err)) {
    fprintf(stderr, "%s: %s\n", prog, err.msg);
    nl_study_paths_free(paths);
    exit(2);
  }
  return paths;
}

/* Photograph i of l2_exemplar_fits: its fit from its own streams
 * (seeded by i), written to its own slots only. */
typedef struct {
  double **lum;
  int *w, *h, *nb, tile, nseeds, nsyn;
  double frac;
  unsigned long seed;
  double (*res)[NL_BYEXAMPLE_ESTIMATORS][2];
} fits_job;

static void fit_item(void *ctx, size_t i, int thread)
{
  (void)thread;
  fits_job *j = ctx;
  j->nb[i] =
      nl_byexample_fit_all(j->lum[i], j->w[i], j->h[i], j->tile, j->frac, j->nseeds,
                           nl_seed_stream(j->seed, "l2.photo_transfer", (unsigned long)i), j->nsyn,
                           nl_seed_stream(j->seed, "l2.photo", (unsigned long)i), j->res[i]);
}

nl_table *l2_exemplar_fits(nl_harness *r, char *const *paths, int n, int max, int tile, double frac,
                           int nseeds, int nsyn, unsigned long seed)
{
  static const char *const cols[] = { "exemplar",  "width",     "height",     "bands",
                                      "estimator", "resid_raw", "resid_taper" };
  nl_table *t = nl_table_alloc(7, cols);
  size_t m = n > 0 ? (size_t)n : 1;
  fits_job j = { nl_xmalloc(m * sizeof *j.lum),
                 nl_xmalloc(m * sizeof(int)),
                 nl_xmalloc(m * sizeof(int)),
                 nl_xmalloc(m * sizeof(int)),
                 tile,
                 nseeds,
                 nsyn,
                 frac,
                 seed,
                 nl_xmalloc(m * sizeof *j.res) };
  for (int i = 0; i < n; i++) { /* read on this thread, in order: errors exit before any fit */
    nl_error err;
    if (exemplar_luminance(paths[i], max, &j.lum[i], &j.w[i], &j.h[i], &err))
      nl_harness_die(r, 2, "%s", err.msg);
    if (j.w[i] < NL_BYEXAMPLE_MIN_SIZE || j.h[i] < NL_BYEXAMPLE_MIN_SIZE)
      nl_harness_die(r, 2, "%s: %d x %d pixels, smaller than %d", paths[i], j.w[i], j.h[i],
                     NL_BYEXAMPLE_MIN_SIZE);
  }
  /* nl_byexample_sigma2 keeps its value in plain statics: filled before the threads start, so no
   * item writes them. */
  nl_byexample_sigma2(tile);
  nl_parallel_for((size_t)n, nl_harness_threads(r), fit_item, &j);
  for (int i = 0; i < n; i++) {
    const char *name = strrchr(paths[i], '/');
    if (j.nb[i] < 0) {   /* nl_byexample_fit_all: a size no transform is allowed */
      nl_error err;
      nl_spectrum_check_size(j.w[i], j.h[i], &err);
      nl_harness_die(r, 1, "%s: %s", paths[i], err.msg);
    }
    for (int q = 0; q < NL_BYEXAMPLE_ESTIMATORS; q++)
      nl_table_append(t, "siiisdd", name ? name + 1 : paths[i], j.w[i], j.h[i], j.nb[i],
                      nl_byexample_estimator_names[q], j.res[i][q][0], j.res[i][q][1]);
    free(j.lum[i]);
  }
  free(j.lum);
  free(j.w);
  free(j.h);
  free(j.nb);
  free(j.res);
  return t;
}
