#include "bounds/nl_bounds.h"

#include <gsl/gsl_rng.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#ifdef __SSE2__
#include <emmintrin.h>
#endif

/* ---- fractal bounds ---------------------------------------------------- */

double nl_bounds_octave(int i) { return ldexp(1.0, -i); }

double nl_bounds_series(int n) { return 2.0 - ldexp(1.0, -n); }

/* eq. 4.2: n octaves, i = 0..n-1, are bounded by S_{n-1}; S_{-1} = 0. */
double nl_bounds_fractal(int n) { return n <= 0 ? 0.0 : nl_bounds_series(n - 1); }

void nl_bounds_remainders(const nl_noise_octaves *o, double basis_bound, double *rem)
{
  /* Summed from the smallest term up, so rem[0] equals nl_noise_octaves_bound()
   * up to rounding and every rem[k] is the exact tail of eq. 5.3. */
  rem[o->n] = 0.0;
  for (int k = o->n - 1; k >= 0; k--) rem[k] = rem[k + 1] + basis_bound * fabs(o->amp[k]);
}

nl_bounds_interval nl_bounds_incremental(double partial, double remainder)
{
  nl_bounds_interval iv = {partial - remainder, partial + remainder};
  return iv;
}

/* ---- incremental evaluation -------------------------------------------- */

/* 1 if CLAMP(base + s) is already decided for every s in [partial - rem,
 * partial + rem], with the decided value in *v. */
static int clamp_decided(double base, double partial, double rem, double *v)
{
  if (base + partial + rem <= 0.0) { *v = 0.0; return 1; }
  if (base + partial - rem >= 1.0) { *v = 1.0; return 1; }
  return 0;
}

static double clamp01(double x) { return x < 0.0 ? 0.0 : x > 1.0 ? 1.0 : x; }

/* The loop behind nl_bounds_clamped_fractal and Fig. 5.3: *decided is the
 * number of terms after which eq. 5.4 fixed the clamp (checked before each
 * term and after the last), o->n + 1 if the value lies strictly inside
 * (0, 1); plain evaluation (incremental = 0) never checks. */
static double clamped_sum(const nl_noise_perm3 *p, const nl_noise_octaves *o, const double *rem,
                          double base, const double *xyz, int incremental,
                          int *terms, int *decided, double *max_abs)
{
  double partial = 0.0, v;
  for (int k = 0; k <= o->n; k++) {
    if (incremental && clamp_decided(base, partial, rem[k], &v)) {
      *terms = k;
      *decided = k;
      return v;
    }
    if (k == o->n) break;
    double f = o->freq[k];
    double nz = nl_noise_perm3_eval(p, f * xyz[0], f * xyz[1], f * xyz[2]);
    if (max_abs && fabs(nz) > *max_abs) *max_abs = fabs(nz);
    partial += o->amp[k] * nz;
  }
  *terms = o->n;
  *decided = o->n + 1;
  return clamp01(base + partial);
}

double nl_bounds_clamped_fractal(const nl_noise_perm3 *p, const nl_noise_octaves *o,
                                 const double *rem, double base, const double *xyz, int incremental,
                                 int *terms, double *max_abs)
{
  int t, d;
  double v = clamped_sum(p, o, rem, base, xyz, incremental, &t, &d, max_abs);
  if (terms) *terms = t;
  return v;
}

/* One point: partial sums of every prefix, then the checks. */
static void check_point(const nl_noise_perm3 *p, const nl_noise_octaves *o, const double *rem,
                        const double *xyz, nl_bounds_check *c)
{
  double partial[NL_MAX_OCTAVES + 1] = {0};
  for (int l = 0; l < o->n; l++) {
    double f = o->freq[l], v = nl_noise_perm3_eval(p, f * xyz[0], f * xyz[1], f * xyz[2]);
    c->max_abs_noise = fmax(c->max_abs_noise, fabs(v));
    partial[l + 1] = partial[l] + o->amp[l] * v;
  }
  double full = partial[o->n];
  c->max_abs_sum = fmax(c->max_abs_sum, fabs(full));
  c->over_fractal += fabs(full) > rem[0];
  int out = 0;
  for (int k = 0; k <= o->n; k++) {
    nl_bounds_interval iv = nl_bounds_incremental(partial[k], rem[k]);
    out |= !(iv.lo <= full && full <= iv.hi);
  }
  c->over_incremental += out;
}

void nl_bounds_check_random(const nl_noise_perm3 *p, const nl_noise_octaves *o, double basis_bound,
                            long npoints, unsigned long seed, nl_bounds_check *out)
{
  double rem[NL_MAX_OCTAVES + 1];
  nl_bounds_remainders(o, basis_bound, rem);
  memset(out, 0, sizeof *out);
  gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(r, nl_seed_stream(seed, "bounds.points", 0));
  for (long s = 0; s < npoints; s++) {
    double xyz[3];
    for (int a = 0; a < 3; a++) xyz[a] = 200.0 * gsl_rng_uniform(r) - 100.0;
    check_point(p, o, rem, xyz, out);
  }
  out->points = npoints;
  gsl_rng_free(r);
}

/* ---- smoke ball -------------------------------------------------------- */

nl_bounds_smoke nl_bounds_smoke_default(void)
{
  nl_bounds_smoke s = {.width = 512, .height = 512, .step = 0.01, .stop_opacity = 0.99,
                .slope = -4.0, .freq = 4.0, .kappa = 30.0,
                .octave_bound = NL_NOISE3_BOUND, .octaves = 1, .incremental = 0};
  return s;
}

static nl_status smoke_check(const nl_bounds_smoke *s, nl_error *err)
{
  if (s->width < 1 || s->height < 1)
    return nl_fail(err, NL_EINVAL, "smoke: image size must be positive");
  if (!(s->step > 0.0)) return nl_fail(err, NL_EINVAL, "smoke: step must be positive");
  if (!(s->slope < 0.0)) return nl_fail(err, NL_EINVAL, "smoke: slope a must be negative");
  if (s->octaves < 0 || s->octaves > NL_MAX_OCTAVES)
    return nl_fail(err, NL_EINVAL, "smoke: octaves must be in 0..%d", NL_MAX_OCTAVES);
  if (!(s->octave_bound >= 0.0)) return nl_fail(err, NL_EINVAL, "smoke: octave bound must be >= 0");
  return NL_OK;
}

/* Fnoise(f0 p): octave l at frequency f0 2^l with amplitude 2^-l. */
static nl_noise_octaves smoke_octaves(const nl_bounds_smoke *s)
{
  nl_noise_octaves o = nl_noise_octaves_fractal(s->octaves);
  for (int l = 0; l < o.n; l++) o.freq[l] *= s->freq;
  return o;
}

/* The march, batched. The rays of a block of pixels
 * step together, kept packed (compacted only at a step where one
 * stopped): at step i every ray still below the stop opacity gives one
 * sample at z_i. Plain evaluation: each octave of those samples is one
 * call of nl_noise_perm3_points_sum (scale, noise and partial += amp noise
 * in one pass). Incremental bounding: the check before term 0 packs the
 * undecided samples (position, base, partial sum, ray), and each octave is
 * one call of nl_noise_perm3_points_bounded, which adds the term, runs the
 * eq. 5.4 check before the next one and packs the still undecided to the
 * front (stream compaction, no index lists to gather through): the octave
 * count is still decided per sample, and what a sample costs beyond its
 * evaluations is little (so the time ratio can approach the evaluation
 * ratio). Every sample sees the same operations in the same
 * order as one ray marched alone (the kernels return the bits of
 * nl_noise_perm3_eval and its sums): images and counts do not depend on the
 * batching. What a ray alone pays per sample (a call per octave, a loop,
 * exp) is shared: |p|^2 = (x^2 + y^2) + z^2 keeps x^2 + y^2 per ray, the
 * roots go two at a time, and the Beer-Lambert factor exp(-kappa density
 * h) is 1 at density 0 (the transmittance stays the same bits) and one
 * constant at density 1. */
enum { SMOKE_BLOCK = 1024 };

typedef struct {
  const nl_noise_perm3 *p;
  const nl_bounds_smoke *s;
  const nl_noise_octaves *o;
  const double *rem;
  /* Beyond |p|^2 = far2 eq. 5.4 decides density 0 before term 0, as the
   * check itself would: a |p| + 1 + rem_0 <= 0 for |p| >= (1 + rem_0) / -a,
   * and the bound is raised by 1e-6 relative so that the computed sum (a
   * few roundings of 2^-53) is certainly <= 0 there; those samples need no
   * root. The check runs on the rest. */
  double far2;
  /* the active rays, packed: position, x^2 + y^2, transmittance, colour, pixel in the block */
  double x[SMOKE_BLOCK], y[SMOKE_BLOCK], r2[SMOKE_BLOCK], trans[SMOKE_BLOCK], colour[SMOKE_BLOCK];
  int pix[SMOKE_BLOCK];
  /* a step's samples: base a|p| + 1, partial sum, density, z */
  double base[SMOKE_BLOCK], partial[SMOKE_BLOCK], dens[SMOKE_BLOCK], z[SMOKE_BLOCK];
  /* the undecided samples, packed (nl_noise_pack): position, base, partial sum, ray */
  double ux[SMOKE_BLOCK + NL_NOISE_PACK_PAD], uy[SMOKE_BLOCK + NL_NOISE_PACK_PAD];
  double uz[SMOKE_BLOCK + NL_NOISE_PACK_PAD], ub[SMOKE_BLOCK + NL_NOISE_PACK_PAD];
  double up[SMOKE_BLOCK + NL_NOISE_PACK_PAD];
  int ur[SMOKE_BLOCK + NL_NOISE_PACK_PAD], hi[SMOKE_BLOCK];
} smoke_block;

/* base_j = a |p_j| + 1, |p_j| = sqrt((x^2 + y^2) + z^2), for j < n, the
 * roots two at a time where SSE2 is (correctly rounded: the bits of sqrt). */
static void smoke_bases(const double *r2, int n, double z2, double slope, double *base)
{
  int j = 0;
#ifdef __SSE2__
  for (; j + 2 <= n; j += 2) {
    __m128d root = _mm_sqrt_pd(_mm_add_pd(_mm_loadu_pd(r2 + j), _mm_set1_pd(z2)));
    _mm_storeu_pd(base + j, _mm_add_pd(_mm_mul_pd(_mm_set1_pd(slope), root), _mm_set1_pd(1.0)));
  }
#endif
  for (; j < n; j++) base[j] = slope * sqrt(r2[j] + z2) + 1.0;
}

/* The densities of the nact active samples at height z (clamped_sum, batched). */
static void smoke_densities(smoke_block *b, int nact, double z, nl_bounds_smoke_stats *st)
{
  const nl_bounds_smoke *s = b->s;
  const nl_noise_octaves *o = b->o;
  int n = o->n;
  double top = st->max_abs_noise, z2 = z * z;
  st->samples += nact;
  if (!s->incremental) {
    smoke_bases(b->r2, nact, z2, s->slope, b->base);
    for (int j = 0; j < nact; j++) { b->partial[j] = 0.0; b->z[j] = z; }
    for (int k = 0; k < n; k++) {
      double t = nl_noise_perm3_points_sum(b->p, o->freq[k], b->x, b->y, b->z, (size_t)nact,
                                           o->amp[k], b->partial);
      top = t > top ? t : top;
    }
    st->noise_evals += (long)n * nact;
    for (int j = 0; j < nact; j++) b->dens[j] = clamp01(b->base[j] + b->partial[j]);
    st->max_abs_noise = top;
    return;
  }
  int m = 0;
  double r0 = b->rem[0];
  for (int j0 = 0; j0 < nact; j0 += 2) {   /* the check before term 0, packing the undecided */
    double root[2];
    b->dens[j0] = b->dens[j0 + 1] = 0.0;
#ifdef __SSE2__
    __m128d d2 = _mm_add_pd(_mm_loadu_pd(b->r2 + j0), _mm_set1_pd(z2));
    if (_mm_movemask_pd(_mm_cmpge_pd(d2, _mm_set1_pd(b->far2))) == 3) continue;
    _mm_storeu_pd(root, _mm_sqrt_pd(d2));   /* two correctly rounded roots at once */
#else
    double d2[2] = {b->r2[j0] + z2, b->r2[j0 + 1] + z2};
    if (d2[0] >= b->far2 && d2[1] >= b->far2) continue;
    root[0] = sqrt(d2[0]); root[1] = sqrt(d2[1]);
#endif
    for (int j = j0; j < j0 + 2 && j < nact; j++) {
      double base = s->slope * root[j - j0] + 1.0, sum = base + 0.0;
      int lo = sum + r0 <= 0.0, hi = sum - r0 >= 1.0;
      b->dens[j] = hi ? 1.0 : 0.0;
      b->ux[m] = b->x[j];
      b->uy[m] = b->y[j];
      b->uz[m] = z;
      b->ub[m] = base;
      b->up[m] = 0.0;
      b->ur[m] = j;
      m += !(lo | hi);
    }
  }
  /* term k, then the check before term k + 1, in one pass
   * (nl_noise_perm3_points_bounded): the decided leave the pack */
  nl_noise_pack pk = {b->ux, b->uy, b->uz, b->ub, b->up, b->ur, (size_t)m};
  for (int k = 0; k < n && pk.n > 0; k++) {
    size_t before = pk.n;
    size_t nhi = nl_noise_perm3_points_bounded(b->p, o->freq[k], o->amp[k], b->rem[k + 1], &pk,
                                               b->hi, &top);
    for (size_t h = 0; h < nhi; h++) b->dens[b->hi[h]] = 1.0;
    st->noise_evals += (long)(before - pk.n) * (k + 1);
  }
  for (size_t j = 0; j < pk.n; j++)   /* never decided */
    b->dens[b->ur[j]] = clamp01(b->ub[j] + b->up[j]);
  st->noise_evals += (long)n * (long)pk.n;
  st->max_abs_noise = top;
}

/* Rays of pixels first .. first + count - 1 (row-major) along +z through
 * the unit cube; emission-absorption. */
static void smoke_block_march(smoke_block *b, size_t first, int count, double *img,
                              nl_bounds_smoke_stats *st)
{
  const nl_bounds_smoke *s = b->s;
  double stop = 1.0 - s->stop_opacity, full = exp(-s->kappa * 1.0 * s->step);
  long nsteps = (long)floor(1.0 / s->step);
  int nact = 0;
  for (int j = 0; j < count; j++) {
    size_t pix = first + (size_t)j;
    int r = (int)(pix / (size_t)s->width), c = (int)(pix % (size_t)s->width);
    double x = -0.5 + (c + 0.5) / s->width, y = -0.5 + (r + 0.5) / s->height;
    img[pix] = 0.0;
    b->x[nact] = x; b->y[nact] = y; b->r2[nact] = x * x + y * y;
    b->trans[nact] = 1.0; b->colour[nact] = 0.0; b->pix[nact] = j;
    nact += 1.0 > stop;   /* trans > stop */
  }
  for (long i = 0; i <= nsteps && nact > 0; i++) {
    double z = -0.5 + (double)i * s->step;
    smoke_densities(b, nact, z, st);
    int stopped = 0;
    for (int j = 0; j < nact; j++) {
      double d = b->dens[j], trans = b->trans[j];
      if (d == 0.0) continue;   /* exp(-0) = 1: nothing absorbed */
      double t1 = trans * (d == 1.0 ? full : exp(-s->kappa * d * s->step));
      b->colour[j] += trans - t1;
      b->trans[j] = t1;
      stopped += !(t1 > stop);
    }
    if (!stopped) continue;
    int left = 0;   /* rays that stopped leave their colour and the pack */
    for (int j = 0; j < nact; j++) {
      if (!(b->trans[j] > stop)) { img[first + (size_t)b->pix[j]] = b->colour[j]; continue; }
      b->x[left] = b->x[j]; b->y[left] = b->y[j]; b->r2[left] = b->r2[j];
      b->trans[left] = b->trans[j]; b->colour[left] = b->colour[j]; b->pix[left] = b->pix[j];
      left++;
    }
    nact = left;
  }
  for (int j = 0; j < nact; j++) img[first + (size_t)b->pix[j]] = b->colour[j];
}

nl_status nl_bounds_smoke_render(const nl_noise_perm3 *p, const nl_bounds_smoke *s, double *img,
                                 nl_bounds_smoke_stats *st, nl_error *err)
{
  nl_status rc = smoke_check(s, err);
  if (rc) return rc;
  nl_noise_octaves o = smoke_octaves(s);
  double rem[NL_MAX_OCTAVES + 1];
  nl_bounds_remainders(&o, s->octave_bound, rem);
  memset(st, 0, sizeof *st);
  smoke_block *b = nl_xmalloc(sizeof *b);
  /* the pairs of roots read one ray past the last: never an unset value */
  memset(b, 0, sizeof *b);
  b->p = p; b->s = s; b->o = &o; b->rem = rem;
  double far = (1.0 + rem[0]) / -s->slope * (1.0 + 1e-6);
  b->far2 = far * far;
  size_t npix = (size_t)s->width * s->height;
  for (size_t first = 0; first < npix; first += SMOKE_BLOCK) {
    int count = (int)(npix - first < SMOKE_BLOCK ? npix - first : SMOKE_BLOCK);
    smoke_block_march(b, first, count, img, st);
  }
  free(b);
  return NL_OK;
}

nl_status nl_bounds_smoke_decision_map(const nl_noise_perm3 *p, const nl_bounds_smoke *s, double z,
                                       int *terms, nl_error *err)
{
  nl_status rc = smoke_check(s, err);
  if (rc) return rc;
  nl_noise_octaves o = smoke_octaves(s);
  double rem[NL_MAX_OCTAVES + 1];
  nl_bounds_remainders(&o, s->octave_bound, rem);
  for (int r = 0; r < s->height; r++)
    for (int c = 0; c < s->width; c++) {
      double xyz[3] = {-0.5 + (c + 0.5) / s->width, -0.5 + (r + 0.5) / s->height, z};
      double d = sqrt(xyz[0] * xyz[0] + xyz[1] * xyz[1] + xyz[2] * xyz[2]);
      int t;
      int *decided = &terms[(size_t)r * s->width + c];
      clamped_sum(p, &o, rem, s->slope * d + 1.0, xyz, 1, &t, decided, NULL);
    }
  return NL_OK;
}

/* ---- spectral bandwidth ------------------------------------------------ */

void nl_bounds_psd1_tail(const double *P, size_t m, double *gamma)
{
  double s = 0.0;
  for (size_t k = m; k-- > 0;) { s += P[k]; gamma[k] = s; }
}

double nl_bounds_psd1_tail_inverse(const double *f, const double *gamma, size_t m, double e)
{
  for (size_t k = 0; k < m; k++)
    if (gamma[k] <= e) return f[k];
  return f[m - 1];
}

void nl_bounds_moments(const double *x, size_t n, double *mean, double *sigma)
{
  double s = 0.0, ss = 0.0;
  for (size_t k = 0; k < n; k++) s += x[k];
  *mean = s / (double)n;
  for (size_t k = 0; k < n; k++) ss += (x[k] - *mean) * (x[k] - *mean);
  *sigma = sqrt(ss / (double)n);
}

nl_status nl_bounds_bandwidth_1d(const double *x, size_t n, double rate, double T,
                                 nl_bounds_bandwidth *bw, nl_error *err)
{
  return nl_bounds_bandwidth_1d_with(x, n, rate, T, NULL, bw, err);
}

nl_status nl_bounds_bandwidth_1d_with(const double *x, size_t n, double rate, double T,
                                      const nl_bounds_bandwidth_options *opt,
                                      nl_bounds_bandwidth *bw, nl_error *err)
{
  static const nl_bounds_bandwidth_options plain = {0};
  const nl_bounds_bandwidth_options *o = opt ? opt : &plain;
  if (!(T > 0.0)) return nl_fail(err, NL_EINVAL, "bandwidth: threshold T must be positive");
  size_t m = n / 2 + 1;
  double *f = nl_xmalloc(m * sizeof *f), *P = nl_xmalloc(m * sizeof *P);
  nl_status rc = nl_spectrum_psd1_window(x, n, rate, o->window, f, P, err);
  if (!rc) {
    double *g = nl_xmalloc(m * sizeof *g), res = rate / (double)n;
    for (size_t k = 1; o->two_sided && 2 * k < n; k++)
      P[k] *= 0.5;   /* positive half of the two-sided PSD */
    if (o->no_dc) P[0] = 0.0;
    if (o->bin_edge || o->radians)
      for (size_t k = 0; k < m; k++)
        f[k] = (o->bin_edge ? fmax(f[k] - 0.5 * res, 0.0) : f[k]) * (o->radians ? 2.0 * M_PI : 1.0);
    nl_bounds_psd1_tail(P, m, g);
    nl_bounds_moments(x, n, &bw->mean, &bw->sigma);
    double rms = sqrt(bw->mean * bw->mean + bw->sigma * bw->sigma);
    double lo = (o->sigma_rms ? rms : bw->sigma) - sqrt(T);
    bw->f_sup = nl_bounds_psd1_tail_inverse(f, g, m, T);
    bw->f_inf = nl_bounds_psd1_tail_inverse(f, g, m, lo > 0.0 ? lo * lo : 0.0);
    double lr = sqrt(g[0]) - sqrt(T);
    bw->f_inf_rms = nl_bounds_psd1_tail_inverse(f, g, m, lr > 0.0 ? lr * lr : 0.0);
    bw->resolution = res;
    bw->nyquist = 0.5 * rate;
    free(g);
  }
  free(f);
  free(P);
  return rc;
}

nl_status nl_bounds_psd1_fraction_above(const double *x, size_t n, double rate, double fc,
                                        double *fraction, nl_error *err)
{
  size_t m = n / 2 + 1;
  double *f = nl_xmalloc(m * sizeof *f), *P = nl_xmalloc(m * sizeof *P);
  nl_status rc = nl_spectrum_psd1(x, n, rate, f, P, err);
  if (!rc) {
    double above = 0.0, var = 0.0;
    for (size_t k = 1; k < m; k++) { var += P[k]; if (f[k] > fc) above += P[k]; }
    *fraction = var > 0.0 ? above / var : 0.0;
  }
  free(f); free(P);
  return rc;
}

void nl_bounds_sample_line(const nl_noise_perm3 *p, const nl_noise_octaves *o,
                           const double *origin, const double *dir, double rate, size_t n,
                           double *out)
{
  for (size_t k = 0; k < n; k++) {
    double t = (double)k / rate, s = 0.0;
    for (int l = 0; l < o->n; l++) {
      double f = o->freq[l];
      double x = origin[0] + t * dir[0], y = origin[1] + t * dir[1], z = origin[2] + t * dir[2];
      s += o->amp[l] * nl_noise_perm3_eval(p, f * x, f * y, f * z);
    }
    out[k] = s;
  }
}
