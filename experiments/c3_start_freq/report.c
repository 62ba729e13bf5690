/* C3's report prose (Cheng 2009 sec. 4.3.1, Fig 4.7): every number
 * formatted from the summary table or the run's setting. */
#include "c3.h"
#include "harness/nl_harness.h"

#include <stdio.h>
#include <string.h>

/* "v0, v1, ..." of n values, each formatted by fmt. */
static void list(char *buf, size_t len, const char *fmt, const double *v, int n)
{
  buf[0] = 0;
  for (int i = 0; i < n; i++) {
    size_t used = strlen(buf);
    if (i) used += (size_t)snprintf(buf + used, len - used, ", ");
    snprintf(buf + used, len - used, fmt, v[i]);
  }
}

void c3_intro_text(nl_harness *r, const nl_study_cheng *s, const char *pattern, const double *f1s,
                   int n, const nl_table *sum)
{
  const nl_cheng_config *c = &s->c;
  nl_harness_text(
      r,
      "**Thesis:** the controlled fractal sum for f1 = 2, 4, 6, 8 (Fig 4.7, images only); \"the "
      "appearance of lower starting frequency is smoother\". **Ours:** pattern %s, %d x %d control "
      "grid, F = %d, a1 = %g, w1 = %g, w2 = %g, %d seeds per f1. Smoothness is measured as the rms "
      "gradient of the control value (\"roughness\", per unit length).\n",
      pattern, s->grid, s->grid, c->octaves, c->a1, c->w1, c->w2, nl_harness_seeds(r));
  char f1_list[128], cap[192];
  list(f1_list, sizeof f1_list, "%g", f1s, n);
  snprintf(cap, sizeof cap, "Controlled value (top) and cloud texture (bottom) for f1 = %s",
           f1_list);
  nl_harness_figure(r, "panels.png", cap);
  nl_harness_report_columns(r, sum, "summary.tsv", "f1,seeds," NL_STUDY_CHENG_STORY,
                            "Statistics per f1 (mean and spread over seeds)", 4);
}

void c3_result_text(nl_harness *r, const nl_table *sum, const double *f1s, int n)
{
  double ro[16], ec[16];
  int best = 0, monotone = 1;
  if (n > 16) n = 16;
  for (int i = 0; i < n; i++) {
    ro[i] = nl_table_value(sum, (size_t)i, "roughness");
    ec[i] = nl_table_value(sum, (size_t)i, "E_con");
    if (i && !(ro[i] > ro[i - 1])) monotone = 0;
    if (ec[i] < ec[best]) best = i;
  }
  char f1_list[128], ro_list[256], ec_list[256];
  list(f1_list, sizeof f1_list, "%g", f1s, n);
  list(ro_list, sizeof ro_list, "%.3g", ro, n);
  list(ec_list, sizeof ec_list, "%.4g", ec, n);
  nl_harness_text(r,
                  "Roughness %s for f1 = %s: %s. E_Con %s is lowest at f1 = %g (the thesis gives "
                  "no E_Con per f1 to compare).\n",
                  ro_list, f1_list,
                  monotone
                      ? "strictly increasing with f1, so lower f1 is smoother, as the thesis says"
                      : "NOT monotone in f1",
                  ec_list, f1s[best]);
}

void c3_trend_text(nl_harness *r, const nl_table *tt, const nl_table *per_f1)
{
  nl_harness_text(
      r,
      "Headline reading: smoothness is the rms gradient of the control value (the usual measure of "
      "how fast a function varies), fixed before any run; the thesis prints no number for C3, so "
      "nothing could be matched to choose it. Decided by Spearman's rho of roughness on f1 over "
      "every run, with a one-sided permutation p, beside the same test on random (unoptimised) "
      "tables, since a fractal sum's roughness grows with its frequencies whatever the table.\n");
  nl_harness_report_table(r, tt,
                          "Trend test of roughness on f1: optimised tables (one run per seed and "
                          "f1) and random tables (the same tables at every f1)",
                          4);
  nl_harness_verdict_p(r, "trend_test.tsv", tt, 0, "lower f1 is smoother: roughness trend on f1",
                       "the appearance of lower starting frequency is smoother", "rho", "p_perm",
                       "p 0.01 0.05", "independent",
                       "Spearman's rho of roughness on f1 over the runs, one-sided permutation p");
  /* Any fractal sum is smoother at a lower f1: the same test on random
   * tables is the control, and the claim as printed says no more than that,
   * so the rule stays (the row is what the control makes it). */
  nl_harness_verdict_control(r, "random (unoptimised) tables at the same f1s", "trend_test.tsv", tt,
                             1);
  nl_harness_report_table(
      r, per_f1, "Roughness per f1: optimised against random tables (ratio and two-sided Welch p)",
      4);
  double ro = nl_table_value(tt, 0, "slope"), rr = nl_table_value(tt, 1, "slope");
  char ratios[256] = "", ps[256] = "", up[128] = "", down[128] = "";
  int differ = 0;
  for (size_t q = 0; q < per_f1->nrows; q++) {
    size_t a = strlen(ratios), b = strlen(ps);
    double p = nl_table_value(per_f1, q, "p_welch"), ratio = nl_table_value(per_f1, q, "ratio");
    snprintf(ratios + a, sizeof ratios - a, "%s%.3f", q ? ", " : "", ratio);
    snprintf(ps + b, sizeof ps - b, "%s%.2g", q ? ", " : "", p);
    if (p <= 0.05) {
      char *to = ratio > 1 ? up : down; /* rougher or smoother than a random table */
      size_t c = strlen(to);
      snprintf(to + c, sizeof up - c, "%s%g", c ? ", " : "", nl_table_value(per_f1, q, "f1"));
      differ++;
    }
  }
  char adds[320];
  if (differ)
    snprintf(adds, sizeof adds,
             "the optimisation makes the value rougher than a random table's at f1 = %s and "
             "smoother at f1 = %s, so it %s the trend (slope %.3f x the random one) but does not "
             "make it.",
             *up ? up : "none", *down ? down : "none", ro < rr ? "flattens" : "steepens", ro / rr);
  else
    snprintf(adds, sizeof adds,
             "the optimisation leaves the roughness where a random table has it.");
  nl_harness_text(
      r,
      "What the optimisation adds: random tables give rho %.3f (p %.3g) and a slope of %.3g "
      "roughness per unit f1, the optimised tables rho %.3f (p %.3g) and %.3g, %.3f x the random "
      "slope. Per f1 the optimised roughness is %s x the random tables' (Welch p %s): %d of %zu f1 "
      "differ at p <= 0.05. Lower f1 is smoother because the fractal sum's frequencies are lower; "
      "%s\n",
      nl_table_value(tt, 1, "rho"), nl_table_value(tt, 1, "p_perm"), rr,
      nl_table_value(tt, 0, "rho"), nl_table_value(tt, 0, "p_perm"), ro, ro / rr, ratios, ps,
      differ, per_f1->nrows, adds);
}

void c3_low_text(nl_harness *r, const nl_table *ctl, const nl_table *bl)
{
  char f1[32];
  snprintf(f1, sizeof f1, "%s", nl_table_text(ctl, 0, "f1"));
  nl_harness_report_table(r, ctl,
                          "\"We can even control the lower frequency appearance\": the lowest f1 "
                          "against its pattern (r against random tables, E_Con against the flat "
                          "image)",
                          3);
  nl_harness_report_table(r, bl,
                          "Its negative controls: the optimised tables against the pattern "
                          "shuffled, the unoptimised start tables",
                          3);
  char qty[96];
  const char *claim = "we can even control the lower frequency appearance";
  snprintf(qty, sizeof qty, "low f1 controlled: r with the pattern vs random tables, f1 %s", f1);
  nl_harness_verdict_p(
      r, "control.tsv", ctl, 0, qty, claim, "r_pattern", "p_random", "p 0.01 0.05", "independent",
      "one-sided Monte-Carlo p of the seeds' mean r against single random tables from the seed");
  nl_harness_verdict_control(r, "the optimised tables against the pattern shuffled",
                             "baselines.tsv", bl, 0);
  snprintf(qty, sizeof qty, "low f1 controlled: E_Con below a flat image's, f1 %s", f1);
  nl_harness_verdict_p(r, "control.tsv", ctl, 0, qty, claim, "con_vs_const", "p_flat",
                       "p 0.01 0.05", "independent",
                       "E_Con over the best constant image's; one-sided t over the seeds");
  nl_harness_verdict_control(r, "the unoptimised start tables", "baselines.tsv", bl, 1);
}
