/* Tests of nl_simd.c: names round-trip, the best level is supported, a
 * level is set only where the CPU runs it, and the scalar and SSE2 levels
 * always exist on x86-64 (SSE2 is its baseline); elsewhere (aarch64) the
 * scalar level only. */
#include "simd/nl_simd.h"
#include "nl_test.h"

#include <string.h>

NL_TEST(levels_names_and_setting)
{
  for (int l = NL_SIMD_SCALAR; l <= NL_SIMD_AVX512; l++)
    NL_CHECK(nl_simd_from_name(nl_simd_name(l)) == l);
  NL_CHECK(nl_simd_from_name("mmx") == -1 && nl_simd_from_name(NULL) == -1);
  NL_CHECK(!strcmp(nl_simd_name(9), "unknown"));
  NL_CHECK(nl_simd_supported(NL_SIMD_SCALAR));
#if NL_SIMD_X86
  NL_CHECK(nl_simd_supported(NL_SIMD_SSE2));
#else
  for (int l = NL_SIMD_SSE2; l <= NL_SIMD_AVX512; l++) NL_CHECK(!nl_simd_supported(l));
#endif
  int best = nl_simd_best();
  NL_CHECK(nl_simd_supported(best));
  printf("  best level here: %s\n", nl_simd_name(best));
  /* nl_status, the library's one vocabulary (GSL's codes share its numbers with other
   * meanings): a wrong level is NL_EINVAL, and the level in use stays. */
  NL_CHECK(nl_simd_set(best) == NL_OK);
  NL_CHECK(nl_simd_set(7) == NL_EINVAL && nl_simd_set(-1) == NL_EINVAL && nl_simd_get() == best);
  for (int l = NL_SIMD_SCALAR; l <= NL_SIMD_AVX512; l++) {
    nl_status rc = nl_simd_set(l);
    NL_CHECK(rc == (nl_simd_supported(l) ? NL_OK : NL_EINVAL));
    NL_CHECK(nl_simd_get() == (rc == NL_OK ? l : best));
    nl_simd_set(best);
  }
  NL_CHECK(nl_simd_set(best) == NL_OK && nl_simd_get() == best);
}

int main(void) { return nl_test_run(); }
