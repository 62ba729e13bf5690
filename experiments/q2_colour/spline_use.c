/* spline_use.c - Q2: how much of eq. 4's spline a pattern uses. */
#include "q2.h"

#include <gsl/gsl_statistics_double.h>
#include <math.h>
#include <string.h>
#include <stdlib.h>

void q2_spline_use(const double *v, size_t n, int spans, double *clamped, double *entropy)
{
  double *h = calloc((size_t)spans, sizeof *h);
  size_t out = 0;
  for (size_t q = 0; q < n; q++) {
    double t = v[q];
    if (t < 0 || t > 1) out++;
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    int s = (int)(t * spans);
    h[s < spans ? s : spans - 1] += 1;
  }
  double e = 0;
  for (int s = 0; s < spans; s++)
    if (h[s] > 0) e -= h[s] / n * log2(h[s] / n);
  free(h);
  *clamped = (double)out / n;
  *entropy = e;
}

int q2_linear(const char *pattern)
{
  if (!strncmp(pattern, "Perlin", 6)) return -1;
  for (const char *c = pattern; *c; c++)
    if (c[0] == 'F' && c[1] >= '1' && c[1] <= '9' && c[2] == 'F') return 0;
  return 1;
}

nl_table *q2_group_table(const nl_table *use, const double *ent, const double *clp, int seeds)
{
  const char *cols[] = { "pattern",    "group",      "clamped", "clamped_sd",
                         "entropy", "entropy_sd", "seeds" };
  nl_table *t = nl_table_alloc(7, cols);
  double *c = nl_xmalloc((size_t)seeds * sizeof *c), *e = nl_xmalloc((size_t)seeds * sizeof *e);
  for (size_t i = 0; i + (size_t)seeds <= use->nrows; i += (size_t)seeds) {
    for (int k = 0; k < seeds; k++) {
      c[k] = nl_table_value(use, i + k, "clamped");
      e[k] = nl_table_value(use, i + k, "entropy");
    }
    nl_table_append(t, "ssddddi", nl_table_text(use, i, "pattern"), "pattern",
                    gsl_stats_mean(c, 1, seeds), seeds > 1 ? gsl_stats_sd(c, 1, seeds) : 0,
                    gsl_stats_mean(e, 1, seeds), seeds > 1 ? gsl_stats_sd(e, 1, seeds) : 0, seeds);
  }
  const char *names[3] = { "linear", "non-linear", "linear, other seeds" };
  nl_table *g = nl_table_alloc(7, cols);
  for (int j = 0; j < 3; j++) {
    const double *x = ent + (size_t)j * seeds, *y = clp + (size_t)j * seeds;
    nl_table_append(g, "ssddddi", names[j], "mean", gsl_stats_mean(y, 1, seeds),
                    seeds > 1 ? gsl_stats_sd(y, 1, seeds) : 0, gsl_stats_mean(x, 1, seeds),
                    seeds > 1 ? gsl_stats_sd(x, 1, seeds) : 0, seeds);
  }
  for (size_t i = 0; i < t->nrows; i++)
    nl_table_append(g, "ssddddi", nl_table_text(t, i, "pattern"), "pattern",
                    nl_table_value(t, i, "clamped"), nl_table_value(t, i, "clamped_sd"),
                    nl_table_value(t, i, "entropy"), nl_table_value(t, i, "entropy_sd"), seeds);
  nl_table_free(t);
  free(c);
  free(e);
  return g;
}
