/* nl_cheng.h - controllable Perlin noise (Cheng 2009, sections 3.2-3.4, 4.1-4.5):
 * the angles of a 2D gradient table are optimised by multi-level simulated
 * annealing so that a fractal sum follows a user's control pattern while the
 * angles stay uniformly distributed.
 *
 *   nl_cheng_pattern *pat;
 *   nl_cheng_pattern_read("data/patterns/flower.png", 64, &pat, &err);  // 64 x 64 control grid
 *   nl_cheng_config c = nl_cheng_config_default();                      // thesis setting
 *   nl_grad2 *g = nl_grad2_alloc(512);
 *   nl_grad2_seed(g, seed);                        // random start (level 1's initial guess)
 *   nl_cheng_problem *p = nl_cheng_problem_alloc(&c, pat, g, &err);     // g is edited in place
 *   nl_cheng_optimise(p, seed, stats);             // levels 1..F, stats may be NULL
 *   nl_cheng_eval ev; nl_cheng_evaluate(g, &c, pat, &ev, &err);         // E_KS, V, chi2, p, E_Con
 *   nl_cheng_value_grid(g, &c, 256, 256, v);       // the controlled value on [0,1)^2
 *   nl_image *tex = nl_cheng_texture(c.con, v, 256, 256);
 *
 * THE MODEL (thesis setting in nl_cheng_config_default)
 *   Noise(x, y) = sum over the 4 cell corners (i, j) of w(x-i) w(y-j) (Delta_ij . G_ij)
 *   (eq. 3.1-3.2), G_ij = G[P[P[i] + j]] (nl_grad2, M = 512 angles, quintic fade);
 *   fractal sum F_sum = sum_{l=1..F} Noise(f_l x, f_l y) / a_l, f_l = f1 2^(l-1),
 *   a_l = a1 2^(l-1), F = 4, f1 = 8, a1 = 4 (eq. 3.10), over the unit square.
 *
 * OBJECTIVE (eq. 3.9)  E = w1 E_stat + w2 E_Con,  w1 = 0.995, w2 = 0.005.
 *   E_stat, a statistic of the angles X against uniform on [0, 2 pi):
 *     NL_CHENG_STAT_KS      D = max |F_obs - F_ideal| (eq. 3.5-3.7);
 *     NL_CHENG_STAT_KUIPER  V = D+ + D- (independent of where the circle is cut);
 *     NL_CHENG_STAT_CHISQ   Pearson chi2 on K = 500 equal bins (eq. 3.4), entered as
 *                           Cramer's V = sqrt(chi2 / (n (K - 1))) - see READINGS.
 *   E_Con = sum_i (c(x_i) - D_i)^2 over the control points, with the control value
 *     NL_CHENG_CON_PLAIN   c = (1 + V) / 2                   (cloud, eq. 3.8)
 *     NL_CHENG_CON_SIN     c = (1 + sin(pi V)) / 2           (marble, eq. 4.1)
 *     NL_CHENG_CON_ABS     c = |V|                           (erosion, eq. 4.2)
 *     NL_CHENG_CON_FIRE    c = s sum_l |Noise_l| / a_l       (fire, eq. 4.3)
 *   where V = s F_sum, s = 1 / (sqrt(2)/2 sum_l 1/a_l): the sum over its analytic
 *   bound, so V is in [-1, 1] and every c in [0, 1] like D (see READINGS).
 *
 * MULTI-LEVEL RULE (sec. 3.4.2, eq. 3.13-3.15). Level l = 1..F, low to high
 *   frequency. The lattice of octave l is the (ceil(f_l) + 1)^2 points that the
 *   unit square touches. Level l's variables are the table entries used by that
 *   lattice and by no lower octave's lattice. At level l:
 *     E_stat^l is over the entries used by octave l's lattice (eq. 3.14, X^l_obs),
 *     E_Con^l uses the partial sum of octaves 1..l (eq. 3.15, V^l_i),
 *   so a move on a level-l variable changes only octave l's values. Before level
 *   l >= 2 is annealed its variables get the angle of their parent (eq. 3.13):
 *   entry k first used by lattice point (I, J) of octave l (row-major first) takes
 *   the angle of the entry at (floor(I/2), floor(J/2)), a point of octave l-1.
 *
 * ANNEALING (nl_cheng_anneal, one level; gsl_rng MT19937 from a seed).
 *   Move: one variable k (uniform), theta' = theta + U(-sigma, sigma) wrapped to
 *   [0, 2 pi), sigma = pi max(T / T0, 0.01). Metropolis acceptance exp(-dE / T).
 *   T0 = mean uphill dE of 200 trial moves / ln(1 / p0), p0 = 0.8 (start accepting
 *   ~80% of uphill moves). Geometric cooling T <- alpha T after moves_per_var *
 *   n_vars moves, alpha = 10^(-t_decades / n_temps). STOPPING RULE: after n_temps
 *   temperatures, or earlier when, once T < T0 / 100, the best E has not improved
 *   by more than 1e-12 relative in `stall` consecutive temperatures. The best
 *   end-of-temperature state is restored.
 *   Defaults: n_temps = 60, moves_per_var = 20, t_decades = 4, stall = 10.
 *
 * INCREMENTAL EVALUATION. Every control point stores, per octave, its four
 *   corner entries and weight vectors W = w(u) w(v) Delta (eq. 3.2: a corner
 *   contributes W . G) and its current octave values; for each octave and entry
 *   an inverted list names the points whose cells use the entry, with W summed
 *   over those corners. A move on entry k adds W . (G_new - G_old) to only those
 *   points' octave values, re-evaluates their terms, and updates the statistic
 *   through nl_ks_incr (KS; Kuiper's V = D+ + D- of the same state: O(log n +
 *   rank shift + n/32)) or bin counts (chi-square: O(1), the sum of squared
 *   counts kept exactly in integers). nl_cheng_undo restores the saved values
 *   exactly. At every temperature step all points are re-evaluated from the
 *   stored corners and E_Con is re-summed, so rounding from differences never
 *   outlives one temperature. Tested: incremental == full recomputation to 1e-12
 *   (relative) after every move of a random sequence.
 *
 * READINGS of what the thesis leaves open.
 *   - Scale of the value. The thesis says black = noise 0, red = noise 1 and uses
 *     the noise as an alpha, but gradient noise is signed and its fractal sum only
 *     spans +-0.33. We read "noise value" as the value in [0, 1] a texture uses:
 *     c = (1 + V) / 2 with V the sum over its analytic bound (and the variants
 *     above). A literal V - D would leave black = the noise's mean 0 and make red
 *     unreachable (measured: pattern correlation 0.49 instead of 0.64 on the
 *     flower). Either way gradient noise is band-pass with sd(c) ~ 0.1, and it is
 *     0 at every lattice point (so c = 1/2 on the f1 grid whatever the table): the
 *     optimum follows the pattern's shape at low contrast (E_Con per point ~0.18
 *     for a 0/1 pattern); images are shown with a display stretch. Marble's
 *     sin(pi V) (our reading of eq. 4.1's sine: one period over V's range) has pi
 *     times the gain near V = 0 and follows patterns visibly better.
 *   - Control points are the cells of a G x G grid over the pattern (default 64):
 *     D = mean red of the pixels in the cell with alpha > 0; cells whose mean alpha
 *     is below 1/2 carry no control. Image row 0 is y = 0 (top of the picture).
 *     Choose G a power of two >= the highest frequency f1 2^(F-1) (64 for the
 *     thesis): with G = 32 every cell centre lies on a lattice point of f = 64,
 *     where that octave is exactly 0, so level 4 would not see the pattern.
 *   - Chi-square as an objective term. Raw chi2 (~ K for a uniform table) would
 *     swamp E_Con at w1 = 0.995; Cramer's V puts it on KS's scale (~0.04 for a
 *     uniform table of 512) so the thesis weights keep the same balance.
 *   - Entries shared between levels through the hash belong to the lowest level
 *     that uses them and are not moved again; two parents hashing to one entry:
 *     the first lattice point in row-major order wins (eq. 3.13 gives no rule).
 *   - Reported statistics (nl_cheng_evaluate) are always over all M entries, with
 *     E_Con from all F octaves.
 *   - Side effect of the hash, not a reading: column i's lattice points use the
 *     consecutive slots P[P[i] + j], so a run of slots the optimiser made coherent
 *     reappears, shifted, in other columns of the higher octaves: optimised tables
 *     show faint vertical streaks (with or without propagation).
 */
#ifndef NL_CHENG_H
#define NL_CHENG_H

#include "base/nl_base.h"
#include "image/nl_image.h"
#include "noise/nl_noise.h"

#include "stats/nl_gmm.h"

#include <gsl/gsl_rng.h>

/* ---- control pattern ---------------------------------------------------- */

typedef struct {
  int grid;          /* control grid is grid x grid cells over [0,1)^2 */
  size_t n;          /* number of control points */
  double *x, *y, *d; /* cell centres and target values in [0, 1] */
  int *cell;         /* row-major cell index (r * grid + c) of each point */
} nl_cheng_pattern;

/* From an RGBA/RGB/grey image: D = red (grey) channel, alpha 0 = no control.
 * NL_EINVAL if no cell carries control or grid < 1. */
nl_status nl_cheng_pattern_from_image(const nl_image *im, int grid, nl_cheng_pattern **out,
                                      nl_error *err);
nl_status nl_cheng_pattern_read(const char *path, int grid, nl_cheng_pattern **out,
                                nl_error *err);
void nl_cheng_pattern_free(nl_cheng_pattern *p);
/* The pattern as an RGB image (grid x grid): red = D, no-control cells grey. */
nl_image *nl_cheng_pattern_image(const nl_cheng_pattern *p);

/* Built-in shapes for the shipped patterns (tools/patterns.c): "flower", "x",
 * "star", "rings", "disc", "letter" (an "N"), "gradient", "spiral". RGBA size x
 * size, red = 1 inside, black outside, alpha 1 everywhere except "disc", whose
 * outer corners are transparent (no control) to exercise alpha. NULL if unknown. */
nl_image *nl_cheng_shape(const char *name, int size);
extern const char *const nl_cheng_shape_names[];   /* NULL-terminated */

/* Removes "--patterns DIR" from argv (before nl_run_begin sees it) and sets
 * *dir to DIR, or "data/patterns" (experiments run from the repository root);
 * "--patterns: missing value" on error. */
nl_status nl_cheng_patterns_parse(int *argc, char **argv, const char **dir, nl_error *err);
/* The same; on error prints "PROG: message" and exits 2. */
const char *nl_cheng_patterns_option(int *argc, char **argv);
/* A pattern folder is what tools/patterns.c writes: the folder exists and
 * every shape of nl_cheng_shape_names is there as NAME.png and reads as a
 * pattern at `grid`. Checked before an experiment touches its output. */
nl_status nl_cheng_patterns_check(const char *dir, int grid, nl_error *err);
/* DIR/NAME.png read at `grid`; on failure prints "PROG: reason" and exits 2. */
nl_cheng_pattern *nl_cheng_pattern_load_or_die(const char *prog, const char *dir,
                                               const char *name, int grid);

/* ---- configuration ------------------------------------------------------ */

typedef enum { NL_CHENG_STAT_KS = 0, NL_CHENG_STAT_CHISQ = 1, NL_CHENG_STAT_KUIPER = 2 } nl_cheng_stat;
typedef enum { NL_CHENG_CON_PLAIN = 0, NL_CHENG_CON_SIN = 1, NL_CHENG_CON_ABS = 2,
               NL_CHENG_CON_FIRE = 3 } nl_cheng_con;

typedef struct {
  int n_temps;          /* temperature steps per level */
  double moves_per_var; /* moves per temperature = moves_per_var * n_vars */
  double t_decades;     /* total cooling, in decades of T */
  double p0;            /* initial acceptance of an average uphill move */
  int stall;            /* stop after this many temperatures without improvement */
} nl_cheng_schedule;

typedef struct {
  nl_cheng_stat stat;
  nl_cheng_con con;
  double w1, w2;        /* eq. 3.9 */
  int octaves;          /* F */
  double f1, a1;        /* eq. 3.10 */
  size_t m;             /* table size M; must match the table given */
  size_t chisq_bins;    /* K of eq. 3.4 */
  int propagate;        /* 1: eq. 3.13 initial guess per level (thesis); 0: keep the random start */
  nl_cheng_schedule sched;
} nl_cheng_config;

nl_cheng_config nl_cheng_config_default(void);
/* Weights >= 0 and not both 0, f1 > 0, a1 > 0, 1 <= octaves <= 8, K >= 2, sane
 * schedule; one-line message otherwise. */
nl_status nl_cheng_config_check(const nl_cheng_config *c, nl_error *err);
/* "ks", "chisq", "kuiper" / "cloud"|"plain", "marble"|"sin", "erosion"|"abs", "fire". */
nl_status nl_cheng_stat_parse(const char *s, nl_cheng_stat *out, nl_error *err);
nl_status nl_cheng_con_parse(const char *s, nl_cheng_con *out, nl_error *err);
const char *nl_cheng_stat_name(nl_cheng_stat s);
const char *nl_cheng_con_name(nl_cheng_con c);   /* texture name: cloud, marble, ... */

/* ---- the problem: incremental objective --------------------------------- */

typedef struct nl_cheng_problem nl_cheng_problem;

/* Borrows the pattern and the table (the table is edited by moves; keep both
 * alive). Starts at level 1. */
nl_cheng_problem *nl_cheng_problem_alloc(const nl_cheng_config *c, const nl_cheng_pattern *pat,
                                         nl_grad2 *table, nl_error *err);
void nl_cheng_problem_free(nl_cheng_problem *p);

/* Switches to level l (1..F): variables, statistic sample and E_Con's partial
 * sum; recomputes everything from the table. */
void nl_cheng_set_level(nl_cheng_problem *p, int level);
int nl_cheng_level(const nl_cheng_problem *p);
/* The current level's variables (table entries), n_vars of them. */
const size_t *nl_cheng_vars(const nl_cheng_problem *p, size_t *n_vars);
/* Current E, and its two terms (either pointer may be NULL). */
double nl_cheng_energy(const nl_cheng_problem *p, double *e_stat, double *e_con);

/* Sets entry k's angle (any k < M, theta in [0, 2pi)) and returns the new E,
 * updated incrementally. nl_cheng_undo reverts the last move exactly. */
double nl_cheng_move(nl_cheng_problem *p, size_t k, double theta);
void nl_cheng_undo(nl_cheng_problem *p);
/* E of the current level recomputed from scratch from the table, without
 * touching the incremental state (the tests' oracle). */
double nl_cheng_energy_full(const nl_cheng_problem *p, double *e_stat, double *e_con);
/* Re-evaluates every point from its stored corners and re-sums E_Con: clears
 * the rounding that moves by differences accumulate (O(points x level)). */
void nl_cheng_resum(nl_cheng_problem *p);

/* ---- annealing and the multi-level loop --------------------------------- */

typedef struct {
  int level;
  size_t n_vars;
  long moves, accepted;
  int temps;            /* temperatures actually run */
  double t0, t_end;
  double e_start, e_best;
  double seconds;
} nl_cheng_level_stats;

/* Anneals the current level's variables (schedule from the config). */
void nl_cheng_anneal(nl_cheng_problem *p, gsl_rng *rng, nl_cheng_level_stats *st);
/* Eq. 3.13: the current level's variables take their parents' angles. No-op at
 * level 1. */
void nl_cheng_propagate(nl_cheng_problem *p);
/* Levels 1..F: set level, propagate, anneal. stats: F entries or NULL. Seeds a
 * private gsl_rng MT19937 with `seed`. Leaves the problem at level F. */
void nl_cheng_optimise(nl_cheng_problem *p, unsigned long seed, nl_cheng_level_stats *stats);

/* ---- evaluation, values and textures ------------------------------------ */

typedef struct {
  double e_ks, p_ks;          /* over all M angles */
  double kuiper_v, p_kuiper;
  double chi2, p_chi2;        /* K bins */
  double e_con;               /* all F octaves, the config's control variant */
  double e;                   /* w1 E_stat + w2 E_con with the config's statistic */
  double rms_con;             /* sqrt(E_con / n points) */
  double roughness;           /* rms gradient of the control value on a 128^2 raster
                                 of [0,1)^2, per unit length (smoothness, Fig 4.7) */
} nl_cheng_eval;

nl_status nl_cheng_evaluate(const nl_grad2 *table, const nl_cheng_config *c,
                            const nl_cheng_pattern *pat, nl_cheng_eval *out, nl_error *err);

/* The control value c(x, y) of the config's variant (all F octaves) at the
 * centres of a w x h raster of [0,1)^2, row 0 at y = 0. */
void nl_cheng_value_grid(const nl_grad2 *table, const nl_cheng_config *c, int w, int h,
                         double *out);
/* Sec. 4.1: cloud / erosion / fire alpha-blend two colours with the value as
 * alpha; marble maps the value through the marble ramp. The optimised value
 * spans only part of [0, 1] (see READINGS), so alpha 0..1 is the value's own
 * 1st..99th percentile: a display stretch, not part of the optimisation. */
nl_image *nl_cheng_texture(nl_cheng_con kind, const double *v, int w, int h);

/* The value as grey with the same display stretch. */
nl_image *nl_cheng_grey_image(const double *v, int w, int h);

/* One complete run, the loop the experiments share: random table from `seed`,
 * multi-level optimisation, evaluation; the optimised table is returned in
 * *table_out if not NULL (caller frees). stats: F entries or NULL. */
nl_status nl_cheng_run(const nl_cheng_config *c, const nl_cheng_pattern *pat, unsigned long seed,
                       nl_cheng_eval *ev, nl_cheng_level_stats *stats, nl_grad2 **table_out,
                       nl_error *err);

/* ---- what the experiments share (nl_cheng_exp.c) ------------------------ */

struct nl_run;
struct nl_table;
/* The opening every Cheng experiment shares: strips "--patterns DIR"
 * (nl_cheng_patterns_option) into *patterns, starts the run, reads the
 * standard --set parameters into *c and *grid: grid (64), w1, w2, f1, a1,
 * octaves, temps (n_temps; quick 8), moves_per_var (quick 5), defaults
 * otherwise, and checks the patterns folder (nl_cheng_patterns_check; "NAME:
 * control patterns: ...", exit 2), all before the output folder is touched. The experiment then reads its own parameters and calls
 * nl_cheng_params_done. */
struct nl_run *nl_cheng_begin(const char *name, const char *title, int *argc, char **argv,
                              nl_cheng_config *c, int *grid, const char **patterns);
/* nl_run_params_done, then nl_cheng_config_check ("NAME: message", exit 2),
 * and the patterns folder into the manifest. */
void nl_cheng_params_done(struct nl_run *r, const nl_cheng_config *c, const char *patterns);
/* nl_cheng_run for seeds seed0 .. seed0+k-1 into evs[k]; the first seed's
 * table in *first if not NULL. */
nl_status nl_cheng_run_seeds(const nl_cheng_config *c, const nl_cheng_pattern *pat,
                             unsigned long seed0, int k, nl_cheng_eval *evs, nl_grad2 **first,
                             nl_error *err);
/* Summary table: nlabels label columns, then seeds, E_ks (mean), E_ks_sd, p_ks
 * (mean), p_ks_min, V_kuiper, V_kuiper_sd, p_kuiper, p_kuiper_min, chi2, chi2_sd,
 * p_chi2, E_con, E_con_sd, rms_con, E, uniform_ks, uniform_kuiper (fractions of
 * runs not rejected as non-uniform at alpha = 0.05), roughness, roughness_sd. */
struct nl_table *nl_cheng_summary_alloc(int nlabels, const char *const *labels);
void nl_cheng_summary_add(struct nl_table *t, int nlabels, const char *const *labels,
                          const nl_cheng_eval *evs, int k);
/* ECDF of each table's angles: F = i/M and u_NAME = sorted angle / 2 pi. */
struct nl_table *nl_cheng_cdf_table(const nl_grad2 *const *tables, const char *const *names, int n);
/* Histogram of each table's angles in `bins` bins: theta (bin centre), NAME counts. */
struct nl_table *nl_cheng_hist_table(const nl_grad2 *const *tables, const char *const *names,
                                     int n, size_t bins);
/* size x size images: the control value (grey), the config's texture, and
 * the pattern (nearest-neighbour upscaled). */
nl_image *nl_cheng_value_image(const nl_grad2 *g, const nl_cheng_config *c, int size);
nl_image *nl_cheng_texture_image(const nl_grad2 *g, const nl_cheng_config *c, int size);
nl_image *nl_cheng_pattern_panel(const nl_cheng_pattern *p, int size);
/* Median of the one-sample KS statistic D_n under the null (bisection on
 * nl_ks_cdf): the yardstick for "as uniform as a random table". */
double nl_cheng_ks_median(size_t n);
/* A w x h raster as a table of h rows and w columns c0..c{w-1} (gnuplot's
 * "matrix columnheaders" layout, for height maps). */
struct nl_table *nl_cheng_matrix_table(const double *v, int w, int h);

/* ---- noise reproduction (sec. 3.5, Tables 4.2-4.4; nl_cheng_reproduce.c) --
 *
 *   nl_cheng_pool_options po; nl_cheng_pool_options_default(&po);   // Q 100, N 100, eps 10
 *   nl_cheng_pool *pool;
 *   nl_cheng_pool_collect(opt, &c, pat, &po, seed, &pool, &err);   // opt: an optimised table
 *   nl_cheng_model_options mo; nl_cheng_model_options_default(&mo);
 *   nl_cheng_model *m;
 *   nl_cheng_model_fit(pool, &mo, seed, &m, &err);                  // cluster -> K0 -> GMM/AIC
 *   nl_cheng_reproduce(opt, m, rng, out);                           // one new table, real time
 *
 * LOW / HIGH SPLIT (sec. 3.5.1). The low-frequency entries are the variables of
 *   levels 1..low_levels (entries whose lowest lattice is octave <= low_levels;
 *   nl_cheng.h MULTI-LEVEL RULE); all other entries are high. Default
 *   low_levels = 1, the thesis's "gradient vectors shared by low frequency
 *   noise" read as the coarsest lattice (9 x 9 points at f1 = 8: ~80 entries);
 *   low_levels = 2 (~280 entries) is the other reading, a parameter of C5.
 * E_R (eq. 3.16-3.18). The problem in reproduction mode
 *   (nl_cheng_set_reproduction): variables = the low entries, statistic over
 *   ALL M entries ({X_opt high, X_rep low}, eq. 3.16), E_Con with all F octaves
 *   (V_rep, eq. 3.17), E_R = w1 E_u + w2 E_Con with the config's weights
 *   (eq. 3.18 prints w1 = 0.955, we read the 0.995 of eq. 3.9: a typo, the
 *   weights of sec. 3.4 sum to 1). Annealed by nl_cheng_anneal.
 * POOL RULE (sec. 3.5.2). Q runs; run q uses the stream (seed, "cheng.pool.run",
 *   q) of the seed rule (nl_base.h), not a thread's, sets the
 *   low entries to uniform random angles (random initial condition), keeps the
 *   optimised high entries, anneals. "The N solutions before the end of the
 *   optimization": the annealer returns its best state, and the walk goes on
 *   at its final temperature (step pi/100, the annealer's floor) for N sweeps
 *   of n_low moves; the state after each sweep is a solution. Solutions whose
 *   E_R exceeds the run's best (anneal or tail) by more than epsilon are left
 *   out (counted in `excluded`). The annealer is not modified; a cold tail is
 *   what its last temperatures are once its stall rule has fired.
 * CIRCULAR REPRESENTATION. Angles are points on a circle; a Euclidean distance
 *   on raw angles puts 0.01 and 2 pi - 0.01 2 pi apart. NL_CHENG_REP_COSSIN
 *   (default) maps each angle to (cos, sin): d = 2 n_low, distance = chord
 *   2 sin(dtheta / 2), monotone in the arc, no cut anywhere, which matters
 *   because across runs an entry's angle covers the whole circle; mixture
 *   draws are mapped back by atan2 (projection onto the circle).
 *   The chord is also the metric of the clustering, whatever the mixture's
 *   representation. But for the MIXTURE cos/sin has a cost: the rows lie on a
 *   torus of dimension n_low inside R^(2 n_low), so each Gaussian sees a thin,
 *   curved, one-sided spread across the circle and AIC keeps buying
 *   components to follow the curvature (measured in test_reproduce.c: 3
 *   blobs of sd 0.05 select K = 10). NL_CHENG_REP_UNWRAP: each angle unwrapped
 *   to (mu_j - pi, mu_j + pi] with mu_j opposite the middle of the widest
 *   empty arc of column j in the pool (d = n_low, intrinsic coordinates; the
 *   cut falls where the pool has no angles, if it has such an arc; a cut
 *   opposite the circular mean split a blob in the same test).
 * CUTOFF (sec. 3.5.2). "The merge stops when the Hausdorff distance between
 *   the two clusters exceeds the cutoff": complete linkage (max pairwise
 *   distance) is the Hausdorff-type distance between point sets that makes
 *   "every pair in a cluster within the cutoff" true; flat clusters by
 *   nl_fcluster_distance. The true Hausdorff distance is not a reducible
 *   linkage; we say so rather than approximate it. The initial K is the number
 *   of clusters. cutoff < 0 asks for the cutoff that gives target_k clusters
 *   (midpoint of the merge heights around it): the thesis tuned its cutoff
 *   "case by case" for a proper K, and its absolute values (15.5-19.5) are in
 *   units we cannot reconstruct.
 * AIC RULE (sec. 3.5.3, eq. 3.19 AIC = -2L + 2m). The printed rule
 *   "delta_i = AIC_i - AIC_{i-1}; stop if delta_i < T" would stop at the first
 *   improvement; we read it as: fit K0, K0+1, ... and stop when AIC falls by
 *   less than T; the model kept is the last that improved by >= T
 *   (nl_gmm_select_aic). Path capped at K0 + k_extra. m is scikit-learn's
 *   parameter count (nl_gmm.h).
 * REPRODUCTION (sec. 3.5.3). Copy the optimised table, draw one vector from
 *   the mixture, decode it into the low entries, and permute a fraction of
 *   the high entries among themselves (swap_fraction 1: a uniform random
 *   permutation; the angle multiset, hence E_u's high part, is unchanged).
 * DEGENERATE CASES are reported in nl_cheng_model.status, never a crash:
 *   pool too small (< 2 solutions or K0 >= samples), one cluster, one cluster
 *   per point, EM not converged in max_iter, EM failure, path reached k_max.
 */

typedef enum { NL_CHENG_REP_COSSIN = 0, NL_CHENG_REP_UNWRAP = 1 } nl_cheng_rep;

typedef struct {
  int low_levels;       /* 1 (see LOW / HIGH SPLIT) */
  int runs;             /* Q, 100 */
  int keep;             /* N, 100 */
  double epsilon;       /* error bound on E_R, 10.0 */
  int threads;          /* worker threads, 2; results do not depend on it */
} nl_cheng_pool_options;

typedef struct {
  size_t nlow, *low;    /* the low entries (table indices) */
  size_t n;             /* solutions kept */
  double *theta;        /* n x nlow angles in [0, 2 pi) */
  double *e;            /* n values of E_R */
  int *run;             /* n: run of each solution */
  int runs;             /* Q */
  double *run_best;     /* Q: best E_R of each run */
  double *run_start;    /* Q: E_R at the random start */
  double *run_seconds;  /* Q: wall time of each run (anneal + tail) */
  size_t excluded;      /* solutions over the error bound */
  double e_opt;         /* E_R of the optimised table itself */
} nl_cheng_pool;

void nl_cheng_pool_options_default(nl_cheng_pool_options *o);
/* Reproduction mode of eq. 3.16-3.18 (see E_R): level F, variables = entries
 * of levels 1..low_levels, statistic over all M entries. */
void nl_cheng_set_reproduction(nl_cheng_problem *p, int low_levels);
/* The low entries of levels 1..low_levels of `table` (its permutation
 * decides them) under this config, ascending; caller frees. NULL on error. */
size_t *nl_cheng_low_entries(const nl_grad2 *table, const nl_cheng_config *c,
                             const nl_cheng_pattern *pat, int low_levels, size_t *nlow,
                             nl_error *err);
nl_status nl_cheng_pool_collect(const nl_grad2 *opt, const nl_cheng_config *c,
                                const nl_cheng_pattern *pat, const nl_cheng_pool_options *o,
                                unsigned long seed, nl_cheng_pool **out, nl_error *err);
void nl_cheng_pool_free(nl_cheng_pool *p);
size_t nl_cheng_pool_bytes(const nl_cheng_pool *p);

/* Representation (see CIRCULAR REPRESENTATION): dimension; reference angles
 * mu (nlow: per column, the point opposite the middle of its widest empty
 * arc; unused by COSSIN's encoding); encode n rows of nlow angles into n x d;
 * decode n x d into angles in [0, 2 pi). */
size_t nl_cheng_rep_dim(nl_cheng_rep rep, size_t nlow);
void nl_cheng_circular_centre(const double *theta, size_t n, size_t nlow, double *mu);
void nl_cheng_rep_encode(nl_cheng_rep rep, const double *theta, size_t n, size_t nlow,
                         const double *mu, double *x);
void nl_cheng_rep_decode(nl_cheng_rep rep, const double *x, size_t n, size_t nlow,
                         const double *mu, double *theta);
nl_status nl_cheng_rep_parse(const char *s, nl_cheng_rep *out, nl_error *err);  /* cossin, unwrap */
const char *nl_cheng_rep_name(nl_cheng_rep rep);

/* Complete-linkage clusters of n rows of d cut at `cutoff` (labels 1..k, may
 * be NULL): the initial K. nl_cheng_cutoff_for_k: the cutoff (midpoint of
 * two merge heights) giving k clusters from a linkage Z of n points. */
nl_status nl_cheng_initial_k(const double *x, size_t n, size_t d, double cutoff, int *labels,
                             size_t *k, nl_error *err);
double nl_cheng_cutoff_for_k(const double *Z, size_t n, size_t k);

typedef enum {
  NL_CHENG_MODEL_OK = 0, NL_CHENG_MODEL_TOO_SMALL, NL_CHENG_MODEL_ONE_CLUSTER,
  NL_CHENG_MODEL_ONE_PER_POINT, NL_CHENG_MODEL_NOT_CONVERGED, NL_CHENG_MODEL_EM_FAILED,
  NL_CHENG_MODEL_K_MAX
} nl_cheng_model_status;
const char *nl_cheng_model_status_name(nl_cheng_model_status s);

typedef struct {
  nl_cheng_rep rep;     /* COSSIN */
  size_t samples;       /* input samples drawn from the pool, 1000 (0 = all) */
  double cutoff;        /* complete-linkage cutoff; < 0: the cutoff giving target_k */
  size_t target_k;      /* used when cutoff < 0 */
  double threshold;     /* T: AIC must fall by at least T, 0 */
  size_t k_extra;       /* path capped at K0 + k_extra, 12 */
  nl_gmm_options gmm;   /* nl_gmm_options_default, full covariance */
} nl_cheng_model_options;

typedef struct {
  nl_cheng_rep rep;
  size_t nlow, d, *low; /* low entries (copy of the pool's) */
  double *mu;           /* nlow reference angles */
  size_t n_in;          /* input samples used */
  size_t *in;           /* their pool rows (n_in) */
  double cutoff;
  size_t k0, k;         /* initial and final K */
  nl_gmm *gmm;          /* NULL if no model could be fitted */
  nl_gmm_step *path;    /* AIC/BIC path, npath entries */
  size_t npath;
  nl_cheng_model_status status;
  char msg[160];        /* status in words */
  double seconds_cluster, seconds_gmm;
  size_t cluster_bytes; /* distance matrix + linkage */
} nl_cheng_model;

void nl_cheng_model_options_default(nl_cheng_model_options *o);
/* Subsample (seed), encode, cluster, select by AIC. NL_OK whenever a status
 * can be reported (including degenerate ones, see DEGENERATE CASES); an error
 * only for invalid options. */
nl_status nl_cheng_model_fit(const nl_cheng_pool *pool, const nl_cheng_model_options *o,
                             unsigned long seed, nl_cheng_model **out, nl_error *err);
void nl_cheng_model_free(nl_cheng_model *m);
/* out = opt with low entries drawn from the mixture and a swap_fraction of
 * the high entries permuted at random. NL_EINVAL without a mixture. */
nl_status nl_cheng_reproduce(const nl_grad2 *opt, const nl_cheng_model *m, double swap_fraction,
                             gsl_rng *rng, nl_grad2 *out, nl_error *err);
/* Does the mixture describe the pool? (beyond the paper) Mean log-likelihood
 * per row of the input samples and of the pool rows not used (held out;
 * NAN if none), and per-dimension two-sample KS between n_draw mixture draws
 * (decoded to angles, cut in the widest empty arc) and n_draw pool rows
 * evenly spaced through the pool: median D and the fraction of dimensions
 * with p < 0.05. */
typedef struct {
  double ll_train, ll_held;
  size_t n_held;
  double ks_median, ks_reject;
} nl_cheng_model_check;
nl_status nl_cheng_model_assess(const nl_cheng_pool *pool, const nl_cheng_model *m, size_t n_draw,
                                gsl_rng *rng, nl_cheng_model_check *out, nl_error *err);

/* ---- what C5 and C6 share (nl_cheng_repro_exp.c) ------------------------ */

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
} nl_cheng_thesis_gmm;
extern const nl_cheng_thesis_gmm nl_cheng_thesis_gmm_tables[3];   /* erosion, marble, cloud */

/* --set parameters: runs (Q; quick 6), keep (N; quick 20), epsilon,
 * low_levels, threads, samples (quick 100), T, k_extra, unwrap (0/1), diag
 * (0/1: diagonal covariances), max_iter. */
void nl_cheng_repro_params(struct nl_run *r, nl_cheng_pool_options *po, nl_cheng_model_options *mo);

/* Original optimised table (nl_cheng_run, timed) and its pool (timed). */
typedef struct {
  nl_grad2 *opt;
  nl_cheng_eval ev;
  double seconds_opt, seconds_pool;
  nl_cheng_pool *pool;
} nl_cheng_repro;
nl_status nl_cheng_repro_original(const nl_cheng_config *c, const nl_cheng_pattern *pat,
                                  unsigned long seed, nl_cheng_repro *out, nl_error *err);
nl_status nl_cheng_repro_pool(nl_cheng_repro *rp, const nl_cheng_config *c, const nl_cheng_pattern *pat,
                              const nl_cheng_pool_options *po, unsigned long seed, nl_error *err);
void nl_cheng_repro_clear(nl_cheng_repro *rp);
/* Number of complete-linkage clusters of the model's input rows (cos/sin) at
 * each of ncut cutoffs: K against the cutoff. */
nl_status nl_cheng_k_curve(const nl_cheng_pool *pool, const nl_cheng_model *m, const double *cut,
                           size_t ncut, size_t *k, nl_error *err);

#endif
