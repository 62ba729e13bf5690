/* joint.c - A2's joint fit of slope, frequency and extinction (joint.h). */
#include "joint.h"

#include <math.h>
#include <stdlib.h>

a2_joint_grid a2_joint_grid_default(int quick)
{
  a2_joint_grid q = { 2, 1, 2, { -4, -6 }, { 2 }, { 60, 240 } };
  a2_joint_grid g = {
    9, 4, 11, { -3, -4, -4.5, -5, -5.25, -5.5, -6, -7, -8 }, { 1, 2, 4, 8 }, { 0 }
  };
  for (int k = 0; k < g.nk; k++) g.kappa[k] = 15.0 * ldexp(1.0, k);
  return quick ? q : g;
}

/* 1 when x is the first or last of v[0..n-1] and n >= 3 (a number, not a
 * two-way choice: the optimum may lie beyond). */
static int at_edge(double x, const double *v, int n)
{
  return n >= 3 && (x == v[0] || x == v[n - 1]);
}

a2_smoke_scene a2_joint_fit(nl_harness *r, const a2_smoke_scene *center, const a2_joint_grid *g,
                            const int *octaves, const double *paper, int n, int seeds,
                            nl_table **out)
{
  const char *cols[] = { "slope",        "freq",          "kappa",  "rss_log", "rms_factor",
                         "worst_factor", "worst_octaves", "growth", "best",    "edge" };
  nl_table *t = nl_table_alloc(10, cols);
  a2_smoke_point *pt = nl_xmalloc((size_t)n * sizeof *pt);
  double *er = nl_xmalloc((size_t)n * sizeof *er), best_rss = INFINITY;
  a2_smoke_scene best = *center;
  size_t best_row = 0;
  for (int a = 0; a < g->ns; a++)
    for (int f = 0; f < g->nf; f++)
      for (int k = 0; k < g->nk; k++) {
        a2_smoke_scene sc = *center;
        sc.offset = 1;
        sc.s.slope = g->slope[a];
        sc.s.freq = g->freq[f];
        sc.s.kappa = g->kappa[k];
        nl_harness_substage(r, (a * g->nf + f) * g->nk + k, g->ns * g->nf * g->nk);
        a2_smoke_curve(r, &sc, octaves, n, seeds, 0, pt, NULL);
        for (int i = 0; i < n; i++) er[i] = pt[i].eval_ratio;
        double rms;
        int worst = 0;
        double rss = a2_smoke_fit(er, paper, n, &rms, &worst);
        nl_table_append(t, "dddddddddi", sc.s.slope, sc.s.freq, sc.s.kappa, rss, rms,
                        exp(fabs(log(er[worst]) - log(paper[worst]))), (double)octaves[worst],
                        er[n - 1] / er[2], 0.0, 0);
        if (rss < best_rss) {
          best_rss = rss;
          best = sc;
          best_row = t->nrows - 1;
        }
      }
  nl_table_set(t, best_row, "best", 1.0);
  int edge = at_edge(best.s.slope, g->slope, g->ns) || at_edge(best.s.freq, g->freq, g->nf) ||
             at_edge(best.s.kappa, g->kappa, g->nk);
  nl_table_set(t, best_row, "edge", (double)edge);
  free(pt);
  free(er);
  *out = t;
  return best;
}

nl_table *a2_joint_growth(const a2_smoke_point *pt, const double *paper, int n,
                          const nl_table *joint)
{
  const char *cols[] = { "quantity", "paper_growth", "growth",  "growth_sd",
                         "grid_min", "grid_max",     "readings" };
  nl_table *t = nl_table_alloc(7, cols);
  double g = pt[n - 1].eval_ratio / pt[2].eval_ratio;
  double a = pt[n - 1].eval_ratio_sd / pt[n - 1].eval_ratio;
  double b = pt[2].eval_ratio_sd / pt[2].eval_ratio;
  double lo = INFINITY, hi = -INFINITY;
  for (size_t k = 0; k < joint->nrows; k++) {
    lo = fmin(lo, nl_table_value(joint, k, "growth"));
    hi = fmax(hi, nl_table_value(joint, k, "growth"));
  }
  nl_table_append(t, "sdddddi", "plain/bounded ratio at the largest N over the third",
                  paper[n - 1] / paper[2], g, g * sqrt(a * a + b * b), lo, hi, (int)joint->nrows);
  return t;
}
