#include "tables.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { NSIG = A3_NSIGNALS, MAXR = 32 };

nl_table *a3_psd(const a3_reading *rd, unsigned long seed, nl_error *err)
{
  const char *cols[] = { "freq",       "psd_oct1",   "psd_oct2", "psd_sum",
                         "gamma_oct1", "gamma_oct2", "gamma_sum" };
  nl_noise_perm3 p;
  nl_noise_perm3_seed(&p, seed);
  size_t n, m = 0;
  double *f = NULL, *P[NSIG] = { NULL }, *G[NSIG] = { NULL };
  nl_status rc = NL_OK;
  for (int s = 0; s < NSIG && !rc; s++) {
    double *x = a3_reading_sample(&p, s, rd, seed, &n);
    m = n / 2 + 1;
    f = f ? f : nl_xmalloc(m * sizeof *f);
    P[s] = nl_xmalloc(m * sizeof *P[s]);
    G[s] = nl_xmalloc(m * sizeof *G[s]);
    rc = nl_spectrum_psd1(x, n, rd->rate, f, P[s], err);
    if (!rc) nl_bounds_psd1_tail(P[s], m, G[s]);
    free(x);
  }
  nl_table *t = rc ? NULL : nl_table_alloc(7, cols);
  for (size_t k = 1; t && k < m && f[k] <= 8.0; k++)
    nl_table_append(t, "ddddddd", f[k], P[0][k], P[1][k], P[2][k], G[0][k], G[1][k], G[2][k]);
  for (int s = 0; s < NSIG; s++) {
    free(P[s]);
    free(G[s]);
  }
  free(f);
  return t;
}

nl_table *a3_ratio_table(const double m[A3_NSIGNALS][7], const double mc[A3_NSIGNALS][7],
                         const double paper[][2])
{
  const char *cols[] = { "reading", "paper", "ratio", "ratio_sd" };
  nl_table *t = nl_table_alloc(4, cols);
  const double(*v[2])[7] = { m, mc };
  const char *name[2] = { "headline", "shuffled control" };
  for (int k = 0; k < 2; k++) {
    double a = v[k][2][2], sa = v[k][2][3], b = v[k][1][2], sb = v[k][1][3], q = a / b;
    nl_table_append(t, "sddd", name[k], paper[2][1] / paper[1][1], q,
                    q * sqrt(sa * sa / (a * a) + sb * sb / (b * b)));
  }
  return t;
}

nl_table *a3_bandwidth_table(const a3_reading *rd, unsigned long seed0, int seeds,
                             const double paper[][2], const char *const *sig,
                             double m[A3_NSIGNALS][7], nl_error *err)
{
  if (a3_bandwidth_seeds(rd, seed0, seeds, m, err)) return NULL;
  const char *cols[] = { "signal",     "f_inf",      "f_inf_sd",    "f_sup",
                         "f_sup_sd",   "sigma",      "paper_f_inf", "paper_f_sup",
                         "f_inf_bins", "f_sup_bins", "f_inf_rms" };
  nl_table *t = nl_table_alloc(11, cols);
  double res = (rd->radians ? 2.0 * M_PI : 1.0) / rd->length;
  for (int s = 0; s < NSIG; s++)
    nl_table_append(t, "sdddddddddd", sig[s], m[s][0], m[s][1], m[s][2], m[s][3], m[s][4],
                    paper[s][0], paper[s][1], m[s][0] / res, m[s][2] / res, m[s][6]);
  return t;
}

nl_table *a3_hypotheses(const a3_reading *base, unsigned long seed0, int seeds,
                        const double paper[][2], const char *const *sig, nl_error *err)
{
  const char *cols[] = { "hypothesis", "signal",      "f_inf",       "f_inf_sd", "f_sup",
                         "f_sup_sd",   "paper_f_inf", "paper_f_sup", "within",   "within_inf",
                         "within_sup", "z_inf",       "z_sup",       "sigma",    "resolution" };
  a3_reading rd[MAXR];
  const char *name[MAXR];
  int nr = a3_readings(base, rd, name, MAXR);
  nl_table *t = nl_table_alloc(15, cols);
  for (int h = 0; h < nr; h++) {
    double m[NSIG][7];
    if (a3_bandwidth_seeds(&rd[h], seed0, seeds, m, err)) {
      nl_table_free(t);
      return NULL;
    }
    /* the resolution in the reading's unit: one bin, 1/length cycles per unit */
    double res = (rd[h].radians ? 2.0 * M_PI : 1.0) / rd[h].length;
    for (int s = 0; s < NSIG; s++) {
      double zi = (paper[s][0] - m[s][0]) / fmax(m[s][1], res / 4);
      double zs = (paper[s][1] - m[s][2]) / fmax(m[s][3], res / 4);
      int wi = fabs(zi) <= 2.0, ws = fabs(zs) <= 2.0;
      nl_table_append(t, "ssddddddiiidddd", name[h], sig[s], m[s][0], m[s][1], m[s][2], m[s][3],
                      paper[s][0], paper[s][1], wi && ws, wi, ws, zi, zs, m[s][4], res);
    }
  }
  return t;
}

int a3_summary(const nl_table *t, int max, double (*worst)[2], int *within)
{
  int h = -1;
  for (size_t r = 0; r < t->nrows; r++) {
    if (r % NSIG == 0) {
      if (++h >= max) return max;
      worst[h][0] = worst[h][1] = 0.0;
      within[h] = 0;
    }
    worst[h][0] = fmax(worst[h][0], fabs(nl_table_value(t, r, "z_sup")));
    worst[h][1] = fmax(worst[h][1], fabs(nl_table_value(t, r, "z_inf")));
    within[h] += (int)nl_table_value(t, r, "within_inf") + (int)nl_table_value(t, r, "within_sup");
  }
  return h + 1;
}

/* One row of the sensitivity table: mean F_inf, F_sup of each signal. */
static nl_status sweep_row(nl_table *t, const char *what, const a3_reading *rd, unsigned long seed0,
                           int seeds, nl_error *err)
{
  double m[NSIG][7];
  nl_status rc = a3_bandwidth_seeds(rd, seed0, seeds, m, err);
  if (!rc)
    nl_table_append(t, "sddiidddddd", what, rd->length, rd->rate, rd->shader, rd->axis, m[0][0],
                    m[0][2], m[1][0], m[1][2], m[2][0], m[2][2]);
  return rc;
}

nl_table *a3_sweep(const a3_reading *rd, int nvary, unsigned long seed0, int seeds, nl_error *err)
{
  const char *cols[] = { "vary",       "length",     "rate",       "shader",
                         "axis",       "oct1_f_inf", "oct1_f_sup", "oct2_f_inf",
                         "oct2_f_sup", "sum_f_inf",  "sum_f_sup" };
  const double lengths[] = { 64, 128, 256, 512, 1024, 2048 }, rates[] = { 4, 8, 16, 32, 64, 128 };
  nl_table *t = nl_table_alloc(11, cols);
  nl_status rc = NL_OK;
  nvary = nvary < 6 ? nvary : 6;
  for (int k = 0; k < 2 * nvary && !rc; k++) { /* the lengths, then the rates */
    a3_reading v = *rd;
    if (k < nvary)
      v.length = lengths[k];
    else
      v.rate = rates[k - nvary];
    rc = sweep_row(t, k < nvary ? "length" : "rate", &v, seed0, seeds, err);
  }
  a3_reading enc = *rd, line = *rd;
  enc.shader = !rd->shader;
  line.axis = !rd->axis;
  if (!rc) rc = sweep_row(t, "shader", &enc, seed0, seeds, err);
  if (!rc) rc = sweep_row(t, "axis", &line, seed0, seeds, err);
  if (rc) {
    nl_table_free(t);
    return NULL;
  }
  return t;
}

void a3_list(const nl_table *t, int s, const char *col, char *buf, size_t size)
{
  size_t used = 0;
  buf[0] = '\0';
  for (size_t r = (size_t)s; r < t->nrows && used < size; r += NSIG) {
    int w = snprintf(buf + used, size - used, "%s%s %.4f", used ? ", " : "",
                     nl_table_text(t, r, "hypothesis"), nl_table_value(t, r, col));
    if (w < 0) break;
    used += (size_t)w;
  }
}

void a3_range(const nl_table *sw, double min_length, const char *col, double *lo, double *hi)
{
  *lo = INFINITY;
  *hi = -INFINITY;
  for (size_t k = 0; k < sw->nrows; k++) {
    const char *what = nl_table_text(sw, k, "vary");
    if ((strcmp(what, "length") && strcmp(what, "rate")) ||
        nl_table_value(sw, k, "length") < min_length)
      continue;
    *lo = fmin(*lo, nl_table_value(sw, k, col));
    *hi = fmax(*hi, nl_table_value(sw, k, col));
  }
}
