/* wood.c - Q4's wood panels (Qin & Yang 2000 Fig. 6) over seeds:
 * the GCTBF through the wood shader of the literature (nl_texture_wood) and,
 * as the measured alternative, through a two-colour ramp. */
#include "wood.h"
#include "study/nl_study.h"

#include "cellular/nl_cellular.h"

#include <gsl/gsl_statistics_double.h>
#include <stdlib.h>

nl_table *q4_wood_table(void)
{
  const char *cols[] = {"panel",    "gctbf",          "value_sd",   "perturb_rings_sd",
                        "ring_sd",  "rings",          "rings_sd",   "rings_geometry",
                        "ramp_bands", "ramp_bands_sd"};
  return nl_table_alloc(10, cols);
}

nl_status q4_wood(nl_table *table, const char *panel, const char *expr, double k,
                  const nl_noise_window *win, const nl_texture_wood *wd,
                  const nl_texture_ramp *ramp, double lo, double hi, int vertical, int index,
                  unsigned long seed0, int K, nl_image **rings, nl_image **ramped, nl_error *err)
{
  q4_wood_result r, *res = &r;
  size_t n = (size_t)win->w * win->h;
  double *g = nl_xmalloc(n * sizeof *g);
  double *t = nl_xmalloc(n * sizeof *t);
  double *cr = nl_xcalloc((size_t)K, sizeof *cr);
  double *cb = nl_xcalloc((size_t)K, sizeof *cb);
  nl_status st = NL_OK;
  res->value_sd = res->ring_sd = 0;
  *rings = *ramped = NULL;
  for (int s = 0; s < K && !st; s++) {
    unsigned long seed = nl_seed_replicate(seed0, s);
    st = nl_cellular_texture_grid(NL_GCTBF_PLAIN, expr, 0, k, win, seed, g, err);
    if (st) break;
    nl_texture_wood_grid(wd, win, g, t);
    nl_image *a = nl_texture_wood_image(wd, t, win->w, win->h);
    nl_image *b = nl_texture_ramp_image(ramp, g, win->w, win->h, lo, hi);
    cr[s] = nl_texture_band_count(a, vertical, index);
    cb[s] = nl_texture_band_count(b, vertical, index);
    res->value_sd += gsl_stats_sd(g, 1, n) / K;
    res->ring_sd += gsl_stats_sd(t, 1, n) / K;
    if (s == 0) {
      *rings = a;
      *ramped = b;
    } else {
      nl_image_free(a);
      nl_image_free(b);
    }
  }
  if (!st) {
    nl_stats_mean_sd(cr, K, NL_STATS_SUMMED, &res->rings, &res->rings_sd);
    nl_stats_mean_sd(cb, K, NL_STATS_SUMMED, &res->ramp_bands, &res->ramp_bands_sd);
    nl_texture_wood_grid(wd, win, NULL, t); /* the rings without the basis: the geometry's count */
    nl_image *a = nl_texture_wood_image(wd, t, win->w, win->h);
    res->rings_geometry = nl_texture_band_count(a, vertical, index);
    nl_image_free(a);
    nl_table_append(table, "ssdddddddd", panel, expr, res->value_sd, wd->turb * res->value_sd,
                    res->ring_sd, res->rings, res->rings_sd, res->rings_geometry, res->ramp_bands,
                    res->ramp_bands_sd);
  } else {
    nl_image_free(*rings);
    nl_image_free(*ramped);
    *rings = *ramped = NULL;
  }
  free(g);
  free(t);
  free(cr);
  free(cb);
  return st;
}

nl_table *q4_rings_table(const nl_table *wood, int K)
{
  const char *cols[] = { "panel", "gctbf", "reading", "bands", "bands_sd", "seeds" };
  nl_table *t = nl_table_alloc(6, cols);
  for (size_t i = 0; i < wood->nrows; i++) {
    const char *p = nl_table_text(wood, i, "panel"), *g = nl_table_text(wood, i, "gctbf");
    nl_table_append(t, "sssddi", p, g, "ramp", nl_table_value(wood, i, "ramp_bands"),
                    nl_table_value(wood, i, "ramp_bands_sd"), K);
    nl_table_append(t, "sssddi", p, g, "wood shader", nl_table_value(wood, i, "rings"),
                    nl_table_value(wood, i, "rings_sd"), K);
    nl_table_append(t, "sssddi", p, g, "wood shader without the GCTBF",
                    nl_table_value(wood, i, "rings_geometry"), 0.0, K);
  }
  return t;
}
