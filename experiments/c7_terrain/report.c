/* C7's report prose (Cheng 2009 sec. 4.5, Fig 4.15-4.17): every number
 * formatted from the run's setting or its summary table. */
#include "c7.h"
#include "harness/nl_harness.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void c7_text(nl_harness *r, const nl_study_cheng *s, const nl_table *sum, int mesh, double zscale)
{
  nl_harness_text(
      r,
      "**Thesis:** terrain from the flower, \"X\" and star patterns, height = controlled noise "
      "(Fig 4.15-4.17, images only). **Ours:** height = the controlled value c = (1 + V)/2 of the "
      "cloud variant (eq. 3.8) on a %d x %d mesh over the texture's unit square (the noise's [1, 2]^2, nl_cheng.h), %d x %d control grid, "
      "thesis setting, %d seeds from the seed role %s (so these are not C1's cloud runs); relief "
      "shaded from the north-west with vertical exaggeration %g.\n",
      mesh, mesh, s->grid, s->grid, nl_harness_seeds(r), s->role, zscale);
  nl_harness_text(
      r, "Headline reading: the rescaled cloud value, fixed by the thesis's own scale (black = 0, "
         "red = 1 in the pattern, so the height is read on D's 0..1 scale); the thesis prints no "
         "number for C7, so nothing could be matched to choose it.\n");
  nl_harness_figure(r, "heightmaps.png",
                    "Pattern, height map on its own 0..1 scale (no stretch) and shaded relief, per "
                    "pattern (first seed)");
  nl_harness_figure(r, "terrain.png",
                    "Per pattern: the target, the height map (x, y on the unit square) and the "
                    "surface (first seed)");
  nl_harness_report_columns(
      r, sum, "summary.tsv", "pattern,seeds," NL_STUDY_CHENG_STORY,
      "Statistics and controllability of the optimised tables (mean and spread over seeds)", 4);
  nl_study_cheng_control_text(r, sum, 1);
}

/* The seams table's row (pattern, tables_from) at origin 1; exit 1 if
 * absent (a bug). */
static size_t seam_row(const nl_table *t, const char *pattern, const char *from)
{
  for (size_t q = 0; q < t->nrows; q++)
    if (!strcmp(nl_table_text(t, q, "pattern"), pattern) &&
        !strcmp(nl_table_text(t, q, "tables_from"), from) && nl_table_value(t, q, "origin") == 1)
      return q;
  fprintf(stderr, "c7_terrain: no seams row %s/%s\n", pattern, from);
  exit(1);
}

static void seams_text(nl_harness *r, const nl_table *t)
{
  nl_study_cheng_seams_text(r, t,
                            "the height maps (every seed's table; on the last pattern also with "
                            "the control term off, without propagation and the start tables)");
  const char *star = nl_table_text(t, t->nrows - 1, "pattern"); /* the controls' pattern */
  size_t o = seam_row(t, star, "optimised"), w = seam_row(t, star, "w2=0");
  size_t np = seam_row(t, star, "no propagation"), st = seam_row(t, star, "start table");
  nl_harness_text(
      r,
      "On %s over [1, 2]^2, at the borders: optimised %.2f, with the control term off (w2 = 0) "
      "%.2f, without eq. 3.13's propagation %.2f, start tables %.2f; octave 1's border gradients "
      "point outward by %.2f +- %.2f (start tables %.2f, w2 = 0 %.2f).\n",
      star, nl_table_value(t, o, "seam_border"), nl_table_value(t, w, "seam_border"),
      nl_table_value(t, np, "seam_border"), nl_table_value(t, st, "seam_border"),
      nl_table_value(t, o, "border_outward"), nl_table_value(t, o, "border_outward_sd"),
      nl_table_value(t, st, "border_outward"), nl_table_value(t, w, "border_outward"));
}

void c7_control_text(nl_harness *r, const nl_table *ctl, const nl_table *bl,
                     const nl_table *seams, const nl_cheng_config *c)
{
  nl_harness_report_table(r, ctl,
                          "\"The height follows the pattern\": r with the pattern against random "
                          "tables, and E_Con against the best constant image, per pattern",
                          3);
  char claim[] = "the height follows the pattern";
  for (size_t q = 0; q < ctl->nrows; q++) {
    const char *p = nl_table_text(ctl, q, "pattern");
    char qty[96];
    snprintf(qty, sizeof qty, "r with the pattern vs random tables, %s", p);
    nl_harness_verdict_p(
        r, "control.tsv", ctl, q, qty, claim, "r_pattern", "p_random", "p 0.01 0.05", "independent",
        "one-sided Monte-Carlo p of the seeds' mean r against single random tables from the seed");
    nl_harness_verdict_control(r, "the optimised tables against the pattern shuffled",
                               "baselines.tsv", bl, 2 * q);
    snprintf(qty, sizeof qty, "E_Con below a flat image's, %s", p);
    nl_harness_verdict_p(r, "control.tsv", ctl, q, qty, claim, "con_vs_const", "p_flat",
                         "p 0.01 0.05", "independent",
                         "E_Con over the best constant image's; one-sided t over the seeds");
    nl_harness_verdict_control(r, "the unoptimised start tables", "baselines.tsv", bl, 2 * q + 1);
  }
  nl_harness_verdict_figure(r, "terrain appearance (Fig 4.15-4.17)",
                            "terrain height maps from the flower, X and star patterns",
                            "heightmaps.png", "the likeness to the thesis's renderings");
  double rlo = INFINITY, rhi = -INFINITY, plo = INFINITY, phi = -INFINITY;
  for (size_t q = 0; q < ctl->nrows; q++) {
    rlo = fmin(rlo, nl_table_value(ctl, q, "r_pattern"));
    rhi = fmax(rhi, nl_table_value(ctl, q, "r_pattern"));
    plo = fmin(plo, nl_table_value(ctl, q, "p_random"));
    phi = fmax(phi, nl_table_value(ctl, q, "p_random"));
  }
  nl_harness_text(r,
                  "r with the pattern: %.3f..%.3f (seeds' means) against random tables' r of mean "
                  "%.3f, sd %.3f (first row; %g tables per pattern): Monte-Carlo p %.3g..%.3g (the "
                  "smallest possible is %.3g).\n",
                  rlo, rhi, nl_table_value(ctl, 0, "r_random_mean"),
                  nl_table_value(ctl, 0, "r_random_sd"), nl_table_value(ctl, 0, "n_random"), plo,
                  phi, 1 / (1 + nl_table_value(ctl, 0, "n_random")));
  nl_study_cheng_flat_text(r, ctl, 1);
  nl_harness_report_table(r, bl,
                          "Negative controls of the two verdicts per pattern: the optimised tables "
                          "against the pattern with its targets shuffled among the cells (r, p "
                          "against random tables on that pattern), and the unoptimised start "
                          "tables on the pattern (E_Con against the flat image)",
                          3);
  /* The offset's size: the cloud value (1 + V)/2 is 1/2 wherever the noise
   * is 0, so a table that leaves c's mean alone is off by |1/2 - mean D|. */
  char md[160] = "", oa[160] = "", gap[160] = "";
  for (size_t q = 0; q < ctl->nrows; q++) {
    double d = nl_table_value(ctl, q, "mean_D"), o = nl_table_value(ctl, q, "offset_abs");
    const char *sep = q ? ", " : "";
    snprintf(md + strlen(md), sizeof md - strlen(md), "%s%.3f", sep, d);
    snprintf(oa + strlen(oa), sizeof oa - strlen(oa), "%s%.3f", sep, o);
    snprintf(gap + strlen(gap), sizeof gap - strlen(gap), "%s%.3f", sep, fabs(0.5 - d));
  }
  /* does the offset's share of E_Con order the patterns as their gap does? */
  int concordant = 1;
  for (size_t a = 0; a < ctl->nrows; a++)
    for (size_t b = a + 1; b < ctl->nrows; b++) {
      double dg = fabs(0.5 - nl_table_value(ctl, a, "mean_D")) -
                  fabs(0.5 - nl_table_value(ctl, b, "mean_D"));
      double df =
          nl_table_value(ctl, a, "con_offset_frac") - nl_table_value(ctl, b, "con_offset_frac");
      concordant &= dg * df > 0;
    }
  nl_harness_text(r,
                  "The mean offset: the patterns' mean target D is %s, the optimised tables' |mean "
                  "c - mean D| %s, against |1/2 - mean D| = %s for a value whose mean stays at the "
                  "cloud value's zero-noise 1/2. %s\n",
                  md, oa, gap,
                  concordant ? "The further a pattern's mean is from 1/2, the larger the offset's "
                               "share of E_Con (in every pair of patterns)."
                             : "The offset's share of E_Con does not order the patterns as their "
                               "distance from 1/2 does.");
  seams_text(r, seams);
  (void)c;
}
