/* C7 - Cheng 2009 Fig 4.15-4.17 (sec. 4.5): terrain height maps from the
 * flower, "X" and star patterns; the controlled value is the height. Runs of
 * its own (seed role "cheng.terrain"), not C1's cloud runs again. "The
 * height follows the pattern" is decided per pattern by r against random
 * tables and E_Con against a flat image (control.tsv); the seams of the
 * height maps are located and their cause measured (seams.tsv). */
#include "c7.h"
#include "study/nl_study_cheng.h"
#include "harness/nl_harness.h"

#include <stdio.h>
#include <stdlib.h>

#define NPAT  3
#define NCOL  3   /* panels per pattern: pattern, height, relief */
#define PANEL 192 /* side in pixels of the panels */

static const char *const names[NPAT] = { "flower", "x", "star" };

int main(int argc, char **argv)
{
  nl_study_cheng s;
  nl_study_cheng_open(&s, "c7_terrain", "C7 - terrain height maps (Fig 4.15-4.17)", &argc, argv);
  nl_harness *r = s.r;
  int mesh = (int)nl_harness_param_int(r, "mesh", nl_harness_quick(r) ? 48 : 96, 8, 512,
                                       "height-map mesh side: mesh x mesh heights per terrain "
                                       "(quick 48)");
  double zscale = nl_harness_param(r, "relief_z", 0.08, 1e-3, 100,
                                   "vertical exaggeration of the shaded relief (heights 0..1 "
                                   "over the unit square)");
  int nrand =
      (int)nl_harness_param_int(r, "random_tables", nl_harness_quick(r) ? 99 : 999, 9, 1000000,
                                "random (unoptimised) tables per pattern: the null "
                                "distribution of r with the pattern (quick 99)");
  nl_study_cheng_ready(&s);
  /* C1 runs the same cloud setting on these patterns: C7 gets its own runs. */
  s.role = "cheng.terrain";
  const nl_cheng_config c = s.c;
  const char *labels[] = { "pattern" };
  nl_table *sum = nl_study_cheng_summary_alloc(1, labels);
  nl_table *ctl = nl_study_cheng_control_alloc(1, labels);
  const char *blabels[] = { "pattern", "baseline" };
  nl_table *bl = nl_study_cheng_control_alloc(2, blabels);
  const char *slabels[] = { "pattern", "tables_from" };
  nl_table *seams = nl_study_cheng_seams_alloc(2, slabels);
  int k = nl_harness_seeds(r);
  nl_noise_grad2 **tables = nl_xmalloc((size_t)k * sizeof *tables);
  double *h = nl_xmalloc((size_t)mesh * mesh * sizeof *h);
  double *hp = nl_xmalloc((size_t)PANEL * PANEL * sizeof *hp);
  nl_image *panels[NCOL * NPAT];
  /* the figure's tables (tests/oracle_cheng.c) */
  nl_table *tabs = nl_study_cheng_tables_alloc(1, labels);
  const char *plab[NCOL * NPAT];
  for (int i = 0; i < NPAT; i++) {
    nl_cheng_pattern *pat = nl_study_cheng_pattern(&s, names[i]);
    nl_cheng_eval *evs = c7_runs(&s, &c, pat, tables);
    nl_study_cheng_rows_add(&s, sum, 1, &names[i], evs);
    unsigned long rseed = nl_seed_stream(nl_harness_seed(r), "c7.random_r", (unsigned long)i);
    nl_study_cheng_control_add(&s, ctl, 1, &names[i], &c, pat, evs, nrand, rseed, NULL);
    /* the verdicts' negative controls: the pattern shuffled, the start tables */
    nl_study_cheng_baselines_add(&s, bl, 2, &names[i], &c, pat, tables, nrand, rseed);
    const char *sl[2] = { names[i], "optimised" };
    nl_study_cheng_seams_add(seams, 2, sl, (const nl_noise_grad2 *const *)tables, k, &c, pat);
    /* the alternative domain [0, 1]^2 (origin 0; nl_cheng.h READINGS): the
     * same runs, their seams */
    {
      nl_cheng_config c0 = c;
      c0.origin = 0;
      nl_noise_grad2 **t0 = nl_xmalloc((size_t)k * sizeof *t0);
      free(c7_runs(&s, &c0, pat, t0));
      nl_study_cheng_seams_add(seams, 2, sl, (const nl_noise_grad2 *const *)t0, k, &c0, pat);
      for (int j = 0; j < k; j++) nl_noise_grad2_free(t0[j]);
      free(t0);
    }
    /* the seams' controls on the last pattern (star) */
    if (i == NPAT - 1) c7_seam_controls(&s, seams, &c, pat, names[i]);
    free(evs);
    for (int j = 1; j < k; j++) nl_noise_grad2_free(tables[j]);
    nl_noise_grad2 *first = tables[0];
    nl_study_cheng_tables_add(tabs, 1, &names[i], first);
    /* The height: the controlled value on the mesh, then at the panels' size. */
    nl_cheng_value_grid(first, &c, mesh, mesh, h);
    char file[64];
    nl_table *ht = c7_matrix_table(h, mesh, mesh);
    snprintf(file, sizeof file, "height_%s.tsv", names[i]);
    nl_harness_write_table(r, ht, file);
    nl_table *pt = c7_pattern_table(pat);
    snprintf(file, sizeof file, "pattern_%s.tsv", names[i]);
    nl_harness_write_table(r, pt, file);
    nl_table_free(ht);
    nl_table_free(pt);
    nl_cheng_value_grid(first, &c, PANEL, PANEL, hp);
    panels[NCOL * i] = nl_study_cheng_pattern_panel(pat, PANEL);
    panels[NCOL * i + 1] = nl_study_cheng_value_image_raw(first, &c, PANEL);
    panels[NCOL * i + 2] = c7_relief_image(hp, PANEL, PANEL, zscale);
    plab[NCOL * i] = names[i];
    plab[NCOL * i + 1] = "height, grey 0..1";
    plab[NCOL * i + 2] = "shaded relief";
    nl_noise_grad2_free(first);
    nl_cheng_pattern_free(pat);
    nl_harness_progress(r, (i + 1.0) / NPAT, names[i]);
  }
  nl_study_cheng_montage(r, panels, plab, NCOL * NPAT, NCOL,
                         "Fig 4.15-4.17: pattern | height | relief", "heightmaps.png");
  nl_harness_write_table(r, tabs, "tables.tsv");
  nl_table_free(tabs);
  nl_harness_write_table(r, sum, "summary.tsv");
  nl_harness_write_table(r, ctl, "control.tsv");
  nl_harness_write_table(r, bl, "baselines.tsv");
  nl_harness_write_table(r, seams, "seams.tsv");
  c7_text(r, &s, sum, mesh, zscale);
  c7_control_text(r, ctl, bl, seams, &c);
  nl_table_free(bl);
  nl_table_free(sum);
  nl_table_free(ctl);
  nl_table_free(seams);
  free(tables);
  free(h);
  free(hp);
  nl_harness_check_measured(r, "*", 100); /* measured tolerances (nl_harness.h) */
  return nl_harness_end(r);
}
