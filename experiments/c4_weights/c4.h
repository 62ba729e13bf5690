/* c4.h - C4's runs (cases.c), Table 4.1 analysis (table41.c), E_Con over
 * grids and budgets (econ.c), seams (seams.c), verdicts (verdicts.c) and
 * report prose (report.c).
 *
 * Cheng 2009 sec. 4.3.2 weighs the statistic term against the control term,
 * E = w1 E_KS + w2 E_Con (eq. 3.9), and prints six pairs (w1, w2) in Table
 * 4.1. The table's text reads some weights the other way round, so C4 runs
 * every pair printed (rows 0, 2, 4, ... of its run table) and swapped (rows
 * 1, 3, 5, ...); the verdicts read the table as printed, and the other
 * readings are measured beside it.
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
void c4_case_set(nl_cheng_config *c, c4_case *w, const char *reading, const char *panel, double w1,
                 double w2);
/* The 2 npair + nsweep cases, each from base: Table 4.1's pairs printed at
 * cases 0, 2, 4, ... and swapped at 1, 3, 5, ... (panel panel_name[i]),
 * then the sweep, log-spaced in w1 / w2 = rhos[j] from lo to hi with
 * w1 + w2 = 1 (rhos filled here). */
void c4_cases_set(nl_cheng_config *cs, c4_case *wc, const nl_cheng_config *base,
                  const c4_thesis_row *thesis, const char *const *panel_name, int npair, double lo,
                  double hi, int nsweep, double *rhos);
/* Writes tables.tsv: the first seed's tables of the n cases wc behind
 * Fig 4.8 (tests/oracle_cheng.c reads them). */
void c4_tables_write(nl_harness *r, const c4_case *wc, nl_noise_grad2 *const *firsts, int n);
/* Fig 4.8 as textures.png: the pattern, then the first seed's controlled
 * value per pair on its own 0..1 scale (no display stretch); top row the
 * printed pairs (firsts[2i]), bottom the swapped ones (firsts[2i + 1]). */
void c4_fig48(nl_harness *r, const nl_cheng_pattern *pat, nl_noise_grad2 *const *firsts, int npair,
              const nl_cheng_config *c);

/* ---- analysis (table41.c) ---------------------------------------------- */

/* Table 4.1, ours beside the thesis's: from the summary rows of the npair
 * pairs (printed at rows 0, 2, 4, ..., swapped at 1, 3, 5, ...) a table of
 * panel, w1, w2, paper_E_ks, E_ks, E_ks_sd, paper_E_con, E_con, E_con_sd,
 * E_ks_swapped, E_con_swapped, p_ks_min, p_kuiper_min (caller frees). */
nl_table *c4_table41(const nl_table *runs, const c4_thesis_row *thesis, int npair);

/* The three readings of Table 4.1's weight columns, in readings.tsv's row
 * order: printed (the table as printed: the headline), swapped (w1 <-> w2 on
 * every row) and mixed_a_printed ((a) as printed, (b)-(f) swapped: the only
 * reading under which the text's "(a) small KS weight, (f) large KS weight"
 * holds). */
#define C4_READINGS 3
extern const char *const c4_reading_names[C4_READINGS];
/* 1 when reading rd takes the swapped run at panel i (0-based). */
int c4_reading_swapped(int rd, int panel);

/* Per reading (rows in c4_reading_names order), over the rows: Pearson r of
 * log E_KS (and log E_Con), ours against the thesis's, its exact one-sided
 * permutation p (n! orderings), the rms of the centred log ratio (shape: 0
 * when ours = the thesis's times one factor) and of the uncentred log ratio
 * (scale: 0 when ours = the thesis's); from c4_table41's table. At most 8
 * rows (8! orderings). */
nl_table *c4_readings(const nl_table *cmp, const c4_thesis_row *thesis, int npair);
/* The reading closest to the thesis's E_KS on absolute scale: smallest
 * rms_abs_log_ks (a selection against the thesis's numbers, 1 of 3). */
size_t c4_readings_closest(const nl_table *rd);
/* Welch tests, per panel, of printed vs swapped E_KS and E_Con over seeds
 * (rows 2i, 2i + 1 of the run table): reading_tests.tsv and its table. */
void c4_reading_tests(nl_harness *r, const nl_table *tab, int npair);

/* ---- E_Con at the printed pairs: grid x budget x reading (econ.c) ------ */

/* Table 4.1's pairs, printed and swapped, on `pattern` at the control grids
 * gmin, 2 gmin, ... <= gmax and s's own grid, each at the run's annealing
 * schedule (budget 1) and with moves_per_var scaled by budget_low: a summary
 * table labelled grid, points, budget, reading, panel, w1, w2, rows in that
 * order (grid, budget, panel, then printed before swapped). The runs at s's
 * grid and budget 1 are main_evs (the Table 4.1 runs, case 2i + swapped),
 * not run again. */
nl_table *c4_econ_runs(const nl_study_cheng *s, const nl_cheng_config *base, const char *pattern,
                       const c4_thesis_row *thesis, int npair, const nl_cheng_eval *main_evs,
                       int gmin, int gmax, double budget_low);
/* Per grid, budget and reading (c4_reading_names) over the npair panels of
 * c4_econ_runs: grid, points, budget, moves_per_var, reading, E_con (mean
 * over the panels), E_con_lo, E_con_hi, E_con_per_point, paper_E_con (the
 * thesis's mean), con_ratio (ours / thesis), rms_abs_log_ks, rms_abs_log_con
 * (uncentred rms of log ours / thesis over the panels), E_ks, r_pattern,
 * seam_ratio (means over the panels). */
nl_table *c4_econ_grid(const nl_table *runs, const c4_thesis_row *thesis, int npair,
                       double moves_per_var);
/* The row of c4_econ_grid's table, reading printed at budget 1, whose E_con
 * is closest to its paper_E_con on a log scale: the grid fitted to the
 * thesis's E_Con. */
size_t c4_econ_fitted(const nl_table *eg);
/* The row of c4_econ_grid's table at `grid`, reading printed, budget 1. */
size_t c4_econ_row(const nl_table *eg, int grid);

/* ---- seams (seams.c) --------------------------------------------------- */

/* The seam ratio (nl_cheng_eval) of Table 4.1's panels against the
 * unoptimised start tables of the same seeds: seams.tsv (summary rows:
 * printed a..f, swapped a..f, then "unoptimised"), seam_tests.tsv (Welch,
 * each panel against the unoptimised row) and one sentence. main_evs as for
 * c4_econ_runs. Returns the seams.tsv table (its last row: the unoptimised
 * start tables; caller frees). */
nl_table *c4_seams(const nl_study_cheng *s, const nl_cheng_config *base,
                   const nl_cheng_pattern *pat, const nl_cheng_eval *main_evs, int npair);
/* Fig 4.8's seams on both domains: seams_domain.tsv (nl_study_cheng_seams_add
 * rows panel, tables_from "optimised", origin) for the printed panels' first
 * seed tables firsts[2i] under cs[2i] (origin 1), and the same cases run
 * again at origin 0 (nl_cheng.h READINGS), with their prose. */
void c4_seams_domain(const nl_study_cheng *s, const nl_cheng_config *cs, const nl_cheng_pattern *pat,
                     nl_noise_grad2 *const *firsts, int npair);

/* ---- the trend (trend.c) ------------------------------------------------ */

/* "The pattern is better preserved with a larger control weight": over the
 * sweep's nsweep points (summary rows of sweep, w1 / w2 = rhos[j], the
 * runs' tables at tables[j k + seed]), Spearman's rho of the mean r with the
 * pattern on log(w2 / w1) and its one-sided permutation p; row 0 the
 * optimised tables against the pattern, row 1 the same tables against the
 * pattern shuffled (the negative control). Columns tables, points, rho,
 * p_perm, n_perm. Writes trend.tsv; caller frees. */
nl_table *c4_trend(const nl_study_cheng *s, const nl_cheng_config *base, const nl_cheng_pattern *pat,
                   const nl_table *sweep, nl_noise_grad2 *const *tables, const double *rhos,
                   int nsweep);

/* ---- verdicts (verdicts.c) --------------------------------------------- */

/* E_KS per panel: the printed reading (independent) and the reading closest
 * on absolute scale (selected 1/3, each panel's column as that reading
 * takes it); E_Con per panel at the run's grid (independent) and the mean at
 * the grid fitted to the thesis (fitted 1/6). The independent rows' negative
 * control: the unoptimised start tables (seams.tsv's last row). Then the
 * trend (trend.tsv) and "(a) keeps the pattern better than (f)": E_Con of
 * the printed panels a and f (rows 0 and 10 of runs, table41_runs.tsv),
 * Welch. */
void c4_verdicts(nl_harness *r, const nl_table *cmp, const nl_table *rd, const nl_table *eg,
                 const nl_table *seams, const nl_table *runs, const nl_table *trend);

/* ---- report prose (report.c), every number from the tables or the run --- */

/* The run at the configured (w1, w2) alone (table=0): its sentence and table. */
void c4_configured_text(nl_harness *r, const nl_table *one, const nl_cheng_config *c);
/* The thesis's claim, our setting and Table 4.1 ours vs thesis. */
void c4_table41_text(nl_harness *r, const nl_table *cmp, int grid, int nsweep, double lo, double hi,
                     size_t points);
/* The readings table and its prose: the headline reading and why, and the
 * reading closest on absolute scale (c4_readings_closest). */
void c4_readings_text(nl_harness *r, const nl_table *rd);
/* The grid x budget x reading table and its prose: the headline grid and
 * why, E_Con per point, and the grid fitted to the thesis's E_Con. */
void c4_econ_text(nl_harness *r, const nl_table *eg, const nl_cheng_config *c, int grid,
                  double budget_low);
/* Uniformity over Table 4.1's runs (printed rows 0, 2, ...) and the sweep
 * (w1 / w2 = rhos[q]): the smallest fractions not rejected and the smallest
 * swept ratio from which every run passes. */
void c4_uniformity_text(nl_harness *r, const nl_table *tab, const nl_table *sweep,
                        const double *rhos, int npair);
/* The figures textures.png (Fig 4.8, captioned with the printed pairs) and
 * tradeoff.png, then the sweep's table. */
void c4_figures_text(nl_harness *r, const c4_thesis_row *thesis, int npair, const nl_table *sweep);

#endif
