/* line.c - A4's sampling line (line.h). */
#include "line.h"

nl_study_line a4_line(void)
{
  nl_study_line l = { { 0.31, 17.7, 34.2 }, { 0.80902, 0.5, 0.30902 } };
  return l;
}

double *a4_line_sample(const nl_noise_perm3 *p, double f, double length, double rate, size_t *n)
{
  nl_noise_octaves o = nl_noise_octaves_fbm(1, 1.0, 1.0);
  o.freq[0] = f;
  nl_study_line l = a4_line();
  return nl_study_line_sample(p, &o, &l, length, rate, n);
}
