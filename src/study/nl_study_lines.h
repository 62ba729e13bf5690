/* nl_study_lines.h - the lines along which A3 and A4 sample a fractal sum
 * of improved noise to measure its spectral bandwidth (Arnerin 2009,
 * sec. 5.2; the measure is bounds/nl_bounds.h).
 *
 * The paper samples "a line" but says neither which nor how long. Along a
 * lattice axis improved noise repeats every 256 units (noise(x, 0, 0) is
 * periodic), so a long sample would see one period many times over. The
 * experiments' oblique lines run along (1, 1/phi, 1/phi^2), phi the golden
 * ratio, a direction parallel to no lattice axis or diagonal: the sample is
 * not periodic. Each experiment picks its own origin and the precision of
 * that direction (experiments/a3_bandwidth/readings.h, a4_normalised/line.h).
 *
 *   nl_study_line l = {{0.31, 17.7, 34.2}, {0.80902, 0.5, 0.30902}};
 *   size_t n;
 *   double *x = nl_study_line_sample(&perm, &octaves, &l, 512.0, 64.0, &n);
 *   nl_bounds_bandwidth_1d(x, n, 64.0, NL_BOUNDS_T, &bw, &err);
 *   free(x);
 */
#ifndef NL_STUDY_LINES_H
#define NL_STUDY_LINES_H

#include "bounds/nl_bounds.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The points origin + t dir, t in noise units (dir of unit length for t to
 * be the arc length). */
typedef struct {
  double origin[3], dir[3];
} nl_study_line;

/* n = llround(length rate) samples of the octaves along the line, k / rate
 * units apart from the origin (nl_bounds_sample_line); the caller frees. */
double *nl_study_line_sample(const nl_noise_perm3 *p, const nl_noise_octaves *o,
                             const nl_study_line *l, double length, double rate, size_t *n);

#ifdef __cplusplus
}
#endif

#endif
