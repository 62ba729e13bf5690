/* C7 - Cheng 2009 Fig 4.15-4.17 (sec. 4.5): terrain height maps from the
 * flower, "X" and star patterns; the controlled value is the height. Runs of
 * its own (seed role "cheng.terrain"), not C1's cloud runs again. */
#include "study/nl_study_cheng.h"
#include "harness/nl_harness.h"

#include <stdio.h>
#include <stdlib.h>

#define NPAT 3
#define NCOL 3

int main(int argc, char **argv)
{
  nl_study_cheng s;
  nl_study_cheng_open(&s, "c7_terrain", "C7 - terrain height maps (Fig 4.15-4.17)", &argc, argv);
  nl_harness *r = s.r;
  int mesh = (int)nl_harness_param_int(r, "mesh", nl_harness_quick(r) ? 48 : 96, 8, 512, "height-map mesh side: mesh x mesh heights per terrain (quick 48)");
  double zscale = nl_harness_param(r, "relief_z", 0.08, 1e-3, 100, "vertical exaggeration of the shaded relief (heights 0..1 over the unit square)");
  nl_study_cheng_ready(&s);
  s.role = "cheng.terrain";   /* C1 runs the same cloud setting on these patterns: C7 gets its own runs */
  const char *names[NPAT] = {"flower", "x", "star"};
  const nl_cheng_config c = s.c;
  int grid = s.grid, k = nl_harness_seeds(r), px = 192;
  const char *labels[] = {"pattern"};
  nl_table *sum = nl_study_cheng_summary_alloc(1, labels);
  double *h = nl_xmalloc((size_t)mesh * mesh * sizeof *h), *hp = nl_xmalloc((size_t)px * px * sizeof *hp);
  nl_image *panels[NCOL * NPAT];
  const char *plab[NCOL * NPAT];
  for (int i = 0; i < NPAT; i++) {
    nl_cheng_pattern *pat = nl_study_cheng_pattern(&s, names[i]);
    nl_noise_grad2 *first = nl_study_cheng_seeds(&s, &c, pat, sum, 1, &names[i]);
    nl_cheng_value_grid(first, &c, mesh, mesh, h);   /* the height: the controlled value */
    char file[64];
    nl_table *ht = nl_study_cheng_matrix_table(h, mesh, mesh), *pt = nl_study_cheng_pattern_table(pat);
    snprintf(file, sizeof file, "height_%s.tsv", names[i]);
    nl_harness_write_table(r, ht, file);
    snprintf(file, sizeof file, "pattern_%s.tsv", names[i]);
    nl_harness_write_table(r, pt, file);
    nl_table_free(ht);
    nl_table_free(pt);
    nl_cheng_value_grid(first, &c, px, px, hp);
    panels[NCOL * i] = nl_study_cheng_pattern_panel(pat, px);
    panels[NCOL * i + 1] = nl_study_cheng_value_image_raw(first, &c, px);
    panels[NCOL * i + 2] = nl_study_cheng_relief_image(hp, px, px, zscale);
    plab[NCOL * i] = names[i];
    plab[NCOL * i + 1] = "height, grey 0..1";
    plab[NCOL * i + 2] = "shaded relief";
    nl_noise_grad2_free(first);
    nl_cheng_pattern_free(pat);
    nl_harness_progress(r, (i + 1.0) / NPAT, names[i]);
  }
  nl_study_cheng_montage(r, panels, plab, NCOL * NPAT, NCOL, "Fig 4.15-4.17: pattern | height | relief", "heightmaps.png");
  nl_harness_write_table(r, sum, "summary.tsv");
  nl_harness_text(r, "**Thesis:** terrain from the flower, \"X\" and star patterns, height = controlled noise "
                     "(Fig 4.15-4.17, images only). **Ours:** height = the controlled value c = (1 + V)/2 of the "
                     "cloud variant (eq. 3.8) on a %d x %d mesh over the unit square, %d x %d control grid, thesis "
                     "setting, %d seeds from the seed role cheng.terrain (so these are not C1's cloud runs); "
                     "relief shaded from the north-west with vertical exaggeration %g.\n", mesh, mesh, grid, grid, k, zscale);
  nl_harness_figure(r, "heightmaps.png", "Pattern, height map on its own 0..1 scale (no stretch) and shaded relief, per pattern (first seed)");
  nl_harness_figure(r, "terrain.png", "Per pattern: the target, the height map (x, y on the unit square) and the surface (first seed)");
  nl_harness_report_columns(r, sum, "summary.tsv", "pattern,seeds," NL_STUDY_CHENG_STORY, "Statistics and controllability of the optimised tables (mean and spread over seeds)", 4);
  nl_study_cheng_control_text(r, sum, 1);
  nl_table_free(sum);
  free(h);
  free(hp);
  nl_harness_check_measured(r, "*", 100);   /* measured tolerances (nl_harness.h) */
  return nl_harness_end(r);
}
