/* Readings of the pool's "last N solutions" (Cheng sec. 3.5.2): successive
 * cold-tail states or states spaced by a stride, and the pool's effective
 * sample size (rules in nl_cheng_repro.h, "pool readings"). */
#include "cheng/nl_cheng_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

nl_cheng_pool *nl_cheng_pool_thin(const nl_cheng_pool *p, int per_run, int stride)
{
  size_t nl = p->nlow, n = 0, cap = p->n ? p->n : 1;
  nl_cheng_pool *t = nl_xcalloc(1, sizeof *t);
  *t = *p;
  t->low = nl_xmalloc(nl * sizeof *t->low);
  memcpy(t->low, p->low, nl * sizeof *t->low);
  t->theta = nl_xmalloc(cap * nl * sizeof *t->theta);
  t->e = nl_xmalloc(cap * sizeof *t->e);
  t->run = nl_xmalloc(cap * sizeof *t->run);
  size_t rs = (size_t)p->runs * sizeof(double);
  t->run_best = nl_xmalloc(rs); memcpy(t->run_best, p->run_best, rs);
  t->run_start = nl_xmalloc(rs); memcpy(t->run_start, p->run_start, rs);
  t->run_seconds = nl_xmalloc(rs); memcpy(t->run_seconds, p->run_seconds, rs);
  /* rows are grouped by run in run order (nl_cheng_pool_collect) */
  for (size_t i = 0, pos = 0; i < p->n; i++, pos++) {
    if (i > 0 && p->run[i] != p->run[i - 1]) pos = 0;
    if ((pos + 1) % (size_t)stride || (pos + 1) / (size_t)stride > (size_t)per_run) continue;
    memcpy(t->theta + n * nl, p->theta + i * nl, nl * sizeof *t->theta);
    t->e[n] = p->e[i];
    t->run[n++] = p->run[i];
  }
  t->n = n;
  return t;
}

void nl_cheng_pool_ess(const nl_cheng_pool *p, nl_cheng_pool_ess_result *out)
{
  size_t nl = p->nlow, maxlen = 0;
  size_t *start = nl_xmalloc(((size_t)p->runs + 1) * sizeof *start), nrun = 0;
  for (size_t i = 0; i < p->n; i++)
    if (i == 0 || p->run[i] != p->run[i - 1]) start[nrun++] = i;
  start[nrun] = p->n;
  for (size_t q = 0; q < nrun; q++) if (start[q + 1] - start[q] > maxlen) maxlen = start[q + 1] - start[q];
  double *g = nl_xcalloc(maxlen ? maxlen : 1, sizeof *g), *x = nl_xmalloc((maxlen ? maxlen : 1) * sizeof *x);
  double *gm = nl_xcalloc(2 * nl, sizeof *gm), *rm = nl_xmalloc((nrun ? nrun : 1) * 2 * nl * sizeof *rm);
  double within = 0, msd = 0, nmsd = 0;
  for (size_t q = 0; q < nrun; q++) {
    size_t a = start[q], m = start[q + 1] - a;
    for (size_t c = 0; c < 2 * nl; c++) {   /* cos, sin of each low angle, centred by the run's mean */
      double mean = 0;
      for (size_t t = 0; t < m; t++) { double th = p->theta[(a + t) * nl + c / 2]; x[t] = c % 2 ? sin(th) : cos(th); mean += x[t]; }
      mean /= (double)m;
      for (size_t t = 0; t + 1 < m; t++) { msd += (x[t + 1] - x[t]) * (x[t + 1] - x[t]); nmsd++; }
      for (size_t t = 0; t < m; t++) x[t] -= mean;
      rm[q * 2 * nl + c] = mean;
      gm[c] += mean * (double)m;
      for (size_t l = 0; l < m; l++)
        for (size_t t = 0; t + l < m; t++) g[l] += x[t] * x[t + l];
    }
  }
  within = g[0];   /* sum of squares about the run means */
  double between = 0;
  for (size_t c = 0; c < 2 * nl; c++) gm[c] /= (double)(p->n ? p->n : 1);
  for (size_t q = 0; q < nrun; q++)
    for (size_t c = 0; c < 2 * nl; c++) {
      double d = rm[q * 2 * nl + c] - gm[c];
      between += d * d * (double)(start[q + 1] - start[q]);
    }
  double s = 1;
  size_t l = 1;
  out->capped = 1;
  for (; l < maxlen && g[0] > 0; l++) {
    double rho = g[l] / g[0];
    if (rho < 0.05) { out->capped = 0; break; }
    s += 2 * rho;
  }
  if (l >= maxlen / 2) out->capped = 1;   /* window-limited: a lower bound */
  double n = (double)p->n, mbar = nrun ? n / (double)nrun : 1;
  out->tau = g[0] > 0 ? s : NAN;
  out->ess_tau = n / out->tau;
  out->icc = between + within > 0 ? between / (between + within) : NAN;
  out->ess_kish = n / (1 + (mbar - 1) * out->icc);
  out->var_total = n > 0 ? (between + within) / n / (double)(2 * nl) : NAN;   /* per coordinate */
  out->msd1 = nmsd > 0 ? msd / nmsd : NAN;
  out->dec = out->msd1 > 0 ? 2 * out->var_total / out->msd1 : NAN;
  free(start); free(g); free(x); free(gm); free(rm);
}
