/* cheng_gradient_noise.c - see cheng_gradient_noise.h. */
#include "reference/cheng_gradient_noise.h"

#include <math.h>

static long mod(long a, long m)
{
  long r = a % m;
  return r < 0 ? r + m : r;
}

static double weight(double t)
{
  double u = fabs(t);
  return 1 - u * u * u * (u * (u * 6 - 15) + 10);
}

double cheng_gradient_noise(const double *angle, const unsigned *perm, size_t m, double x,
                            double y)
{
  double cx = floor(x), cy = floor(y), fx = x - cx, fy = y - cy, sum = 0;
  long M = (long)m;
  for (int dj = 0; dj <= 1; dj++)
    for (int di = 0; di <= 1; di++) {
      long i = (long)cx + di, j = (long)cy + dj;
      double theta = angle[perm[mod((long)perm[mod(i, M)] + mod(j, M), M)]];
      double dx = fx - di, dy = fy - dj;
      sum += weight(dx) * weight(dy) * (cos(theta) * dx + sin(theta) * dy);
    }
  return sum;
}
