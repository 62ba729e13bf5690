/* C4's analysis of Cheng 2009 Table 4.1 (sec. 4.3.2): ours beside the
 * thesis's, and how each reading of the table's weight columns compares with
 * it over all six rows. */
#include "c4.h"
#include "study/nl_study_cheng.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

nl_table *c4_table41(const nl_table *runs, const c4_thesis_row *thesis, int npair)
{
  const char *cc[] = {
    "panel",         "w1",          "w2",           "paper_E_ks", "E_ks",
    "E_ks_sd",       "paper_E_con", "E_con",        "E_con_sd",   "E_ks_swapped",
    "E_con_swapped", "p_ks_min",    "p_kuiper_min", "seam_ratio", "seam_ratio_swapped"
  };
  nl_table *cmp = nl_table_alloc(sizeof cc / sizeof *cc, cc);
  for (int i = 0; i < npair; i++) {
    size_t p = 2 * (size_t)i, s = p + 1; /* printed, swapped */
    char panel[4] = { (char)('a' + i), 0 };
    nl_table_append(cmp, "sdddddddddddddd", panel, thesis[i][0], thesis[i][2], thesis[i][1],
                    nl_table_value(runs, p, "E_ks"), nl_table_value(runs, p, "E_ks_sd"),
                    thesis[i][3], nl_table_value(runs, p, "E_con"),
                    nl_table_value(runs, p, "E_con_sd"), nl_table_value(runs, s, "E_ks"),
                    nl_table_value(runs, s, "E_con"), nl_table_value(runs, p, "p_ks_min"),
                    nl_table_value(runs, p, "p_kuiper_min"), nl_table_value(runs, p, "seam_ratio"),
                    nl_table_value(runs, s, "seam_ratio"));
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
 * p, and the rms of the log ratio centred (0 = ours is the thesis's up to one
 * constant factor) and uncentred (0 = ours is the thesis's). */
static void fit(const double *th, const double *ours, int n, double *out)
{
  double lx[8] = { 0 }, ly[8] = { 0 }, m = 0, q = 0, a = 0;
  for (int i = 0; i < n; i++) {
    lx[i] = log(th[i]);
    ly[i] = log(ours[i]);
    m += ly[i] - lx[i];
    a += (ly[i] - lx[i]) * (ly[i] - lx[i]);
  }
  m /= n;
  for (int i = 0; i < n; i++) q += (ly[i] - lx[i] - m) * (ly[i] - lx[i] - m);
  out[0] = pearson(lx, ly, n);
  out[1] = perm_p(lx, ly, n, out[0]);
  out[2] = sqrt(q / n);
  out[3] = sqrt(a / n);
}

const char *const c4_reading_names[C4_READINGS] = { "printed", "swapped", "mixed_a_printed" };

int c4_reading_swapped(int rd, int panel) { return rd == 1 || (rd == 2 && panel > 0); }

nl_table *c4_readings(const nl_table *cmp, const c4_thesis_row *thesis, int npair)
{
  const char *cc[] = { "reading",         "r_log_ks",  "p_perm_ks",   "rms_log_ks",
                       "rms_abs_log_ks",  "r_log_con", "p_perm_con",  "rms_log_con",
                       "rms_abs_log_con", "E_ks_a",    "paper_E_ks_a" };
  nl_table *t = nl_table_alloc(sizeof cc / sizeof *cc, cc);
  double tks[8], tcon[8], ks[8], con[8];
  if (npair > 8) npair = 8;
  for (int i = 0; i < npair; i++) {
    tks[i] = thesis[i][1];
    tcon[i] = thesis[i][3];
  }
  for (int rd = 0; rd < C4_READINGS; rd++) {
    for (int i = 0; i < npair; i++) {
      int sw = c4_reading_swapped(rd, i);
      ks[i] = nl_table_value(cmp, (size_t)i, sw ? "E_ks_swapped" : "E_ks");
      con[i] = nl_table_value(cmp, (size_t)i, sw ? "E_con_swapped" : "E_con");
    }
    double f1[4], f2[4];
    fit(tks, ks, npair, f1);
    fit(tcon, con, npair, f2);
    nl_table_append(t, "sdddddddddd", c4_reading_names[rd], f1[0], f1[1], f1[2], f1[3], f2[0],
                    f2[1], f2[2], f2[3], ks[0], tks[0]);
  }
  return t;
}

size_t c4_readings_closest(const nl_table *rd)
{
  size_t best = 0;
  for (size_t q = 1; q < rd->nrows; q++)
    if (nl_table_value(rd, q, "rms_abs_log_ks") < nl_table_value(rd, best, "rms_abs_log_ks"))
      best = q;
  return best;
}

void c4_reading_tests(nl_harness *r, const nl_table *tab, int npair)
{
  nl_table *wt = nl_study_cheng_welch_alloc();
  for (int i = 0; i < npair; i++) {
    size_t p = 2 * (size_t)i;
    char panel[4] = { (char)('a' + i), 0 };
    nl_study_cheng_welch_add(wt, tab, p, p + 1, "E_ks", panel, "printed", "swapped");
    nl_study_cheng_welch_add(wt, tab, p, p + 1, "E_con", panel, "printed", "swapped");
  }
  nl_harness_write_table(r, wt, "reading_tests.tsv");
  nl_harness_report_table(
      r, wt,
      "Printed vs swapped weights per row of Table 4.1 (group = panel): Welch's t-test over seeds",
      4);
  nl_table_free(wt);
}
