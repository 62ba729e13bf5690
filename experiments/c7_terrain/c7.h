/* c7.h - C7's height maps as tables and images (terrain.c) and its report
 * prose (report.c).
 *
 * Cheng 2009 sec. 4.5 (Fig 4.15-4.17) shows terrain whose height is the
 * controlled value; C7 writes each height map and its target pattern as
 * gnuplot matrices and shades the height as relief.
 */
#ifndef C7_H
#define C7_H

#include "study/nl_study_cheng.h"

/* A w x h raster (row-major, row 0 first) as a table of h rows and w columns
 * c0..c{w-1}: gnuplot's "matrix columnheaders" layout. */
nl_table *c7_matrix_table(const double *v, int w, int h);
/* The pattern's targets D as a grid x grid matrix table (c7_matrix_table);
 * cells without control hold -1. */
nl_table *c7_pattern_table(const nl_cheng_pattern *p);
/* Shaded relief of a w x h height field on the unit square: Lambertian
 * light from the north-west, 45 degrees up, heights exaggerated by zscale,
 * tinted by height (0..1). */
nl_image *c7_relief_image(const double *height, int w, int h, double zscale);

/* The thesis's claim, our setting (mesh side, vertical exaggeration), the
 * figures and the summary table. */
void c7_text(nl_harness *r, const nl_study_cheng *s, const nl_table *sum, int mesh,
             double zscale);

#endif
