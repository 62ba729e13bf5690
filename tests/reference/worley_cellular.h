/* worley_cellular.h - Worley's cellular distances F1..F4 by brute force, as
 * a test oracle for src/cellular.
 *
 * Feature points as Qin & Yang sec. 3.2 and nl_cellular.h describe them,
 * written from that description and sharing no code with src/cellular: the
 * cube (i, j, k) gets s = PERM(i + PERM(j + PERM(k))) with PERM(v) =
 * perm[v mod 2^16] (mathematical modulo, for negative v too); splitmix64
 * (Steele, Lea & Flood 2014) started from s draws r = top 53 bits / 2^53,
 * then 3 m coordinates inside the cube; m from r by the count rule over the
 * Poisson probabilities p(m) = e^-lambda lambda^m / m!, computed here by the
 * product recursion p(m) = p(m-1) lambda / m (the library: exp of a
 * logarithm with lgamma; the two agree within a few ulps, and a count could
 * differ only for an r within those ulps of a boundary).
 *
 * F_i is then the i-th smallest distance from x to every feature point of
 * the cubes within `reach` of x's cube: all of them listed, their squared
 * distances sorted (qsort), no early rejection. reach 1 is the library's
 * contract (27 cubes); reach 2 is Worley's F_i wherever F_i <= 2, since any
 * point outside those 125 cubes is at least 2 away. The permutation table
 * is the caller's (a random table drawn from a seed is data, not algorithm).
 */
#ifndef WORLEY_CELLULAR_H
#define WORLEY_CELLULAR_H

enum { WORLEY_CLOSEST_FIRST, WORLEY_INVERSE_CDF, WORLEY_CLOSEST_LAST };

typedef struct {
  const unsigned short *perm;   /* 65536 entries */
  int M, rule;
  double pmf[65], cdf[65];
} worley_ref;

void worley_ref_init(worley_ref *w, const unsigned short *perm, double lambda, int M, int rule);
/* The m feature points of cube (i, j, k) into xyz (3 m doubles); returns m. */
int worley_ref_cube(const worley_ref *w, long i, long j, long k, double *xyz);
/* d2[0..3]: the four smallest squared distances from p to the points of the
 * (2 reach + 1)^3 cubes around p's cube, ascending (+inf where fewer). */
void worley_ref_d2(const worley_ref *w, const double *p, int reach, double d2[4]);

#endif
