/* c1.h - C1's cost table (cost.c), controls (control.c), figures
 * (figures.c) and report prose (report.c).
 *
 * Cheng 2009 sec. 4.1 (Fig 4.1-4.4) shows cloud, marble, erosion and fire
 * textures, each from three control patterns with its own control term
 * (eq. 3.8, 4.1, 4.2, 4.3). C1 runs each (texture, pattern) with our
 * rescaled formulas and with the thesis's taken literally.
 */
#ifndef C1_H
#define C1_H

#include "study/nl_study_cheng.h"

/* The cost of the optimisations behind a summary, filled by
 * nl_study_cheng_rows_add when set as nl_study_cheng.cost: case (the row's
 * labels joined by "/"), seeds, moves (mean per optimisation), cpu_s (mean
 * thread CPU seconds per full multi-level optimisation, set-up included),
 * cpu_s_sd, moves_per_s (moves over CPU seconds, summed over seeds). */
nl_table *c1_cost_alloc(void);
/* Writes timing.tsv (its times marked "ignore": never regression-checked),
 * its table and a sentence formatted from it into the report. */
void c1_cost_report(nl_harness *r, const nl_table *t);

/* "The texture follows the pattern", pooled over a texture's np patterns:
 * columns texture, patterns, seeds, r_pattern (the patterns' mean of the
 * seeds' mean r), r_random_mean, r_random_sd, n_random, p_random
 * (nl_study_mc_p_greater against the patterns' mean r of one random table
 * each: nulls[p] holds pattern p's nrand values), E_con (mean over the
 * seeds of the patterns' summed E_Con), E_con_const (the summed flat
 * images'), con_vs_const, p_flat (nl_study_t_below_p over the seeds) and
 * E_Con's split as fractions (con_offset_frac, con_contrast_frac,
 * con_shape_frac). evs[p]: pattern p's k evaluations. */
nl_table *c1_claims_alloc(void);
void c1_claims_add(nl_table *t, const char *texture, int np, int k, const nl_cheng_eval *const *evs,
                   const double *const *nulls, int nrand);
/* The seams row (texture, pattern, "start table") of the first seed's
 * unoptimised start table under config c on pat. */
void c1_seams_start(const nl_study_cheng *s, nl_table *seams, const nl_cheng_config *c,
                    const nl_cheng_pattern *pat, const char *pattern);
/* The alternative domain [0, 1]^2 (origin 0; nl_cheng.h READINGS): the n
 * headline cases cs[2 i] (pattern pats[i], named names[i]) run again, the
 * seams rows (texture, pattern, "optimised") of their first seed's tables. */
void c1_seams_domain(const nl_study_cheng *s, nl_table *seams, int n, const nl_cheng_config *cs,
                     nl_cheng_pattern *const *pats, const char *const *names);
/* "Statistics kept" per texture: columns texture, tables, runs (patterns x
 * seeds), E_ks (mean), p_ks_min (the smallest KS p of the runs) and
 * p_uniform = min(1, runs p_ks_min) (Bonferroni: is any run non-uniform?).
 * _add: one row from np patterns' k evaluations each. */
nl_table *c1_uniform_alloc(void);
void c1_uniform_add(nl_table *t, const char *texture, const char *tables, int np, int k,
                    const nl_cheng_eval *const *evs);
/* "Statistics kept": per texture t, the headline cases cs[2 (t npat + j)]
 * (evaluations evs, k per case) against the same cases optimised for E_Con
 * alone (w1 = 0, run here on pats[t npat + j]); two uni rows per texture. */
void c1_uniformity(const nl_study_cheng *s, nl_table *uni, int ntex, int npat,
                   const nl_cheng_config *cs, nl_cheng_pattern *const *pats,
                   const nl_cheng_eval *evs, int k);
/* The verdicts: per headline case (ctl's rescaled rows) r against random
 * tables and E_Con against the flat image, each with its negative control
 * (bl rows 2q: the pattern shuffled, 2q + 1: the start tables, q the
 * case's index among the headline rows); per texture "statistics kept"
 * (uni rows 2t: optimised, 2t + 1: w1 = 0, the control); one qualitative
 * row per figure TEXTURE.png; the pooled table, E_Con's split and the
 * seams. */
void c1_control_text(nl_harness *r, const nl_table *pooled, const nl_table *ctl,
                     const nl_table *bl, const nl_table *uni, const nl_table *seams);

/* figures.c. Fig 4.1-4.4, one montage TEXTURE.png per texture t from its
 * npat patterns' first-seed tables (headline firsts[2 i], literal
 * firsts[2 i + 1], i = t npat + j): pattern | value on its own 0..1 scale |
 * stretched | texture | the literal formula's value, with its caption
 * (c1_figure_text). Frees the patterns pats[i]. */
void c1_figures(nl_harness *r, int ntex, int npat, const nl_cheng_config *cs,
                nl_noise_grad2 *const *firsts, nl_cheng_pattern **pats, const char *const *names,
                const char *const *equation, int size);
/* Texture t's figure (Fig 4.(t+1)): its caption, control term `con` by
 * equation `equation`, image `file`. */
void c1_figure_text(nl_harness *r, int t, nl_cheng_con con, const char *equation, const char *file);
/* The thesis's claim, our setting (c), the summary table, controllability,
 * marble's gain and uniformity. */
void c1_text(nl_harness *r, const nl_table *sum, const nl_cheng_config *c, int grid);

#endif
