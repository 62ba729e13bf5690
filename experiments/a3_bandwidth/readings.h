/* readings.h - A3's readings of Arnerin 2009 Table 5.2: the choices the
 * paper leaves open in "the bandwidth of Perlin noise", as one struct, and
 * the family of readings A3 measures over seeds.
 *
 * The signals of Table 5.2 (a3_signal_octaves): 0 noise(x), 1 noise(2x)/2,
 * 2 their sum Fnoise_2.
 *
 * Sampling: line length (units) and rate (samples per unit), the shader's
 * encoding (noise + 1)/2 or raw values, the x axis through the origin (a GPU
 * shader's noise(x, 0, 0)) or an oblique line (study/nl_study_lines.h) from
 * an origin drawn from stream ("a3.line_origin", 0) of the seed.
 *
 * The noise (a3_noise). The nl_noise_alt ones are sampled on the same line;
 * the 1D noise at unit speed along x from the line's origin, the 2D noise
 * at unit speed along the line's direction in the xy plane.
 *
 * The paper's import (sec. 5.2.2): hash24 sends the encoded value through
 * its shader code, val = int(v 2^24) split over three channels as
 * (val / 65536) / 256.0 etc., stored in an 8-bit framebuffer (nearest of
 * 0..255 of the channel in [0, 1]) and rebuilt as
 * (R 65536 + G 256 + B) / 2^24.
 *
 * The estimator: window (NL_SPECTRUM_RECT or _HANN), two_sided (Gamma
 * integrates the positive half of the two-sided PSD: half the energy of
 * each f > 0), sigma_rms (sigma = RMS, the DC in sigma), gamma_no_dc (the
 * DC bin left out of Gamma), bin_edge (a bin's frequency is its lower edge,
 * f - res/2, not its centre), radians (frequencies times 2 pi). All 0 is
 * nl_bounds_bandwidth_1d bit for bit.
 *
 *   a3_reading rd = {.length = 512, .rate = 64, .shader = 1};
 *   double m[A3_NSIGNALS][7];
 *   a3_bandwidth_seeds(&rd, seed0, 10, m, &err);   // m[s][2]: mean F_sup of signal s
 */
#ifndef A3_READINGS_H
#define A3_READINGS_H

#include "bounds/nl_bounds.h"
#include "study/nl_study_lines.h"

enum { A3_NSIGNALS = 3, A3_MAX_SEEDS = 64 };

/* The octave list of signal s of Table 5.2. */
nl_noise_octaves a3_signal_octaves(int s);

/* The x axis through the origin when axis, else the oblique line along
 * (1, 1/phi, 1/phi^2) (unit length) from an origin drawn from seed. */
nl_study_line a3_line(int axis, unsigned long seed);

typedef enum {
  A3_NOISE_IMPROVED = 0,   /* Perlin 2002, nl_noise_perm3 */
  A3_NOISE_IMPROVED_CUBIC, /* 2002 gradients, 1985's cubic fade */
  A3_NOISE_CLASSIC,        /* Perlin 1985: unit gradients, cubic fade */
  A3_NOISE_LINE1_CUBIC,    /* 1D gradient noise, gradients in [-1, 1] (Perlin's noise1) */
  A3_NOISE_LINE1_QUINTIC,  /* the same with the quintic fade */
  A3_NOISE_GPU8,           /* 2002 noise, RGBA8 gradients, float32 */
  A3_NOISE_CLASSIC_GPU8,   /* 1985 noise, RGBA8 gradients, float32 */
  A3_NOISE_SIMPLEX06,      /* Gustavson 2005 3D simplex noise, kernel radius^2 0.6 */
  A3_NOISE_SIMPLEX05,      /* the same, radius^2 0.5 (continuous) */
  A3_NOISE_SIMPLEX2        /* Gustavson 2005 2D simplex noise, on the line's xy direction */
} a3_noise;
/* What each a3_noise is, in a few words, for the report. */
const char *a3_noise_text(int noise);

typedef struct {
  double length, rate;
  int shader, axis;
  int noise, hash24;
  int window, two_sided, sigma_rms, gamma_no_dc, bin_edge, radians;
  int shuffle; /* 1: the line's samples in a random order (stream "a3.shuffle" of the
                * seed): the same values and variance, a flat spectrum; the control */
} a3_reading;

/* One sample of signal s under a reading, on the line of seed (caller
 * frees). */
double *a3_reading_sample(const nl_noise_perm3 *p, int s, const a3_reading *rd, unsigned long seed,
                          size_t *n);
/* The bandwidth of x under rd's estimator (nl_bounds_bandwidth_1d when all
 * its estimator fields are 0); f_inf_rms uses the same Gamma. */
nl_status a3_bandwidth_reading(const double *x, size_t n, const a3_reading *rd, double T,
                               nl_bounds_bandwidth *bw, nl_error *err);

/* A3's family of readings, each base with one choice changed (base itself
 * first, in this order; the last, simplex06_rms, changes two: simplex
 * noise with r2 0.6 and sigma = RMS): fills at most max of out and name (a
 * short label) and returns how many there are. */
enum {
  A3_BASE,
  A3_IMPROVED_CUBIC,
  A3_CLASSIC,
  A3_LINE1_CUBIC,
  A3_LINE1_QUINTIC,
  A3_GPU8,
  A3_CLASSIC_GPU8,
  A3_HASH24,
  A3_HANN,
  A3_TWO_SIDED,
  A3_SIGMA_RMS,
  A3_SIGMA_RMS_NO_DC,
  A3_BIN_EDGE,
  A3_RAW,
  A3_RADIANS,
  A3_SIMPLEX06,
  A3_SIMPLEX05,
  A3_SIMPLEX2,
  A3_SIMPLEX06_RMS,
  A3_COUNT
};
int a3_readings(const a3_reading *base, a3_reading *out, const char **name, int max);

/* Per signal, over seeds replicates of seed0 (at most A3_MAX_SEEDS):
 * out[s] = {mean F_inf, sd, mean F_sup, sd, mean sigma, sd, mean F_inf_rms}
 * (a3_bandwidth_reading with T = NL_BOUNDS_T; sd 0 for one seed). */
nl_status a3_bandwidth_seeds(const a3_reading *rd, unsigned long seed0, int seeds,
                             double out[A3_NSIGNALS][7], nl_error *err);

#endif
