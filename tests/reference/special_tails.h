/* special_tails.h - the tails behind chi-square, Student's t and F tests,
 * from their textbook definitions in long double, as test oracles for the
 * p-values of src/stats (which take GSL's).
 *
 *   tail_gamma_q(a, x)   Q(a, x) = Gamma(a, x) / Gamma(a): the series of
 *                        P for x < a + 1 (Q = 1 - P), else Legendre's
 *                        continued fraction for Q itself (Lentz's method);
 *   tail_beta_i(a, b, x) I_x(a, b): its continued fraction (Lentz), on the
 *                        side x < (a + 1) / (a + b + 2) where it converges
 *                        fast, by I_x(a, b) = 1 - I_{1-x}(b, a) otherwise.
 * (Numerical Recipes, 3rd ed., sec. 6.2 and 6.4, the formulas; written here
 * in long double with 1e-19 convergence.) Chi-square: Q(df / 2, chi2 / 2);
 * Student: P(|T_df| > t) = I_{df / (df + t^2)}(df / 2, 1 / 2); F(d1, d2):
 * P(F <= f) = I_{d1 f / (d1 f + d2)}(d1 / 2, d2 / 2).
 */
#ifndef SPECIAL_TAILS_H
#define SPECIAL_TAILS_H

long double tail_gamma_q(long double a, long double x);
long double tail_beta_i(long double a, long double b, long double x);

#endif
