/* nl_cheng_repro.h - noise reproduction (Cheng 2009 sec. 3.5, Tables
 * 4.2-4.4, Fig 4.9-4.14): from one optimised table, a pool of re-optimised
 * low-frequency angles, a Gaussian mixture over the pool, and new tables
 * drawn from it in real time. Pools: nl_cheng_pool.c; representation,
 * clustering, mixture and reproduction: nl_cheng_model.c. The optimiser it
 * builds on is nl_cheng.h.
 *
 * API
 *   pool      nl_cheng_pool_options_default, nl_cheng_set_reproduction,
 *             nl_cheng_low_entries, nl_cheng_pool_collect / _free / _bytes
 *   angles    nl_cheng_rep_dim, nl_cheng_circular_centre, nl_cheng_rep_encode /
 *             _decode, nl_cheng_rep_parse / _name
 *   clusters  nl_cheng_initial_k, nl_cheng_cutoff_for_k, nl_cheng_k_curve
 *   model     nl_cheng_model_options_default, nl_cheng_model_fit / _free,
 *             nl_cheng_model_status_name, nl_cheng_model_assess
 *   tables    nl_cheng_reproduce
 *
 *   nl_cheng_pool_options po; nl_cheng_pool_options_default(&po);   // Q 100, N 100, eps 10
 *   nl_cheng_pool *pool;
 *   nl_cheng_pool_collect(opt, &c, pat, &po, seed, &pool, &err);   // opt: an optimised table
 *   nl_cheng_model_options mo; nl_cheng_model_options_default(&mo);
 *   nl_cheng_model *m;
 *   nl_cheng_model_fit(pool, &mo, seed, &m, &err);                  // cluster -> K0 -> GMM/AIC
 *   nl_cheng_reproduce(opt, m, 1.0, rng, out, &err);                // one new table, real time
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
 *   components to follow the curvature (measured in test_cheng_repro.c: 3
 *   blobs of sd 0.05 select K = 10). NL_CHENG_REP_UNWRAP: each angle unwrapped
 *   to (mu_j - pi, mu_j + pi] with mu_j opposite the middle of the widest
 *   empty arc of column j in the pool (d = n_low, intrinsic coordinates; the
 *   cut falls where the pool has no angles, if it has such an arc; a cut
 *   opposite the circular mean split a blob in the same test).
 * CUTOFF (sec. 3.5.2). "The merge stops when the Hausdorff distance between
 *   the two clusters exceeds the cutoff": we use complete linkage (the
 *   farthest pair), which makes "every pair in a cluster within the cutoff"
 *   true; flat clusters by nl_cluster_fcluster_distance. The Hausdorff
 *   distance of two sets lies between the single-linkage (nearest pair) and
 *   the complete-linkage distance and is not a reducible linkage; we say so
 *   rather than approximate it. The initial K is the number
 *   of clusters. cutoff < 0 asks for the cutoff that gives target_k clusters
 *   (midpoint of the merge heights around it): the thesis tuned its cutoff
 *   "case by case" for a proper K, and its absolute values (15.5-19.5) are in
 *   units we cannot reconstruct.
 * AIC RULE (sec. 3.5.3, eq. 3.19 AIC = -2L + 2m). The printed rule
 *   "delta_i = AIC_i - AIC_{i-1}; stop if delta_i < T" would stop at the first
 *   improvement; we read it as: fit K0, K0+1, ... and stop when AIC falls by
 *   less than T; the model kept is the last that improved by >= T
 *   (nl_gmm_select_aic). The path runs until AIC turns, at most to K0 +
 *   k_extra (default 30, a cost limit: on 10,000 rows of 152 columns a step
 *   costs 1-3 s, and such paths fall steadily until components hold about
 *   d rows, K ~ n / d); a path still falling there has status
 *   k_max_reached. m is scikit-learn's parameter count (nl_gmm.h).
 * REPRODUCTION (sec. 3.5.3). Copy the optimised table, draw one vector from
 *   the mixture, decode it into the low entries, and permute a fraction of
 *   the high entries among themselves (swap_fraction 1: a uniform random
 *   permutation; the angle multiset, hence E_u's high part, is unchanged).
 * DEGENERATE CASES are reported in nl_cheng_model.status, never a crash:
 *   pool too small (< 2 solutions or K0 >= samples), one cluster, one cluster
 *   per point, EM not converged in max_iter, EM failure, path reached k_max.
 */

#ifndef NL_CHENG_REPRO_H
#define NL_CHENG_REPRO_H

#include "cheng/nl_cheng.h"
#include "stats/nl_gmm.h"

#ifdef __cplusplus
extern "C" {
#endif

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
size_t *nl_cheng_low_entries(const nl_noise_grad2 *table, const nl_cheng_config *c,
                             const nl_cheng_pattern *pat, int low_levels, size_t *nlow,
                             nl_error *err);
nl_status nl_cheng_pool_collect(const nl_noise_grad2 *opt, const nl_cheng_config *c,
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
  size_t k_extra;       /* path capped at K0 + k_extra, 30 (AIC RULE) */
  nl_gmm_options gmm;   /* nl_gmm_options_default, full covariance */
  size_t cluster_samples; /* rows clustered (drawn by the same stream as the
                             mixture's input, so equal sizes give the same rows);
                             0: the mixture's input rows (default) */
  int cluster_angles;   /* 0: chords of (cos, sin) (default); 1: Euclidean on the
                           raw angles in [0, 2 pi), the thesis's own variables */
} nl_cheng_model_options;

typedef struct {
  nl_cheng_rep rep;
  size_t nlow, d, *low; /* low entries (copy of the pool's) */
  double *mu;           /* nlow reference angles */
  size_t n_in;          /* input samples used */
  size_t *in;           /* their pool rows (n_in) */
  size_t n_cl;          /* rows clustered */
  size_t *cl;           /* their pool rows (n_cl) */
  int cluster_angles;   /* distance of the clustering (options) */
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
nl_status nl_cheng_reproduce(const nl_noise_grad2 *opt, const nl_cheng_model *m, double swap_fraction,
                             gsl_rng *rng, nl_noise_grad2 *out, nl_error *err);
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
/* Number of complete-linkage clusters of the model's clustered rows (in the
 * model's clustering distance) at each of ncut cutoffs: K against the cutoff. */
nl_status nl_cheng_k_curve(const nl_cheng_pool *pool, const nl_cheng_model *m, const double *cut,
                           size_t ncut, size_t *k, nl_error *err);

/* ---- pool readings (nl_cheng_model_pool.c) ------------------------------
 * "The last N solutions" (sec. 3.5.2) read two ways from one pool collected
 * with keep = N x stride tail states per run: successive states (the first N
 * after the anneal, the default pool) or states spaced `stride` sweeps apart
 * (every stride-th state). nl_cheng_pool_thin builds that pool (a copy).
 * nl_cheng_pool_ess, on the coordinates cos, sin of every low angle:
 *   tau    integrated autocorrelation time (pool rows) of the within-run
 *          series centred by the run's mean, pooled over runs and coordinates,
 *          1 + 2 sum rho(l) up to the first lag with rho < 0.05; capped = 1
 *          when that lag is past half the run (window-limited). Centring by
 *          the run's mean bounds tau by the run length for a diffusing walk,
 *          hence the two measures below;
 *   icc    intraclass correlation: between-run variance / total variance;
 *          ess_kish = n / (1 + (m - 1) icc) for runs of m rows (Kish's design
 *          effect of cluster sampling);
 *   dec    decorrelation interval in rows, diffusive extrapolation: the lag
 *          at which the mean squared step msd(l) = l msd(1) reaches twice the
 *          pool's total variance (where two states of one run are as far
 *          apart as two states of different runs). */
typedef struct { double tau, ess_tau, icc, ess_kish, msd1, var_total, dec; int capped; } nl_cheng_pool_ess_result;
nl_cheng_pool *nl_cheng_pool_thin(const nl_cheng_pool *p, int per_run, int stride);
void nl_cheng_pool_ess(const nl_cheng_pool *p, nl_cheng_pool_ess_result *out);

#ifdef __cplusplus
}
#endif

#endif
