/* special_tails.c - see special_tails.h. */
#include "reference/special_tails.h"

#include <math.h>

#define EPS 1e-19L
#define TINY 1e-4000L

long double tail_gamma_q(long double a, long double x)
{
  if (x <= 0)
    return 1;
  long double lead = expl(-x + a * logl(x) - lgammal(a));
  if (x < a + 1) {   /* P = lead / a sum_n x^n / ((a + 1) ... (a + n)) */
    long double term = 1 / a, sum = term;
    for (int n = 1; n < 100000 && fabsl(term) > fabsl(sum) * EPS; n++) {
      term *= x / (a + n);
      sum += term;
    }
    return 1 - lead * sum;
  }
  /* Q = lead / (x + 1 - a - 1 (1 - a) / (x + 3 - a - 2 (2 - a) / (x + 5 - a - ...))) */
  long double b = x + 1 - a, c = 1 / TINY, d = 1 / b, h = d;
  for (int i = 1; i < 100000; i++) {
    long double an = -i * (i - a);
    b += 2;
    d = an * d + b;
    if (fabsl(d) < TINY)
      d = TINY;
    c = b + an / c;
    if (fabsl(c) < TINY)
      c = TINY;
    d = 1 / d;
    long double del = d * c;
    h *= del;
    if (fabsl(del - 1) < EPS)
      break;
  }
  return lead * h;
}

/* The continued fraction of I_x(a, b) without its leading factor. */
static long double beta_cf(long double a, long double b, long double x)
{
  long double qab = a + b, qap = a + 1, qam = a - 1, c = 1, d = 1 - qab * x / qap, h;
  if (fabsl(d) < TINY)
    d = TINY;
  d = 1 / d;
  h = d;
  for (int m = 1; m < 100000; m++) {
    int m2 = 2 * m;
    long double aa = m * (b - m) * x / ((qam + m2) * (a + m2));
    d = 1 + aa * d;
    if (fabsl(d) < TINY)
      d = TINY;
    c = 1 + aa / c;
    if (fabsl(c) < TINY)
      c = TINY;
    d = 1 / d;
    h *= d * c;
    aa = -(a + m) * (qab + m) * x / ((a + m2) * (qap + m2));
    d = 1 + aa * d;
    if (fabsl(d) < TINY)
      d = TINY;
    c = 1 + aa / c;
    if (fabsl(c) < TINY)
      c = TINY;
    d = 1 / d;
    long double del = d * c;
    h *= del;
    if (fabsl(del - 1) < EPS)
      break;
  }
  return h;
}

long double tail_beta_i(long double a, long double b, long double x)
{
  if (x <= 0)
    return 0;
  if (x >= 1)
    return 1;
  long double lead = expl(lgammal(a + b) - lgammal(a) - lgammal(b) + a * logl(x)
                          + b * log1pl(-x));
  if (x < (a + 1) / (a + b + 2))
    return lead * beta_cf(a, b, x) / a;
  return 1 - lead * beta_cf(b, a, 1 - x) / b;
}
