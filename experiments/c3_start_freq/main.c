/* C3 - Cheng 2009 Fig 4.7 (sec. 4.3.1): the starting frequency f1 = 2, 4, 6,
 * 8 of the controlled fractal sum (eq. 3.10: f_l = f1 2^(l-1)); lower f1
 * should look smoother. Decided by a trend test of roughness on f1 beside
 * the same test on random tables (trend.c). */
#include "c3.h"
#include "study/nl_study_cheng.h"
#include "harness/nl_harness.h"

#include <stdio.h>
#include <stdlib.h>

#define NF    4
#define PANEL 160 /* side in pixels of the panels */

static const double f1s[NF] = { 2, 4, 6, 8 };
static const char *const pattern = "star";

int main(int argc, char **argv)
{
  nl_study_cheng s;
  nl_study_cheng_open(&s, "c3_start_freq", "C3 - starting frequency f1 (Fig 4.7)", &argc, argv);
  nl_harness *r = s.r;
  int q = nl_harness_quick(r);
  int nrand = (int)nl_harness_param_int(r, "random_tables", q ? 10 : 100, 2, 100000,
                                        "random (unoptimised) tables per f1: the baseline "
                                        "trend of roughness (quick 10)");
  int nrand_r = (int)nl_harness_param_int(r, "random_r", q ? 99 : 999, 9, 1000000,
                                          "random (unoptimised) tables: the null distribution of "
                                          "r with the pattern at the lowest f1 (quick 99)");
  int nperm = (int)nl_harness_param_int(r, "permutations", 9999, 99, 10000000,
                                        "permutations of the trend test's roughness values");
  nl_study_cheng_ready(&s);
  const nl_cheng_config base = s.c;
  nl_cheng_pattern *pat = nl_study_cheng_pattern(&s, pattern);
  const char *labels[] = { "f1" };
  nl_table *sum = nl_study_cheng_summary_alloc(1, labels);
  int k = nl_harness_seeds(r);

  /* every f1 over the seeds as one set of independent runs */
  nl_cheng_config cs[NF];
  const nl_cheng_pattern *pp[NF];
  nl_noise_grad2 *firsts[NF];
  for (int i = 0; i < NF; i++) {
    cs[i] = base;
    cs[i].f1 = f1s[i];
    pp[i] = pat;
  }
  nl_noise_grad2 **tables = nl_xmalloc((size_t)NF * (size_t)k * sizeof *tables);
  nl_cheng_eval *evs = nl_study_cheng_runs_tables(&s, NF, cs, pp, tables);
  for (int i = 0; i < NF; i++) firsts[i] = nl_noise_grad2_alloc(base.m);
  for (int i = 0; i < NF; i++) nl_noise_grad2_copy(firsts[i], tables[(size_t)i * k]);
  /* the first seed's tables behind the figure (tests/oracle_cheng.c) */
  c3_tables_write(r, f1s, firsts, NF);
  /* "we can even control the lower frequency appearance": the lowest f1's
   * value against its pattern (r against random tables, E_Con against the
   * flat image), with the negative controls of nl_study_cheng_baselines_add */
  nl_table *ctl = nl_study_cheng_control_alloc(1, (const char *const[]){ "f1" });
  nl_table *bl = nl_study_cheng_control_alloc(2, (const char *const[]){ "f1", "baseline" });
  c3_low_control(&s, ctl, bl, &cs[0], pat, evs, tables, nrand_r, f1s[0]);
  for (size_t i = 0; i < (size_t)NF * k; i++) nl_noise_grad2_free(tables[i]);
  free(tables);
  /* the alternative domain [0, 1]^2 (origin 0; nl_cheng.h READINGS): the
   * same runs, for the seams of their first seed's tables */
  nl_cheng_config cs0[NF];
  nl_noise_grad2 *firsts0[NF];
  for (int i = 0; i < NF; i++) {
    cs0[i] = cs[i];
    cs0[i].origin = 0;
  }
  free(nl_study_cheng_runs(&s, NF, cs0, pp, firsts0));

  /* Fig 4.7: the controlled value (top row) and the cloud texture (bottom)
   * per f1, first seed, each row after the pattern. */
  enum { COLS = NF + 1 };
  nl_image *panels[2 * COLS];
  char lab[2 * COLS][48];
  const char *labp[2 * COLS];
  for (int row = 0; row < 2; row++) {
    panels[row * COLS] = nl_study_cheng_pattern_panel(pat, PANEL);
    snprintf(lab[row * COLS], sizeof lab[0], "pattern");
  }
  /* the trend: every run's (f1, roughness), and random tables' at each f1
   * (the same tables at every f1: one stream) */
  double *xo = nl_xmalloc((size_t)NF * k * sizeof *xo),
         *yo = nl_xmalloc((size_t)NF * k * sizeof *yo);
  double *xr = nl_xmalloc((size_t)NF * nrand * sizeof *xr);
  double *yr = nl_xmalloc((size_t)NF * nrand * sizeof *yr);
  nl_table *per_f1 = c3_per_f1_alloc(), *tt = c3_trend_test_alloc();
  const char *slabels[] = { "f1", "tables_from" };
  nl_table *seams = nl_study_cheng_seams_alloc(2, slabels);
  unsigned long rseed = nl_seed_stream(nl_harness_seed(r), "c3.random", 0);
  for (int i = 0; i < NF; i++) {
    char f[32];
    nl_table_format_double(f, f1s[i]);
    const char *l[1] = { f };
    nl_study_cheng_rows_add(&s, sum, 1, l, evs + (size_t)i * k);
    for (int j = 0; j < k; j++) {
      xo[i * k + j] = f1s[i];
      yo[i * k + j] = evs[(size_t)i * k + j].roughness;
    }
    c3_random_roughness(&cs[i], pat, rseed, nrand, nl_harness_threads(r), yr + (size_t)i * nrand);
    for (int j = 0; j < nrand; j++) xr[i * nrand + j] = f1s[i];
    c3_per_f1_add(per_f1, f1s[i], yo + i * k, k, yr + (size_t)i * nrand, nrand);
    panels[1 + i] = nl_study_cheng_value_image(firsts[i], &cs[i], PANEL);
    panels[COLS + 1 + i] = nl_study_cheng_texture_image(firsts[i], &cs[i], PANEL);
    snprintf(lab[1 + i], sizeof lab[0], "(%c) f1=%g", 'a' + i, f1s[i]);
    snprintf(lab[COLS + 1 + i], sizeof lab[0], "(%c) f1=%g cloud", 'a' + i, f1s[i]);
    /* seams of the first seed's table and of its start table (C7 explains them) */
    const char *sl[2] = { f, "optimised" };
    nl_study_cheng_seams_add(seams, 2, sl, (const nl_noise_grad2 *const *)&firsts[i], 1, &cs[i],
                             pat);
    nl_noise_grad2_seed(firsts[i], nl_seed_replicate(nl_harness_seed(r), 0)); /* the start */
    sl[1] = "start table";
    nl_study_cheng_seams_add(seams, 2, sl, (const nl_noise_grad2 *const *)&firsts[i], 1, &cs[i],
                             pat);
    nl_noise_grad2_free(firsts[i]);
    nl_harness_progress(r, (i + 1.0) / NF, "f1");
  }
  c3_seams_add(seams, f1s, cs0, firsts0, NF, pat);
  c3_trend_tests(tt, xo, yo, (size_t)NF * k, xr, yr, (size_t)NF * nrand, nperm, nl_harness_seed(r));
  for (int i = 0; i < 2 * COLS; i++) labp[i] = lab[i];
  nl_study_cheng_montage(r, panels, labp, 2 * COLS, COLS,
                         "Fig 4.7: starting frequency f1 (first seed)", "panels.png");
  nl_harness_write_table(r, sum, "summary.tsv");
  nl_harness_write_table(r, per_f1, "trend.tsv");
  nl_harness_write_table(r, tt, "trend_test.tsv");
  nl_harness_write_table(r, seams, "seams.tsv");
  nl_harness_write_table(r, ctl, "control.tsv");
  nl_harness_write_table(r, bl, "baselines.tsv");
  c3_intro_text(r, &s, pattern, f1s, NF, sum);
  c3_result_text(r, sum, f1s, NF);
  c3_trend_text(r, tt, per_f1);
  c3_low_text(r, ctl, bl);
  nl_table_free(ctl);
  nl_table_free(bl);
  nl_study_cheng_seams_text(r, seams, "the first seed's table and its start table per f1");
  nl_study_cheng_control_text(r, sum, 1);
  free(evs);
  free(xo);
  free(yo);
  free(xr);
  free(yr);
  nl_table_free(per_f1);
  nl_table_free(tt);
  nl_table_free(seams);
  nl_table_free(sum);
  nl_cheng_pattern_free(pat);
  nl_harness_check_measured(r, "*", 100); /* measured tolerances (nl_harness.h) */
  return nl_harness_end(r);
}
