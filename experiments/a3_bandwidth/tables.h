/* tables.h - the tables of A3 (Arnerin 2009 Table 5.2, Fig. 5.5) that
 * take loops: the PSD and Gamma of the three signals of one seed, and the
 * family of readings of the paper's method measured over seeds.
 *
 * hypotheses: one row per (reading of a3_readings, signal): mean
 * and sd over seeds of F_inf, F_sup and sigma, the paper's values, and how
 * far they lie: z = (paper - mean) / sd_eff with sd_eff = max(sd, res/4),
 * res the frequency resolution in the reading's unit (a value that is the
 * same bin on every seed is still "within" half a bin); within_inf,
 * within_sup = |z| <= 2, within = both.
 */
#ifndef A3_TABLES_H
#define A3_TABLES_H

#include "readings.h"
#include "table/nl_table.h"

/* Table 5.2 beside ours under one reading: per signal sig[s], the mean
 * and sd over seeds of F_inf, F_sup and sigma, the paper's pair, both
 * frequencies in bins of 1/length, and F_inf with sigma = RMS; columns
 * signal, f_inf, f_inf_sd, f_sup, f_sup_sd, sigma, paper_f_inf,
 * paper_f_sup, f_inf_bins, f_sup_bins, f_inf_rms. m receives
 * a3_bandwidth_seeds. NULL on error. */
nl_table *a3_bandwidth_table(const a3_reading *rd, unsigned long seed0, int seeds,
                             const double paper[][2], const char *const *sig,
                             double m[A3_NSIGNALS][7], nl_error *err);
/* Columns freq, psd_oct1.., gamma_oct1.. up to 8 cycles per unit (DC left out). */
/* Table 5.2's F_sup of Fnoise_2 over the 2nd octave's (the paper's is
 * 14.8% above): one row for the headline (m) and one for the control (mc,
 * a3_bandwidth_seeds of each), columns quantity, paper, ratio, ratio_sd
 * (the sds of the two means propagated as if independent). */
nl_table *a3_ratio_table(const double m[A3_NSIGNALS][7], const double mc[A3_NSIGNALS][7],
                         const double paper[][2]);
nl_table *a3_psd(const a3_reading *rd, unsigned long seed, nl_error *err);
/* The sensitivity table: mean F_inf, F_sup of each signal when the length
 * (64 .. 2048 units), then the rate (4 .. 128 per unit), takes the first
 * nvary (<= 6) of its values, then with the other encoding and the other
 * line; columns vary, length, rate, shader, axis, oct1_f_inf .. sum_f_sup. */
nl_table *a3_sweep(const a3_reading *rd, int nvary, unsigned long seed0, int seeds, nl_error *err);
/* paper[s] = {F_inf, F_sup} of signal s, named sig[s]; NULL on error. */
nl_table *a3_hypotheses(const a3_reading *base, unsigned long seed0, int seeds,
                        const double paper[][2], const char *const *sig, nl_error *err);

/* Summary of a hypotheses table, per reading h (rows in order): worst[h] =
 * the largest |z_sup| and |z_inf| over the signals, within[h] = how many
 * of the paper's bounds (F_inf and F_sup of each signal) are within.
 * Returns the number of readings (at most max). */
int a3_summary(const nl_table *t, int max, double (*worst)[2], int *within);

/* "reading value, ..." of column col for signal s of a hypotheses table
 * (%.4f), truncated to size. */
void a3_list(const nl_table *t, int s, const char *col, char *buf, size_t size);
/* Smallest and largest of column col over the length and rate rows of a
 * sweep table whose length is at least min_length. */
void a3_range(const nl_table *sw, double min_length, const char *col, double *lo, double *hi);

#endif
