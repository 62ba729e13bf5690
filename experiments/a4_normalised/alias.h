/* alias.h - A4's aliased energy (Arnerin 2009 sec. 5.2, Fig. 5.7): the
 * energy of a line sample above the Nyquist frequency of the image's
 * sampling, in units of the threshold T = (2/255)^2.
 *
 * T is two 8-bit levels of the value the shader stores, (noise + 1) / 2 in
 * [0, 1] (sec. 5.2.2), so the energy is that of the stored value: a quarter
 * of the raw noise's. The paper's claim: Nnoise(x) = noise(x / F_sup) keeps
 * the first octave's band below 1 cycle per unit, so at 2 samples per unit
 * what aliases is below T, where noise(x) itself aliases above T.
 *
 *   double e;
 *   a4_alias_energy(&perm, 1.0 / 1.7460938, 512, 64, 1.0, &e, &err);   // e in units of T
 */
#ifndef A4_ALIAS_H
#define A4_ALIAS_H

#include "bounds/nl_bounds.h"
#include "table/nl_table.h"

/* Energy of (noise(f p) + 1) / 2 along a4_line() (length units at rate per
 * unit) above the frequency nyquist, over T = NL_BOUNDS_T. */
nl_status a4_alias_energy(const nl_noise_perm3 *p, double f, double length, double rate,
                          double nyquist, double *e_over_t, nl_error *err);

/* The same for Fig. 5.7's 2D image: the stored value (noise(f p) + 1) / 2
 * on the plane z = 0.5 over [0, extent)^2 at rate samples per unit, Hann
 * tapered (nl_spectrum_hann2: its power sums to the variance), and the
 * power outside the square |f_x|, |f_y| <= nyquist (cycles per unit) that
 * a grid of 2 nyquist samples per unit folds back, over T. */
nl_status a4_alias_energy2(const nl_noise_perm3 *p, double f, double extent, double rate,
                           double nyquist, double *e_over_t, nl_error *err);

/* One-sided p-values of Student's t test of the mean of x[0..n-1] against
 * mu: *p_below for the alternative mean < mu, *p_above for mean > mu (both
 * 0.5 when n < 2 or the sd is 0 and the mean equals mu; 0 or 1 when the sd
 * is 0 otherwise). */
void a4_t_test(const double *x, int n, double mu, double *p_below, double *p_above);

/* aliased_energy.tsv: per normalisation (noise(x); noise(x / F_sup) with
 * our mean F_sup f_ours of raw values; with the paper's f_paper) the mean
 * and sd over seeds of e[v][0..seeds-1] (energy above Nyquist in T) and the
 * one-sided t-test p-values against 1 (alias.h, a4_t_test); columns
 * signal, divisor, energy_over_t, energy_over_t_sd, p_below, p_above,
 * seeds. */
nl_table *a4_energy_table(double e[3][64], int seeds, double f_ours, double f_paper);

#endif
