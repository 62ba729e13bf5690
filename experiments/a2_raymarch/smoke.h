/* smoke.h - the loops of A2 (Arnerin 2009, Table 5.1): the smoke
 * ball of bounds/nl_bounds.h rendered plainly and with incremental bounding
 * over seeds, at the table's octave counts, and swept over the scene
 * parameters the paper does not state.
 *
 * A scene is an nl_bounds_smoke (its `octaves` ignored) and a reading of
 * "N octaves": the march sums terms = N + offset octaves, offset 1 the
 * octaves 0..N (the sum of eq. 5.4 and the cost formula run i = 0..N),
 * offset 0 N terms (Fnoise_N, octaves 0..N-1; N = 0 has no noise).
 *
 * The fitting quantity is the noise-evaluation ratio plain / bounded: a
 * deterministic count for a given seed, image size and scene. The time
 * ratio is measured beside it but is a CPU wall-clock on a shared machine
 * (and the paper's is a GPU's): it is reported, never fitted.
 *
 *   a2_smoke_scene sc = {nl_bounds_smoke_default(), 1};
 *   a2_smoke_point pt[6];
 *   a2_smoke_curve(r, &sc, octaves, 6, seeds, 1, pt, panels);
 *
 * Fit of a curve to the paper's six time ratios: least squares on the log
 * ratio, rss_log = sum_i (ln ours_i - ln paper_i)^2, and the rms factor
 * exp(sqrt(rss_log / n)) (ours is within that factor of the paper's on
 * the log-rms average).
 */
#ifndef A2_SMOKE_H
#define A2_SMOKE_H

#include "bounds/nl_bounds.h"
#include "harness/nl_harness.h"
#include "image/nl_image.h"
#include "table/nl_table.h"

/* ---- plain against bounded -------------------------------------------- */

typedef struct {
  double ms[2];     /* thread-CPU ms of the plain [0] and the bounded [1] render */
  long evals[2];    /* noise calls of each */
  long samples;     /* density samples (the same in both) */
  int diff;         /* largest difference of the two images in 8-bit levels */
  double max_noise; /* largest |noise| of the plain march */
} a2_smoke_pair;
/* Renders s plainly into img0 and incrementally into img1 (s.incremental
 * is ignored), each timed by the calling thread's CPU clock
 * (nl_time_thread_cpu, so that renders on other threads at once do not
 * count). img0 or img1 NULL: both images are temporaries. */
nl_status a2_smoke_render_pair(const nl_noise_perm3 *p, nl_bounds_smoke s, double *img0,
                               double *img1, a2_smoke_pair *t, nl_error *err);

/* ---- curves, fits and the sweep --------------------------------------- */

typedef struct {
  nl_bounds_smoke s; /* scene; s.octaves and s.incremental are set per row */
  int offset;        /* terms = N + offset */
} a2_smoke_scene;

/* One row of Table 5.1 over seeds: ratios are of the seed means (the
 * paper's times are totals), their sd the sd of the per-seed ratios. */
typedef struct {
  int terms;
  double plain_evals, bounded_evals, eval_ratio, eval_ratio_sd;
  double plain_ms, plain_ms_sd, bounded_ms, bounded_ms_sd, time_ratio, time_ratio_sd;
  int diff;         /* largest plain/bounded difference, 8-bit levels */
  double max_noise; /* largest |noise| of the plain march */
} a2_smoke_point;

/* Renders the scene at octave counts N = octaves[0..n-1] for seeds
 * nl_seed_replicate(run seed, k), k < seeds. timed: plain and bounded
 * renders, timed; untimed: the bounded march only, and the plain count is
 * samples * terms (both marches meet the same densities, hence stop at the
 * same samples; the plain one evaluates every term), times 0. With no
 * noise term both counts are 0 and the ratio is 1 (the same work).
 * panels (may be NULL): the first seed's bounded image per row (caller
 * frees). A renderer error is fatal (nl_harness_die). */
void a2_smoke_curve(nl_harness *r, const a2_smoke_scene *sc, const int *octaves, int n, int seeds,
                    int timed, a2_smoke_point *out, nl_image **panels);

/* rss_log and, if not NULL, the rms factor and the row with the largest
 * |ln ours - ln paper|. */
double a2_smoke_fit(const double *ours, const double *paper, int n, double *rms_factor, int *worst);

/* The image sizes of the size check: width / 16, / 8, / 4 and width itself,
 * each at least 8 pixels and larger than the one before, into sizes[4].
 * Returns their count. */
int a2_smoke_check_sizes(int width, int *sizes);

/* size_check.tsv: does the evaluation ratio depend on the image size? For
 * each slope and size (the last size is the reference), the untimed curve
 * over `seeds`: columns slope, size, octaves, eval_ratio, eval_ratio_sd,
 * ref_eval_ratio, ref_eval_ratio_sd, rel_diff (|ours - ref| / ref),
 * within (1 if |ours - ref| <= the reference's sd). Returns the smallest
 * size whose rows are all within at every slope (the reference if none). */
int a2_smoke_size_check(nl_harness *r, const a2_smoke_scene *sc, const double *slopes, int nslopes,
                        const int *sizes, int nsizes, const int *octaves, int n, int seeds,
                        nl_table **out);

/* A scene parameter varied one at a time: "freq", "kappa", "step",
 * "stop_opacity", "octave_bound", or "offset" (the reading of N); a value
 * equal to the center's is skipped (it is the best slope's row). is_free: the
 * paper does not state it, so the fit may choose it; else (a number the
 * paper gives) the rows measure the sensitivity only. */
typedef struct {
  const char *name;
  int is_free, n;
  double v[4];
} a2_smoke_vary;

/* The value of scene parameter `name` (as vary[] names them, or "slope"). */
double a2_smoke_param(nl_harness *r, const a2_smoke_scene *sc, const char *name);

/* The sweep: first the slope over slopes[] with the other parameters of
 * center, then each vary[] one at a time around the slope that fitted
 * best; timed curves over `seeds` at the center's image size.
 *   sweep (slope_sweep.tsv): vary, slope, freq, kappa, step, stop_opacity,
 *     octave_bound, offset, size, octaves, terms, eval_ratio, eval_ratio_sd,
 *     time_ratio, time_ratio_sd, paper_ratio; one row per reading and N;
 *   fit (fit.tsv): vary, reading (e.g. "slope=-5"), the scene columns,
 *     rss_log, rms_factor, worst_factor (the largest factor ours / paper or
 *     paper / ours) and worst_octaves (its N), time_rms_factor (the same fit
 *     of the time ratio, for comparison only), best (1 on the reading with
 *     the smallest rss_log among the free readings), free (1: the slope
 *     rows and the free parameters' rows).
 * Returns the best reading's scene (image size of center). */
a2_smoke_scene a2_smoke_sweep(nl_harness *r, const a2_smoke_scene *center, const double *slopes,
                              int nslopes, const a2_smoke_vary *vary, int nvary, const int *octaves,
                              const double *paper, int n, int seeds, nl_table **sweep,
                              nl_table **fit);

/* Among the slope rows of a sweep table at octave count N: the row whose
 * eval_ratio is nearest the paper's in log. */
size_t a2_smoke_nearest(const nl_table *sweep, int octaves);
/* eval_ratio of the sweep row with vary, slope and N (NaN if none). */
double a2_smoke_ratio_at(const nl_table *sweep, const char *vary, double slope, int octaves);
/* timing.tsv, Table 5.1 beside ours: octaves, terms, plain_ms, plain_ms_sd,
 * bounded_ms, bounded_ms_sd, ratio (time), paper_plain_ms,
 * paper_bounded_ms, paper_ratio, plain_evals, bounded_evals, eval_ratio,
 * eval_ratio_sd, max_diff_levels, max_noise, and a measured alternative
 * from the size check's reference size: alt_slope, alt_eval_ratio,
 * alt_eval_ratio_sd (the size check's rows at alt_slope and its largest
 * size); and per term: plain_evals_per_term, plain_ms_per_term, and
 * paper_plain_ms_per_term (the paper's plain ms over its N + 1 terms). */
nl_table *a2_smoke_timing(const a2_smoke_point *pt, const int *octaves, const double (*paper_ms)[2],
                          int n, const nl_table *size_check, double alt_slope);
/* rss_log (and rms factor) of two columns of a table, ours against paper's. */
double a2_smoke_fit_columns(const nl_table *t, const char *ours, const char *paper,
                            double *rms_factor);
/* Fig. 5.2: writes the panels (one per N) as balls.png and the last as
 * ball.png, and frees them. */
void a2_smoke_panels(nl_harness *r, nl_image **panels, const int *octaves, int n);

/* Fig. 5.3: the decision map of s in the plane z = 0 as colours by the
 * number of terms that decided each pixel (blue few ... red all, black
 * never decided). */
nl_image *a2_smoke_decision_image(nl_harness *r, const nl_noise_perm3 *p, const nl_bounds_smoke *s);

#endif
