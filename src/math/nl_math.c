/* nl_math.c - the coefficient table of nl_math.h's kernel, and the external
 * definitions of its inline functions (C99 inline: a call the compiler does
 * not inline, or a program that takes the function's address, links to
 * these). */
#include "math/nl_math.h"

const double nl_math__coef[2][NL_MATH__NCOEF] = {
  {0.0, NL_MATH__SINPI_P0, NL_MATH__SINPI_P1, NL_MATH__SINPI_P2, NL_MATH__SINPI_P3,
   NL_MATH__SINPI_P4, NL_MATH__SINPI_P5, NL_MATH__SINPI_P6},
  {1.0, NL_MATH__COSPI_Q1, NL_MATH__COSPI_Q2, NL_MATH__COSPI_Q3, NL_MATH__COSPI_Q4,
   NL_MATH__COSPI_Q5, NL_MATH__COSPI_Q6, NL_MATH__COSPI_Q7},
};

const double nl_math__coef_sign[2] = {1.0, -1.0};

extern inline uint64_t nl_math__bits(double x);
extern inline double nl_math__double(uint64_t b);
extern inline double nl_math__reduce_huge(double a);
extern inline double nl_math__reduce(double x, unsigned *quadrant);
extern inline double nl_math__kernel(double r, double u, unsigned quadrant);
extern inline double nl_math_sinpi(double x);
extern inline double nl_math_cospi(double x);
extern inline void nl_math_sincospi(double x, double *s, double *c);
