/* C4's analysis (Cheng 2009 Table 4.1, sec. 4.3.2): which reading of the
 * table's weight columns fits all six rows, and which control grid puts E_Con
 * on the thesis's scale. */
#include "weights.h"
#include "study/nl_study_cheng.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static double pearson(const double *x, const double *y, int n)
{
  double mx = 0, my = 0, sxy = 0, sxx = 0, syy = 0;
  for (int i = 0; i < n; i++) { mx += x[i]; my += y[i]; }
  mx /= n; my /= n;
  for (int i = 0; i < n; i++) {
    sxy += (x[i] - mx) * (y[i] - my); sxx += (x[i] - mx) * (x[i] - mx); syy += (y[i] - my) * (y[i] - my);
  }
  return sxx > 0 && syy > 0 ? sxy / sqrt(sxx * syy) : 0;
}

/* Exact one-sided permutation p of Pearson's r: the fraction of the n!
 * orderings of y whose r is >= the observed one (n <= 8: at most 40320). */
static double perm_p(const double *x, const double *y, int n, double r_obs)
{
  int idx[8], c[8] = {0}, i = 1;
  double yp[8];
  long hit = 0, total = 0;
  for (int k = 0; k < n; k++) idx[k] = k;
  for (;;) {   /* Heap's algorithm over idx */
    for (int k = 0; k < n; k++) yp[k] = y[idx[k]];
    total++;
    hit += pearson(x, yp, n) >= r_obs - 1e-12;
    while (i < n && c[i] >= i) c[i++] = 0;
    if (i >= n) break;
    int j = i % 2 ? c[i] : 0, t = idx[j];
    idx[j] = idx[i]; idx[i] = t;
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
  double lx[8] = {0}, ly[8] = {0}, m = 0, q = 0;
  for (int i = 0; i < n; i++) { lx[i] = log(th[i]); ly[i] = log(ours[i]); m += ly[i] - lx[i]; }
  m /= n;
  for (int i = 0; i < n; i++) q += (ly[i] - lx[i] - m) * (ly[i] - lx[i] - m);
  *r = pearson(lx, ly, n);
  *p = perm_p(lx, ly, n, *r);
  *rms = sqrt(q / n);
}

nl_table *nl_study_cheng_table41_readings(const nl_table *cmp, const double (*thesis)[NL_STUDY_TABLE41_COLS], int npair)
{
  const char *cc[] = {"reading", "r_log_ks", "p_perm_ks", "rms_log_ks", "r_log_con", "p_perm_con", "rms_log_con", "E_ks_a", "paper_E_ks_a"};
  const char *names[3] = {"printed", "swapped", "mixed_a_printed"};   /* (a) as printed, (b)-(f) swapped */
  nl_table *t = nl_table_alloc(sizeof cc / sizeof *cc, cc);
  double tks[8], tcon[8], ks[8], con[8];
  for (int i = 0; i < npair && i < 8; i++) { tks[i] = thesis[i][1]; tcon[i] = thesis[i][3]; }
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

nl_table *nl_study_cheng_grid_sweep(const nl_study_cheng *s, const nl_cheng_config *c, const char *pattern,
                                    int gmin, int gmax, double paper_e_con)
{
  const char *cc[] = {"grid", "points", "E_ks", "E_ks_sd", "E_con", "E_con_sd", "E_con_per_point", "paper_E_con",
                      "r_pattern", "con_vs_const"};
  nl_table *t = nl_table_alloc(sizeof cc / sizeof *cc, cc);
  const char *labels[] = {"grid"};
  nl_table *sum = nl_study_cheng_summary_alloc(1, labels);
  /* The grids' runs as one set of seed runs on the run's threads (nl_study_cheng_runs), rows in grid order. */
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
    const char *l[1] = {lab};
    nl_study_cheng_rows_add(s, sum, 1, l, evs + (size_t)i * k);
    size_t q = sum->nrows - 1;
    double e = nl_table_value(sum, q, "E_con");
    nl_table_append(t, "dddddddddd", (double)grid, (double)pats[i]->n, nl_table_value(sum, q, "E_ks"),
                    nl_table_value(sum, q, "E_ks_sd"), e, nl_table_value(sum, q, "E_con_sd"), e / (double)pats[i]->n,
                    paper_e_con, nl_table_value(sum, q, "r_pattern"), nl_table_value(sum, q, "con_vs_const"));
    nl_cheng_pattern_free(pats[i]);
  }
  nl_harness_progress(s->r, 1.0, "grid sweep");
  free(evs); free(cs); free(pats);
  nl_table_free(sum);
  return t;
}

size_t nl_study_cheng_table41_readings_text(nl_harness *r, const nl_table *rd)
{
  size_t best = 0, bc = 0;
  int sig = 0;
  for (size_t q = 0; q < rd->nrows; q++) {
    if (nl_table_value(rd, q, "rms_log_ks") < nl_table_value(rd, best, "rms_log_ks")) best = q;
    if (nl_table_value(rd, q, "rms_log_con") < nl_table_value(rd, bc, "rms_log_con")) bc = q;
    sig += nl_table_value(rd, q, "p_perm_ks") < 0.05;
  }
  nl_harness_report_table(r, rd, "Readings of Table 4.1's weights over all six rows: Pearson r of log E_KS and log E_Con (ours vs thesis), exact one-sided permutation p over all orderings of the rows, rms of the centred log ratio", 4);
  nl_harness_text(r, "Over all six rows, E_KS fits the thesis best under the reading \"%s\": rms centred log ratio %.3g "
                     "(printed %.3g, swapped %.3g, mixed_a_printed = (a) as printed and (b)-(f) swapped %.3g), r of log E_KS "
                     "%.2f, permutation p = %.3g; %d of %zu readings order the rows' E_KS like the thesis at alpha = 0.05%s. "
                     "Row (a): thesis E_KS %.4g, ours %.4g under it. E_Con's shape fits best under \"%s\" (rms %.3g; "
                     "printed %.3g, swapped %.3g, mixed %.3g).\n", nl_table_text(rd, best, "reading"),
                 nl_table_value(rd, best, "rms_log_ks"), nl_table_value(rd, 0, "rms_log_ks"), nl_table_value(rd, 1, "rms_log_ks"),
                 nl_table_value(rd, 2, "rms_log_ks"), nl_table_value(rd, best, "r_log_ks"), nl_table_value(rd, best, "p_perm_ks"),
                 sig, rd->nrows, sig ? "" : " (no reading reproduces the E_KS column's order; the E_KS choice is the least bad, not a fit)",
                 nl_table_value(rd, best, "paper_E_ks_a"), nl_table_value(rd, best, "E_ks_a"), nl_table_text(rd, bc, "reading"),
                 nl_table_value(rd, bc, "rms_log_con"), nl_table_value(rd, 0, "rms_log_con"), nl_table_value(rd, 1, "rms_log_con"),
                 nl_table_value(rd, 2, "rms_log_con"));
  if (bc != best)
    nl_harness_text(r, "The two columns disagree on the reading: E_KS prefers \"%s\", E_Con \"%s\"; the verdicts below use "
                       "E_KS's choice.\n", nl_table_text(rd, best, "reading"), nl_table_text(rd, bc, "reading"));
  return best;
}

void nl_study_cheng_weights_uniformity_text(nl_harness *r, const nl_table *tab, const nl_table *sweep, const double *rhos, int npair)
{
  double worst_ks = fmin(nl_study_column_min(tab, "uniform_ks"), nl_study_column_min(sweep, "uniform_ks"));
  double worst_ku = fmin(nl_study_column_min(tab, "uniform_kuiper"), nl_study_column_min(sweep, "uniform_kuiper"));
  /* Smallest swept w1 / w2 from which every run passes both tests, and how
   * many printed pairs have a rejected run. */
  double safe = NAN;
  for (size_t q = sweep->nrows; q-- > 0;) {
    if (nl_table_value(sweep, q, "uniform_ks") < 1 || nl_table_value(sweep, q, "uniform_kuiper") < 1) break;
    safe = rhos[q];
  }
  int rejected = 0;
  for (size_t q = 0; q < 2 * (size_t)npair; q += 2)
    rejected += nl_table_value(tab, q, "uniform_ks") < 1 || nl_table_value(tab, q, "uniform_kuiper") < 1;
  char safe_txt[96];
  if (isnan(safe)) snprintf(safe_txt, sizeof safe_txt, "even the largest swept w1 / w2 has a rejected run");
  else snprintf(safe_txt, sizeof safe_txt, "every run passes both tests from w1 / w2 = %.3g upwards", safe);
  nl_harness_text(r, "Uniformity: over all pairs and sweep points, the smallest fraction of runs not rejected "
                     "as non-uniform at alpha = 0.05 is %.2f (KS) and %.2f (Kuiper). %d of the six printed pairs "
                     "have at least one run rejected by KS or Kuiper (see p_ks_min, p_kuiper_min), so the "
                     "thesis's claim that the statistics are preserved %s. In the sweep %s; the default "
                     "w1 / w2 = 0.995 / 0.005 = 199.\n", worst_ks, worst_ku, rejected,
                 rejected ? "does not hold for control-dominated weights" : "holds for every printed pair here",
                 safe_txt);
}
