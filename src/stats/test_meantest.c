/* Tests of nl_stats_welch_p and nl_stats_ftest_p against scipy 1.10
 * (tests/reference/make_meantest_vectors.py -> tests/data/stats/meantest.tsv).
 * Tolerance: 1e-12 relative (+1e-300 absolute). Both sides evaluate the same
 * formulas; the p-values differ only in how GSL's and scipy's (Boost's)
 * incomplete beta functions round, measured at a few 1e-15 relative. */
#include "stats/nl_stats.h"
#include "nl_test.h"
#include "test_vectors.h"

NL_TEST(welch_and_ftest_match_scipy)
{
  nl_table *t = vec_read("meantest.tsv");
  NL_CHECK(t->nrows >= 10);
  for (size_t r = 0; r < t->nrows; r++) {
    double m1 = vec_get(t, r, "m1"), s1 = vec_get(t, r, "s1"), m2 = vec_get(t, r, "m2"), s2 = vec_get(t, r, "s2");
    size_t n1 = (size_t)vec_get(t, r, "n1"), n2 = (size_t)vec_get(t, r, "n2");
    double p = -1;
    nl_error err;
    NL_CHECK(nl_stats_welch_p(m1, s1, n1, m2, s2, n2, &p, &err) == NL_OK);
    NL_CHECK(vec_close(p, vec_get(t, r, "welch_p"), 1e-12, 1e-300));
    NL_CHECK(nl_stats_ftest_p(s1, n1, s2, n2, &p, &err) == NL_OK);
    NL_CHECK(vec_close(p, vec_get(t, r, "ftest_p"), 1e-12, 1e-300));
  }
  nl_table_free(t);
}

NL_TEST(welch_and_ftest_refuse_what_cannot_be_tested)
{
  double p = 0.5;
  nl_error err;
  NL_CHECK(nl_stats_welch_p(1, 0, 5, 2, 0, 5, &p, &err) == NL_EINVAL);   /* no spread at all */
  NL_CHECK(nl_stats_welch_p(1, 1, 1, 2, 1, 5, &p, &err) == NL_EINVAL);   /* n < 2 */
  NL_CHECK(nl_stats_welch_p(1, -1, 5, 2, 1, 5, &p, &err) == NL_EINVAL);
  NL_CHECK(nl_stats_welch_p(NAN, 1, 5, 2, 1, 5, &p, &err) == NL_EINVAL);
  NL_CHECK(nl_stats_ftest_p(0, 5, 0, 5, &p, &err) == NL_EINVAL);
  NL_CHECK(nl_stats_ftest_p(1, 5, INFINITY, 5, &p, &err) == NL_EINVAL);
  NL_CHECK(nl_stats_ftest_p(1, 5, 1, 0, &p, &err) == NL_EINVAL);
  NL_CHECK(p == 0.5);   /* untouched on error */
  NL_CHECK(nl_stats_ftest_p(1, 5, 0, 5, &p, &err) == NL_OK && p == 0);
  /* identical summaries: no evidence against equality */
  NL_CHECK(nl_stats_welch_p(3, 1, 8, 3, 1, 8, &p, &err) == NL_OK && p == 1);
  NL_CHECK(nl_stats_ftest_p(1, 8, 1, 8, &p, &err) == NL_OK && p > 1 - 1e-12 && p <= 1);
}

int main(void) { return nl_test_run(); }
