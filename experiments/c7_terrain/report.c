/* C7's report prose (Cheng 2009 sec. 4.5, Fig 4.15-4.17): every number
 * formatted from the run's setting or its summary table. */
#include "c7.h"
#include "harness/nl_harness.h"

void c7_text(nl_harness *r, const nl_study_cheng *s, const nl_table *sum, int mesh,
             double zscale)
{
  nl_harness_text(r,
                  "**Thesis:** terrain from the flower, \"X\" and star patterns, height = "
                  "controlled noise (Fig 4.15-4.17, images only). **Ours:** height = the "
                  "controlled value c = (1 + V)/2 of the cloud variant (eq. 3.8) on a %d x %d "
                  "mesh over the unit square, %d x %d control grid, thesis setting, %d seeds from "
                  "the seed role %s (so these are not C1's cloud runs); relief shaded from the "
                  "north-west with vertical exaggeration %g.\n",
                  mesh, mesh, s->grid, s->grid, nl_harness_seeds(r), s->role, zscale);
  nl_harness_figure(r, "heightmaps.png",
                    "Pattern, height map on its own 0..1 scale (no stretch) and shaded relief, "
                    "per pattern (first seed)");
  nl_harness_figure(r, "terrain.png",
                    "Per pattern: the target, the height map (x, y on the unit square) and the "
                    "surface (first seed)");
  nl_harness_report_columns(r, sum, "summary.tsv", "pattern,seeds," NL_STUDY_CHENG_STORY,
                            "Statistics and controllability of the optimised tables (mean and "
                            "spread over seeds)",
                            4);
  nl_study_cheng_control_text(r, sum, 1);
}
