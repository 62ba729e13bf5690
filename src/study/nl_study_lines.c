/* nl_study_lines.c - samples along a line (nl_study_lines.h). */
#include "study/nl_study_lines.h"

#include <math.h>

double *nl_study_line_sample(const nl_noise_perm3 *p, const nl_noise_octaves *o,
                             const nl_study_line *l, double length, double rate, size_t *n)
{
  *n = (size_t)llround(length * rate);
  double *x = nl_xmalloc(*n * sizeof *x);
  nl_bounds_sample_line(p, o, l->origin, l->dir, rate, *n, x);
  return x;
}
