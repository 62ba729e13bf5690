/* maxnoise.h - A1's checks of the paper's premise |noise| <= 1 (Arnerin
 * 2009 eq. 4.1) on Perlin's improved 3D noise.
 *
 * The octave bound |b_i| <= 2^-i of b_i(x) = noise(2^i x) / 2^i holds
 * exactly where |noise| <= 1 at 2^i x: a1_octave_over counts the points of
 * nl_bounds_check_random (the same stream, so the same points) where some
 * octave i < n breaks it.
 *
 * The largest |noise|: random sampling finds the typical extremes, not the
 * supremum, which sits where the eight corner gradients of a cell point
 * the same way. a1_local_max draws `candidates` uniform points in [0, 256)^3
 * (one period), keeps the `starts` largest |noise| and climbs from each
 * with a Nelder-Mead simplex (GSL nmsimplex2, initial step 0.05, until the
 * simplex is below 1e-8 or 400 iterations) on -|noise|: a lower bound of
 * the supremum, deterministic for a seed.
 *
 *   double xyz[3], sampled;
 *   double m = a1_local_max(&perm, 100000, 32, seed, xyz, &sampled);
 */
#ifndef A1_MAXNOISE_H
#define A1_MAXNOISE_H

#include "noise/nl_noise.h"

/* Points (of npoints drawn as nl_bounds_check_random draws them from seed)
 * where |noise(2^i x)| > 1 for some octave i < n. */
long a1_octave_over(const nl_noise_perm3 *p, int n, long npoints, unsigned long seed);

/* The largest |noise| found by the local climbs; *sampled: the largest of
 * the candidates before climbing; xyz: where the largest was found. */
double a1_local_max(const nl_noise_perm3 *p, long candidates, int starts, unsigned long seed,
                    double xyz[3], double *sampled);

/* The climbs of a1_local_max on |Fnoise_n(x)| / S_{n-1} (n = 1: |noise|,
 * the octave bound of eq. 4.1 at every octave; n >= 2: the fractal bound
 * of eq. 4.2): the largest ratio reached and where, the largest candidate,
 * and how many candidates (random points, not climbed) and how many climbs
 * end above 1, i.e. outside the paper's bound as printed. */
typedef struct {
  double best, sampled, xyz[3];
  long candidates_over, climbs_over;
} a1_climbs;
void a1_climb_sum(const nl_noise_perm3 *p, int n, long candidates, int starts, unsigned long seed,
                  a1_climbs *out);

/* Eq. 5.4 as printed, |Fnoise_Nmax| <= |Fnoise_n + S_{Nmax-1} - S_n| for
 * n = 1..nmax-1, on the points of nl_bounds_check_random: *printed counts
 * the points where it fails for some n; *dropped those where |Fnoise_Nmax|
 * > |Fnoise_n| for some n (the remainder's bound taken as 0: a bound
 * without the method, which must fail). */
void a1_printed_over(const nl_noise_perm3 *p, int nmax, long npoints, unsigned long seed,
                     long *printed, long *dropped);

#endif
