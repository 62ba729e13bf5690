/* Tests of the seed rule (nl_base.h): splitmix64 against its published
 * reference, distinct stream ids give different and uncorrelated streams,
 * replicates are consecutive run seeds. */
#include "base/nl_base.h"
#include "nl_test.h"

#include <gsl/gsl_rng.h>
#include <gsl/gsl_statistics_double.h>

NL_TEST(splitmix64_matches_reference)
{
  /* Vigna's splitmix64.c from state 0: the first two outputs are
   * 0xe220a8397b1dcdaf and 0x6e789e6aa1b965f4 (state advanced by the golden
   * increment each call, so output 2 is mix(0x9e3779b97f4a7c15)). */
  NL_CHECK(nl_seed_mix(0) == 0xe220a8397b1dcdafULL);
  NL_CHECK(nl_seed_mix(0x9E3779B97F4A7C15ULL) == 0x6e789e6aa1b965f4ULL);
}

NL_TEST(stream_ids_give_distinct_seeds)
{
  /* Pins the rule itself: a change of derivation changes every result. */
  unsigned long a = nl_seed_stream(1, "noise.grad2", 0);
  NL_CHECK(a == nl_seed_stream(1, "noise.grad2", 0));
  NL_CHECK(a != nl_seed_stream(1, "noise.grad2", 1));
  NL_CHECK(a != nl_seed_stream(1, "noise.perm3", 0));
  NL_CHECK(a != nl_seed_stream(2, "noise.grad2", 0));
  /* Role and index do not trade: ("x", 1) is not ("x1", 0) and the like. */
  NL_CHECK(nl_seed_stream(7, "x", 1) != nl_seed_stream(7, "x1", 0));
  NL_CHECK(nl_seed_stream(0, "", 0) != nl_seed_stream(0, "", 1));
  /* No collision in the low 32 bits (what MT19937 reads) over 2 x 20000 ids. */
  enum { N = 20000 };
  static unsigned int lo[2 * N];
  for (int k = 0; k < N; k++) {
    lo[k] = (unsigned int)nl_seed_stream(1, "pool", (unsigned long)k);
    lo[N + k] = (unsigned int)nl_seed_stream(1, "table", (unsigned long)k);
  }
  int dup = 0;
  for (int i = 0; i < 2 * N && dup < 1; i++)
    for (int j = i + 1; j < 2 * N; j++) if (lo[i] == lo[j]) { dup++; break; }
  /* Birthday bound: P(any duplicate among 40000 32-bit values) ~ 0.17, so
   * a single duplicate would not prove a bug; count none for these ids
   * (measured), which pins the derivation as well. */
  NL_CHECK(dup == 0);
}

NL_TEST(two_streams_of_one_seed_are_uncorrelated)
{
  /* Seeds that differ by one (the old ad hoc rule seed, seed + 1) and two
   * roles of one seed: Pearson correlation of 100000 uniforms each. Under
   * independence r ~ N(0, 1/n), sd 0.0032; bound 5 sd = 0.016. */
  enum { N = 100000 };
  static double x[N], y[N], z[N];
  gsl_rng *a = gsl_rng_alloc(gsl_rng_mt19937), *b = gsl_rng_alloc(gsl_rng_mt19937),
          *c = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(a, nl_seed_stream(5, "cheng.anneal", 0));
  gsl_rng_set(b, nl_seed_stream(5, "noise.grad2", 0));
  gsl_rng_set(c, nl_seed_stream(5, "cheng.anneal", 1));
  int same = 0;
  for (int i = 0; i < N; i++) {
    x[i] = gsl_rng_uniform(a); y[i] = gsl_rng_uniform(b); z[i] = gsl_rng_uniform(c);
    same += x[i] == y[i];
  }
  NL_CHECK(same < 5);
  NL_CHECK(fabs(gsl_stats_correlation(x, 1, y, 1, N)) < 0.016);
  NL_CHECK(fabs(gsl_stats_correlation(x, 1, z, 1, N)) < 0.016);
  /* Lagged: stream b is not stream a shifted by a few draws. */
  for (int lag = 1; lag <= 3; lag++)
    NL_CHECK(fabs(gsl_stats_correlation(x + lag, 1, y, 1, N - lag)) < 0.016);
  gsl_rng_free(a); gsl_rng_free(b); gsl_rng_free(c);
}

NL_TEST(replicates_are_consecutive_run_seeds)
{
  NL_CHECK(nl_seed_replicate(10, 0) == 10);
  NL_CHECK(nl_seed_replicate(10, 3) == 13);
  /* A sweep task with base 13 and K = 2 runs replicates 3, 4 of base 10. */
  NL_CHECK(nl_seed_replicate(nl_seed_replicate(10, 3), 1) == nl_seed_replicate(10, 4));
}

int main(void) { return nl_test_run(); }
