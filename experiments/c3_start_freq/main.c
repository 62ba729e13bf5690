/* C3 - Cheng 2009 Fig 4.7 (sec. 4.3.1): the starting frequency f1 = 2, 4, 6,
 * 8 of the controlled fractal sum; lower f1 should look smoother. */
#include "study/nl_study_cheng.h"
#include "harness/nl_harness.h"

#include <stdio.h>
#include <stdlib.h>

#define NF 4

int main(int argc, char **argv)
{
  nl_study_cheng s;
  nl_study_cheng_open(&s, "c3_start_freq", "C3 - starting frequency f1 (Fig 4.7)", &argc, argv);
  nl_study_cheng_ready(&s);
  nl_harness *r = s.r;
  const nl_cheng_config base = s.c;
  int grid = s.grid, k = nl_harness_seeds(r);
  nl_cheng_pattern *pat = nl_study_cheng_pattern(&s, "star");
  const double f1s[NF] = {2, 4, 6, 8};
  const char *labels[] = {"f1"};
  nl_table *sum = nl_study_cheng_summary_alloc(1, labels);
  nl_image *panels[2 * NF + 2];
  char lab[2 * NF + 2][48];
  const char *labp[2 * NF + 2];
  panels[0] = nl_study_cheng_pattern_panel(pat, 160);
  panels[NF + 1] = nl_study_cheng_pattern_panel(pat, 160);
  snprintf(lab[0], sizeof lab[0], "pattern");
  snprintf(lab[NF + 1], sizeof lab[NF + 1], "pattern");
  for (int i = 0; i < NF; i++) {
    nl_cheng_config c = base;
    c.f1 = f1s[i];
    char f[32];
    nl_table_format_double(f, f1s[i]);
    const char *l[1] = {f};
    nl_noise_grad2 *first = nl_study_cheng_seeds(&s, &c, pat, sum, 1, l);
    panels[i + 1] = nl_study_cheng_value_image(first, &c, 160);
    panels[NF + 2 + i] = nl_study_cheng_texture_image(first, &c, 160);
    snprintf(lab[i + 1], sizeof lab[i + 1], "(%c) f1=%g", 'a' + i, f1s[i]);
    snprintf(lab[NF + 2 + i], sizeof lab[NF + 2 + i], "(%c) f1=%g cloud", 'a' + i, f1s[i]);
    nl_noise_grad2_free(first);
    nl_harness_progress(r, (i + 1.0) / NF, "f1");
  }
  for (int i = 0; i < 2 * NF + 2; i++) labp[i] = lab[i];
  nl_study_cheng_montage(r, panels, labp, 2 * NF + 2, NF + 1, "Fig 4.7: starting frequency f1 (first seed)",
                         "panels.png");
  nl_harness_write_table(r, sum, "summary.tsv");

  double ro[NF], ec[NF];
  for (int i = 0; i < NF; i++) {
    ro[i] = nl_table_value(sum, (size_t)i, "roughness");
    ec[i] = nl_table_value(sum, (size_t)i, "E_con");
  }
  int monotone = 1;
  for (int i = 1; i < NF; i++) monotone &= ro[i] > ro[i - 1];
  nl_harness_text(r, "**Thesis:** the controlled fractal sum for f1 = 2, 4, 6, 8 (Fig 4.7, images only); "
                     "\"the appearance of lower starting frequency is smoother\". **Ours:** pattern star, "
                     "%d x %d control grid, F = %d, a1 = %g, w1 = %g, w2 = %g, %d seeds per f1. Smoothness is "
                     "measured as the rms gradient of the control value (\"roughness\", per unit length).\n",
                 grid, grid, base.octaves, base.a1, base.w1, base.w2, k);
  nl_harness_figure(r, "panels.png", "Controlled value (top) and cloud texture (bottom) for f1 = 2, 4, 6, 8");
  nl_harness_report_columns(r, sum, "summary.tsv", "f1,seeds," NL_STUDY_CHENG_STORY, "Statistics per f1 (mean and spread over seeds)", 4);
  int best = 0;
  for (int i = 1; i < NF; i++) if (ec[i] < ec[best]) best = i;
  nl_harness_text(r, "Roughness %.3g, %.3g, %.3g, %.3g for f1 = 2, 4, 6, 8: %s. E_Con %.4g, %.4g, %.4g, %.4g is "
                     "lowest at f1 = %g (the thesis gives no E_Con per f1 to compare).\n",
                 ro[0], ro[1], ro[2], ro[3],
                 monotone ? "strictly increasing with f1, so lower f1 is smoother, as the thesis says"
                          : "NOT monotone in f1",
                 ec[0], ec[1], ec[2], ec[3],
                 f1s[best]);
  nl_study_cheng_control_text(r, sum, 1);
  nl_table_free(sum);
  nl_cheng_pattern_free(pat);
  nl_harness_check_measured(r, "*", 100);   /* measured tolerances (nl_harness.h) */
  return nl_harness_end(r);
}
