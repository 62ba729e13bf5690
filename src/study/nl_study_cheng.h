/* nl_study_cheng.h - the harness side of the Cheng experiments (C1-C9): what
 * the optimiser (cheng/nl_cheng.h) and the reproduction
 * (cheng/nl_cheng_repro.h) deliberately do not know about: control patterns
 * read from PNG files and the built-in shapes that make them, values and
 * textures as images, the opening every Cheng experiment shares (--patterns,
 * the standard --set parameters, exit 2 on bad input), the runs over seeds,
 * the summary and CDF tables, Welch tests between rows, and the thesis's
 * Tables 4.2-4.4 with the chain original -> pool that C5 and C6 share. What
 * one experiment alone needs lives in its folder under experiments/.
 *
 * API
 *   patterns  nl_study_cheng_pattern_from_image, nl_study_cheng_shape,
 *             nl_study_cheng_shape_names, nl_study_cheng_patterns_parse,
 *             nl_study_cheng_patterns_check, nl_study_cheng_pattern_load_or_die
 *                                                          (nl_study_cheng_image.c)
 *   images    nl_study_cheng_grey_image, nl_study_cheng_value_image / _raw,
 *             nl_study_cheng_texture_image, nl_study_cheng_pattern_panel
 *                                                          (nl_study_cheng_image.c)
 *   runs      nl_study_cheng_open / _ready / _pattern, nl_study_cheng_runs,
 *             nl_study_cheng_rows_add, nl_study_cheng_seeds, nl_study_cheng_montage,
 *             nl_study_cheng_summary_alloc, nl_study_cheng_cdf_table,
 *             nl_study_cheng_welch_alloc / _add, nl_study_cheng_control_text,
 *             nl_study_column_min                          (nl_study_cheng.c)
 *   control   nl_study_cheng_pattern_r, nl_study_cheng_random_r,
 *             nl_study_mc_p_greater, nl_study_t_below_p,
 *             nl_study_cheng_control_alloc / _add, nl_study_cheng_flat_text,
 *             nl_study_cheng_seams_measure,
 *             nl_study_cheng_seams_alloc / _add          (nl_study_cheng_control.c)
 *   C5, C6    nl_study_cheng_thesis_gmm_tables, nl_study_cheng_repro_params,
 *             nl_study_cheng_repro_original / _pool / _clear  (nl_study_cheng_repro.c)
 *
 * The names keep their cheng prefix for now (they moved here from src/cheng;
 * the project-wide rename to nl_<module>_<verb> comes later).
 */
#ifndef NL_STUDY_CHENG_H
#define NL_STUDY_CHENG_H

#include "cheng/nl_cheng.h"
#include "cheng/nl_cheng_repro.h"
#include "image/nl_image.h"
#include "harness/nl_harness.h"
#include "study/nl_study.h"
#include "table/nl_table.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- control patterns from images (sec. 3.4.1) -------------------------- */

/* From an RGBA/RGB/grey image: D = red (grey) channel, alpha 0 = no control.
 * NL_EINVAL if no cell carries control or grid < 1. */
nl_status nl_study_cheng_pattern_from_image(const nl_image *im, int grid, nl_cheng_pattern **out,
                                            nl_error *err);

/* Built-in shapes for the shipped patterns (tools/patterns.c): "flower", "x",
 * "star", "rings", "disc", "letter" (an "N"), "gradient", "spiral". RGBA size
 * x size, red = 1 inside, black outside, alpha 1 everywhere except "disc",
 * whose outer corners are transparent (no control) to exercise alpha. NULL if
 * unknown. */
nl_image *nl_study_cheng_shape(const char *name, int size);
extern const char *const nl_study_cheng_shape_names[];   /* NULL-terminated */

/* Removes "--patterns DIR" from argv (before nl_harness_begin sees it) and
 * sets *dir to DIR, or "data/patterns" (experiments run from the repository
 * root); "--patterns: missing value" on error. */
nl_status nl_study_cheng_patterns_parse(int *argc, char **argv, const char **dir, nl_error *err);
/* A pattern folder is what tools/patterns.c writes: the folder exists and
 * every shape of nl_study_cheng_shape_names is there as NAME.png and reads as
 * a pattern at `grid`. Checked before an experiment touches its output. */
nl_status nl_study_cheng_patterns_check(const char *dir, int grid, nl_error *err);
/* DIR/NAME.png read at `grid`; on failure prints "PROG: reason" and exits 2. */
nl_cheng_pattern *nl_study_cheng_pattern_load_or_die(const char *prog, const char *dir,
                                                     const char *name, int grid);

/* ---- values and textures as images (sec. 4.1) --------------------------- */

/* The value as grey with a display stretch: grey 0..1 is the value's own
 * 1st..99th percentile, since the optimised value spans only part of [0, 1]
 * (nl_cheng.h, READINGS). */
nl_image *nl_study_cheng_grey_image(const double *v, int w, int h);
/* size x size images of an optimised table under config c: the control value
 * (grey, stretched) and the config's texture (sec. 4.1: cloud / erosion /
 * fire alpha-blend two colours with the value as alpha, marble maps it
 * through the marble ramp; alpha 0..1 is the same display stretch). */
nl_image *nl_study_cheng_value_image(const nl_noise_grad2 *g, const nl_cheng_config *c, int size);
nl_image *nl_study_cheng_texture_image(const nl_noise_grad2 *g, const nl_cheng_config *c,
                                       int size);
/* The value without the display stretch: grey 0..1 = c 0..1 (literal V and
 * sin V: -1..1), so the contrast the eye sees is the value's own. */
nl_image *nl_study_cheng_value_image_raw(const nl_noise_grad2 *g, const nl_cheng_config *c,
                                         int size);
/* The pattern, nearest-neighbour upscaled to size x size: red = D, cells
 * without control grey. */
nl_image *nl_study_cheng_pattern_panel(const nl_cheng_pattern *p, int size);

/* ---- what the Cheng experiments share (nl_study_cheng.c) ---------------- */

/* One Cheng experiment's run and its standard setting, so that an
 * experiment opens in two lines:
 *   nl_study_cheng s;
 *   nl_study_cheng_open(&s, "c3_start_freq", "C3 - ...", &argc, argv);
 *   ... its own nl_harness_param calls on s.r ...
 *   nl_study_cheng_ready(&s);
 *   nl_cheng_pattern *pat = nl_study_cheng_pattern(&s, "star");
 *   nl_noise_grad2 *first = nl_study_cheng_seeds(&s, &s.c, pat, sum, 1, labels);  */
typedef struct {
  nl_harness *r;
  nl_cheng_config c;      /* the standard parameters (nl_study_cheng_open) */
  int grid;               /* control grid */
  const char *patterns;   /* the --patterns folder */
  const char *role;       /* NULL: runs from the run's seed; else from
                             nl_seed_stream(seed, role, 0), so an experiment
                             repeating another's setting gets runs of its own */
  nl_table *cost;         /* NULL, or a table of columns case, seeds, moves, cpu_s, cpu_s_sd,
                             moves_per_s: nl_study_cheng_rows_add appends each row's cost
                             (labels joined by "/"; means per optimisation over the seeds) */
} nl_study_cheng;
/* The opening every Cheng experiment shares: strips "--patterns DIR"
 * (nl_study_cheng_patterns_parse; "NAME: message", exit 2) into s->patterns,
 * starts the run, reads the standard --set parameters into s->c and s->grid:
 * grid (64), w1, w2, f1, a1, octaves, literal (0/1), temps (n_temps; quick
 * 8), moves_per_var (quick 5), defaults otherwise. role and cost start NULL.
 * The experiment then reads its own parameters and calls
 * nl_study_cheng_ready, all before the output folder is touched. */
void nl_study_cheng_open(nl_study_cheng *s, const char *name, const char *title, int *argc,
                         char **argv);
/* nl_harness_params_done (--help and --params print and exit there), then
 * nl_cheng_config_check ("NAME: message", exit 2), the patterns folder at the
 * grid (nl_study_cheng_patterns_check; "NAME: control patterns: ...", exit 2)
 * and the folder into the manifest. The patterns are read after the listing
 * and the parameter checks because reading a PNG loads the image back-end
 * (OpenImageIO, ~0.6 s of CPU per process), which `--help`, `--params` and a
 * refused --set do not need. */
void nl_study_cheng_ready(nl_study_cheng *s);
/* The pattern NAME of s's folder at s's grid (nl_study_cheng_pattern_load_or_die). */
nl_cheng_pattern *nl_study_cheng_pattern(const nl_study_cheng *s, const char *name);

/* Summary table: nlabels label columns, then seeds, E_ks (mean), E_ks_sd,
 * p_ks (mean), p_ks_min, V_kuiper, V_kuiper_sd, p_kuiper, p_kuiper_min, chi2,
 * chi2_sd, p_chi2, E_con, E_con_sd, rms_con, E, uniform_ks, uniform_kuiper
 * (fractions of runs not rejected as non-uniform at alpha = 0.05), roughness,
 * roughness_sd, and controllability: r_pattern, r_pattern_sd (Pearson r of the
 * control value with the pattern), contrast, contrast_sd (sd of the control
 * value), E_con_random, E_con_random_sd (the unoptimised start table's E_Con),
 * E_con_const (the best constant image's E_Con) and con_vs_const = E_con /
 * E_con_const (> 1: the optimised table follows the pattern worse than a flat
 * image). Rows come from nl_study_cheng_rows_add. */
nl_table *nl_study_cheng_summary_alloc(int nlabels, const char *const *labels);
/* ECDF of each table's angles: F = i/M and u_NAME = sorted angle / 2 pi. */
nl_table *nl_study_cheng_cdf_table(const nl_noise_grad2 *const *tables, const char *const *names,
                                   int n);
/* n cases, config cs[i] on pattern pats[i], each over the run's seeds
 * (nl_cheng_run at nl_seed_replicate(seed, 0 .. k-1)), all n x k runs as one
 * nl_parallel_for on the run's --threads (case-major items; each run from its
 * seed alone, so the results do not depend on the thread count). Returns the
 * n k evaluations, case i's at [i k .. i k + k - 1] (caller frees); firsts, if
 * not NULL, gets each case's first-seed optimised table (caller frees). Exit
 * 1 on error (the first failing run in case and seed order). */
nl_cheng_eval *nl_study_cheng_runs(const nl_study_cheng *s, int n, const nl_cheng_config *cs,
                                   const nl_cheng_pattern *const *pats, nl_noise_grad2 **firsts);
/* The same runs, every run's optimised table into tables[i k + seed] (n k of
 * them, caller frees each). */
nl_cheng_eval *nl_study_cheng_runs_tables(const nl_study_cheng *s, int n,
                                          const nl_cheng_config *cs,
                                          const nl_cheng_pattern *const *pats,
                                          nl_noise_grad2 **tables);
/* One case's k evaluations as a summary row of sum under the nlabels labels
 * (label cells as text, then the mean, sd and min over the runs), and its
 * cost row if s->cost. */
void nl_study_cheng_rows_add(const nl_study_cheng *s, nl_table *sum, int nlabels,
                             const char *const *labels, const nl_cheng_eval *evs);
/* Config c on pat over the run's seeds (nl_study_cheng_runs, n = 1), its
 * summary row appended to sum under the nlabels labels
 * (nl_study_cheng_rows_add); returns the first seed's optimised table
 * (caller frees). Exit 1 on error. */
nl_noise_grad2 *nl_study_cheng_seeds(const nl_study_cheng *s, const nl_cheng_config *c,
                                     const nl_cheng_pattern *pat, nl_table *sum, int nlabels,
                                     const char *const *labels);
/* The n panels as a labelled montage of `cols` columns written to the run's
 * FILE; frees the panels. */
void nl_study_cheng_montage(nl_harness *r, nl_image **panels, const char *const *labels, int n,
                            int cols, const char *title, const char *file);
/* The gradient tables behind a run's figures, as data (tables.tsv): nlabels
 * label columns naming the table, then k (entry), angle (radians,
 * round-trip) and perm (P[k]); _add appends table g's m rows under labels.
 * tests/oracle_cheng.c rebuilds each table from them and recomputes the
 * panels through the noise's point call. */
nl_table *nl_study_cheng_tables_alloc(int nlabels, const char *const *labels);
void nl_study_cheng_tables_add(nl_table *t, int nlabels, const char *const *labels,
                               const nl_noise_grad2 *g);
/* The smallest value of column `col` over the table's rows (+inf if none). */
double nl_study_column_min(const nl_table *t, const char *col);

/* Between-condition tests: a table of group, quantity, a, b, mean_a, sd_a,
 * mean_b, sd_b, seeds, diff_pct (100 (mean_a - mean_b) / mean_b) and p_welch
 * (Welch's t-test on the two rows' means and sds over their seeds; both sds 0:
 * p = 1 if the means are equal, else 0). _add appends the test of column col
 * (sd in col_sd) between summary rows ra and rb and returns p. */
nl_table *nl_study_cheng_welch_alloc(void);
double nl_study_cheng_welch_add(nl_table *t, const nl_table *sum, size_t ra, size_t rb,
                                const char *col, const char *group, const char *a, const char *b);
/* The columns of a Cheng summary table (nl_study_cheng_summary_alloc) that
 * carry the story in a report section (nl_harness_report_columns); the TSV
 * keeps them all. Prefix the table's label columns: "pattern,seeds," ... */
#define NL_STUDY_CHENG_STORY                                                                       \
  "E_ks,E_ks_sd,p_ks_min,V_kuiper,p_kuiper_min,chi2,p_chi2,E_con,E_con_sd,uniform_ks,"             \
  "uniform_kuiper,roughness," NL_STUDY_CHENG_CONTROL
/* The controllability columns alone (a report table of their own). */
#define NL_STUDY_CHENG_CONTROL                                                                     \
  "r_pattern,r_pattern_sd,contrast,contrast_sd,E_con_random,E_con_const,con_vs_const"
/* Controllability in prose, formatted from a summary table's rows (labels =
 * its first nlabels columns joined by "/"): the range of r and contrast, and
 * every row whose optimised E_Con is worse than the best constant image's,
 * named as not controlled in that sense. Returns the number of such rows. */
int nl_study_cheng_control_text(nl_harness *r, const nl_table *sum, int nlabels);

/* ---- controllability tests and seams (nl_study_cheng_control.c) ---------- */

/* Pearson r of the control value c (config c, all octaves) with the targets
 * D over the pattern's points: nl_cheng_evaluate's r_pattern, computed from
 * one grid x grid raster (the points are the cells' centres), without the
 * rest of the evaluation. */
double nl_study_cheng_pattern_r(const nl_noise_grad2 *g, const nl_cheng_config *c,
                                const nl_cheng_pattern *pat);
/* The same r for n random (unoptimised) tables, table j seeded from
 * nl_seed_stream(seed, "cheng.random_table", j): the null distribution of
 * "the texture follows the pattern", on `threads` (thread-count independent). */
void nl_study_cheng_random_r(const nl_cheng_config *c, const nl_cheng_pattern *pat,
                             unsigned long seed, int n, int threads, double *out);
/* Monte-Carlo p of obs against n null draws, one-sided (large obs):
 * (1 + #{null >= obs}) / (n + 1); the smallest p is 1 / (n + 1). */
double nl_study_mc_p_greater(const double *null, size_t n, double obs);
/* One-sided one-sample t-test of mean(x) < mu over k values (k - 1 degrees
 * of freedom); with no spread, 0 when the mean is below mu, else 1. */
double nl_study_t_below_p(const double *x, size_t k, double mu);

/* "Follows the pattern" per case: nlabels label columns, then seeds,
 * r_pattern (mean over the seeds), r_random_mean, r_random_sd, n_random and
 * p_random (nl_study_mc_p_greater of the seeds' mean r against n_random
 * random tables: a mean of k against single tables, so conservative), E_con
 * (mean), E_con_const (the best constant image's), con_vs_const, p_flat
 * (nl_study_t_below_p of the seeds' E_con against E_con_const: better than a
 * flat image), and E_Con's split (nl_cheng_eval) as fractions of the seeds'
 * summed E_Con: con_offset_frac (mean offset), con_contrast_frac (sd
 * mismatch), con_shape_frac (1 - r), then mean_D (the pattern's mean target)
 * and offset_abs (|mean c - mean D| over the points, mean over the seeds).
 * _add: the row of config c on pat from
 * the run's k evaluations evs (nl_study_cheng_runs), random tables from
 * `seed`; r_random (may be NULL) gets the n_random null values. */
nl_table *nl_study_cheng_control_alloc(int nlabels, const char *const *labels);
void nl_study_cheng_control_add(const nl_study_cheng *s, nl_table *t, int nlabels,
                                const char *const *labels, const nl_cheng_config *c,
                                const nl_cheng_pattern *pat, const nl_cheng_eval *evs,
                                int n_random, unsigned long seed, double *r_random);
/* The pattern with its targets D shuffled among its points (cells and
 * positions kept; gsl MT19937 from seed): the same values, no shape. Free
 * with nl_cheng_pattern_free. */
nl_cheng_pattern *nl_study_cheng_pattern_shuffled(const nl_cheng_pattern *p, unsigned long seed);
/* Evaluations (nl_cheng_evaluate under c on pat) of n tables; exit 1 on
 * error. Caller frees. */
nl_cheng_eval *nl_study_cheng_evaluate_tables(const nl_study_cheng *s, const nl_cheng_config *c,
                                              const nl_cheng_pattern *pat,
                                              nl_noise_grad2 *const *tables, int n);
/* The run's k unoptimised start tables of nl_cheng_run (seed
 * nl_seed_replicate(seed0, i), seed0 as nl_study_cheng_runs); caller frees
 * each and the array. */
nl_noise_grad2 **nl_study_cheng_start_tables(const nl_study_cheng *s, size_t m);
/* The negative controls of "follows the pattern" (rows of a control table
 * whose last label column names the baseline; labels: the first nlabels
 * - 1): "shuffled pattern", the k optimised tables against pat with its
 * targets shuffled (nl_study_cheng_pattern_shuffled from seed), its random
 * tables' r on that pattern as the null; and "start tables", the run's k
 * unoptimised start tables (nl_study_cheng_start_tables) on pat. Returns the
 * first of the two rows. */
size_t nl_study_cheng_baselines_add(const nl_study_cheng *s, nl_table *t, int nlabels,
                                    const char *const *labels, const nl_cheng_config *c,
                                    const nl_cheng_pattern *pat, nl_noise_grad2 *const *tables,
                                    int n_random, unsigned long seed);
/* Spearman's rho of y on x (GSL; ties get average ranks). */
double nl_study_spearman(const double *x, const double *y, size_t n);
/* rho into *rho and its one-sided permutation p (rho large): y shuffled
 * nperm times (MT19937 from seed), p = (1 + #{rho_perm >= rho}) / (nperm +
 * 1). */
double nl_study_spearman_perm_p(const double *x, const double *y, size_t n, int nperm,
                                unsigned long seed, double *rho);
/* E_Con against the flat image per row of a control table, split (in units
 * of the flat image's E_Con) into offset + contrast + shape, naming the rows
 * whose offset alone makes them worse than flat. Returns the number of rows
 * worse than flat (con_vs_const >= 1). */
int nl_study_cheng_flat_text(nl_harness *r, const nl_table *ctl, int nlabels);

/* Where a table's seams are, on a 128^2 raster of the control value over
 * the config's domain (row 0 = y = 0). The fractal sum evaluates one noise
 * field at f_l x, so on the domain at the noise's origin (origin 0) octave
 * l's lattice contains octave l-1's whole lattice in the quarter [0, 1/2]^2
 * (the same points, the same gradients): octave l-1's lines x = 1 and y = 1
 * reappear in octave l as the half-lines x = 1/2 over y < 1/2 and y = 1/2
 * over x < 1/2; on the headline domain [1, 2]^2 no octave's lattice lies in
 * another's (nl_cheng.h READINGS). Each value is a mean |step| across one
 * boundary over the mean of all boundaries of the same strip (1 = no seam),
 * in the raster's coordinates (the quarter is its top-left quarter):
 *   quarter   across those two half-lines (the quarter's edges);
 *   other     across x = 1/2 over y > 1/2 and y = 1/2 over x > 1/2 (no copy);
 *   border    across the first and last column and row boundaries;
 *   octave_quarter   `quarter` for octave l + 1 alone, l < 4 (NAN past F);
 *   outward   the mean outward component (-gx at x = o, gx at x = o + 1, -gy,
 *             gy) of the unit gradients on octave 1's border lattice lines (0
 *             for a random table; 1 for gradients all pointing out). */
#define NL_STUDY_CHENG_SEAM_OCTAVES 4
typedef struct {
  double quarter, other, border, outward;
  double octave_quarter[NL_STUDY_CHENG_SEAM_OCTAVES];
} nl_study_cheng_seams;
void nl_study_cheng_seams_measure(const nl_noise_grad2 *g, const nl_cheng_config *c,
                                  nl_study_cheng_seams *out);
/* A table of nlabels label columns, then origin (the config's domain
 * origin), tables, seam_ratio (nl_cheng_eval's:
 * the largest boundary over the mean), seam_quarter, seam_quarter_sd,
 * seam_other, seam_border, seam_octave1 .. seam_octave4 (octave_quarter),
 * border_outward, border_outward_sd:
 * _add appends the means (and sds) over n tables evaluated under config c
 * on pattern pat. */
nl_table *nl_study_cheng_seams_alloc(int nlabels, const char *const *labels);
void nl_study_cheng_seams_add(nl_table *t, int nlabels, const char *const *labels,
                              const nl_noise_grad2 *const *tables, int n,
                              const nl_cheng_config *c, const nl_cheng_pattern *pat);
/* The seams table (the column tables_from names what the tables are:
 * "optimised", "start table", ...) in the report, and the domain's effect
 * in one paragraph: the quarter's edges, the borders and the largest
 * boundary of the "optimised" rows at origin 1 (the headline) against
 * origin 0, and the start tables' where there are rows of them. `what`
 * names the tables in the caption ("the first seed's textures"). */
void nl_study_cheng_seams_text(nl_harness *r, const nl_table *t, const char *what);

/* ---- what C5 and C6 share (nl_study_cheng_repro.c) ----------------------- */

/* Tables 4.2-4.4 of the thesis, with the pattern and control term we use for
 * each texture (the thesis does not name its patterns). */
typedef struct {
  const char *texture, *pattern;
  nl_cheng_con con;
  const char *table;
  int samples;
  double epsilon;
  int k0, k;
  double cutoff, aic;
} nl_study_cheng_thesis_gmm;
/* erosion, marble, cloud */
extern const nl_study_cheng_thesis_gmm nl_study_cheng_thesis_gmm_tables[3];

/* --set parameters: runs (Q; quick 6), keep (N; quick 20), epsilon,
 * low_levels, threads, samples (quick 100), T, k_extra, unwrap (0/1), diag
 * (0/1: diagonal covariances), max_iter. */
void nl_study_cheng_repro_params(nl_harness *r, nl_cheng_pool_options *po,
                                 nl_cheng_model_options *mo);

/* Original optimised table (nl_cheng_run, timed) and its pool (timed). */
typedef struct {
  nl_noise_grad2 *opt;
  nl_cheng_eval ev;
  double seconds_opt, seconds_pool;
  nl_cheng_pool *pool;
} nl_study_cheng_repro;
nl_status nl_study_cheng_repro_original(const nl_cheng_config *c, const nl_cheng_pattern *pat,
                                        unsigned long seed, nl_study_cheng_repro *out,
                                        nl_error *err);
nl_status nl_study_cheng_repro_pool(nl_study_cheng_repro *rp, const nl_cheng_config *c,
                                    const nl_cheng_pattern *pat, const nl_cheng_pool_options *po,
                                    unsigned long seed, nl_error *err);
void nl_study_cheng_repro_clear(nl_study_cheng_repro *rp);

#ifdef __cplusplus
}
#endif

#endif
