/* continuity.c - Q1: "F_i is a continuous function of x" (sec. 3.1) across
 * the faces of the unit cubes, where the 27 cubes searched change. */
#include "continuity.h"
#include "harness/nl_harness.h"

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

static nl_cellular *make(nl_harness *r, double lambda, int M, nl_cellular_count_rule rule,
                         unsigned long seed)
{
  nl_cellular *c;
  nl_error err;
  if (nl_cellular_alloc(lambda, M, rule, seed, &c, &err)) nl_harness_die(r, 2, "%s", err.msg);
  return c;
}

/* Sec. 3.1's "F_i is a continuous function of x", across cube faces, for
 * the paper's rule as written and for its control, the search without the
 * 26 neighbouring cubes (q1_face_jumps): continuity.tsv, the verdict, a
 * paragraph. */
void q1_continuity(q1 *q, unsigned long seed0)
{
  nl_harness *r = q->r;
  const double h = 1e-7;
  const char *cols[] = { "search", "faces", "jumps", "jump_frac", "max_ratio", "paper_jumps" };
  nl_table *t = nl_table_alloc(6, cols);
  for (int own = 0; own < 2; own++) {
    long all = 0;
    double top = 0;
    for (int k = 0; k < q->seeds; k++) {
      unsigned long seed = nl_seed_replicate(seed0, k);
      nl_cellular *c = make(r, q->lambda, q->M, NL_COUNT_CLOSEST, seed);
      long j;
      double mr;
      q1_face_jumps(c, own, q->points, seed, h, &j, &mr);
      all += j;
      top = fmax(top, mr);
      nl_cellular_free(c);
    }
    double faces = (double)q->points * q->seeds;
    nl_table_append(t, "sddddd", own ? "own cube only" : "27 cubes", faces, (double)all,
                    all / faces, top, 0.0);
  }
  nl_harness_write_table(r, t, "continuity.tsv");
  nl_harness_verdict(r, "continuity.tsv", t, 0, "faces where some F_i jumps, paper's rule",
                     "paper_jumps", "jumps", NULL, "abs 0.5 0.5", "independent",
                     "F_i at both sides of random cube faces, 1e-7 apart");
  nl_harness_verdict_control(r, "the search without the 26 neighbouring cubes", "continuity.tsv", t,
                             1);
  nl_harness_report_table(r, t,
                          "F1..F4 at both sides of random cube faces x = i, 1e-7 apart, paper's "
                          "rule (continuity.tsv): faces where some F_i moves by more than twice "
                          "the step, and the largest |dF_i| / step",
                          4);
  nl_harness_text(r,
                  "Sec. 3.1 says F_i is continuous. Across %.0f cube faces, where the 27 cubes "
                  "searched change, F1..F4 jump at %.0f (largest |dF_i| / step %.3f, 1 for a "
                  "distance); searching x's own cube alone they jump at %.0f: the 26 neighbours "
                  "are what makes F_i continuous.\n",
                  nl_table_value(t, 0, "faces"), nl_table_value(t, 0, "jumps"),
                  nl_table_value(t, 0, "max_ratio"), nl_table_value(t, 1, "jumps"));
  nl_table_free(t);
}
