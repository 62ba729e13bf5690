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

/* Config c on pat over the run's seeds (seeds and results as
 * nl_study_cheng_runs under s->role), every seed's optimised table into
 * tables[0..k-1] (caller frees); returns the k evaluations (caller frees).
 * Exit 1 on error. */
nl_cheng_eval *c7_runs(const nl_study_cheng *s, const nl_cheng_config *c,
                       const nl_cheng_pattern *pat, nl_noise_grad2 **tables);
/* The same runs' unoptimised start tables (nl_cheng_run's random table). */
void c7_start_tables(const nl_study_cheng *s, const nl_cheng_config *c, nl_noise_grad2 **tables);
/* The seam controls on pattern `name`: rows (name, "w2=0"), (name, "no
 * propagation") and (name, "start table") of the seams table
 * (nl_study_cheng_seams_add), each over the run's seeds, measured under c. */
void c7_seam_controls(const nl_study_cheng *s, nl_table *seams, const nl_cheng_config *c,
                      const nl_cheng_pattern *pat, const char *name);

/* The thesis's claim, our setting (mesh side, vertical exaggeration), the
 * figures and the summary table. */
void c7_text(nl_harness *r, const nl_study_cheng *s, const nl_table *sum, int mesh, double zscale);
/* "The height follows the pattern": the control table's verdicts (r against
 * random tables, E_Con against a flat image), each with its negative control
 * from the baselines table (rows 2q: the pattern shuffled, 2q + 1: the start
 * tables, nl_study_cheng_baselines_add), E_Con's split for every row worse
 * than flat, and the seams table. */
void c7_control_text(nl_harness *r, const nl_table *ctl, const nl_table *bl,
                     const nl_table *seams, const nl_cheng_config *c);

#endif
