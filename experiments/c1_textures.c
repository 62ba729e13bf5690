/* C1 - Cheng 2009 Fig 4.1-4.4 (sec. 4.1): cloud, marble, erosion and fire
 * textures, each from three control patterns with its own control term
 * (eq. 3.8, 4.1, 4.2, 4.3); one montage per texture: pattern | controlled
 * value | texture. */
#include "study/nl_study_cheng.h"
#include "harness/nl_harness.h"

#include <stdio.h>
#include <stdlib.h>

#define NTEX 4
#define NPAT 3

static const char *const patterns[NTEX][NPAT] = {
  {"flower", "x", "star"}, {"rings", "spiral", "letter"}, {"disc", "star", "x"}, {"flower", "gradient", "letter"}};
static const char *const equation[NTEX] = {"eq. 3.8", "eq. 4.1", "eq. 4.2", "eq. 4.3"};

int main(int argc, char **argv)
{
  nl_study_cheng s;
  nl_study_cheng_open(&s, "c1_textures", "C1 - controlled cloud, marble, erosion and fire (Fig 4.1-4.4)", &argc, argv);
  nl_harness *r = s.r;
  int size = (int)nl_harness_param_int(r, "size", nl_harness_quick(r) ? 128 : 256, 16, 2048, "side in pixels of the texture and control-value images (quick 128)");
  nl_study_cheng_ready(&s);
  const nl_cheng_config base = s.c;
  int grid = s.grid, k = nl_harness_seeds(r);
  const char *labels[] = {"texture", "pattern"};
  nl_table *sum = nl_study_cheng_summary_alloc(2, labels);
  for (int t = 0; t < NTEX; t++) {
    nl_cheng_config c = base;
    c.con = (nl_cheng_con)t;   /* eq. 3.8, 4.1, 4.2, 4.3 in nl_cheng_con's order */
    nl_image *panels[3 * NPAT];
    const char *plab[3 * NPAT];
    for (int j = 0; j < NPAT; j++) {
      nl_cheng_pattern *pat = nl_study_cheng_pattern(&s, patterns[t][j]);
      const char *lab[2] = {nl_cheng_con_name(c.con), patterns[t][j]};
      nl_noise_grad2 *first = nl_study_cheng_seeds(&s, &c, pat, sum, 2, lab);
      panels[3 * j] = nl_study_cheng_pattern_panel(pat, size);
      panels[3 * j + 1] = nl_study_cheng_value_image(first, &c, size);
      panels[3 * j + 2] = nl_study_cheng_texture_image(first, &c, size);
      plab[3 * j] = patterns[t][j];
      plab[3 * j + 1] = "controlled value";
      plab[3 * j + 2] = nl_cheng_con_name(c.con);
      nl_noise_grad2_free(first);
      nl_cheng_pattern_free(pat);
      nl_harness_progress(r, (t * NPAT + j + 1.0) / (NTEX * NPAT), nl_cheng_con_name(c.con));
    }
    char title[96], file[64], cap[160];
    snprintf(title, sizeof title, "Fig 4.%d: %s (%s)", t + 1, nl_cheng_con_name(c.con), equation[t]);
    snprintf(file, sizeof file, "%s.png", nl_cheng_con_name(c.con));
    nl_study_cheng_montage(r, panels, plab, 3 * NPAT, 3, title, file);
    snprintf(cap, sizeof cap, "Fig 4.%d: %s textures, control term %s; pattern | controlled value | texture (first seed)",
             t + 1, nl_cheng_con_name(c.con), equation[t]);
    nl_harness_figure(r, file, cap);
  }
  nl_harness_write_table(r, sum, "summary.tsv");
  nl_harness_text(r, "**Thesis:** three patterns per texture (images only); cloud, erosion and fire blend two "
                     "colours with the noise value as alpha, marble goes through a sine; the control term "
                     "follows the texture (eq. 3.8, 4.1, 4.2, 4.3). **Ours:** %d x %d control grid, thesis "
                     "setting (F = %d, f1 = %g, a1 = %g, w1 = %g, w2 = %g), %d seeds per panel; the control "
                     "value is c = (1 + V)/2, (1 + sin(pi V))/2, |V| or the octave sum of |noise| over its "
                     "bound (nl_cheng.h); images stretch each value's 1st..99th percentile to alpha 0..1.\n",
                 grid, grid, base.octaves, base.f1, base.a1, base.w1, base.w2, k);
  nl_harness_report_columns(r, sum, "summary.tsv", "texture,pattern,seeds," NL_STUDY_CHENG_STORY, "Per texture and pattern: statistics of the optimised tables (mean and spread over seeds)", 4);
  double wks = nl_study_column_min(sum, "uniform_ks"), wku = nl_study_column_min(sum, "uniform_kuiper");
  nl_harness_text(r, "Uniformity: the smallest fraction of runs not rejected as non-uniform at alpha = 0.05 is "
                     "%.2f (KS) and %.2f (Kuiper) over the twelve panels.\n", wks, wku);
  nl_table_free(sum);
  nl_harness_check_measured(r, "*", 100);   /* measured tolerances (nl_harness.h) */
  return nl_harness_end(r);
}
