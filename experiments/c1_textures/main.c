/* C1 - Cheng 2009 Fig 4.1-4.4 (sec. 4.1): cloud, marble, erosion and fire
 * textures, each from three control patterns with its own control term
 * (eq. 3.8, 4.1, 4.2, 4.3); one montage per texture: pattern | controlled
 * value without and with the display stretch | texture | the literal
 * formula's value. Each panel also runs with the thesis's formulas taken
 * literally (V unscaled: c = V, sin V, |V|), the reading beside ours. */
#include "study/nl_study_cheng.h"
#include "harness/nl_harness.h"

#include <stdio.h>
#include <stdlib.h>

#define NTEX 4
#define NPAT 3
#define NCOL 5

static const char *const patterns[NTEX][NPAT] = {
  {"flower", "x", "star"}, {"rings", "spiral", "letter"}, {"disc", "star", "x"}, {"flower", "gradient", "letter"}};
static const char *const equation[NTEX] = {"eq. 3.8", "eq. 4.1", "eq. 4.2", "eq. 4.3"};
static const char *const formula[2] = {"rescaled", "literal"};

int main(int argc, char **argv)
{
  nl_study_cheng s;
  nl_study_cheng_open(&s, "c1_textures", "C1 - controlled cloud, marble, erosion and fire (Fig 4.1-4.4)", &argc, argv);
  nl_harness *r = s.r;
  int size = (int)nl_harness_param_int(r, "size", nl_harness_quick(r) ? 128 : 256, 16, 2048, "side in pixels of the texture and control-value images (quick 128)");
  nl_study_cheng_ready(&s);
  const nl_cheng_config base = s.c;
  int grid = s.grid, k = nl_harness_seeds(r);
  const char *labels[] = {"texture", "pattern", "formula"};
  nl_table *sum = nl_study_cheng_summary_alloc(3, labels);
  s.cost = nl_study_cheng_cost_alloc();
  /* Every (texture, pattern, formula) case over the seeds as one set of
   * independent runs on the run's threads; rows in case order. */
  nl_cheng_config cs[2 * NTEX * NPAT];
  nl_cheng_pattern *pats[NTEX * NPAT];
  const nl_cheng_pattern *pp[2 * NTEX * NPAT];
  nl_noise_grad2 *firsts[2 * NTEX * NPAT];
  for (int i = 0; i < NTEX * NPAT; i++) {
    cs[2 * i] = base;
    cs[2 * i].con = (nl_cheng_con)(i / NPAT);   /* eq. 3.8, 4.1, 4.2, 4.3 in nl_cheng_con's order */
    cs[2 * i + 1] = cs[2 * i];
    cs[2 * i + 1].literal = 1;
    pp[2 * i] = pp[2 * i + 1] = pats[i] = nl_study_cheng_pattern(&s, patterns[i / NPAT][i % NPAT]);
  }
  nl_cheng_eval *evs = nl_study_cheng_runs(&s, 2 * NTEX * NPAT, cs, pp, firsts);
  for (int i = 0; i < 2 * NTEX * NPAT; i++) {
    const char *lab[3] = {nl_cheng_con_name(cs[i].con), patterns[i / 2 / NPAT][i / 2 % NPAT], formula[i % 2]};
    nl_study_cheng_rows_add(&s, sum, 3, lab, evs + (size_t)i * k);
  }
  free(evs);
  for (int t = 0; t < NTEX; t++) {
    nl_cheng_config c = cs[2 * NPAT * t], cl = cs[2 * NPAT * t + 1];
    nl_image *panels[NCOL * NPAT];
    const char *plab[NCOL * NPAT];
    for (int j = 0; j < NPAT; j++) {
      nl_cheng_pattern *pat = pats[t * NPAT + j];
      nl_noise_grad2 *first = firsts[2 * (t * NPAT + j)], *lit = firsts[2 * (t * NPAT + j) + 1];
      nl_image **p = panels + NCOL * j;
      p[0] = nl_study_cheng_pattern_panel(pat, size);
      p[1] = nl_study_cheng_value_image_raw(first, &c, size);
      p[2] = nl_study_cheng_value_image(first, &c, size);
      p[3] = nl_study_cheng_texture_image(first, &c, size);
      p[4] = nl_study_cheng_value_image(lit, &cl, size);
      const char *pl[NCOL] = {patterns[t][j], "c, raw 0..1", "c, stretched", nl_cheng_con_name(c.con), "literal c"};
      for (int q = 0; q < NCOL; q++) plab[NCOL * j + q] = pl[q];
      nl_noise_grad2_free(first);
      nl_noise_grad2_free(lit);
      nl_cheng_pattern_free(pat);
      nl_harness_progress(r, (t * NPAT + j + 1.0) / (NTEX * NPAT), nl_cheng_con_name(c.con));
    }
    char title[96], file[64], cap[256];
    snprintf(title, sizeof title, "Fig 4.%d: %s (%s)", t + 1, nl_cheng_con_name(c.con), equation[t]);
    snprintf(file, sizeof file, "%s.png", nl_cheng_con_name(c.con));
    nl_study_cheng_montage(r, panels, plab, NCOL * NPAT, NCOL, title, file);
    snprintf(cap, sizeof cap, "Fig 4.%d: %s textures, control term %s; pattern | controlled value on its own 0..1 scale "
             "| the same stretched to its 1st..99th percentile | texture | the literal formula's value, stretched (first seed)",
             t + 1, nl_cheng_con_name(c.con), equation[t]);
    nl_harness_figure(r, file, cap);
  }
  nl_harness_write_table(r, sum, "summary.tsv");
  nl_harness_text(r, "**Thesis:** three patterns per texture (images only); cloud, erosion and fire blend two "
                     "colours with the noise value as alpha, marble goes through a sine; the control term "
                     "follows the texture (eq. 3.8, 4.1, 4.2, 4.3). **Ours:** %d x %d control grid, thesis "
                     "setting (F = %d, f1 = %g, a1 = %g, w1 = %g, w2 = %g), %d seeds per row. Formula "
                     "\"rescaled\" (our headline reading): c = (1 + V)/2, (1 + sin(pi V))/2, |V| or the octave "
                     "sum of |noise| over its bound, V = the fractal sum over its analytic bound (nl_cheng.h); "
                     "\"literal\": the thesis's formulas as printed, c = V, sin V, |V|, sum |noise| / a with V "
                     "unscaled (E_Con = sum (c - D)^2 either way). Images stretch each value's 1st..99th "
                     "percentile to 0..1 except the \"no stretch\" panel.\n",
                 grid, grid, base.octaves, base.f1, base.a1, base.w1, base.w2, k);
  nl_harness_report_columns(r, sum, "summary.tsv", "texture,pattern,formula,seeds," NL_STUDY_CHENG_STORY, "Per texture, pattern and formula: statistics and controllability of the optimised tables (mean and spread over seeds)", 4);
  nl_study_cheng_control_text(r, sum, 3);
  /* Marble's gain: the sine's argument is pi s F_sum rescaled, F_sum literally (eq. 4.1's sin V). */
  nl_noise_octaves o = nl_noise_octaves_cheng(base.octaves, base.f1, base.a1);
  double asum = 0;
  for (int l = 0; l < o.n; l++) asum += o.amp[l];
  double gain = NL_PI / (NL_NOISE2_BOUND * asum);
  nl_harness_text(r, "Marble's control term: the rescaled sine's argument is pi V = %.3g F_sum (V = F_sum over its bound), "
                     "%.2fx eq. 4.1's literal sin(F_sum); after (1 + sin)/2 the slope of c at F_sum = 0 is %.3g, "
                     "against 1 for the literal sin and %.3g for the rescaled cloud term (1 + V)/2. Much of marble's "
                     "r rests on this gain: compare its literal rows.\n", gain, gain, gain / 2, gain / (2 * NL_PI));
  double wks = nl_study_column_min(sum, "uniform_ks"), wku = nl_study_column_min(sum, "uniform_kuiper");
  nl_harness_text(r, "Uniformity: the smallest fraction of runs not rejected as non-uniform at alpha = 0.05 is "
                     "%.2f (KS) and %.2f (Kuiper) over the %zu rows.\n", wks, wku, sum->nrows);
  nl_study_cheng_cost_report(r, s.cost);
  nl_table_free(s.cost);
  nl_table_free(sum);
  nl_harness_check_measured(r, "*", 100);   /* measured tolerances (nl_harness.h) */
  return nl_harness_end(r);
}
