/* nl_study.h - the loops that several experiments share, written once.
 *
 * nl_study_series: a row of panels (the slides' (a), (b), ...) of sums of
 * octaves, one per setting, surveyed over the run's seeds. It writes
 *   PREFIX_panels.png        the first seed's raster of each setting, labelled
 *   PREFIX_distribution.tsv  value distribution per setting (nl_survey_series)
 *   PREFIX_spectrum.tsv      seed-averaged radial power per setting
 * into the run's folder and adds them to the report; the spectrum figure is
 * PREFIX_spectrum.png, drawn by scripts/gnuplot/NAME-PREFIX_spectrum.gp.
 * Returns the distribution table (caller frees) for the text that
 * interprets it.
 */
#ifndef NL_STUDY_H
#define NL_STUDY_H

#include "noise/nl_noise.h"
#include "report/nl_report.h"

nl_table *nl_study_series(nl_run *r, const char *prefix, const char *title, nl_basis_kind kind,
                          const nl_setting *settings, int n, const nl_window *win);

/* The square window of the S experiments from the run's parameters:
 * size (pixels; 512, or 128 with --quick), extent (4 units) and z (0.5). */
nl_window nl_study_window(nl_run *r);

/* Fills settings[i] for octave counts oct[i] of Shaffer's fractal sum (gain
 * 1/2, lacunarity 2), optionally turbulent; labels "(a) 1 octave" are
 * written into labels[i] (32 bytes each). */
void nl_study_octave_settings(const int *oct, int n, int turbulence, nl_setting *settings,
                              char (*labels)[32]);

#endif
