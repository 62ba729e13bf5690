/* nl_cheng.h - controllable Perlin noise, the optimiser (Cheng 2009, sections
 * 3.2-3.4, 4.1-4.3): the angles of a 2D gradient table are optimised by
 * multi-level simulated annealing so that a fractal sum follows a user's
 * control pattern while the angles stay uniformly distributed. The noise
 * reproduction of sec. 3.5 (solution pools, clustering, mixtures) is
 * nl_cheng_repro.h; reading patterns from PNGs, the built-in shapes and the
 * textures as images are on the harness side (study/nl_study_cheng.h), so
 * this module needs no image, table or report code.
 *
 * API (sections below in this order)
 *   pattern   nl_cheng_pattern_from_pixels, nl_cheng_pattern_free
 *   config    nl_cheng_config_default / _check, nl_cheng_stat_parse / _name,
 *             nl_cheng_con_parse / _name, nl_cheng_objective (eq. 3.9, the one
 *             place E = w1 E_stat + w2 E_Con is formed)
 *   problem   nl_cheng_problem_alloc / _free, nl_cheng_set_level, nl_cheng_vars,
 *             nl_cheng_energy, nl_cheng_move / _undo,
 *             nl_cheng_energy_full, nl_cheng_resum
 *   anneal    nl_cheng_anneal, nl_cheng_propagate, nl_cheng_optimise
 *   eval      nl_cheng_evaluate, nl_cheng_value_grid, nl_cheng_run,
 *             nl_cheng_ks_median
 *   amplitudes nl_cheng_octaves, nl_cheng_log_gains (X6, nl_cheng_amp.c)
 *
 *   nl_cheng_pattern *pat;
 *   nl_cheng_pattern_from_pixels(rgba, w, h, 4, 64, &pat, &err);      // 64 x 64 control grid
 *   nl_cheng_config c = nl_cheng_config_default();                      // thesis setting
 *   nl_noise_grad2 *g = nl_noise_grad2_alloc(512);
 *   nl_noise_grad2_seed(g, seed);                        // random start (level 1's initial guess)
 *   nl_cheng_problem *p = nl_cheng_problem_alloc(&c, pat, g, &err);     // g is edited in place
 *   nl_cheng_optimise(p, seed, stats);             // levels 1..F, stats may be NULL
 *   nl_cheng_eval ev; nl_cheng_evaluate(g, &c, pat, &ev, &err);         // E_KS, V, chi2, p, E_Con
 *   nl_cheng_value_grid(g, &c, 256, 256, v);       // the controlled value over the domain
 * (nl_cheng_run does the last five lines in one call.)
 *
 * THE MODEL (thesis setting in nl_cheng_config_default)
 *   Noise(x, y) = sum over the 4 cell corners (i, j) of w(x-i) w(y-j) (Delta_ij . G_ij)
 *   (eq. 3.1-3.2), G_ij = G[P[P[i] + j]] (nl_noise_grad2, M = 512 angles, quintic fade);
 *   fractal sum F_sum = sum_{l=1..F} Noise(f_l x, f_l y) / a_l, f_l = f1 2^(l-1),
 *   a_l = a1 2^(l-1), F = 4, f1 = 8, a1 = 4 (eq. 3.10), over the domain [o, o + 1]^2:
 *   a texture point (x, y) in [0, 1)^2 (pattern cell centres, raster pixels) is
 *   evaluated at (o + x, o + y), o = config.origin = 1 (READINGS: the domain).
 *
 * OBJECTIVE (eq. 3.9)  E = w1 E_stat + w2 E_Con,  w1 = 0.995, w2 = 0.005.
 *   E_stat, a statistic of the angles X against uniform on [0, 2 pi):
 *     NL_CHENG_STAT_KS      D = max |F_obs - F_ideal| (eq. 3.5-3.7);
 *     NL_CHENG_STAT_KUIPER  V = D+ + D- (independent of where the circle is cut);
 *     NL_CHENG_STAT_CHISQ   Pearson chi2 on K = 500 equal bins (eq. 3.4), entered as
 *                           Cramer's V = sqrt(chi2 / (n (K - 1))) - see READINGS;
 *     NL_CHENG_STAT_CHISQ_RAW  the same chi2 entered as printed (eq. 3.4), unscaled.
 *   E_Con = sum_i (c(x_i) - D_i)^2 over the control points, with the control value
 *     NL_CHENG_CON_PLAIN   c = (1 + V) / 2                   (cloud, eq. 3.8)
 *     NL_CHENG_CON_SIN     c = (1 + sin(pi V)) / 2           (marble, eq. 4.1)
 *     NL_CHENG_CON_ABS     c = |V|                           (erosion, eq. 4.2)
 *     NL_CHENG_CON_FIRE    c = s sum_l |Noise_l| / a_l       (fire, eq. 4.3)
 *   where V = s F_sum, s = 1 / (sqrt(2)/2 sum_l 1/a_l): the sum over its analytic
 *   bound, so V is in [-1, 1] and every c in [0, 1] like D (see READINGS).
 *   config.literal = 1 takes the formulas as printed instead: V = F_sum (s = 1),
 *   c = V, sin V, |V|, sum_l |Noise_l| / a_l (the measured alternative reading;
 *   marble's rescaled sine has pi s ~ 9.5 times the literal sine's gain).
 *
 * MULTI-LEVEL RULE (sec. 3.4.2, eq. 3.13-3.15). Level l = 1..F, low to high
 *   frequency. The lattice of octave l is the points floor(f_l o) .. ceil(f_l (o + 1))
 *   (each axis) that the domain touches: (f_l + 1)^2 of them for integer f_l o. Level l's variables are the table entries used by that
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
 *   through nl_stats_ks_incr (KS; Kuiper's V = D+ + D- of the same state: O(log n +
 *   rank shift + n/32)) or bin counts (chi-square: O(1), the sum of squared
 *   counts kept exactly in integers). nl_cheng_undo restores the saved values
 *   exactly. Since annealing moves only the top octave of its level, each point
 *   also keeps the sum of its lower octaves (set at the re-evaluation below and
 *   marked invalid when a lower octave or gain moves): a top-octave move adds
 *   one term to it, the same additions in the same order as the full sum. At
 *   every temperature step all points are re-evaluated from the stored corners
 *   (only the top octave when nothing below it moved) and E_Con is re-summed,
 *   so rounding from differences never outlives one temperature. Tested: incremental == full recomputation to 1e-12
 *   (relative) after every move of a random sequence.
 *
 * OCTAVE AMPLITUDES AS VARIABLES (X6, the thesis's ch. 5 future work: "adjust
 *   the amplitude in the fractal sum"; config.amp_vary = 1, off by default).
 *   Octave l's amplitude is 1/a_l = g_l / a_l^thesis with a log gain u_l =
 *   ln g_l in [-ln R, ln R], R = config.amp_range (default 4: a_l within
 *   [1/4, 4] x the thesis's). Rule: level l's variables are its table entries
 *   plus u_l (variable index M + l - 1 in nl_cheng_vars), so an octave's gain
 *   moves only at the level where the octave enters and is frozen after it,
 *   like its entries. Propagation: u_l starts at config.log_gain[l] (0: the
 *   thesis's a_l) - a gain has no lattice parent for eq. 3.13 to copy. Move:
 *   u' = u + (sigma / pi) ln R U(-1, 1), reflected at the bounds (a symmetric
 *   proposal, as for the angles). Scale: s = 1 / (sqrt(2)/2 sum_l 1/a_l) is
 *   recomputed from the current amplitudes after every move, so V stays in
 *   [-1, 1] and c in [0, 1] like D (the reading below); E is then invariant to
 *   a common gain, so the optimiser changes the octaves' relative weights, not
 *   a global contrast knob outside c's range. A gain move changes every
 *   point's value: O(points x level) per move, E_Con re-summed exactly (the
 *   same left-to-right sum as nl_cheng_resum). With amp_vary = 0 and
 *   log_gain = 0 every result is bit-identical to the fixed amplitudes
 *   (exp(0) = 1). nl_cheng_run evaluates with the optimised gains, returned
 *   in nl_cheng_eval.log_gain. The reproduction (nl_cheng_repro.h) moves
 *   angles only: its problem keeps the config's log_gain fixed.
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
 *   - The domain. The thesis states none. Every octave evaluates the one noise
 *     field at f_l x (eq. 3.10), so lattice point (I, J) has the same gradient
 *     in every octave. On the unit square at the noise's origin (o = 0) octave
 *     l's lattice holds octave l-1's whole lattice in its quarter [0, 1/2]^2:
 *     octave l there is octave l-1 over the square, shrunk, with entries frozen
 *     at level l-1; a control term that pushes the border's value one way (a
 *     dark border under the signed cloud or marble terms) turns octave 1's
 *     border gradients outward, and the quarter's edges x = 1/2 (y < 1/2) and
 *     y = 1/2 (x < 1/2) repeat that steep border as straight seams. On
 *     [o, o + 1]^2 octave l covers the noise's [f_l o, f_l (o + 1)] per axis
 *     and octave l-1 [f_l o / 2, f_l (o + 1) / 2]: the two overlap unless
 *     o >= 1, whatever f1 and F. So o = 1, the smallest origin at which no
 *     octave's cells lie inside another's (adjacent octaves share only the
 *     corner lattice point f_l (o + 1) = f_{l+1} o of both axes), and an
 *     integer, so every point keeps its fractional position in its cell (the
 *     grid rule above) and each lattice has (f_l + 1)^2 points. Chosen by that
 *     criterion alone, not by any number of the thesis; eq. 3.10-3.13 hold as
 *     written (eq. 3.13's parent (floor(I/2), floor(J/2)) of a point of octave
 *     l's lattice lies on octave l-1's over the same domain). The highest
 *     index, f_F (o + 1) = 128 in the thesis setting, stays below M = 512, so
 *     the hash does not wrap. o = 0 is the alternative reading, measured
 *     beside it (seams.tsv of C1, C3, C4, C7).
 */
#ifndef NL_CHENG_H
#define NL_CHENG_H

#include "base/nl_base.h"
#include "noise/nl_noise.h"

#include <gsl/gsl_rng.h>

#ifdef __cplusplus
extern "C" {
#endif

/* ---- control pattern ---------------------------------------------------- */

#define NL_CHENG_MAX_OCTAVES 8   /* F <= 8 (nl_cheng_config_check) */

typedef struct {
  int grid;          /* control grid is grid x grid cells over [0,1)^2 */
  size_t n;          /* number of control points */
  double *x, *y, *d; /* cell centres and target values in [0, 1] */
  int *cell;         /* row-major cell index (r * grid + c) of each point */
} nl_cheng_pattern;

/* From interleaved float pixels (width x height, row 0 at the top, 1 grey, 2
 * grey+alpha, 3 RGB or 4 RGBA channels: nl_image's layout): D = the mean red
 * (grey) of the cell's pixels weighted by alpha; cells of mean alpha < 1/2
 * carry no control. NL_EINVAL if a red (grey) or alpha value is outside
 * [0, 1] (the first such pixel named), no cell carries control, grid is outside
 * 1..4096 or the raster is not one of those layouts. */
nl_status nl_cheng_pattern_from_pixels(const float *data, int width, int height, int channels,
                                       int grid, nl_cheng_pattern **out, nl_error *err);
void nl_cheng_pattern_free(nl_cheng_pattern *p);

/* ---- configuration ------------------------------------------------------ */

typedef enum { NL_CHENG_STAT_KS = 0, NL_CHENG_STAT_CHISQ = 1, NL_CHENG_STAT_KUIPER = 2,
               NL_CHENG_STAT_CHISQ_RAW = 3 } nl_cheng_stat;
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
  int literal;          /* 0: V over its bound, c in [0, 1] (READINGS); 1: the thesis's formulas
                           literally, V = F_sum unscaled, c = V, sin V, |V|, sum |Noise_l| / a_l */
  int amp_vary;         /* 1: octave l's log gain is a level-l variable (X6 above); 0: fixed */
  double amp_range;     /* R: gains within [1/R, R] (default 4; >= 1) */
  double log_gain[NL_CHENG_MAX_OCTAVES];   /* u_l: 1/a_l = e^u_l / a_l^thesis (0: the thesis's) */
  double origin;        /* o: the texture's unit square is [o, o + 1]^2 in the noise's coordinates
                           before the octaves' f_l (default 1; 0: anchored at the noise's origin;
                           READINGS) */
} nl_cheng_config;

nl_cheng_config nl_cheng_config_default(void);
/* Weights >= 0 and not both 0, f1 > 0, a1 > 0, 1 <= octaves <= 8, K >= 2, sane
 * schedule, amp_vary 0/1, finite log gains and, with amp_vary, amp_range >= 1
 * and |log_gain| <= ln amp_range; one-line message otherwise. */
nl_status nl_cheng_config_check(const nl_cheng_config *c, nl_error *err);
/* "ks", "chisq", "kuiper", "chisq_raw" / "cloud"|"plain", "marble"|"sin", "erosion"|"abs", "fire". */
nl_status nl_cheng_stat_parse(const char *s, nl_cheng_stat *out, nl_error *err);
nl_status nl_cheng_con_parse(const char *s, nl_cheng_con *out, nl_error *err);
const char *nl_cheng_stat_name(nl_cheng_stat s);
const char *nl_cheng_con_name(nl_cheng_con c);   /* texture name: cloud, marble, ... */
/* Eq. 3.9, E = w1 E_stat + w2 E_Con with the config's weights: the one place
 * the objective is formed (incremental moves, full recomputation, resums,
 * the reproduction's E_R of eq. 3.18 and nl_cheng_evaluate all call it). */
double nl_cheng_objective(const nl_cheng_config *c, double e_stat, double e_con);

/* ---- the problem: incremental objective --------------------------------- */

typedef struct nl_cheng_problem nl_cheng_problem;

/* Borrows the pattern and the table (the table is edited by moves; keep both
 * alive). Starts at level 1. */
nl_cheng_problem *nl_cheng_problem_alloc(const nl_cheng_config *c, const nl_cheng_pattern *pat,
                                         nl_noise_grad2 *table, nl_error *err);
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

/* One incremental problem as the annealer sees it: `move` proposes a step of
 * width sigma on variable var (0 <= var < n_vars), applies it and returns
 * the new E; `undo` reverts it exactly; save/restore copy the variables
 * (state_size doubles); resum clears the rounding of running sums. */
typedef struct {
  void *ctx;
  size_t n_vars, state_size;
  double (*energy)(void *ctx);
  double (*move)(void *ctx, size_t var, double sigma, gsl_rng *rng);
  void (*undo)(void *ctx);
  void (*save)(void *ctx, double *state);
  void (*restore)(void *ctx, const double *state);
  void (*resum)(void *ctx);
} nl_cheng_sa_ops;

/* The ANNEALING schedule above on any such problem (the 2D levels and the
 * 3D model both run it): T0 from 200 trial moves of width pi, Metropolis
 * sweeps, geometric cooling, the stall rule, the best end-of-temperature
 * state restored. st (may be NULL) gets level 1; a caller running several
 * levels sets its own. */
void nl_cheng_sa_run(const nl_cheng_sa_ops *ops, const nl_cheng_schedule *s, gsl_rng *rng,
                     nl_cheng_level_stats *st);
/* Anneals the current level's variables (schedule from the config) with
 * nl_cheng_sa_run. */
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
  /* Controllability: how well the value follows the pattern, and two baselines. */
  double r_pattern;           /* Pearson r of c(x_i) and D_i over the control points */
  /* E_Con = offset + contrast + shape (population moments over the n points):
   * n (mean c - mean D)^2, n (sd c - sd D)^2, 2 n sd c sd D (1 - r_pattern). */
  double e_con_offset, e_con_contrast, e_con_shape;
  double seam_ratio;          /* largest mean |step| across one raster column or row
                                 boundary over the mean of all (128^2 raster; ~1.4-1.5 for
                                 unoptimised tables, ~2 along a seam) */
  double contrast;            /* sd of c on the 128^2 raster */
  double e_con_const;         /* E_Con of the best constant image, sum (D_i - mean D)^2 */
  double e_con_random;        /* E_Con of the unoptimised table (nl_cheng_run's start; NAN
                                 from nl_cheng_evaluate alone) */
  double log_gain[NL_CHENG_MAX_OCTAVES];   /* the amplitudes evaluated (config's; nl_cheng_run's optimised) */
  /* Cost of nl_cheng_run's optimisation (0 from nl_cheng_evaluate alone): moves
   * tried over all levels, and the thread's CPU seconds from the problem's set-up
   * to the end of the last level (set-up included, evaluation excluded). */
  long moves;
  double cpu_seconds;
} nl_cheng_eval;

nl_status nl_cheng_evaluate(const nl_noise_grad2 *table, const nl_cheng_config *c,
                            const nl_cheng_pattern *pat, nl_cheng_eval *out, nl_error *err);

/* The control value c(x, y) of the config's variant (all F octaves) at the
 * centres of a w x h raster of [0,1)^2, row 0 at y = 0. */
void nl_cheng_value_grid(const nl_noise_grad2 *table, const nl_cheng_config *c, int w, int h,
                         double *out);

/* One complete run, the loop the experiments share: random table from `seed`,
 * multi-level optimisation, evaluation; the optimised table is returned in
 * *table_out if not NULL (caller frees). stats: F entries or NULL. */
nl_status nl_cheng_run(const nl_cheng_config *c, const nl_cheng_pattern *pat, unsigned long seed,
                       nl_cheng_eval *ev, nl_cheng_level_stats *stats, nl_noise_grad2 **table_out,
                       nl_error *err);
/* Median of the one-sample KS statistic D_n under the null (bisection on
 * nl_stats_ks_cdf): the yardstick for "as uniform as a random table". */
double nl_cheng_ks_median(size_t n);

/* ---- octave amplitudes (X6, nl_cheng_amp.c) ------------------------------ */

/* Eq. 3.10's octaves with the config's gains: amp[l] = e^log_gain[l] / a_l. */
nl_noise_octaves nl_cheng_octaves(const nl_cheng_config *c);
/* The problem's current log gains u_1..u_F into out[0..F-1] (the config's
 * until a level with amp_vary has moved them). */
void nl_cheng_log_gains(const nl_cheng_problem *p, double *out);

#ifdef __cplusplus
}
#endif

#endif
