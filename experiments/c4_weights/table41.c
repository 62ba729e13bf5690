/* C4's analysis of Cheng 2009 Table 4.1 (sec. 4.3.2): ours beside the
 * thesis's, which reading of the table's weight columns fits all six rows, and
 * which control grid puts E_Con on the thesis's scale. */
#include "c4.h"
#include "study/nl_study_cheng.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

nl_table *c4_table41(const nl_table *runs, const c4_thesis_row *thesis, int npair)
{
  const char *cc[] = { "panel",         "w1",          "w2",          "paper_E_ks", "E_ks",
                       "E_ks_sd",       "paper_E_con", "E_con",       "E_con_sd",   "E_ks_swapped",
                       "E_con_swapped", "p_ks_min",    "p_kuiper_min" };
  nl_table *cmp = nl_table_alloc(sizeof cc / sizeof *cc, cc);
  for (int i = 0; i < npair; i++) {
    size_t p = 2 * (size_t)i, s = p + 1; /* printed, swapped */
    char panel[4] = { (char)('a' + i), 0 };
    nl_table_append(cmp, "sdddddddddddd", panel, thesis[i][0], thesis[i][2], thesis[i][1],
                    nl_table_value(runs, p, "E_ks"), nl_table_value(runs, p, "E_ks_sd"),
                    thesis[i][3], nl_table_value(runs, p, "E_con"),
                    nl_table_value(runs, p, "E_con_sd"), nl_table_value(runs, s, "E_ks"),
                    nl_table_value(runs, s, "E_con"), nl_table_value(runs, p, "p_ks_min"),
                    nl_table_value(runs, p, "p_kuiper_min"));
  }
  return cmp;
}

static double pearson(const double *x, const double *y, int n)
{
  double mx = 0, my = 0, sxy = 0, sxx = 0, syy = 0;
  for (int i = 0; i < n; i++) {
    mx += x[i];
    my += y[i];
  }
  mx /= n;
  my /= n;
  for (int i = 0; i < n; i++) {
    sxy += (x[i] - mx) * (y[i] - my);
    sxx += (x[i] - mx) * (x[i] - mx);
    syy += (y[i] - my) * (y[i] - my);
  }
  return sxx > 0 && syy > 0 ? sxy / sqrt(sxx * syy) : 0;
}

/* Exact one-sided permutation p of Pearson's r: the fraction of the n!
 * orderings of y whose r is >= the observed one (n <= 8: at most 40320). */
static double perm_p(const double *x, const double *y, int n, double r_obs)
{
  int idx[8], c[8] = { 0 }, i = 1;
  double yp[8];
  long hit = 0, total = 0;
  for (int k = 0; k < n; k++) idx[k] = k;
  for (;;) { /* Heap's algorithm over idx */
    for (int k = 0; k < n; k++) yp[k] = y[idx[k]];
    total++;
    hit += pearson(x, yp, n) >= r_obs - 1e-12;
    while (i < n && c[i] >= i) c[i++] = 0;
    if (i >= n) break;
    int j = i % 2 ? c[i] : 0, t = idx[j];
    idx[j] = idx[i];
    idx[i] = t;
    c[i]++;
    i = 1;
  }
  return (double)hit / (double)total;
}

/* One reading's fit on a log scale: x = thesis, y = ours; r, its permutation
 * p, and the rms of the centred log ratio (0 = ours is the thesis's up to one
 * constant factor). */
static void fit(const double *th, const double *ours, int n, double *r, double *p, double *rms)
{
  double lx[8] = { 0 }, ly[8] = { 0 }, m = 0, q = 0;
  for (int i = 0; i < n; i++) {
    lx[i] = log(th[i]);
    ly[i] = log(ours[i]);
    m += ly[i] - lx[i];
  }
  m /= n;
  for (int i = 0; i < n; i++) q += (ly[i] - lx[i] - m) * (ly[i] - lx[i] - m);
  *r = pearson(lx, ly, n);
  *p = perm_p(lx, ly, n, *r);
  *rms = sqrt(q / n);
}

nl_table *c4_readings(const nl_table *cmp, const c4_thesis_row *thesis, int npair)
{
  const char *cc[] = { "reading",    "r_log_ks",    "p_perm_ks", "rms_log_ks",  "r_log_con",
                       "p_perm_con", "rms_log_con", "E_ks_a",    "paper_E_ks_a" };
  /* mixed_a_printed: (a) as printed, (b)-(f) swapped */
  const char *names[3] = { "printed", "swapped", "mixed_a_printed" };
  nl_table *t = nl_table_alloc(sizeof cc / sizeof *cc, cc);
  double tks[8], tcon[8], ks[8], con[8];
  for (int i = 0; i < npair && i < 8; i++) {
    tks[i] = thesis[i][1];
    tcon[i] = thesis[i][3];
  }
  for (int rd = 0; rd < 3; rd++) {
    for (int i = 0; i < npair && i < 8; i++) {
      int sw = rd == 1 || (rd == 2 && i > 0);
      ks[i] = nl_table_value(cmp, (size_t)i, sw ? "E_ks_swapped" : "E_ks");
      con[i] = nl_table_value(cmp, (size_t)i, sw ? "E_con_swapped" : "E_con");
    }
    double r1, p1, s1, r2, p2, s2;
    fit(tks, ks, npair, &r1, &p1, &s1);
    fit(tcon, con, npair, &r2, &p2, &s2);
    nl_table_append(t, "sdddddddd", names[rd], r1, p1, s1, r2, p2, s2, ks[0], tks[0]);
  }
  return t;
}

nl_table *c4_grid_sweep(const nl_study_cheng *s, const nl_cheng_config *c, const char *pattern,
                        int gmin, int gmax, double paper_e_con)
{
  const char *cc[] = { "grid",     "points",          "E_ks",        "E_ks_sd",   "E_con",
                       "E_con_sd", "E_con_per_point", "paper_E_con", "r_pattern", "con_vs_const" };
  nl_table *t = nl_table_alloc(sizeof cc / sizeof *cc, cc);
  const char *labels[] = { "grid" };
  nl_table *sum = nl_study_cheng_summary_alloc(1, labels);
  /* The grids' runs as one set of seed runs on the run's threads
   * (nl_study_cheng_runs), rows in grid order. */
  int n = 0, k = nl_harness_seeds(s->r);
  for (int grid = gmin; grid <= gmax; grid *= 2) n++;
  nl_cheng_config *cs = nl_xmalloc((size_t)n * sizeof *cs);
  nl_cheng_pattern **pats = nl_xmalloc((size_t)n * sizeof *pats);
  nl_study_cheng g = *s;
  for (int i = 0, grid = gmin; i < n; i++, grid *= 2) {
    g.grid = grid;
    cs[i] = *c;
    pats[i] = nl_study_cheng_pattern(&g, pattern);
  }
  nl_cheng_eval *evs = nl_study_cheng_runs(s, n, cs, (const nl_cheng_pattern *const *)pats, NULL);
  for (int i = 0, grid = gmin; i < n; i++, grid *= 2) {
    char lab[16];
    snprintf(lab, sizeof lab, "%d", grid);
    const char *l[1] = { lab };
    nl_study_cheng_rows_add(s, sum, 1, l, evs + (size_t)i * k);
    size_t q = sum->nrows - 1;
    double e = nl_table_value(sum, q, "E_con");
    nl_table_append(t, "dddddddddd", (double)grid, (double)pats[i]->n,
                    nl_table_value(sum, q, "E_ks"), nl_table_value(sum, q, "E_ks_sd"), e,
                    nl_table_value(sum, q, "E_con_sd"), e / (double)pats[i]->n, paper_e_con,
                    nl_table_value(sum, q, "r_pattern"), nl_table_value(sum, q, "con_vs_const"));
    nl_cheng_pattern_free(pats[i]);
  }
  nl_harness_progress(s->r, 1.0, "grid sweep");
  free(evs);
  free(cs);
  free(pats);
  nl_table_free(sum);
  return t;
}

size_t c4_grid_best(const nl_table *gs, double paper_e_con)
{
  size_t best = 0;
  for (size_t q = 1; q < gs->nrows; q++) {
    double d = fabs(log(nl_table_value(gs, q, "E_con") / paper_e_con));
    if (d < fabs(log(nl_table_value(gs, best, "E_con") / paper_e_con))) best = q;
  }
  return best;
}
