/* direct_dft.c - see direct_dft.h. */
#include "reference/direct_dft.h"

#include <math.h>

void direct_dft2(const double *img, int w, int h, long double *F)
{
  const long double two_pi = 6.283185307179586476925286766559005768L;
  long long turn = (long long)w * h;
  for (int v = 0; v < h; v++)
    for (int u = 0; u < w; u++) {
      long double re = 0, im = 0;
      for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
          long long k = ((long long)u * x % w) * h + ((long long)v * y % h) * w;
          long double a = two_pi * (long double)(k % turn) / (long double)turn;
          re += img[(long)y * w + x] * cosl(a);
          im -= img[(long)y * w + x] * sinl(a);
        }
      F[2 * ((long)v * w + u)] = re;
      F[2 * ((long)v * w + u) + 1] = im;
    }
}
