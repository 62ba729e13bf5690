/* nl_test.h - the smallest test harness that does the job.
 *
 *   NL_TEST(name) { NL_CHECK(x == 1); NL_CHECK_NEAR(a, b, 1e-12); }
 *   int main(void) { return nl_test_run(); }
 * Each failed check prints file:line and the expression; the program's exit
 * status is the number of failed tests (0 = all passed), which is what
 * meson test reads.
 *
 *   nl_test_skip("the %s level: this CPU lacks it", name);
 * records a check that could not run on this machine. When no test failed
 * and something was skipped, nl_test_run prints every skip and returns 77,
 * meson's "skipped": a pass would claim checks that never ran, and a line
 * in a passing test's log is read by nobody. A failure still fails.
 */
#ifndef NL_TEST_H
#define NL_TEST_H
#include <math.h>
#include <stdarg.h>
#include <stdio.h>

typedef void (*nl_test_fn)(void);
#define NL_TEST_MAX 256
static struct { const char *label; nl_test_fn fn; } nl__tests[NL_TEST_MAX];
static int nl__ntests, nl__failed_checks;

#define NL_TEST(name)                                              \
  static void name(void);                                          \
  __attribute__((constructor)) static void name##_reg(void)        \
  { nl__tests[nl__ntests].label = #name; nl__tests[nl__ntests++].fn = name; } \
  static void name(void)

#define NL_CHECK(cond) do { if (!(cond)) {                         \
  fprintf(stderr, "%s:%d: check failed: %s\n", __FILE__, __LINE__, #cond); \
  nl__failed_checks++; } } while (0)

#define NL_CHECK_NEAR(a, b, tol) do { double nl__a = (a), nl__b = (b); \
  if (!(fabs(nl__a - nl__b) <= (tol))) {                           \
  fprintf(stderr, "%s:%d: %s = %.17g, %s = %.17g, |diff| > %g\n",  \
          __FILE__, __LINE__, #a, nl__a, #b, nl__b, (double)(tol)); \
  nl__failed_checks++; } } while (0)

/* A scratch directory for the test program, removed at exit. */
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
static char nl__tmpdir[64];
static pid_t nl__tmpdir_owner;
/* Only the process that made it removes it: a forked child that calls
 * exit() runs this too, and would take its parent's files. */
static void nl__rm_tmpdir(void)
{
  if (getpid() != nl__tmpdir_owner) return;
  char cmd[96];
  snprintf(cmd, sizeof cmd, "rm -rf '%s'", nl__tmpdir);
  if (system(cmd) != 0) fprintf(stderr, "could not remove %s\n", nl__tmpdir);
}
static inline const char *nl_test_tmpdir(void)
{
  if (!nl__tmpdir[0]) {
    strcpy(nl__tmpdir, "/tmp/nl_test_XXXXXX");
    if (!mkdtemp(nl__tmpdir)) { perror("mkdtemp"); exit(1); }
    nl__tmpdir_owner = getpid();
    atexit(nl__rm_tmpdir);
  }
  return nl__tmpdir;
}

/* 1 when folder holds no hidden file: an output's temporary (.NAME.PID.XXXXXX)
 * left behind starts with a dot. */
static inline int nl_test_no_hidden_files(const char *folder)
{
  char cmd[600], out[64] = "";
  snprintf(cmd, sizeof cmd, "ls -A '%s' | grep -c '^\\.' || true", folder);
  FILE *p = popen(cmd, "r");
  if (!p) return 0;
  if (!fgets(out, sizeof out, p)) out[0] = '\0';
  pclose(p);
  return atoi(out) == 0;
}

#define NL_TEST_MAX_SKIPS 16
static char nl__skips[NL_TEST_MAX_SKIPS][128];
static int nl__nskips;
__attribute__((format(printf, 1, 2))) static inline void nl_test_skip(const char *fmt, ...)
{
  if (nl__nskips == NL_TEST_MAX_SKIPS)
    return;
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(nl__skips[nl__nskips++], sizeof nl__skips[0], fmt, ap);
  va_end(ap);
}

static inline int nl_test_run(void)
{
  int failed = 0;
  for (int i = 0; i < nl__ntests; i++) {
    int before = nl__failed_checks;
    nl__tests[i].fn();
    int ok = nl__failed_checks == before;
    printf("%s %s\n", ok ? "ok  " : "FAIL", nl__tests[i].label);
    failed += !ok;
  }
  printf("%d passed, %d failed\n", nl__ntests - failed, failed);
  if (failed)
    return failed;
  for (int k = 0; k < nl__nskips; k++)
    printf("SKIP %s\n", nl__skips[k]);
  return nl__nskips ? 77 : 0;
}
#endif
