/* C8's report (report.h): the prose beside the tables and the figures'
 * captions, every number formatted from the run's tables or parameters. */
#include "report.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

void c8_slices_figure(nl_harness *r, const char *pattern, const char *file)
{
  char cap[320];
  snprintf(cap, sizeof cap,
           "%s: slices xy at z = 1/2 (top) and xz at y = 1/2 (bottom): pattern D | optimised c on "
           "0..1 | the same stretched to its 1st..99th percentile (str) | the random start table's "
           "c, stretched (first seed)",
           pattern);
  nl_harness_figure(r, file, cap);
}

void c8_levels_report(nl_harness *r, const nl_table *lv, const nl_cheng3_config *c,
                      const size_t *cnt)
{
  nl_harness_text(
      r,
      "**Levels.** Multi-level annealing (sec. 3.4.2) gives level l the table entries first used "
      "by octave l's lattice. In 3D with M = %zu: octave 1 (f = %g) uses %d entries, octave 2 adds "
      "%d, so %.0f%% of the table belongs to the first two levels and the last level owns %d. We "
      "anneal all entries against all octaves in one level (levels.tsv).\n",
      c->m, c->f1, (int)cnt[0], c->octaves > 1 ? (int)cnt[1] : 0,
      100.0 * (cnt[0] + (c->octaves > 1 ? cnt[1] : 0)) / c->m, (int)cnt[c->octaves - 1]);
  nl_harness_report_table(
      r, lv,
      "Entries per annealing level under the thesis's multi-level rule (first seed's permutation)",
      3);
}

/* E_Con's split for the optimised row i (its random start row i + 1): which
 * part makes a pattern worse than the best constant volume. */
static void c8_parts_text(nl_harness *r, const nl_table *sum, size_t i, int grid)
{
  double n = (double)grid * grid * grid;
  double off = nl_table_value(sum, i, "E_con_offset");
  double off0 = nl_table_value(sum, i + 1, "E_con_offset");
  double e0 = nl_table_value(sum, i, "E_con_const");
  const char *parts[3] = { "offset", "contrast", "shape" }, *largest = parts[0];
  double best = -1;
  for (int q = 0; q < 3; q++) {
    char col[32];
    snprintf(col, sizeof col, "con_%s_frac", parts[q]);
    if (nl_table_value(sum, i, col) > best) {
      best = nl_table_value(sum, i, col);
      largest = parts[q];
    }
  }
  char pb[64];
  nl_harness_text(
      r,
      "%s, E_Con split (mean fractions over seeds): offset n (mean c - mean D)^2 %.0f%%, "
      "contrast n (sd c - sd D)^2 %.0f%%, shape 2 n sd c sd D (1 - r) %.0f%%. The offset alone "
      "is %.4g, %.2f times the best constant volume's whole E_Con (%.4g): c's mean stays %.3f "
      "away from the pattern's mean D = %.3f (random start tables: %.3f), so %s; the largest part "
      "is the %s.\n",
      nl_table_cell_text(sum, i, 0, pb), 100 * nl_table_value(sum, i, "con_offset_frac"),
      100 * nl_table_value(sum, i, "con_contrast_frac"),
      100 * nl_table_value(sum, i, "con_shape_frac"), off, off / e0, e0, sqrt(off / n),
      nl_table_value(sum, i, "mean_D"), sqrt(off0 / n),
      off > e0 ? "the mean offset alone makes the volume worse than flat, whatever its shape"
               : "the offset alone does not exceed the flat volume's E_Con",
      largest);
}

/* Row of pattern `pat`, table `table` in the baselines table (exit-free: the
 * run wrote every pattern's four rows). */
static size_t base_row(const nl_table *b, const char *pat, const char *table)
{
  size_t q = 0;
  while (q + 1 < b->nrows && (strcmp(nl_table_text(b, q, "pattern"), pat) ||
                              strcmp(nl_table_text(b, q, "table"), table)))
    q++;
  return q;
}

/* The z-phi independence test per pattern (optimised rows): table columns
 * and one verdict row each, with the rank-paired table as its control. */
static void c8_indep_text(nl_harness *r, const nl_table *sum, const nl_table *base,
                          const nl_cheng3_config *c)
{
  nl_harness_text(
      r,
      "**Independence of z and phi.** Uniform on the sphere needs z and phi independent as well "
      "as uniform, and E_stat sees the margins only: the M pairs (z, phi) fall in %d x %d equal "
      "cells and Pearson's chi-square tests their independence (contingency, df %d) and the "
      "grid's uniformity (df %d); p_indep_bonf = min(1, seeds x smallest p) tests every seed's "
      "table at once (p_indep_pooled, the seeds' statistics summed, is the measured "
      "alternative that sees a pairing shared by all seeds). Headline reading: the test of the "
      "definition (uniform on the sphere iff "
      "(z, phi) uniform on the rectangle), with the grid fixed at the expected %g pairs per cell "
      "before the run.\n",
      C8_INDEP_BINS, C8_INDEP_BINS, (C8_INDEP_BINS - 1) * (C8_INDEP_BINS - 1),
      C8_INDEP_BINS * C8_INDEP_BINS - 1, (double)c->m / (C8_INDEP_BINS * C8_INDEP_BINS));
  nl_harness_report_columns(r, sum, "summary.tsv",
                            "pattern,table,seeds,chi2_indep,p_indep,p_indep_min,p_indep_bonf,p_"
                            "indep_pooled,p_joint,p_joint_min",
                            "z-phi independence (chi-square of the contingency table) and "
                            "uniformity of the (z, phi) grid, per pattern and table",
                            4);
  for (size_t i = 0; i < sum->nrows; i += 2) {
    char quantity[96], pb[64];
    const char *pat = nl_table_cell_text(sum, i, 0, pb);
    snprintf(quantity, sizeof quantity, "z and phi independent, optimised tables, %s", pat);
    nl_harness_verdict_p(r, "summary.tsv", sum, i, quantity,
                         "uniform on the sphere: z, phi uniform and independent", "chi2_indep",
                         "p_indep_bonf", "fit 0.05 0.01", "independent",
                         "chi-square of independence on a grid of cells, Bonferroni over seeds");
    /* A law "not rejected" is evidence only if the test rejects a table that
     * breaks it: the random start tables would pass like the optimised ones
     * (they are independent by construction), so the control is the table
     * E_stat cannot tell apart from the optimised one, its z and phi paired
     * by rank (indep.h). Chosen before the run. */
    nl_harness_verdict_control(r, "the optimised tables' z and phi paired by rank (same margins)",
                               "baselines.tsv", base, base_row(base, pat, "paired"));
  }
}

/* "Controllable noise in 3D": c follows the volume better than no control at
 * all, the best constant volume (E_Con below its E_Con, Welch); control: the
 * random start tables against the same flat volume. */
static void c8_control_text(nl_harness *r, const nl_table *base)
{
  nl_harness_report_table(r, base,
                          "Baselines of the verdicts: E_Con of the optimised tables, of the best "
                          "constant volume (flat) and of the random start tables; the z-phi test "
                          "of the optimised tables with z and phi paired by rank",
                          4);
  for (size_t q = 0; q < base->nrows; q++) {
    if (strcmp(nl_table_text(base, q, "table"), "optimised")) continue;
    const char *pat = nl_table_text(base, q, "pattern");
    size_t f = base_row(base, pat, "flat"), rn = base_row(base, pat, "random");
    char quantity[96];
    snprintf(quantity, sizeof quantity, "E_Con below a flat volume, optimised tables, %s", pat);
    nl_harness_text(r,
                    "%s: E_Con %.4g (optimised) against %.4g for the best constant volume "
                    "(%.2f times) and %.4g for the random start tables.\n",
                    pat, nl_table_value(base, q, "E_con"), nl_table_value(base, f, "E_con"),
                    nl_table_value(base, q, "E_con") / nl_table_value(base, f, "E_con"),
                    nl_table_value(base, rn, "E_con"));
    nl_harness_verdict_less(r, "baselines.tsv", base, q, f, quantity,
                            "the noise follows the control pattern (thesis ch. 5: in 3D)", "E_con",
                            "E_con_sd", "seeds", 0.05, "independent");
    nl_harness_verdict_control_less(r, "the random start tables", "baselines.tsv", base, rn, f);
  }
}

void c8_report(nl_harness *r, const nl_table *sum, const nl_table *base,
               const nl_cheng3_config *c, int grid, int k)
{
  nl_harness_text(
      r,
      "**Setting (beyond the thesis).** %d^3 control cells, M = %zu unit gradients, F = %d octaves "
      "from f1 = %g (a1 = %g), w1 = %g, w2 = %g, %d temperatures x %g moves per entry, %d seeds "
      "per row. E_stat = max(D_z, D_phi): KS of z = cos(polar) against U(-1, 1) and of phi against "
      "U(0, 2 pi), uniform on the sphere iff both hold independently; p_stat = min(1, 2 min(p_z, "
      "p_phi)) (Bonferroni). Kuiper on phi and Rayleigh's test (3 M R^2 ~ chi2_3, R the mean "
      "resultant) are checks the objective does not optimise.\n",
      grid, c->m, c->octaves, c->f1, c->a1, c->w1, c->w2, c->sched.n_temps, c->sched.moves_per_var,
      k);
  nl_harness_report_columns(
      r, sum, "summary.tsv",
      "pattern,table,seeds,E_stat,E_stat_sd,p_stat_min,uniform,p_kuiper_min,p_rayleigh_min,E_con,E_"
      "con_sd,r_pattern,r_pattern_sd,contrast,E_con_random,E_con_const,con_vs_const",
      "Per pattern: optimised tables against their random start tables (mean and spread over "
      "seeds)",
      4);
  for (size_t i = 0; i + 1 < sum->nrows; i += 2) { /* rows: optimised, random per pattern */
    double e = nl_table_value(sum, i, "E_con");
    double e0 = nl_table_value(sum, i, "E_con_const");
    double er = nl_table_value(sum, i + 1, "E_con");
    nl_harness_text(r,
                    "%s: E_stat %.4f (random tables %.4f), smallest p_stat %.3f, smallest Rayleigh "
                    "p %.3f; E_Con %.4g +- %.3g, %.0f%% below the random tables' %.4g, r with the "
                    "pattern %.2f (random %.2f), contrast %.3f. %s (best constant volume: E_Con "
                    "%.4g, ratio %.2f; the pattern's own sd is %.3f).\n",
                    nl_table_cell_text(sum, i, 0, (char[64]){ 0 }),
                    nl_table_value(sum, i, "E_stat"), nl_table_value(sum, i + 1, "E_stat"),
                    nl_table_value(sum, i, "p_stat_min"), nl_table_value(sum, i, "p_rayleigh_min"),
                    e, nl_table_value(sum, i, "E_con_sd"), 100 * (1 - e / er), er,
                    nl_table_value(sum, i, "r_pattern"), nl_table_value(sum, i + 1, "r_pattern"),
                    nl_table_value(sum, i, "contrast"),
                    e > e0 ? "**Worse than the best constant volume** in the E_Con sense"
                           : "Better than the best constant volume",
                    e0, e / e0, sqrt(e0 / (double)grid / grid / grid));
    c8_parts_text(r, sum, i, grid);
  }
  c8_control_text(r, base);
  c8_indep_text(r, sum, base, c);
  nl_harness_figure(r, "uniformity.png",
                    "Uniformity on the sphere (torus, first seed): ECDF minus the uniform CDF of "
                    "(z + 1)/2 and phi / 2 pi, optimised and random start table");
  nl_harness_figure(r, "volume.png",
                    "Torus (first seed): the voxels inside the pattern (left) and the voxels of "
                    "the optimised c above the level that encloses the same volume (right)");
}
