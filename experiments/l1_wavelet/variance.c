/* variance.c - L1: readings of the 3D wavelet-noise band variance
 * sigma_N^2 beside Cook & DeRose's normalisation constant 0.210 (their
 * WMultibandNoise divides by sqrt(sum w_b^2 * 0.210) for plain 3D noise). */
#include "variance.h"
#include "expect.h"
#include "study/nl_study.h"

#include <gsl/gsl_cdf.h>
#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>
#include <math.h>
#include <stdlib.h>

#define NREAD L1_NREADINGS
static const char *const READINGS[NREAD] = {
  "volume, 4 samples per unit and axis (ours)",
  "volume, mean subtracted",
  "random points (2^16 per tile)",
  "one plane at random z",
  "plane z = 0 (integer z: images of p = (x, y, 0))",
  "plane z = 1/2 (half-integer z)",
  "lattice points (frac 0)",
  "half-integer lattice (frac 1/2)",
  "appendix odd-shift copy (transposed), volume",
  "appendix odd-shift copy (transposed), plane z = 0",
  "multiband sum of 4 bands (one tile, no offsets) / 4, plane z = 0",
  "tile of twice the period (at most 256), random points"
};

nl_table *l1_variance_readings(int n, int K, unsigned long seed0, double paper)
{
  nl_wavelet_tile *t = nl_wavelet_tile_alloc(3, n);
  nl_wavelet_tile *tt = nl_wavelet_tile_alloc(3, n); /* the appendix's transposed copy */
  nl_wavelet_tile *t2 = nl_wavelet_tile_alloc(3, 2 * n > 256 ? 256 : 2 * n);
  if (!t || !tt || !t2) {
    nl_wavelet_tile_free(t);
    nl_wavelet_tile_free(tt);
    nl_wavelet_tile_free(t2);
    return NULL;
  }
  double *v = nl_xcalloc((size_t)NREAD * K, sizeof *v); /* v[i * K + s] */
  gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
  for (int s = 0; s < K; s++) {
    unsigned long sk = nl_seed_replicate(seed0, s);
    nl_wavelet_tile_seed(t, sk);
    nl_wavelet_tile_seed_transposed(tt, sk);
    nl_wavelet_tile_seed(t2, sk);
    double vol = 0, mu = 0;
    int planes = 4 * n; /* the volume as planes: the same grid as nl_wavelet_tile_variance(t, 4) */
    for (int iz = 0; iz < planes; iz++) {
      double m;
      vol += nl_wavelet_slice_variance(t, (iz + 0.5) / 4, 4, &m) / planes;
      mu += m / planes;
    }
    gsl_rng_set(rng, nl_seed_stream(sk, "l1.readings", 0));
    double r[NREAD] = { vol,
                        vol - mu * mu,
                        nl_wavelet_point_variance(t, 65536, sk),
                        nl_wavelet_slice_variance(t, n * gsl_rng_uniform(rng), 4, NULL),
                        nl_wavelet_slice_variance(t, 0.0, 4, NULL),
                        nl_wavelet_slice_variance(t, 0.5, 4, NULL),
                        nl_wavelet_lattice_variance(t, 0.0),
                        nl_wavelet_lattice_variance(t, 0.5),
                        nl_wavelet_tile_variance(tt, 4),
                        nl_wavelet_slice_variance(tt, 0.0, 4, NULL),
                        nl_wavelet_multiband_variance(t, 4, 0.0, 4),
                        nl_wavelet_point_variance(t2, 65536, sk) };
    for (int i = 0; i < NREAD; i++) v[(size_t)i * K + s] = r[i];
  }
  const char *cols[] = { "reading", "var3d", "var3d_sd", "paper", "gap", "gap_in_sd" };
  nl_table *tab = nl_table_alloc(6, cols);
  for (int i = 0; i < NREAD; i++) {
    double m, sd;
    nl_stats_mean_sd(v + (size_t)i * K, K, NL_STATS_SUMMED, &m, &sd);
    /* gap: relative to the paper; gap_in_sd: in sd over seeds (0 sd: +-inf written as a large
     * number) */
    nl_table_append(tab, "sddddd", READINGS[i], m, sd, paper, m / paper - 1,
                    sd > 0 ? (m - paper) / sd : copysign(1e9, m - paper));
  }
  gsl_rng_free(rng);
  free(v);
  nl_wavelet_tile_free(t);
  nl_wavelet_tile_free(tt);
  nl_wavelet_tile_free(t2);
  return tab;
}

int l1_readings_within(const nl_table *t, double nsd, char *buf, size_t size)
{
  int count = 0;
  size_t used = 0;
  buf[0] = 0;
  for (size_t i = 0; i < t->nrows; i++) {
    double g = nl_table_value(t, i, "gap_in_sd");
    if (fabs(g) > nsd) continue;
    int w = snprintf(buf + used, size - used, "%s%s (%.4f +- %.4f)", count ? "; " : "",
                     nl_table_text(t, i, "reading"), nl_table_value(t, i, "var3d"),
                     nl_table_value(t, i, "var3d_sd"));
    if (w < 0 || (size_t)w >= size - used) break;
    used += (size_t)w;
    count++;
  }
  return count;
}

nl_table *l1_leakage_table(const double *share, int K, int nb)
{
  const char *lcols[] = { "band", "below", "inside", "inside_sd", "above" };
  nl_table *lt = nl_table_alloc(5, lcols);
  double *col = nl_xcalloc((size_t)K, sizeof *col);
  for (int k = 0; k < nb; k++) {
    double in, in_sd, lo = 0, hi = 0;
    for (int s = 0; s < K; s++) {
      const double *row = share + ((size_t)s * nb + k) * nb;
      col[s] = row[k];
      /* band index grows toward low frequencies: j > k is below in frequency */
      for (int j = 0; j < nb; j++) {
        if (j > k) lo += row[j] / K;
        if (j < k) hi += row[j] / K;
      }
    }
    nl_stats_mean_sd(col, K, NL_STATS_SUMMED, &in, &in_sd);
    nl_table_append(lt, "idddd", k, lo, in, in_sd, hi);
  }
  free(col);
  return lt;
}

nl_table *l1_expected_table(int n2, double m2, double s2, int n3, double m3, double s3, int K,
                            int samples, nl_table **period)
{
  const char *cols[] = { "dim",  "period",      "expected", "expected_cont",
                         "measured", "measured_sd", "seeds",    "z" };
  nl_table *t = nl_table_alloc(8, cols);
  const int n[2] = { n2, n3 };
  const double m[2] = { m2, m3 }, sd[2] = { s2, s3 };
  for (int d = 0; d < 2; d++) {
    double e = l1_variance_expected(d + 2, n[d], samples);
    double ec = l1_variance_expected(d + 2, n[d], 0);
    double se = sd[d] / sqrt(K);
    nl_table_append(t, "iiddddid", d + 2, n[d], e, ec, m[d], sd[d], K,
                    se > 0 ? (m[d] - e) / se : 0.0);
  }
  const char *pcols[] = { "period", "var2d", "var3d", "var2d_cont", "var3d_cont" };
  nl_table *pt = nl_table_alloc(5, pcols);
  for (int p = 16; p <= 256; p *= 2) {
    double v2, v3, c2, c3;
    l1_variance_expected2(p, samples, &v2, &v3);
    l1_variance_expected2(p, 0, &c2, &c3);
    nl_table_append(pt, "idddd", p, v2, v3, c2, c3);
  }
  *period = pt;
  return t;
}

double *l1_window(const double *img, int size, int w)
{
  double *o = nl_xmalloc((size_t)w * w * sizeof *o);
  for (int y = 0; y < w; y++)
    for (int x = 0; x < w; x++) o[(size_t)y * w + x] = img[(size_t)y * size + x];
  return o;
}

void l1_raw_tile_seed(nl_wavelet_tile *t, unsigned long seed)
{
  size_t total = (size_t)t->n * (size_t)t->n * (t->dim == 3 ? (size_t)t->n : 1u);
  gsl_rng *g = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(g, nl_seed_stream(seed, "wavelet.tile", 0)); /* the tile's own step 1 */
  for (size_t i = 0; i < total; i++) t->data[i] = (float)gsl_ran_gaussian_ziggurat(g, 1.0);
  gsl_rng_free(g);
}

static int cmp_double(const void *a, const void *b)
{
  double x = *(const double *)a, y = *(const double *)b;
  return (x > y) - (x < y);
}

double l1_gauss_distance(const nl_wavelet_tile *t, int per_unit)
{
  size_t side = (size_t)t->n * (size_t)per_unit, n = side * side;
  double *v = calloc(n, sizeof *v);
  for (size_t y = 0; y < side; y++)
    nl_wavelet_row(t, 0.5 / per_unit, 1.0 / per_unit, (y + 0.5) / per_unit, 0.5, side, 1.0,
                   v + y * side);
  double mean = 0, ss = 0;
  for (size_t i = 0; i < n; i++) mean += v[i];
  mean /= (double)n;
  for (size_t i = 0; i < n; i++) ss += (v[i] - mean) * (v[i] - mean);
  double sd = sqrt(ss / (double)(n - 1));
  qsort(v, n, sizeof *v, cmp_double);
  double d = 0;
  for (size_t i = 0; i < n; i++) {
    double phi = gsl_cdf_ugaussian_P((v[i] - mean) / sd);
    d = fmax(d, fmax(fabs((double)(i + 1) / (double)n - phi), fabs(phi - (double)i / (double)n)));
  }
  free(v);
  return d;
}
