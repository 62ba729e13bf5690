/* C7 - Cheng 2009 Fig 4.15-4.17 (sec. 4.5): terrain height maps from the
 * flower, "X" and star patterns; the controlled value is the height. */
#include "study/nl_study_cheng.h"
#include "harness/nl_harness.h"

#include <stdio.h>
#include <stdlib.h>

#define NPAT 3

int main(int argc, char **argv)
{
  nl_study_cheng s;
  nl_study_cheng_open(&s, "c7_terrain", "C7 - terrain height maps (Fig 4.15-4.17)", &argc, argv);
  nl_harness *r = s.r;
  int mesh = (int)nl_harness_param_int(r, "mesh", nl_harness_quick(r) ? 48 : 96, 8, 512, "height-map mesh side: mesh x mesh heights per terrain (quick 48)");
  nl_study_cheng_ready(&s);
  const char *names[NPAT] = {"flower", "x", "star"};
  const nl_cheng_config c = s.c;
  int grid = s.grid, k = nl_harness_seeds(r);
  const char *labels[] = {"pattern"};
  nl_table *sum = nl_study_cheng_summary_alloc(1, labels);
  double *h = nl_xmalloc((size_t)mesh * mesh * sizeof *h);
  nl_image *panels[2 * NPAT];
  const char *plab[2 * NPAT];
  for (int i = 0; i < NPAT; i++) {
    nl_cheng_pattern *pat = nl_study_cheng_pattern(&s, names[i]);
    nl_noise_grad2 *first = nl_study_cheng_seeds(&s, &c, pat, sum, 1, &names[i]);
    nl_cheng_value_grid(first, &c, mesh, mesh, h);   /* the height: the controlled value */
    nl_table *ht = nl_study_cheng_matrix_table(h, mesh, mesh);
    char file[64];
    snprintf(file, sizeof file, "height_%s.tsv", names[i]);
    nl_harness_write_table(r, ht, file);
    nl_table_free(ht);
    panels[i] = nl_study_cheng_pattern_panel(pat, 192);
    panels[NPAT + i] = nl_study_cheng_value_image(first, &c, 192);
    plab[i] = names[i];
    plab[NPAT + i] = "height map";
    nl_noise_grad2_free(first);
    nl_cheng_pattern_free(pat);
    nl_harness_progress(r, (i + 1.0) / NPAT, names[i]);
  }
  nl_study_cheng_montage(r, panels, plab, 2 * NPAT, NPAT, "Fig 4.15-4.17: patterns and height maps (first seed)", "heightmaps.png");
  nl_harness_write_table(r, sum, "summary.tsv");
  nl_harness_text(r, "**Thesis:** terrain from the flower, \"X\" and star patterns, height = controlled noise "
                     "(Fig 4.15-4.17, images only). **Ours:** height = the controlled value c = (1 + V)/2 of the "
                     "cloud variant (eq. 3.8) on a %d x %d mesh over the unit square, %d x %d control grid, thesis "
                     "setting, %d seeds for the table; surfaces drawn by gnuplot (pm3d).\n", mesh, mesh, grid, grid, k);
  nl_harness_figure(r, "heightmaps.png", "Patterns and height maps (grey, stretched)");
  nl_harness_figure(r, "terrain.png", "Shaded terrain surfaces (first seed)");
  nl_harness_report_columns(r, sum, "summary.tsv", "pattern,seeds," NL_STUDY_CHENG_STORY, "Statistics of the optimised tables (mean and spread over seeds)", 4);
  nl_table_free(sum);
  free(h);
  nl_harness_check_measured(r, "*", 100);   /* measured tolerances (nl_harness.h) */
  return nl_harness_end(r);
}
