/* continuity.c - Q1: "F_i is a continuous function of x" (sec. 3.1) across
 * the faces of the unit cubes, where the 27 cubes searched change. */
#include "continuity.h"

#include <gsl/gsl_rng.h>
#include <math.h>
#include <stdlib.h>

/* F1..F4 from the feature points of x's own cube alone (NL_CELLULAR_FMAX
 * where it holds fewer than four). */
static void own_cube(const nl_cellular *c, const double *p, double *F)
{
  double *xyz = nl_xmalloc(3 * (size_t)(c->M + 1) * sizeof *xyz);
  int m = nl_cellular_cube(c, (long)floor(p[0]), (long)floor(p[1]), (long)floor(p[2]), xyz);
  for (int i = 0; i < 4; i++) F[i] = NL_CELLULAR_FMAX;
  for (int q = 0; q < m; q++) {
    double d = sqrt(pow(xyz[3 * q] - p[0], 2) + pow(xyz[3 * q + 1] - p[1], 2) + pow(xyz[3 * q + 2] - p[2], 2));
    for (int s = 0; s < 4; s++)
      if (d < F[s]) {
        for (int t = 3; t > s; t--) F[t] = F[t - 1];
        F[s] = d;
        break;
      }
  }
  free(xyz);
}

void q1_face_jumps(const nl_cellular *c, int own, long points, unsigned long seed, double h,
                   long *jumps, double *max_ratio)
{
  gsl_rng *g = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(g, nl_seed_stream(seed, "q1.faces", 0));
  *jumps = 0;
  *max_ratio = 0;
  for (long k = 0; k < points; k++) {
    /* a face x = i between cubes i - 1 and i, at a random (y, z) */
    double i = 1 + floor(998 * gsl_rng_uniform(g)), y = 1000 * gsl_rng_uniform(g),
           z = 1000 * gsl_rng_uniform(g);
    double a[3] = { i - h / 2, y, z }, b[3] = { i + h / 2, y, z }, Fa[4], Fb[4];
    if (own) {
      own_cube(c, a, Fa);
      own_cube(c, b, Fb);
    } else {
      nl_cellular_eval(c, a, 4, Fa);
      nl_cellular_eval(c, b, 4, Fb);
    }
    int jumped = 0;
    for (int s = 0; s < 4; s++) {
      double ratio = fabs(Fb[s] - Fa[s]) / h;
      *max_ratio = fmax(*max_ratio, ratio);
      jumped |= ratio > 2; /* a distance moves by at most h: F_i is 1-Lipschitz */
    }
    *jumps += jumped;
  }
  gsl_rng_free(g);
}
