/* nl_cheng3.h - controllable gradient noise in 3D (Cheng 2009, ch. 5 future
 * work; TARGETS C8): the 2D model of nl_cheng.h with the gradients as unit
 * vectors on the sphere, the uniformity term tested on the sphere, control
 * points on a G^3 grid and the same annealing schedule (nl_cheng_schedule).
 *
 * API (sections below in this order)
 *   table     nl_noise_grad3 (nl_noise.h): the noise, its table and its corners;
 *             nl_cheng3_table and nl_cheng3_table_alloc / _seed / _free name it here
 *   pattern   nl_cheng3_pattern_shape, nl_cheng3_pattern_free
 *   config    nl_cheng3_config_default (nl_cheng_config, checked by nl_cheng_config_check)
 *   problem   nl_cheng3_problem_alloc / _free, nl_cheng3_energy, nl_cheng3_move /
 *             _undo, nl_cheng3_energy_full, nl_cheng3_resum, nl_cheng3_propose
 *   anneal    nl_cheng3_optimise (on nl_cheng.h's nl_cheng_sa_run, the schedule
 *             loop written against callbacks)
 *   eval      nl_cheng3_evaluate, nl_cheng3_value, nl_cheng3_value_grid, nl_cheng3_run,
 *             nl_cheng3_level_entries
 *
 *   nl_cheng3_pattern *pat;
 *   nl_cheng3_pattern_shape("torus", 16, &pat, &err);   // 16^3 control points
 *   nl_cheng3_config c = nl_cheng3_config_default();
 *   nl_cheng3_eval ev;
 *   nl_noise_grad3 *t;
 *   nl_cheng3_run(&c, pat, seed, &ev, NULL, &t, &err);  // random start, anneal, evaluate
 *
 * THE MODEL. Noise(x, y, z) = sum over the 8 cell corners (i, j, k) of
 *   w(x-i) w(y-j) w(z-k) (Delta . G_ijk) (eq. 3.1-3.2 in 3D), quintic fade w,
 *   G_ijk = G[P[(P[(P[i mod M] + j) mod M] + k) mod M]], M = 512 unit vectors.
 *   Fractal sum over the unit cube F_sum = sum_l Noise(f_l p) / a_l,
 *   f_l = f1 2^(l-1), a_l = a1 2^(l-1) (eq. 3.10). Defaults F = 3, f1 = 4, a1 = 4:
 *   the highest frequency 16 equals the default control grid G = 16, as the
 *   thesis's f = 64 equals its 64 x 64 grid (cell centres then sit at lattice
 *   cell centres, never on lattice points where every octave is 0).
 *   Storage: each gradient as the unit vector (x, y, z) and its two angles
 *   z = cos(polar) in [-1, 1], phi = azimuth in [0, 2 pi), kept in step.
 *
 * OBJECTIVE (eq. 3.9) E = w1 E_stat + w2 E_Con through nl_cheng_objective's
 *   formula, w1 = 0.995, w2 = 0.005 (the thesis's weights).
 *   E_stat, uniformity on the sphere. Directions are uniform on S^2 iff
 *   z = cos(polar) ~ U(-1, 1) (Archimedes' hat-box theorem) and phi ~ U(0, 2 pi)
 *   independently. We use E_stat = max(D_z, D_phi), the larger of the two
 *   one-sample KS statistics (nl_stats_ks_incr, so a move costs O(log M + M/32)):
 *   each is on the scale of the 2D thesis's E_KS, so the thesis's weights keep
 *   their balance, and the max penalises whichever margin is worse. The test
 *   reported with it: p_stat = min(1, 2 min(p_z, p_phi)) (Bonferroni over the
 *   two KS p-values). Checks the objective does not see: Kuiper's V on phi
 *   (independent of where the circle is cut) and the Rayleigh test of the
 *   resultant R = |mean vector|, 3 M R^2 ~ chi2_3 under uniformity (a
 *   first-moment test on the sphere itself, not on a parametrisation).
 *   Limits: margins do not test the independence of z and phi (a table could
 *   pair them); the Rayleigh test sees only a net direction.
 *   E_Con = sum_i (c_i - D_i)^2, c = (1 + V) / 2, V = F_sum / (B3 sum 1/a_l),
 *   B3 = sqrt(3)/2 the bound of 3D gradient noise with unit gradients (the
 *   2D model's sqrt(2)/2 in 3D), so c is in [0, 1] like D (the "cloud" control
 *   term of eq. 3.8 with nl_cheng.h's scale reading).
 *
 * LEVELS. The thesis anneals octave by octave (sec. 3.4.2). In 3D the lattice
 *   of octave 2 (9^3 = 729 points for f = 8) already touches nearly all 512
 *   entries, so the later levels would own almost no variables:
 *   nl_cheng3_level_entries counts them and C8 reports the counts. We anneal
 *   all M entries in one level against all F octaves (stated, measured reason).
 *
 * MOVE (nl_cheng3_propose). Rotate the direction v by an angle a = sigma U(0, 1)
 *   towards a uniformly random tangent direction t (v' = cos a v + sin a t):
 *   a rotation about a random axis perpendicular to v. The density of v' given v
 *   depends only on the angle between them, so the proposal is symmetric and
 *   Metropolis acceptance keeps the uniform measure on the sphere invariant
 *   when E is flat. sigma = pi max(T / T0, 0.01) as in 2D.
 *
 * ANNEALING (nl_cheng_sa_run): nl_cheng.h's schedule exactly (T0 from 200
 *   trial moves and p0, geometric cooling over t_decades in n_temps steps,
 *   moves_per_var * n_vars moves per temperature, stall rule, best state
 *   restored), from gsl_rng MT19937 seeded by nl_seed_stream(seed, "cheng3.anneal", 0).
 *
 * INCREMENTAL EVALUATION. Every control point stores its F x 8 corner entries
 *   and weight vectors W = w w w Delta / a_l (amplitude folded in) and its
 *   current sum S = sum W . G; for each entry an inverted list names the points
 *   whose cells use it, with W summed over those corners and octaves. Moving
 *   entry k adds W . (G_new - G_old) to those points only and re-evaluates
 *   their terms; the two KS statistics follow through nl_stats_ks_incr.
 *   nl_cheng3_resum re-evaluates every point from its corners (each
 *   temperature), so rounding from differences never outlives one temperature.
 *   Tested (test_cheng3.c): incremental == full recomputation to 1e-12 after
 *   every move of a random sequence, and the stored corners == nl_noise_grad3_eval.
 */
#ifndef NL_CHENG3_H
#define NL_CHENG3_H

#include "base/nl_base.h"
#include "cheng/nl_cheng.h"
#include "noise/nl_noise.h"

#include <gsl/gsl_rng.h>

#ifdef __cplusplus
extern "C" {
#endif

/* ---- gradient table on the sphere -------------------------------------- */

/* The table is nl_noise_grad3 (seeded from stream ("cheng3.table", 0)); the
 * C8 experiment names it by these aliases. */
typedef nl_noise_grad3 nl_cheng3_table;
static inline nl_cheng3_table *nl_cheng3_table_alloc(size_t m) { return nl_noise_grad3_alloc(m); }
static inline void nl_cheng3_table_free(nl_cheng3_table *t) { nl_noise_grad3_free(t); }
static inline void nl_cheng3_table_seed(nl_cheng3_table *t, unsigned long seed)
{
  nl_noise_grad3_seed(t, seed);
}

/* ---- control pattern: a volume ------------------------------------------ */

typedef struct {
  int grid;              /* grid^3 cells over [0,1)^3 */
  size_t n;
  double *x, *y, *z, *d; /* cell centres and targets in [0, 1]; cell index (k grid + j) grid + i */
} nl_cheng3_pattern;

/* Built-in volumes, D = the fraction of the cell inside the solid (4^3
 * sub-samples): "torus" (axis z through the centre, radii 0.3 and 0.12),
 * "ball" (radius 0.3), "slab" (0.35 <= z < 0.65). NL_EINVAL on another name
 * or grid outside 2..256. */
nl_status nl_cheng3_pattern_shape(const char *name, int grid, nl_cheng3_pattern **out, nl_error *err);
void nl_cheng3_pattern_free(nl_cheng3_pattern *p);

/* ---- configuration ------------------------------------------------------ */

/* The 2D model's nl_cheng_config, of which 3D uses w1, w2, octaves, f1, a1, m
 * and sched (stat, con, literal, propagate and chisq_bins do not apply: see
 * OBJECTIVE and LEVELS); checked by nl_cheng_config_check. The default is
 * nl_cheng_config_default's with F = 3, f1 = 4 (see THE MODEL). */
typedef nl_cheng_config nl_cheng3_config;
nl_cheng3_config nl_cheng3_config_default(void);

/* ---- the problem: incremental objective --------------------------------- */

typedef struct nl_cheng3_problem nl_cheng3_problem;

/* Borrows the pattern and the table (edited by moves). */
nl_cheng3_problem *nl_cheng3_problem_alloc(const nl_cheng3_config *c, const nl_cheng3_pattern *pat,
                                           nl_noise_grad3 *t, nl_error *err);
void nl_cheng3_problem_free(nl_cheng3_problem *p);
double nl_cheng3_energy(const nl_cheng3_problem *p, double *e_stat, double *e_con);
/* Entry k := direction u (unit); returns the new E. _undo reverts the last move. */
double nl_cheng3_move(nl_cheng3_problem *p, size_t k, const double u[3]);
void nl_cheng3_undo(nl_cheng3_problem *p);
double nl_cheng3_energy_full(const nl_cheng3_problem *p, double *e_stat, double *e_con);
void nl_cheng3_resum(nl_cheng3_problem *p);
/* The move's proposal (see MOVE): out = v rotated by sigma U(0, 1) towards a random tangent. */
void nl_cheng3_propose(const double v[3], double sigma, gsl_rng *rng, double out[3]);

/* ---- annealing ------------------------------------------------------------ */

/* All M entries, all octaves (see LEVELS). st may be NULL. */
void nl_cheng3_optimise(nl_cheng3_problem *p, unsigned long seed, nl_cheng_level_stats *st);

/* ---- evaluation ------------------------------------------------------------ */

typedef struct {
  double d_z, p_z, d_phi, p_phi;   /* KS of z on U(-1,1), phi on U(0, 2 pi) */
  double e_stat, p_stat;           /* max(d_z, d_phi); min(1, 2 min(p_z, p_phi)) */
  double kuiper_v, p_kuiper;       /* phi */
  double rayleigh_r, p_rayleigh;   /* |mean vector|; P(chi2_3 > 3 M R^2) */
  double e_con, e, rms_con;
  double r_pattern;                /* Pearson r of c and D over the control points */
  /* E_Con = offset + contrast + shape over the n control points (population
   * moments, as nl_cheng_eval's): n (mean c - mean D)^2, n (sd c - sd D)^2,
   * 2 n sd c sd D (1 - r_pattern). */
  double e_con_offset, e_con_contrast, e_con_shape;
  double contrast;                 /* sd of c on a 32^3 raster of [0,1)^3 */
  double e_con_const;              /* sum (D_i - mean D)^2 */
  double e_con_random;             /* E_Con of the start table (NAN from _evaluate alone) */
} nl_cheng3_eval;

nl_status nl_cheng3_evaluate(const nl_noise_grad3 *t, const nl_cheng3_config *c,
                             const nl_cheng3_pattern *pat, nl_cheng3_eval *out, nl_error *err);
/* The control value c = (1 + V) / 2 at one point (the noise kernel, all F octaves). */
double nl_cheng3_value(const nl_noise_grad3 *t, const nl_cheng3_config *c, double x, double y,
                       double z);
/* c at the centres of an n^3 raster of [0,1)^3, index (k n + j) n + i (x fastest). */
void nl_cheng3_value_grid(const nl_noise_grad3 *t, const nl_cheng3_config *c, int n, double *out);
/* Random table from nl_seed_stream(seed, "cheng3.table", 0), its E_Con as
 * e_con_random (its full evaluation in *start if not NULL), optimisation,
 * evaluation; the optimised table in *table_out if not NULL (caller frees). */
nl_status nl_cheng3_run(const nl_cheng3_config *c, const nl_cheng3_pattern *pat, unsigned long seed,
                        nl_cheng3_eval *ev, nl_cheng3_eval *start, nl_cheng_level_stats *st,
                        nl_noise_grad3 **table_out, nl_error *err);
/* counts[l] = entries first used by octave l+1's lattice ((ceil(f_l) + 1)^3
 * points), for l < octaves: what multi-level annealing would give each level. */
void nl_cheng3_level_entries(const nl_noise_grad3 *t, const nl_cheng3_config *c, size_t *counts);

#ifdef __cplusplus
}
#endif

#endif
