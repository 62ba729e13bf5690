/* Unit tests of A3's readings (readings.c). */
#include "nl_test.h"
#include "readings.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

NL_TEST(lines_and_signals)
{
  /* the oblique line runs along (1, 1/phi, 1/phi^2), unit length */
  nl_study_line l = a3_line(0, 7), ax = a3_line(1, 7);
  double phi = 0.5 * (1.0 + sqrt(5.0)), n2 = 0;
  for (int k = 0; k < 3; k++) n2 += l.dir[k] * l.dir[k];
  NL_CHECK(fabs(n2 - 1) < 1e-15);
  NL_CHECK(fabs(l.dir[1] / l.dir[0] - 1 / phi) < 1e-15);
  NL_CHECK(fabs(l.dir[2] / l.dir[0] - 1 / (phi * phi)) < 1e-15);
  NL_CHECK(ax.dir[0] == 1 && ax.origin[0] == 0);
  nl_noise_octaves o = a3_signal_octaves(1);
  NL_CHECK(o.n == 1 && o.freq[0] == 2.0 && o.amp[0] == 0.5);
  NL_CHECK(a3_signal_octaves(2).n == 2);
  nl_noise_perm3 p;
  nl_noise_perm3_seed(&p, 1);
  size_t n;
  double *x = nl_study_line_sample(&p, &o, &l, 8.0, 4.0, &n);
  NL_CHECK(n == 32);
  free(x);
}

NL_TEST(bandwidth_seeds)
{
  a3_reading rd = { .length = 16, .rate = 8, .shader = 1 };
  double m[A3_NSIGNALS][7];
  NL_CHECK(a3_bandwidth_seeds(&rd, 1, 2, m, NULL) == NL_OK);
  NL_CHECK(m[0][2] > 0 && m[0][3] >= 0 && m[2][2] >= m[0][2]);
  NL_CHECK(a3_bandwidth_seeds(&rd, 1, 0, m, NULL) == NL_EINVAL);
  NL_CHECK(a3_bandwidth_seeds(&rd, 1, A3_MAX_SEEDS + 1, m, NULL) == NL_EINVAL);
}

/* The readings of the estimator on the sinusoid at bin 37, and of the
 * sample: all 0 is nl_bounds_bandwidth_1d bit for bit; radians scale by
 * 2 pi, bin edges shift by half a bin; the paper's RGB8 import moves a
 * value by at most one step of its top and middle bytes (1/256 + 1/65536). */
/* Field by field: the struct's padding (after `shuffle`) is not copied by
 * assignment, so memcmp would read indeterminate bytes. */
static int same_reading(const a3_reading *a, const a3_reading *b)
{
  return a->length == b->length && a->rate == b->rate && a->shader == b->shader && a->axis == b->axis &&
         a->noise == b->noise && a->hash24 == b->hash24 && a->window == b->window &&
         a->two_sided == b->two_sided && a->sigma_rms == b->sigma_rms && a->gamma_no_dc == b->gamma_no_dc &&
         a->bin_edge == b->bin_edge && a->radians == b->radians && a->shuffle == b->shuffle;
}

NL_TEST(bandwidth_readings)
{
  size_t n = 1024;
  double rate = 8.0, x[1024];
  for (size_t k = 0; k < n; k++) x[k] = 0.25 + 0.5 * sin(NL_TWO_PI * 37.0 * k / n);
  a3_reading base = { .length = 128, .rate = rate, .shader = 1 }, fam[A3_COUNT];
  const char *name[A3_COUNT];
  NL_CHECK(a3_readings(&base, fam, name, A3_COUNT) == A3_COUNT);
  NL_CHECK(same_reading(&fam[0], &base));
  NL_CHECK(!strcmp(name[A3_HANN], "hann") && fam[A3_HANN].window == NL_SPECTRUM_HANN);
  nl_bounds_bandwidth a, b;
  NL_CHECK(nl_bounds_bandwidth_1d(x, n, rate, NL_BOUNDS_T, &a, NULL) == NL_OK);
  NL_CHECK(a3_bandwidth_reading(x, n, &fam[0], NL_BOUNDS_T, &b, NULL) == NL_OK);
  NL_CHECK(memcmp(&a, &b, sizeof a) == 0);
  NL_CHECK(a3_bandwidth_reading(x, n, &fam[A3_RADIANS], NL_BOUNDS_T, &b, NULL) == NL_OK);
  NL_CHECK_NEAR(b.f_sup, NL_TWO_PI * a.f_sup, 1e-12);
  NL_CHECK(a3_bandwidth_reading(x, n, &fam[A3_BIN_EDGE], NL_BOUNDS_T, &b, NULL) == NL_OK);
  NL_CHECK_NEAR(b.f_sup, a.f_sup - 0.5 * rate / n, 1e-12);
  NL_CHECK(a3_bandwidth_reading(x, n, &fam[A3_SIGMA_RMS_NO_DC], NL_BOUNDS_T, &b, NULL) == NL_OK);
  NL_CHECK(b.f_inf == 0.0 && b.f_sup == a.f_sup);
  nl_noise_perm3 p;
  nl_noise_perm3_seed(&p, 3);
  size_t m1, m2;
  double *u = a3_reading_sample(&p, 0, &base, 3, &m1);
  double *h = a3_reading_sample(&p, 0, &fam[A3_HASH24], 3, &m2);
  double worst = 0.0;
  for (size_t k = 0; k < m1; k++) worst = fmax(worst, fabs(u[k] - h[k]));
  /* top and middle byte, and the truncation to float */
  NL_CHECK(m1 == m2 && worst > 0.0 && worst <= 1.0 / 256 + 1.0 / 65536 + 0x1p-23);
  free(u);
  free(h);
}

int main(void) { return nl_test_run(); }
