/* textures.c - Q4's textures over the seeds: one row of textures.tsv and
 * the first seed's image each. See q4.h. */
#include "q4.h"
#include "cellular/nl_cellular.h"
#include "study/nl_study.h"

#include <gsl/gsl_statistics_double.h>
#include <stdlib.h>

nl_image *q4_texture(q4 *q, int kind, const char *label, const char *expr,
                     const nl_texture_ramp *ramp, double lo, double hi)
{
  size_t n = (size_t)q->size * q->size;
  double *v = nl_xmalloc(n * sizeof *v);
  double mean = 0;
  double sd = 0;
  nl_image *im = NULL;
  for (int s = 0; s < q->seeds; s++) {
    unsigned long seed = nl_seed_replicate(nl_harness_seed(q->r), s);
    nl_error err;
    /* Perlin's octaves (expr NULL) off the lattice planes: NL_STUDY_SLICE_Z */
    nl_noise_window w = q->win;
    if (!expr) w.z = NL_STUDY_SLICE_Z;
    if (nl_cellular_texture_grid((nl_cellular_gctbf_texture)kind, expr, q->octaves, q->k, &w, seed,
                                 v, &err))
      nl_harness_die(q->r, 1, "%s", err.msg);
    mean += gsl_stats_mean(v, 1, n) / q->seeds;
    sd += gsl_stats_sd(v, 1, n) / q->seeds;
    if (s > 0) continue;
    if (ramp)
      im = nl_texture_ramp_image(ramp, v, q->size, q->size, lo, hi);
    else
      im = nl_texture_cloud_colour(v, q->size, q->size);
  }
  const char *method = kind == NL_GCTBF_CLOUD   ? "eq. 7 cloud"
                       : kind == NL_GCTBF_FLAME ? "fractal + spline"
                                       : "spline / ramp";
  nl_table_append(q->t, "sssdd", label, method, expr ? expr : "Perlin", mean, sd);
  free(v);
  return im;
}
