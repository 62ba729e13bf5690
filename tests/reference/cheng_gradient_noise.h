/* cheng_gradient_noise.h - Cheng's 2D gradient-table noise (Cheng 2009,
 * eq. 3.1-3.2) by its definition, as a test oracle for nl_noise_grad2.
 *
 * The gradient of lattice point (i, j) is (cos theta, sin theta) for theta =
 * angle[P[(P[i mod m] + j) mod m]] (mathematical modulo, for negative i, j
 * too); the noise is the sum over the four corners c of the cell floor(p)
 * of w(p_x - c_x) w(p_y - c_y) g_c . (p - c), w(t) = 1 - fade(|t|) and
 * fade(t) = 6 t^5 - 15 t^4 + 10 t^3: each corner's weight and dot product
 * on their own (the library blends along y and then x, Perlin's lerps in
 * another order). The fraction is p - floor(p) as Perlin's code rounds it.
 * The table (angles and permutation) is the caller's: data drawn from a
 * seed, not algorithm.
 */
#ifndef CHENG_GRADIENT_NOISE_H
#define CHENG_GRADIENT_NOISE_H

#include <stddef.h>

double cheng_gradient_noise(const double *angle, const unsigned *perm, size_t m, double x,
                            double y);

#endif
