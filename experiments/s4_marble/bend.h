/* bend.h - S4: the slides' "we need to add some noise first" as a number
 * (bend.c). Pure stripes u = (1 + sin(omega y)) / 2 vary along y only;
 * displacing y by a fractal sum that varies along x bends them into veins,
 * which shows as variation of u along x. */
#ifndef S4_BEND_H
#define S4_BEND_H

#include "noise/nl_noise.h"
#include "texture/nl_texture.h"

/* The share of u's squared neighbour differences along x, sum (du_x)^2 /
 * (sum (du_x)^2 + sum (du_y)^2), over a w x h raster: 0 for straight
 * stripes along x, 1/2 for an isotropic field. */
double s4_bend_share(const double *u, int w, int h);

/* The negative control of the bend: the marble of nl_texture_marble_grid
 * with each row displaced by the fractal sum at the row's first pixel, so
 * the stripes move by the same noise amplitude but cannot bend. */
void s4_marble_rows(const nl_noise_basis *b, const nl_noise_octaves *o, const nl_noise_window *win,
                    double omega, double a, double *u);

#endif
