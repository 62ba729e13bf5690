/* c4.h - C4's Table 4.1 analysis (table41.c) and its report prose (report.c).
 *
 * Cheng 2009 sec. 4.3.2 weighs the statistic term against the control term,
 * E = w1 E_KS + w2 E_Con (eq. 3.9), and prints six pairs (w1, w2) in Table
 * 4.1. The table's text reads the weights the other way round, so C4 runs
 * every pair printed (rows 0, 2, 4, ... of its run table) and swapped (rows
 * 1, 3, 5, ...), and asks which reading fits all six rows.
 */
#ifndef C4_H
#define C4_H

#include "study/nl_study_cheng.h"

/* A row of Table 4.1 as printed: w1, E_KS, w2, E_Con. */
#define C4_TABLE41_COLS 4
typedef double c4_thesis_row[C4_TABLE41_COLS];

/* ---- the runs (cases.c) ------------------------------------------------ */

/* One case (w1, w2) and its summary labels: reading, panel, w1, w2 (the
 * weights as the table writes numbers). */
typedef struct {
  const char *lab[4];
  char txt[2][32];
} c4_case;
/* Sets c's weights to (w1, w2) and w's labels; reading and panel are kept
 * by pointer. */
void c4_case_set(nl_cheng_config *c, c4_case *w, const char *reading, const char *panel,
                 double w1, double w2);
/* Fig 4.8 as textures.png: the pattern, then the first seed's controlled
 * value per pair on its own 0..1 scale (no display stretch); top row the
 * printed pairs (firsts[2i]), bottom the swapped ones (firsts[2i + 1]). */
void c4_fig48(nl_harness *r, const nl_cheng_pattern *pat, nl_noise_grad2 *const *firsts,
              int npair, const nl_cheng_config *c);

/* ---- analysis (table41.c) ---------------------------------------------- */

/* Table 4.1, ours beside the thesis's: from the summary rows of the npair
 * pairs (printed at rows 0, 2, 4, ..., swapped at 1, 3, 5, ...) a table of
 * panel, w1, w2, paper_E_ks, E_ks, E_ks_sd, paper_E_con, E_con, E_con_sd,
 * E_ks_swapped, E_con_swapped, p_ks_min, p_kuiper_min (caller frees). */
nl_table *c4_table41(const nl_table *runs, const c4_thesis_row *thesis, int npair);

/* Which reading of the weight columns fits all rows: per reading (printed;
 * swapped; mixed_a_printed = (a) printed and (b)-(f) swapped) Pearson r of
 * log E_KS (and log E_Con), ours against the thesis's over the rows, its exact
 * one-sided permutation p (n! orderings), and the rms of the centred log ratio
 * (0: ours = the thesis's times one factor); from c4_table41's table. At most
 * 8 rows (8! orderings). */
nl_table *c4_readings(const nl_table *cmp, const c4_thesis_row *thesis, int npair);

/* Config c on `pattern` read at control grids gmin, 2 gmin, ... <= gmax over
 * s's seeds: grid, points, E_ks, E_ks_sd, E_con, E_con_sd, E_con_per_point,
 * paper_E_con, r_pattern, con_vs_const. The thesis does not state its grid;
 * E_Con sums over the control points, so the grid sets E_Con's scale. */
nl_table *c4_grid_sweep(const nl_study_cheng *s, const nl_cheng_config *c, const char *pattern,
                        int gmin, int gmax, double paper_e_con);
/* The row of c4_grid_sweep's table whose E_con is closest to paper_e_con on
 * a log scale. */
size_t c4_grid_best(const nl_table *gs, double paper_e_con);

/* ---- report prose (report.c), every number from the tables or the run --- */

/* The run at the configured (w1, w2) alone (table=0): its sentence and table. */
void c4_configured_text(nl_harness *r, const nl_table *one, const nl_cheng_config *c);
/* The thesis's claim, our setting and Table 4.1 ours vs thesis. */
void c4_table41_text(nl_harness *r, const nl_table *cmp, int grid, int nsweep, double lo,
                     double hi, size_t points);
/* The readings table and its prose; returns the row of the best-fitting
 * reading (smallest rms_log_ks). */
size_t c4_readings_text(nl_harness *r, const nl_table *rd);
/* The printed vs swapped Welch table (nl_study_cheng_welch_alloc). */
void c4_tests_text(nl_harness *r, const nl_table *wt);
/* The grid sweep's table and the sentence on its best row gb; `grid` is the
 * run's own control grid, the measured alternative. */
void c4_grid_text(nl_harness *r, const nl_table *gs, size_t gb, double paper_con, int grid);
/* Uniformity over Table 4.1's runs (printed rows 0, 2, ...) and the sweep
 * (w1 / w2 = rhos[q]): the smallest fractions not rejected and the smallest
 * swept ratio from which every run passes. */
void c4_uniformity_text(nl_harness *r, const nl_table *tab, const nl_table *sweep,
                        const double *rhos, int npair);
/* The figures textures.png (Fig 4.8, captioned with the printed pairs) and
 * tradeoff.png, then the sweep's table. */
void c4_figures_text(nl_harness *r, const c4_thesis_row *thesis, int npair,
                     const nl_table *sweep);

#endif
