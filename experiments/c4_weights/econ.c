/* C4's E_Con at Table 4.1's printed weight pairs (Cheng 2009 sec. 4.3.2)
 * over the two things the thesis does not state and E_Con depends on: the
 * control grid (E_Con = sum over the control points, eq. 3.8, so it scales
 * with their number) and the annealing budget; and over the readings of the
 * weight columns. */
#include "c4.h"
#include "study/nl_study_cheng.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAXGRIDS 16

/* gmin, 2 gmin, ... <= gmax with `own` inserted in order (once); the count. */
static int grid_list(int gmin, int gmax, int own, int *g)
{
  int n = 0;
  for (int x = gmin; x <= gmax && n < MAXGRIDS - 1; x *= 2) {
    if (own < x && (n == 0 || g[n - 1] < own)) g[n++] = own;
    g[n++] = x;
  }
  if (n == 0 || g[n - 1] < own) g[n++] = own;
  return n;
}

nl_table *c4_econ_runs(const nl_study_cheng *s, const nl_cheng_config *base, const char *pattern,
                       const c4_thesis_row *thesis, int npair, const nl_cheng_eval *main_evs,
                       int gmin, int gmax, double budget_low)
{
  const char *labels[] = { "grid", "points", "budget", "reading", "panel", "w1", "w2" };
  const double budgets[2] = { 1, budget_low };
  int grids[MAXGRIDS], ng = grid_list(gmin, gmax, s->grid, grids), k = nl_harness_seeds(s->r);
  int per = 2 * npair, ncase = ng * 2 * per, nrun = 0;
  nl_cheng_config *cs = nl_xmalloc((size_t)ncase * sizeof *cs);
  const nl_cheng_pattern **pp = nl_xmalloc((size_t)ncase * sizeof *pp);
  nl_cheng_pattern *pats[MAXGRIDS];
  nl_study_cheng g = *s;
  /* Every case not already run by Table 4.1 (s's grid at budget 1), as one
   * set of seed runs on the run's threads. */
  for (int gi = 0; gi < ng; gi++) {
    g.grid = grids[gi];
    pats[gi] = nl_study_cheng_pattern(&g, pattern);
    for (int b = 0; b < 2; b++) {
      if (grids[gi] == s->grid && b == 0) continue;
      for (int q = 0; q < per; q++) {
        int i = q / 2, sw = q % 2;
        cs[nrun] = *base;
        cs[nrun].w1 = thesis[i][sw ? 2 : 0];
        cs[nrun].w2 = thesis[i][sw ? 0 : 2];
        cs[nrun].sched.moves_per_var *= budgets[b];
        pp[nrun++] = pats[gi];
      }
    }
  }
  nl_cheng_eval *evs = nl_study_cheng_runs(s, nrun, cs, pp, NULL);
  nl_table *t = nl_study_cheng_summary_alloc(7, labels);
  const nl_cheng_eval *next = evs;
  for (int gi = 0; gi < ng; gi++)
    for (int b = 0; b < 2; b++) {
      int reuse = grids[gi] == s->grid && b == 0;
      for (int q = 0; q < per; q++) {
        int i = q / 2, sw = q % 2;
        char txt[5][32], panel[4] = { (char)('a' + i), 0 };
        snprintf(txt[0], sizeof txt[0], "%d", grids[gi]);
        snprintf(txt[1], sizeof txt[1], "%zu", pats[gi]->n);
        nl_table_format_double(txt[2], budgets[b]);
        nl_table_format_double(txt[3], thesis[i][sw ? 2 : 0]);
        nl_table_format_double(txt[4], thesis[i][sw ? 0 : 2]);
        const char *l[7] = { txt[0], txt[1], txt[2], sw ? "swapped" : "printed",
                             panel,  txt[3], txt[4] };
        const nl_cheng_eval *e = reuse ? main_evs + (size_t)q * k : next;
        if (!reuse) next += k;
        nl_study_cheng_rows_add(s, t, 7, l, e);
      }
    }
  nl_harness_progress(s->r, 1.0, "grid x budget");
  for (int gi = 0; gi < ng; gi++) nl_cheng_pattern_free(pats[gi]);
  free(evs);
  free(cs);
  free(pp);
  return t;
}

/* A label cell of a summary table (text) as its number. */
static double label(const nl_table *t, size_t q, const char *col)
{
  return strtod(nl_table_text(t, q, col), NULL);
}

nl_table *c4_econ_grid(const nl_table *runs, const c4_thesis_row *thesis, int npair,
                       double moves_per_var)
{
  const char *cc[] = { "grid",
                       "points",
                       "budget",
                       "moves_per_var",
                       "reading",
                       "E_con",
                       "E_con_lo",
                       "E_con_hi",
                       "E_con_per_point",
                       "paper_E_con",
                       "con_ratio",
                       "rms_abs_log_ks",
                       "rms_abs_log_con",
                       "E_ks",
                       "r_pattern",
                       "seam_ratio" };
  nl_table *t = nl_table_alloc(sizeof cc / sizeof *cc, cc);
  double paper = 0;
  for (int i = 0; i < npair; i++) paper += thesis[i][3] / npair;
  for (size_t b0 = 0; b0 + 2 * (size_t)npair <= runs->nrows; b0 += 2 * (size_t)npair)
    for (int rd = 0; rd < C4_READINGS; rd++) {
      double con = 0, lo = INFINITY, hi = 0, lks = 0, lcon = 0, ks = 0, rp = 0, seam = 0;
      for (int i = 0; i < npair; i++) {
        size_t q = b0 + 2 * (size_t)i + (size_t)c4_reading_swapped(rd, i);
        double e = nl_table_value(runs, q, "E_con"), k = nl_table_value(runs, q, "E_ks");
        con += e / npair;
        lo = fmin(lo, e);
        hi = fmax(hi, e);
        lcon += log(e / thesis[i][3]) * log(e / thesis[i][3]) / npair;
        lks += log(k / thesis[i][1]) * log(k / thesis[i][1]) / npair;
        ks += k / npair;
        rp += nl_table_value(runs, q, "r_pattern") / npair;
        seam += nl_table_value(runs, q, "seam_ratio") / npair;
      }
      double grid = label(runs, b0, "grid"), pts = label(runs, b0, "points");
      double bud = label(runs, b0, "budget");
      nl_table_append(t, "ddddsddddddddddd", grid, pts, bud, bud * moves_per_var,
                      c4_reading_names[rd], con, lo, hi, con / pts, paper, con / paper, sqrt(lks),
                      sqrt(lcon), ks, rp, seam);
    }
  return t;
}

/* Rows of the printed reading at budget 1. */
static int headline_budget(const nl_table *eg, size_t q)
{
  return !strcmp(nl_table_text(eg, q, "reading"), "printed") &&
         nl_table_value(eg, q, "budget") == 1;
}

size_t c4_econ_fitted(const nl_table *eg)
{
  size_t best = SIZE_MAX;
  double bd = INFINITY;
  for (size_t q = 0; q < eg->nrows; q++) {
    double d = fabs(log(nl_table_value(eg, q, "con_ratio")));
    if (headline_budget(eg, q) && d < bd) {
      bd = d;
      best = q;
    }
  }
  return best;
}

size_t c4_econ_row(const nl_table *eg, int grid)
{
  for (size_t q = 0; q < eg->nrows; q++)
    if (headline_budget(eg, q) && nl_table_value(eg, q, "grid") == grid) return q;
  return SIZE_MAX;
}
