/* naive_linkage.c - see naive_linkage.h. */
#include "reference/naive_linkage.h"

#include <math.h>
#include <stdlib.h>

static double dist(const double *a, const double *b, size_t d)
{
  double s = 0;
  for (size_t j = 0; j < d; j++)
    s += (a[j] - b[j]) * (a[j] - b[j]);
  return sqrt(s);
}

/* member[p] = the cluster id point p is in now; the score of clusters a, b. */
static double score(const double *x, size_t n, size_t d, int method, const size_t *member,
                    size_t a, size_t b)
{
  double best = method == NAIVE_SINGLE ? INFINITY : 0, sum = 0;
  double *ca = calloc(d, sizeof *ca), *cb = calloc(d, sizeof *cb);
  size_t na = 0, nb = 0;
  for (size_t p = 0; p < n; p++) {
    if (member[p] == a) {
      na++;
      for (size_t j = 0; j < d; j++)
        ca[j] += x[p * d + j] - x[j];
    } else if (member[p] == b) {
      nb++;
      for (size_t j = 0; j < d; j++)
        cb[j] += x[p * d + j] - x[j];
    }
  }
  if (method == NAIVE_WARD) {
    for (size_t j = 0; j < d; j++) {
      ca[j] /= (double)na;
      cb[j] /= (double)nb;
    }
    double f = 2.0 * (double)na * (double)nb / (double)(na + nb);
    best = sqrt(f) * dist(ca, cb, d);
  } else {
    for (size_t p = 0; p < n; p++) {
      if (member[p] != a)
        continue;
      for (size_t q = 0; q < n; q++) {
        if (member[q] != b)
          continue;
        double e = dist(x + p * d, x + q * d, d);
        if (method == NAIVE_SINGLE)
          best = fmin(best, e);
        else if (method == NAIVE_COMPLETE)
          best = fmax(best, e);
        else
          sum += e;
      }
    }
    if (method == NAIVE_AVERAGE)
      best = sum / ((double)na * (double)nb);
  }
  free(ca);
  free(cb);
  return best;
}

void naive_linkage(const double *x, size_t n, size_t d, int method, double *Z, double *gap)
{
  size_t *member = malloc(n * sizeof *member), *size = malloc(2 * n * sizeof *size);
  int *alive = calloc(2 * n, sizeof *alive);
  for (size_t p = 0; p < n; p++) {
    member[p] = p;
    size[p] = 1;
    alive[p] = 1;
  }
  double margin = INFINITY;
  for (size_t step = 0; step + 1 < n; step++) {
    double best = INFINITY, second = INFINITY;
    size_t ba = 0, bb = 0, top = n + step;
    for (size_t a = 0; a < top; a++) {
      if (!alive[a])
        continue;
      for (size_t b = a + 1; b < top; b++) {
        if (!alive[b])
          continue;
        double s = score(x, n, d, method, member, a, b);
        if (s < best) {
          second = best;
          best = s;
          ba = a;
          bb = b;
        } else if (s < second) {
          second = s;
        }
      }
    }
    if (isfinite(second) && second > 0)
      margin = fmin(margin, (second - best) / second);
    size_t id = n + step;
    for (size_t p = 0; p < n; p++)
      if (member[p] == ba || member[p] == bb)
        member[p] = id;
    alive[ba] = alive[bb] = 0;
    alive[id] = 1;
    size[id] = size[ba] + size[bb];
    Z[4 * step] = (double)ba;
    Z[4 * step + 1] = (double)bb;
    Z[4 * step + 2] = best;
    Z[4 * step + 3] = (double)size[id];
  }
  if (gap)
    *gap = margin;
  free(member);
  free(size);
  free(alive);
}
