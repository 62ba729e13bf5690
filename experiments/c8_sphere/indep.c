/* C8's independence test of z and phi on a grid of cells (indep.h). */
#include "indep.h"
#include "stats/nl_stats.h"

#include <gsl/gsl_cdf.h>
#include <math.h>
#include <stdlib.h>

static int bin_of(double u, int bins) /* u in [0, 1] */
{
  int b = (int)floor(u * bins);
  return b < 0 ? 0 : b >= bins ? bins - 1 : b;
}

void c8_indep_pairs(const double *z, const double *phi, size_t m, int bins, c8_indep *out)
{
  double *o = nl_xcalloc((size_t)bins * (size_t)bins + 2 * (size_t)bins, sizeof *o);
  double *row = o + (size_t)bins * bins, *col = row + bins;
  for (size_t k = 0; k < m; k++) {
    int i = bin_of((z[k] + 1) / 2, bins), j = bin_of(phi[k] / NL_TWO_PI, bins);
    o[i * bins + j] += 1;
    row[i] += 1;
    col[j] += 1;
  }
  double n = (double)m, ci = 0, cj = 0, e0 = n / ((double)bins * bins);
  int rows = 0, cols = 0;
  for (int i = 0; i < bins; i++) {
    rows += row[i] > 0;
    cols += col[i] > 0;
  }
  for (int i = 0; i < bins; i++)
    for (int j = 0; j < bins; j++) {
      double x = o[i * bins + j], e = row[i] * col[j] / n;
      if (e > 0) ci += (x - e) * (x - e) / e;
      cj += (x - e0) * (x - e0) / e0;
    }
  out->chi2_indep = ci;
  out->df_indep = (rows - 1) * (cols - 1);
  out->p_indep = out->df_indep > 0 ? gsl_cdf_chisq_Q(ci, out->df_indep) : 1;
  out->chi2_joint = cj;
  out->df_joint = bins * bins - 1;
  out->p_joint = gsl_cdf_chisq_Q(cj, out->df_joint);
  free(o);
}

void c8_indep_test(const nl_cheng3_table *t, int bins, c8_indep *out)
{
  c8_indep_pairs(t->z, t->phi, t->m, bins, out);
}

void c8_indep_paired(const double *z, const double *phi, size_t m, int bins, c8_indep *out)
{
  double *zs = nl_xmalloc(2 * m * sizeof *zs), *ps = zs + m;
  for (size_t k = 0; k < m; k++) {
    zs[k] = z[k];
    ps[k] = phi[k];
  }
  nl_stats_sort(zs, m);
  nl_stats_sort(ps, m);
  c8_indep_pairs(zs, ps, m, bins, out);
  free(zs);
}
