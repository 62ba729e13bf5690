/* line.h - the line along which A4 (Arnerin 2009 Fig. 5.7) measures F_sup
 * of improved noise and the energy that aliases: the oblique direction
 * (1, 1/phi, 1/phi^2) of study/nl_study_lines.h, normalised and written to
 * 5 digits, (0.80902, 0.5, 0.30902), from the fixed origin
 * (0.31, 17.7, 34.2).
 *
 *   size_t n;
 *   double *x = a4_line_sample(&perm, 1.0, 512.0, 64.0, &n);   // noise(p), 64 per unit
 */
#ifndef A4_LINE_H
#define A4_LINE_H

#include "study/nl_study_lines.h"

nl_study_line a4_line(void);
/* n = llround(length rate) samples of noise(f p) along a4_line(), rate per
 * unit (caller frees). */
double *a4_line_sample(const nl_noise_perm3 *p, double f, double length, double rate, size_t *n);

#endif
