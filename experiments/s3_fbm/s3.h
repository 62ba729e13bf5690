/* s3.h - S3's report prose and verdicts (report.c): the paragraphs around
 * the two fBm series of main.c, every number from the run's parameters and
 * tables. */
#ifndef S3_H
#define S3_H

#include "study/nl_study.h"

/* The slides' panels and our slice (win), before both series. */
void s3_report_intro(nl_harness *r, int octaves, const nl_noise_window *win);

/* The sd of each sum against the slides' law for uncorrelated octaves, one
 * verdict row per row of law (nl_study_sd_law_table, written as `file`)
 * whose octaves are distinct and not a lone octave: lacunarity 1 (one noise
 * summed, sd_law exact) and gain 0 (sd1 itself) hold by construction. Row
 * `skip` (-1: none) is left out: a setting with its verdict elsewhere.
 * Each row's negative control is the same row of ctl
 * (nl_study_sd_law_control, written as ctl_file). */
void s3_sd_verdicts(nl_harness *r, const nl_table *law, const char *file, const nl_table *ctl,
                    const char *ctl_file, long skip);

/* After the gain series: law its sd table; spectrum the file name of its
 * spectrum table, read back for gain 1's slope. */
void s3_report_gain(nl_harness *r, int octaves, const nl_table *law, const char *spectrum);

/* After the lacunarity series: law its sd table (rows in the order of
 * main.c's settings), win the window (for the pixel rate). */
void s3_report_lacunarity(nl_harness *r, int octaves, const nl_table *law,
                          const nl_noise_window *win);

#endif
