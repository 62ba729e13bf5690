/* Unit tests of C8's independence test (indep.c): a hand-counted 2 x 2
 * table, a table that pairs z with phi (margins uniform, rejected), and a
 * random table (not rejected). */
#include "indep.h"
#include "nl_test.h"

#include <math.h>

NL_TEST(indep_hand_counted)
{
  /* 2 x 2 cells, counts [[3, 1], [1, 3]]: R = C = (4, 4), E = 2 each,
   * chi2_indep = 4 (1/2) = 2 on 1 df, p = erfc(1) (chi2_1 tail at 2);
   * joint against E = 2: the same 2 on 3 df. */
  double z[8] = { -0.5, -0.5, -0.5, -0.5, 0.5, 0.5, 0.5, 0.5 };
  double phi[8] = { 1, 1, 1, 4, 4, 4, 4, 1 };
  c8_indep r;
  c8_indep_pairs(z, phi, 8, 2, &r);
  NL_CHECK(fabs(r.chi2_indep - 2) < 1e-12 && r.df_indep == 1);
  NL_CHECK(fabs(r.p_indep - erfc(1.0)) < 1e-12);
  NL_CHECK(fabs(r.chi2_joint - 2) < 1e-12 && r.df_joint == 3);
  /* P(chi2_3 > 2) = erfc(1) + 2 sqrt(1 / pi) exp(-1) */
  NL_CHECK(fabs(r.p_joint - (erfc(1.0) + 2 * sqrt(1 / NL_PI) * exp(-1.0))) < 1e-12);
}

NL_TEST(indep_sees_paired_margins)
{
  /* z and phi each exactly uniform but phi a function of z: rejected */
  double z[512], phi[512];
  for (int k = 0; k < 512; k++) {
    z[k] = -1 + 2 * (k + 0.5) / 512;
    phi[k] = NL_TWO_PI * (k + 0.5) / 512;
  }
  c8_indep r;
  c8_indep_pairs(z, phi, 512, 8, &r);
  NL_CHECK(r.p_indep < 1e-10 && r.p_joint < 1e-10 && r.df_indep == 49);
  /* a random table from the 3D model's seeding passes */
  nl_cheng3_table *t = nl_cheng3_table_alloc(512);
  nl_cheng3_table_seed(t, 7);
  c8_indep_test(t, 8, &r);
  NL_CHECK(r.p_indep > 0.001 && r.p_joint > 0.001);
  nl_cheng3_table_free(t);
}

int main(void) { return nl_test_run(); }
