/* Marble's control value c = (1 + sin(pi V)) / 2 (nl_cheng_internal.h):
 * within 1.5e-16 of the true value, and the same bits whichever variant of
 * glibc's libm the machine picks. The second is tested by running this
 * program again with glibc's FMA and AVX2 variants switched off
 * (GLIBC_TUNABLES, read when a process starts) and comparing a hash of c at
 * 10^5 values of V; on a CPU without FMA the two runs would pick the same
 * variant and prove nothing, so the check is skipped there. */
#include "cheng/nl_cheng_internal.h"
#include "nl_test.h"

#include <inttypes.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#define NO_FMA_TUNABLES "glibc.cpu.hwcaps=-AVX2,-FMA,-FMA4,-AVX512F"

static double marble(double v) { return nl_cheng__control_of_sum(NL_CHENG_CON_SIN, v, 1.0, 0); }

/* FNV-1a over the bits of c at 10^5 + 1 points of V in [-1.25, 1.25]. */
static uint64_t marble_hash(void)
{
  uint64_t h = 1469598103934665603u;
  for (int i = 0; i <= 100000; i++) {
    double c = marble(-1.25 + 2.5 * (double)i / 100000.0);
    uint64_t b;
    memcpy(&b, &c, sizeof b);
    h = (h ^ b) * 1099511628211u;
  }
  return h;
}

static const char *self;

NL_TEST(marble_control_is_within_1p5e_16_of_the_true_value)
{
  double worst = 0;
  for (int i = 0; i <= 1000000; i++) {
    double v = -1.0 + 2.0 * (double)i / 1000000.0;
    long double ref = 0.5L * (1.0L + sinl(3.141592653589793238462643383279502884L * v));
    worst = fmax(worst, (double)fabsl((long double)marble(v) - ref));
  }
  printf("worst |c - (1 + sin(pi V)) / 2| over 10^6 V in [-1, 1]: %.3g\n", worst);
  NL_CHECK(worst <= 1.5e-16);   /* measured 1.21e-16; glibc's sin 2.28e-16 */
}

NL_TEST(marble_control_is_the_same_under_every_libm_variant)
{
#if defined(__x86_64__) || defined(__i386__)
  __builtin_cpu_init();
  if (!__builtin_cpu_supports("fma")) {
    nl_test_skip("libm variants: this CPU has no FMA, glibc has one variant only");
    return;
  }
#else
  /* glibc's variants chosen by these tunables are x86-64's */
  nl_test_skip("libm variants: GLIBC_TUNABLES' FMA variants are x86-64's");
  return;
#endif
  char cmd[4200];
  snprintf(cmd, sizeof cmd, "GLIBC_TUNABLES=" NO_FMA_TUNABLES " '%s' --hash", self);
  FILE *p = popen(cmd, "r");
  NL_CHECK(p != NULL);
  if (!p) return;
  uint64_t other = 0;
  NL_CHECK(fscanf(p, "%" SCNx64, &other) == 1);
  NL_CHECK(pclose(p) == 0);
  uint64_t mine = marble_hash();
  if (mine != other)
    fprintf(stderr, "hash %016" PRIx64 ", under " NO_FMA_TUNABLES " %016" PRIx64 "\n", mine, other);
  NL_CHECK(mine == other);
}

int main(int argc, char **argv)
{
  if (argc == 2 && !strcmp(argv[1], "--hash")) {
    printf("%016" PRIx64 "\n", marble_hash());
    return 0;
  }
  static char path[4096];
  ssize_t n = readlink("/proc/self/exe", path, sizeof path - 1);
  if (n <= 0) { perror("/proc/self/exe"); return 99; }
  path[n] = '\0';
  self = path;
  return nl_test_run();
}
