/* s3.h - S3's report prose (report.c): the paragraphs around the two fBm
 * series of main.c, every number from the run's parameters and tables. */
#ifndef S3_H
#define S3_H

#include "study/nl_study.h"

/* The slides' panels and our slice (win), before both series. */
void s3_report_intro(nl_harness *r, int octaves, const nl_noise_window *win);

/* After the gain series. */
void s3_report_gain(nl_harness *r, int octaves);

/* After the lacunarity series: gains and lacs are the two distribution
 * tables (nl_study_series), rows in the order of main.c's settings. */
void s3_report_lacunarity(nl_harness *r, int octaves, const nl_table *gains,
                          const nl_table *lacs);

#endif
