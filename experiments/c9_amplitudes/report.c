/* C9's report prose: fixed against optimised octave amplitudes (Cheng 2009
 * ch. 5), every number formatted from the summary, Welch, gains and timing
 * tables or the run's setting. */
#include "c9.h"
#include "harness/nl_harness.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

void c9_intro_text(nl_harness *r, const nl_study_cheng *s, double range)
{
  nl_harness_text(r,
                  "**Thesis:** ch. 5 proposes adjusting the fractal sum's amplitudes automatically "
                  "to follow the control pattern more closely; not done there. **Ours:** the "
                  "amplitudes 1/a_l = g_l / a_l (a_l = %g 2^(l-1), eq. 3.10) with gains g_l in "
                  "[1/%g, %g] are variables of E = w1 E_KS + w2 E_Con (w1 = %g, w2 = %g): level l "
                  "anneals its table entries and g_l (starting at 1, the thesis's a_l; frozen "
                  "after level l), V = F_sum over its bound recomputed from the current "
                  "amplitudes (so c stays in [0, 1] and only the octaves' relative weights "
                  "matter). %d x %d control grid, %d seeds per row, the same seeds (start tables) "
                  "for fixed and optimised.\n",
                  s->c.a1, range, range, s->c.w1, s->c.w2, s->grid, s->grid, nl_harness_seeds(r));
}

/* The smallest and largest of column col over rows r0, r0 + step, ... */
static void range_of(const nl_table *t, const char *col, size_t r0, size_t step, double *lo,
                     double *hi)
{
  *lo = INFINITY;
  *hi = -INFINITY;
  for (size_t q = r0; q < t->nrows; q += step) {
    *lo = fmin(*lo, nl_table_value(t, q, col));
    *hi = fmax(*hi, nl_table_value(t, q, col));
  }
}

/* Over the Welch table: cases whose E_Con the optimised amplitudes lower
 * or raise significantly and the range of the change; cases whose E_KS
 * changes and the largest change. */
typedef struct {
  int lower, higher, ks_diff;
  double dlo, dhi, kmax;
} c9_counts;

static c9_counts count_tests(const nl_table *tests)
{
  c9_counts n = { 0, 0, 0, INFINITY, -INFINITY, 0 };
  for (size_t q = 0; q < tests->nrows; q++) {
    char buf[32];
    const char *qty = nl_table_cell_text(tests, q, 1, buf);
    double p = nl_table_value(tests, q, "p_welch");
    double d = nl_table_value(tests, q, "diff_pct");
    if (!strcmp(qty, "E_con")) {
      n.lower += p < 0.05 && d < 0;
      n.higher += p < 0.05 && d > 0;
      n.dlo = fmin(n.dlo, d);
      n.dhi = fmax(n.dhi, d);
    } else if (!strcmp(qty, "E_ks")) {
      n.ks_diff += p < 0.05;
      if (fabs(d) > fabs(n.kmax)) n.kmax = d;
    }
  }
  return n;
}

/* Case i's line: fixed (row 2i) -> optimised (row 2i + 1). */
static void case_text(nl_harness *r, const nl_table *sum, const nl_table *tests,
                      const nl_table *gains, size_t i)
{
  char tb[32], pb[32], gl[160] = "", want[72];
  const char *t = nl_table_cell_text(sum, 2 * i, 0, tb);
  const char *p = nl_table_cell_text(sum, 2 * i, 1, pb);
  snprintf(want, sizeof want, "%s/%s", t, p);
  double pe = NAN;   /* Welch p of E_Con for this case */
  for (size_t q = 0; q < tests->nrows; q++) {
    char gb[32], qb[32];
    if (strcmp(nl_table_cell_text(tests, q, 0, gb), want)) continue;
    if (!strcmp(nl_table_cell_text(tests, q, 1, qb), "E_con"))
      pe = nl_table_value(tests, q, "p_welch");
  }
  for (size_t q = 0, n = 0; q < gains->nrows; q++) {
    char gt[32], gp[32];
    if (strcmp(nl_table_cell_text(gains, q, 0, gt), t)) continue;
    if (strcmp(nl_table_cell_text(gains, q, 1, gp), p)) continue;
    snprintf(gl + strlen(gl), sizeof gl - strlen(gl), "%s%.2f", n++ ? ", " : "",
             nl_table_value(gains, q, "gain"));
  }
  size_t f = 2 * i, o = f + 1;
  nl_harness_text(r,
                  "- %s/%s: E_Con %.4g +- %.3g -> %.4g +- %.3g (p = %.2g; best constant %.4g), r "
                  "%.2f -> %.2f, contrast %.3f -> %.3f, E_KS %.4f -> %.4f; mean gains per octave "
                  "%s.\n",
                  t, p, nl_table_value(sum, f, "E_con"), nl_table_value(sum, f, "E_con_sd"),
                  nl_table_value(sum, o, "E_con"), nl_table_value(sum, o, "E_con_sd"), pe,
                  nl_table_value(sum, f, "E_con_const"), nl_table_value(sum, f, "r_pattern"),
                  nl_table_value(sum, o, "r_pattern"), nl_table_value(sum, f, "contrast"),
                  nl_table_value(sum, o, "contrast"), nl_table_value(sum, f, "E_ks"),
                  nl_table_value(sum, o, "E_ks"), gl);
}

void c9_results_text(nl_harness *r, const nl_table *sum, const nl_table *tests,
                     const nl_table *gains, double range)
{
  nl_harness_report_columns(r, sum, "summary.tsv",
                            "texture,pattern,amplitudes,seeds,E_ks,E_ks_sd,p_ks_min,E_con,"
                            "E_con_sd," NL_STUDY_CHENG_CONTROL ",roughness",
                            "Fixed vs optimised amplitudes: statistics and controllability (mean "
                            "and sd over seeds)",
                            4);
  nl_harness_report_table(r, tests,
                          "Optimised (a) vs fixed (b) amplitudes per case: Welch's t-test over "
                          "seeds",
                          4);
  nl_harness_report_table(r, gains,
                          "Optimised amplitudes per octave: a_l (thesis's and optimised, mean and "
                          "sd over seeds), gain = a_thesis / a",
                          4);
  size_t ncase = sum->nrows / 2;
  c9_counts n = count_tests(tests);
  double rf[2], ro[2], cf[2], co[2], bf = 0;   /* fixed and optimised ranges */
  range_of(sum, "r_pattern", 0, 2, rf, rf + 1);
  range_of(sum, "r_pattern", 1, 2, ro, ro + 1);
  range_of(sum, "contrast", 0, 2, cf, cf + 1);
  range_of(sum, "contrast", 1, 2, co, co + 1);
  for (size_t q = 0; q < gains->nrows; q++)
    bf += nl_table_value(gains, q, "at_bound") / (double)gains->nrows;
  nl_harness_text(r,
                  "**Fixed vs optimised amplitudes** (%zu cases, %g seeds each, Welch's t-test at "
                  "0.05): the optimised amplitudes lower E_Con in %d of the cases and raise it in "
                  "%d (change of the mean %+.1f%% .. %+.1f%%); E_KS differs in %d of the cases "
                  "(largest change of the mean %+.1f%%). r with the pattern: fixed %.2f..%.2f, "
                  "optimised %.2f..%.2f; contrast (sd of c): fixed %.3f..%.3f, optimised "
                  "%.3f..%.3f. Gains end at a bound (1/%g or %g) in %.0f%% of octave-seeds.\n",
                  ncase, nl_table_value(sum, 0, "seeds"), n.lower, n.higher, n.dlo, n.dhi,
                  n.ks_diff, n.kmax, rf[0], rf[1], ro[0], ro[1], cf[0], cf[1], co[0], co[1],
                  range, range, 100 * bf);
  for (size_t i = 0; i < ncase; i++) case_text(r, sum, tests, gains, i);
}

void c9_timing_text(nl_harness *r, const nl_table *timing, int ncase)
{
  double tf = 0, to = 0;
  for (size_t k = 0; k < timing->nrows; k += 2) {
    tf += nl_table_value(timing, k, "seconds_per_run");
    to += nl_table_value(timing, k + 1, "seconds_per_run");
  }
  nl_harness_text(r,
                  "Time per optimisation (thread CPU): fixed %.3g s, optimised %.3g s on average "
                  "over the cases (a gain move re-evaluates every control point).\n",
                  tf / ncase, to / ncase);
  nl_harness_figure(r, "control.png",
                    "E_Con, r with the pattern and contrast, fixed vs optimised amplitudes (mean "
                    "and sd over seeds; +: E_Con of the best constant image)");
  nl_harness_figure(r, "gains.png",
                    "Optimised octave amplitudes 1/a_l = gain / a_l against the thesis's 1/a_l and "
                    "the bounds (mean and sd of the gain over seeds)");
  nl_harness_figure(r, "values.png",
                    "Per case: pattern | controlled value with fixed and optimised amplitudes on "
                    "its own 0..1 scale | the same stretched to its 1st..99th percentile (first "
                    "seed)");
}
