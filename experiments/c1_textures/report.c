/* C1's report prose (Cheng 2009 sec. 4.1, Fig 4.1-4.4): every number
 * formatted from the summary table or the run's setting. */
#include "c1.h"
#include "harness/nl_harness.h"

#include <gsl/gsl_statistics_double.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

void c1_figure_text(nl_harness *r, int t, nl_cheng_con con, const char *equation, const char *file)
{
  char cap[256];
  snprintf(cap, sizeof cap,
           "Fig 4.%d: %s textures, control term %s; pattern | controlled value on its own 0..1 "
           "scale | the same stretched to its 1st..99th percentile | texture | the literal "
           "formula's value, stretched (first seed)",
           t + 1, nl_cheng_con_name(con), equation);
  nl_harness_figure(r, file, cap);
}

/* Marble's gain: the rescaled sine's argument is pi V = pi F_sum / bound,
 * the literal one F_sum itself (eq. 4.1's sin V). */
static void marble_text(nl_harness *r, const nl_cheng_config *c)
{
  nl_noise_octaves o = nl_noise_octaves_cheng(c->octaves, c->f1, c->a1);
  double asum = 0;
  for (int l = 0; l < o.n; l++) asum += o.amp[l];
  double gain = NL_PI / (NL_NOISE2_BOUND * asum);
  nl_harness_text(
      r,
      "Marble's control term: the rescaled sine's argument is pi V = %.3g F_sum (V = F_sum over "
      "its bound), %.2fx eq. 4.1's literal sin(F_sum); after (1 + sin)/2 the slope of c at F_sum = "
      "0 is %.3g, against 1 for the literal sin and %.3g for the rescaled cloud term (1 + V)/2. "
      "Much of marble's r rests on this gain: compare its literal rows.\n",
      gain, gain, gain / 2, gain / (2 * NL_PI));
}

void c1_text(nl_harness *r, const nl_table *sum, const nl_cheng_config *c, int grid)
{
  nl_harness_text(
      r,
      "**Thesis:** three patterns per texture (images only); cloud, erosion and fire blend two "
      "colours with the noise value as alpha, marble goes through a sine; the control term follows "
      "the texture (eq. 3.8, 4.1, 4.2, 4.3). **Ours:** %d x %d control grid, thesis setting (F = "
      "%d, f1 = %g, a1 = %g, w1 = %g, w2 = %g), %d seeds per row. Formula \"rescaled\" (our "
      "headline reading): c = (1 + V)/2, (1 + sin(pi V))/2, |V| or the octave sum of |noise| over "
      "its bound, V = the fractal sum over its analytic bound (nl_cheng.h); \"literal\": the "
      "thesis's formulas as printed, c = V, sin V, |V|, sum |noise| / a with V unscaled (E_Con = "
      "sum (c - D)^2 either way). Images stretch each value's 1st..99th percentile to 0..1 except "
      "the \"no stretch\" panel. The headline is fixed by the thesis's own scale (black = 0, red = "
      "1, so c is read on D's 0..1 scale); the thesis prints no number for C1, so nothing could be "
      "matched to choose it.\n",
      grid, grid, c->octaves, c->f1, c->a1, c->w1, c->w2, nl_harness_seeds(r));
  nl_harness_report_columns(r, sum, "summary.tsv",
                            "texture,pattern,formula,seeds," NL_STUDY_CHENG_STORY,
                            "Per texture, pattern and formula: statistics and controllability of "
                            "the optimised tables (mean and spread over seeds)",
                            4);
  nl_study_cheng_control_text(r, sum, 3);
  marble_text(r, c);
  double wks = nl_study_column_min(sum, "uniform_ks");
  double wku = nl_study_column_min(sum, "uniform_kuiper");
  nl_harness_text(r,
                  "Uniformity: the smallest fraction of runs not rejected as non-uniform at alpha "
                  "= 0.05 is %.2f (KS) and %.2f (Kuiper) over the %zu rows.\n",
                  wks, wku, sum->nrows);
}

void c1_control_text(nl_harness *r, const nl_table *pooled, const nl_table *ctl,
                     const nl_table *bl, const nl_table *uni, const nl_table *seams)
{
  nl_harness_report_table(r, ctl,
                          "\"The texture follows the pattern\" per texture, pattern and formula: r "
                          "against random tables, E_Con against the flat image (the rescaled rows "
                          "decide, one pattern at a time as C7; the literal rows are the measured "
                          "alternative)",
                          3);
  size_t q = 0; /* the headline case's index: its baselines are rows 2q, 2q + 1 */
  for (size_t row = 0; row < ctl->nrows; row++) {
    if (strcmp(nl_table_text(ctl, row, "formula"), "rescaled")) continue;
    const char *tex = nl_table_text(ctl, row, "texture"), *pat = nl_table_text(ctl, row, "pattern");
    char qty[128], claim[96];
    snprintf(claim, sizeof claim, "%s follows its pattern", tex);
    snprintf(qty, sizeof qty, "r with the pattern vs random tables, %s/%s", tex, pat);
    nl_harness_verdict_p(
        r, "control.tsv", ctl, row, qty, claim, "r_pattern", "p_random", "p 0.01 0.05",
        "independent",
        "one-sided Monte-Carlo p of the seeds' mean r against single random tables from the seed");
    nl_harness_verdict_control(r, "the optimised tables against the pattern shuffled",
                               "baselines.tsv", bl, 2 * q);
    snprintf(qty, sizeof qty, "E_Con below a flat image's, %s/%s", tex, pat);
    nl_harness_verdict_p(r, "control.tsv", ctl, row, qty, claim, "con_vs_const", "p_flat",
                         "p 0.01 0.05", "independent",
                         "E_Con over the best constant image's; one-sided t over the seeds");
    nl_harness_verdict_control(r, "the unoptimised start tables", "baselines.tsv", bl, 2 * q + 1);
    q++;
  }
  nl_harness_report_table(r, bl,
                          "Negative controls per headline case: the optimised tables against the "
                          "pattern with its targets shuffled among the cells, and the unoptimised "
                          "start tables on the pattern",
                          3);
  nl_harness_report_table(r, uni,
                          "\"Statistics kept\": uniformity of the gradient angles per texture over "
                          "its patterns and seeds (p_uniform: the smallest KS p times the runs, "
                          "Bonferroni), and the same cases optimised for E_Con alone (w1 = 0)",
                          4);
  for (size_t t = 0; t + 1 < uni->nrows; t += 2) {
    const char *tex = nl_table_text(uni, t, "texture");
    char qty[96];
    snprintf(qty, sizeof qty, "statistics kept: angles uniform, %s", tex);
    nl_harness_verdict_p(r, "uniformity.tsv", uni, t, qty,
                         "preserve its original statistical properties", "E_ks", "p_uniform",
                         "fit 0.05 0.01", "independent",
                         "KS test of the angles against uniform, the smallest p over the runs "
                         "times their number");
    nl_harness_verdict_control(r, "the same cases optimised for E_Con alone (w1 = 0)",
                               "uniformity.tsv", uni, t + 1);
  }
  for (size_t t = 0; t < pooled->nrows; t++) {
    const char *tex = nl_table_text(pooled, t, "texture");
    char qty[96], claim[96], file[64];
    snprintf(qty, sizeof qty, "%s textures' appearance (Fig 4.%zu)", tex, t + 1);
    snprintf(claim, sizeof claim, "%s textures from three control patterns", tex);
    snprintf(file, sizeof file, "%s.png", tex);
    nl_harness_verdict_figure(r, qty, claim, file, "the likeness to the thesis's images");
  }
  double rlo = INFINITY, rhi = -INFINITY;
  int pass = 0, n = 0;
  for (size_t row = 0; row < ctl->nrows; row++) {
    if (strcmp(nl_table_text(ctl, row, "formula"), "rescaled")) continue;
    rlo = fmin(rlo, nl_table_value(ctl, row, "r_pattern"));
    rhi = fmax(rhi, nl_table_value(ctl, row, "r_pattern"));
    pass += nl_table_value(ctl, row, "p_random") <= 0.01;
    n++;
  }
  nl_harness_text(r,
                  "r with the pattern, per headline case: %.3f..%.3f; %d of %d cases above the "
                  "random tables at p <= 0.01 (%g tables per case; the smallest Monte-Carlo p is "
                  "%.3g). The per-texture pool of the three patterns (no verdict) follows.\n",
                  rlo, rhi, pass, n, nl_table_value(ctl, 0, "n_random"),
                  1 / (1 + nl_table_value(ctl, 0, "n_random")));
  nl_harness_report_table(
      r, pooled,
      "The same two tests pooled per texture over its three patterns (headline formula)", 3);
  nl_study_cheng_flat_text(r, ctl, 3);
  nl_study_cheng_seams_text(r, seams, "the first seed's textures (headline formula) and of its start table");
}
