/* test_trend.c - C3's trend test (nl_study_spearman_perm_p) against values computed independently in
 * Python (math and itertools alone): Spearman's rho with tied x, and its
 * permutation p against the exact p over all 720 orders of y. */
#include "c3.h"
#include "nl_test.h"

NL_TEST(spearman_with_ties_and_its_permutation_p)
{
  const double x[6] = { 2, 2, 4, 4, 6, 6 }, y[6] = { 1.0, 1.2, 1.1, 2.0, 3.0, 2.5 };
  /* average ranks, then Pearson's r of the ranks: 0.8366600265340756 */
  NL_CHECK_NEAR(nl_study_spearman(x, y, 6), 0.8366600265340756, 1e-12);
  /* 24 of the 720 orders of y reach rho >= 0.83666: exact p = 1/30; the
   * Monte-Carlo p of 99999 shuffles has sd sqrt(p (1 - p) / 99999) =
   * 0.00057, so 0.003 is over 5 sd */
  double rho, p = nl_study_spearman_perm_p(x, y, 6, 99999, 1, &rho);
  NL_CHECK(rho == nl_study_spearman(x, y, 6));
  NL_CHECK_NEAR(p, 1.0 / 30, 0.003);
  /* a perfect trend of 4 points: rho 1, exact p 1/24 (one order of 24);
   * 999 shuffles give sd 0.0063, so 0.03 is over 4 sd */
  const double xs[4] = { 1, 2, 3, 4 }, ys[4] = { 1, 2, 3, 4 };
  p = nl_study_spearman_perm_p(xs, ys, 4, 999, 2, &rho);
  NL_CHECK_NEAR(rho, 1.0, 1e-12);
  NL_CHECK_NEAR(p, 1.0 / 24, 0.03);
}

int main(void) { return nl_test_run(); }
