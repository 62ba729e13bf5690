/* C3 - Cheng 2009 Fig 4.7 (sec. 4.3.1): the starting frequency f1 = 2, 4, 6,
 * 8 of the controlled fractal sum; lower f1 should look smoother. */
#include "study/nl_study_cheng.h"
#include "report/nl_report.h"

#include <stdio.h>
#include <stdlib.h>

#define NF 4

int main(int argc, char **argv)
{
  nl_cheng_config base;
  int grid;
  const char *pdir;
  nl_run *r = nl_cheng_begin("c3_start_freq", "C3 - starting frequency f1 (Fig 4.7)", &argc, argv, &base, &grid, &pdir);
  nl_cheng_params_done(r, &base, pdir);
  nl_cheng_pattern *pat = nl_cheng_pattern_load_or_die("c3_start_freq", pdir, "star", grid);

  const double f1s[NF] = {2, 4, 6, 8};
  int k = nl_run_seeds(r);
  const char *labels[] = {"f1"};
  nl_table *sum = nl_cheng_summary_alloc(1, labels);
  nl_cheng_eval *evs = nl_xmalloc((size_t)k * sizeof *evs);
  nl_image *panels[2 * NF + 2];
  char lab[2 * NF + 2][48];
  const char *labp[2 * NF + 2];
  panels[0] = nl_cheng_pattern_panel(pat, 160);
  panels[NF + 1] = nl_cheng_pattern_panel(pat, 160);
  snprintf(lab[0], sizeof lab[0], "pattern");
  snprintf(lab[NF + 1], sizeof lab[NF + 1], "pattern");
  nl_error err;
  for (int i = 0; i < NF; i++) {
    nl_cheng_config c = base;
    c.f1 = f1s[i];
    nl_grad2 *first;
    if (nl_cheng_run_seeds(&c, pat, nl_run_seed(r), k, evs, &first, &err)) nl_run_die(r, 1, "%s", err.msg);
    char f[32];
    nl_format_double(f, f1s[i]);
    const char *l[1] = {f};
    nl_cheng_summary_add(sum, 1, l, evs, k);
    panels[i + 1] = nl_cheng_value_image(first, &c, 160);
    panels[NF + 2 + i] = nl_cheng_texture_image(first, &c, 160);
    snprintf(lab[i + 1], sizeof lab[i + 1], "(%c) f1=%g", 'a' + i, f1s[i]);
    snprintf(lab[NF + 2 + i], sizeof lab[NF + 2 + i], "(%c) f1=%g cloud", 'a' + i, f1s[i]);
    nl_grad2_free(first);
    nl_run_progress(r, (i + 1.0) / NF, "f1");
  }
  for (int i = 0; i < 2 * NF + 2; i++) labp[i] = lab[i];
  nl_image *m = nl_montage((const nl_image *const *)panels, labp, 2 * NF + 2, NF + 1,
                           "Fig 4.7: starting frequency f1 (first seed)");
  nl_run_image(r, m, "panels.png");
  nl_run_table(r, sum, "summary.tsv");

  size_t RO = (size_t)nl_table_column(sum, "roughness"), EC = (size_t)nl_table_column(sum, "E_con");
  int monotone = 1;
  for (int i = 1; i < NF; i++) monotone &= nl_table_get(sum, (size_t)i, RO) > nl_table_get(sum, (size_t)i - 1, RO);
  nl_report_text(r, "**Thesis:** the controlled fractal sum for f1 = 2, 4, 6, 8 (Fig 4.7, images only); "
                    "\"the appearance of lower starting frequency is smoother\". **Ours:** pattern star, "
                    "%d x %d control grid, F = %d, a1 = %g, w1 = %g, w2 = %g, %d seeds per f1. Smoothness is "
                    "measured as the rms gradient of the control value (\"roughness\", per unit length).\n",
                 grid, grid, base.octaves, base.a1, base.w1, base.w2, k);
  nl_report_figure(r, "panels.png", "Controlled value (top) and cloud texture (bottom) for f1 = 2, 4, 6, 8");
  nl_report_table(r, sum, "Statistics per f1 (mean and spread over seeds)", 4);
  int best = 0;
  for (int i = 1; i < NF; i++) if (nl_table_get(sum, (size_t)i, EC) < nl_table_get(sum, (size_t)best, EC)) best = i;
  nl_report_text(r, "Roughness %.3g, %.3g, %.3g, %.3g for f1 = 2, 4, 6, 8: %s. E_Con %.4g, %.4g, %.4g, %.4g is "
                    "lowest at f1 = %g (the thesis gives no E_Con per f1 to compare).\n",
                 nl_table_get(sum, 0, RO), nl_table_get(sum, 1, RO), nl_table_get(sum, 2, RO), nl_table_get(sum, 3, RO),
                 monotone ? "strictly increasing with f1, so lower f1 is smoother, as the thesis says"
                          : "NOT monotone in f1",
                 nl_table_get(sum, 0, EC), nl_table_get(sum, 1, EC), nl_table_get(sum, 2, EC), nl_table_get(sum, 3, EC),
                 f1s[best]);
  for (int i = 0; i < 2 * NF + 2; i++) nl_image_free(panels[i]);
  nl_image_free(m);
  nl_table_free(sum);
  free(evs);
  nl_cheng_pattern_free(pat);
  nl_run_check_measured(r, "*", 100);   /* measured tolerances (nl_report.h) */
  return nl_run_end(r);
}
