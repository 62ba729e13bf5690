/* readings.c - A3's readings of Table 5.2 (readings.h). */
#include "readings.h"
#include "noise/nl_noise_alt.h"

#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>
#include <gsl/gsl_statistics_double.h>
#include <math.h>
#include <stdlib.h>

nl_study_line a3_line(int axis, unsigned long seed)
{
  nl_study_line l = { { 0.0, 0.0, 0.0 }, { 1.0, 0.0, 0.0 } };
  if (axis) return l;
  double phi = 0.5 * (1.0 + sqrt(5.0)), d[3] = { 1.0, 1.0 / phi, 1.0 / (phi * phi) };
  double len = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  for (int a = 0; a < 3; a++) {
    l.dir[a] = d[a] / len;
    l.origin[a] = 17.0 * a + 0.37 * (double)(nl_seed_stream(seed, "a3.line_origin", 0) % 97);
  }
  return l;
}

nl_noise_octaves a3_signal_octaves(int s)
{
  nl_noise_octaves o = nl_noise_octaves_fractal(s == 2 ? 2 : 1);
  if (s == 1) {
    o.freq[0] = 2.0;
    o.amp[0] = 0.5;
  }
  return o;
}

/* The shader code of sec. 5.2.2 and the 8-bit framebuffer behind it, in
 * float32 as on the GPU: val = int(v 2^24), r = (val / 65536) / 256.0,
 * g = (val / 256 - (val / 65536) 256) / 256.0, b = (val % 256) / 256.0,
 * each stored as the nearest of 0..255 of its value clamped to [0, 1]
 * (so a channel of 128 or more comes back one less: k/256 * 255 rounds
 * to k - 1); Scilab rebuilds (R 65536 + G 256 + B) / 2^24. */
static double hash24_round_trip(double v)
{
  int val = (int)((float)v * 16777216.0f);
  float ch[3] = { (float)(val / 65536) / 256.0f, (float)(val / 256 - (val / 65536) * 256) / 256.0f,
                  (float)(val % 256) / 256.0f };
  long byte[3];
  for (int c = 0; c < 3; c++) byte[c] = lroundf(255.0f * fminf(fmaxf(ch[c], 0.0f), 1.0f));
  return (double)(byte[0] * 65536 + byte[1] * 256 + byte[2]) / 16777216.0;
}

const char *a3_noise_text(int noise)
{
  static const char *text[] = { "Perlin's 2002 improved noise (quintic fade, 12 gradients)",
                                "2002 gradients with the 1985 cubic fade",
                                "Perlin's 1985 noise (unit gradients, cubic fade)",
                                "1D gradient noise (cubic fade)",
                                "1D gradient noise (quintic fade)",
                                "2002 noise with RGBA8 gradients in float32",
                                "1985 noise with RGBA8 gradients in float32",
                                "Gustavson's 2005 3D simplex noise (kernel radius^2 0.6)",
                                "3D simplex noise with kernel radius^2 0.5",
                                "Gustavson's 2005 2D simplex noise" };
  return noise >= 0 && noise <= A3_NOISE_SIMPLEX2 ? text[noise] : "unknown noise";
}

/* One of the nl_noise_alt noises of a reading, on p's permutation. */
static void alt_noise(nl_noise_alt *t, const nl_noise_perm3 *p, int noise, unsigned long seed)
{
  switch (noise) {
  case A3_NOISE_IMPROVED_CUBIC:
    nl_noise_alt_improved(t, p, 0);
    break;
  case A3_NOISE_LINE1_CUBIC:
    nl_noise_alt_line1(t, p, seed, 0);
    break;
  case A3_NOISE_LINE1_QUINTIC:
    nl_noise_alt_line1(t, p, seed, 1);
    break;
  case A3_NOISE_GPU8:
    nl_noise_alt_improved(t, p, 1);
    nl_noise_alt_gpu8(t);
    break;
  case A3_NOISE_CLASSIC_GPU8:
    nl_noise_alt_classic(t, p, seed);
    nl_noise_alt_gpu8(t);
    break;
  case A3_NOISE_SIMPLEX06:
    nl_noise_alt_simplex(t, p, 0.6);
    break;
  case A3_NOISE_SIMPLEX05:
    nl_noise_alt_simplex(t, p, 0.5);
    break;
  case A3_NOISE_SIMPLEX2:
    nl_noise_alt_simplex2(t, p);
    break;
  default:
    nl_noise_alt_classic(t, p, seed);
    break;
  }
}

double *a3_reading_sample(const nl_noise_perm3 *p, int s, const a3_reading *rd, unsigned long seed,
                          size_t *n)
{
  nl_noise_octaves o = a3_signal_octaves(s);
  nl_study_line l = a3_line(rd->axis, seed);
  double *x;
  if (rd->noise == A3_NOISE_IMPROVED)
    x = nl_study_line_sample(p, &o, &l, rd->length, rd->rate, n);
  else {
    nl_noise_alt t;
    alt_noise(&t, p, rd->noise, seed);
    *n = (size_t)llround(rd->length * rd->rate);
    x = nl_xmalloc(*n * sizeof *x);
    for (size_t k = 0; k < *n; k++) {
      double u = (double)k / rd->rate, v = 0.0, q[3];
      double h = t.plane ? hypot(l.dir[0], l.dir[1]) : 1.0; /* unit speed in the plane */
      for (int a = 0; a < 3; a++)
        q[a] = t.line1 ? (a ? 0.0 : l.origin[0] + u) : l.origin[a] + u * l.dir[a] / h;
      for (int j = 0; j < o.n; j++)
        v += o.amp[j] * nl_noise_alt_eval(&t, o.freq[j] * q[0], o.freq[j] * q[1], o.freq[j] * q[2]);
      x[k] = v;
    }
  }
  if (rd->shader)
    for (size_t k = 0; k < *n; k++) x[k] = 0.5 * (x[k] + 1.0); /* the shader stored (noise + 1)/2 */
  if (rd->hash24)
    for (size_t k = 0; k < *n; k++) x[k] = hash24_round_trip(x[k]);
  if (rd->shuffle) {
    gsl_rng *g = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(g, nl_seed_stream(seed, "a3.shuffle", (unsigned long)s));
    gsl_ran_shuffle(g, x, *n, sizeof *x);
    gsl_rng_free(g);
  }
  return x;
}

nl_status a3_bandwidth_reading(const double *x, size_t n, const a3_reading *rd, double T,
                               nl_bounds_bandwidth *bw, nl_error *err)
{
  nl_bounds_bandwidth_options o = {.window = rd->window, .two_sided = rd->two_sided,
                                   .sigma_rms = rd->sigma_rms, .no_dc = rd->gamma_no_dc,
                                   .bin_edge = rd->bin_edge, .radians = rd->radians};
  return nl_bounds_bandwidth_1d_with(x, n, rd->rate, T, &o, bw, err);
}

int a3_readings(const a3_reading *base, a3_reading *out, const char **name, int max)
{
  static const char *names[] = {
    "improved02", "improved02_cubic",   "classic85",   "line1d_cubic", "line1d_quintic",
    "gpu8_f32",   "classic85_gpu8_f32", "hash24_rgb8", "hann",         "two_sided",
    "sigma_rms",  "sigma_rms_no_dc",    "bin_edge",    "raw_value",    "radians",
    "simplex06",  "simplex05",          "simplex2d",   "simplex06_rms"
  };
  int count = A3_COUNT;
  _Static_assert(sizeof names / sizeof names[0] == A3_COUNT, "one name per reading");
  for (int k = 0; k < count && k < max; k++) {
    a3_reading r = *base;
    if (k >= A3_IMPROVED_CUBIC && k <= A3_CLASSIC_GPU8)
      r.noise = k - A3_IMPROVED_CUBIC + A3_NOISE_IMPROVED_CUBIC; /* same order */
    r.hash24 |= k == A3_HASH24;
    r.window = k == A3_HANN ? NL_SPECTRUM_HANN : r.window;
    r.two_sided |= k == A3_TWO_SIDED;
    r.sigma_rms |= k == A3_SIGMA_RMS || k == A3_SIGMA_RMS_NO_DC;
    r.gamma_no_dc |= k == A3_SIGMA_RMS_NO_DC;
    r.bin_edge |= k == A3_BIN_EDGE;
    r.shader = k == A3_RAW ? !base->shader : r.shader;
    r.radians |= k == A3_RADIANS;
    if (k >= A3_SIMPLEX06 && k <= A3_SIMPLEX2)
      r.noise = k - A3_SIMPLEX06 + A3_NOISE_SIMPLEX06; /* same order */
    if (k == A3_SIMPLEX06_RMS) {
      r.noise = A3_NOISE_SIMPLEX06;
      r.sigma_rms = 1;
    }
    out[k] = r;
    name[k] = k == 0 && base->noise != A3_NOISE_IMPROVED ? "base" : names[k];
  }
  return count < max ? count : max;
}

nl_status a3_bandwidth_seeds(const a3_reading *rd, unsigned long seed0, int seeds,
                             double out[A3_NSIGNALS][7], nl_error *err)
{
  if (seeds < 1 || seeds > A3_MAX_SEEDS)
    return nl_fail(err, NL_EINVAL, "bandwidth: seeds must be in 1..%d", A3_MAX_SEEDS);
  double fi[A3_NSIGNALS][A3_MAX_SEEDS], fs[A3_NSIGNALS][A3_MAX_SEEDS];
  double sg[A3_NSIGNALS][A3_MAX_SEEDS], fr[A3_NSIGNALS][A3_MAX_SEEDS];
  for (int k = 0; k < seeds; k++) {
    nl_noise_perm3 p;
    nl_noise_perm3_seed(&p, nl_seed_replicate(seed0, k));
    for (int s = 0; s < A3_NSIGNALS; s++) {
      size_t n;
      double *x = a3_reading_sample(&p, s, rd, nl_seed_replicate(seed0, k), &n);
      nl_bounds_bandwidth bw;
      nl_status rc = a3_bandwidth_reading(x, n, rd, NL_BOUNDS_T, &bw, err);
      free(x);
      if (rc) return rc;
      fi[s][k] = bw.f_inf;
      fs[s][k] = bw.f_sup;
      sg[s][k] = bw.sigma;
      fr[s][k] = bw.f_inf_rms;
    }
  }
  size_t n = (size_t)seeds;
  for (int s = 0; s < A3_NSIGNALS; s++) {
    out[s][0] = gsl_stats_mean(fi[s], 1, n);
    out[s][1] = seeds > 1 ? gsl_stats_sd(fi[s], 1, n) : 0.0;
    out[s][2] = gsl_stats_mean(fs[s], 1, n);
    out[s][3] = seeds > 1 ? gsl_stats_sd(fs[s], 1, n) : 0.0;
    out[s][4] = gsl_stats_mean(sg[s], 1, n);
    out[s][5] = seeds > 1 ? gsl_stats_sd(sg[s], 1, n) : 0.0;
    out[s][6] = gsl_stats_mean(fr[s], 1, n);
  }
  return NL_OK;
}
