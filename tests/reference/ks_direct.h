/* ks_direct.h - Kolmogorov-Smirnov and Kuiper statistics and the exact laws
 * of D, computed from their definitions, as test oracles for src/stats.
 *
 * Statistics, by counting (O(n^2), ties allowed): at every sample value t,
 *   F_n(t) = #{x_i <= t} / n,  F_n(t-) = #{x_i < t} / n,
 *   D+ = max_t F_n(t) - F(t),  D- = max_t F(t) - F_n(t-)
 * (sup |F_n - F| is reached at a sample value, from one side); Kuiper's V
 * is D+ + D-. Two samples: D+ = max_t F_1(t) - F_2(t) over the pooled
 * values, D- = max_t F_2(t) - F_1(t).
 *
 * Laws, in long double:
 *   ks_birnbaum_tingey   P(D+_n >= d), the finite sum of Birnbaum & Tingey
 *                        (1951), every term positive;
 *   ks_durbin_cdf        P(D_n < d) by Durbin's matrix (1973), in the form of
 *                        Marsaglia, Tsang & Wang (2003), H^n by repeated
 *                        squaring without their scaling (long double's
 *                        range suffices for n <= 60);
 *   ks_kolmogorov_sf     P(K > lambda), the alternating series, or 1 minus
 *                        the Jacobi theta form for lambda < 1;
 *   ks2_paths_sf         P(D_{n1,n2} >= D) for D = dnum / (n1 n2), by walking
 *                        the lattice of the pooled sample's orderings
 *                        (every path equally likely) and keeping the
 *                        probability of those with |i n2 - j n1| < dnum.
 */
#ifndef KS_DIRECT_H
#define KS_DIRECT_H

#include <stddef.h>

void ks_direct_one(const double *x, size_t n, double (*cdf)(double), double *d_plus,
                   double *d_minus);
/* *num (may be NULL) = max_t |c_1(t) n2 - c_2(t) n1|, c the counts <= t:
 * D = num / (n1 n2) exactly. */
void ks_direct_two(const double *x, size_t n1, const double *y, size_t n2, double *d_plus,
                   double *d_minus, long *num);
long double ks_birnbaum_tingey(int n, long double d);
long double ks_durbin_cdf(int n, long double d);
long double ks_kolmogorov_sf(long double lambda);
long double ks2_paths_sf(int n1, int n2, long dnum);

#endif
