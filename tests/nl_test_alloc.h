/* nl_test_alloc.h - every allocation of a library call made to fail in turn.
 *
 *   nl_status st;
 *   double *out = NULL;
 *   NL_FAIL_EACH_ALLOC(st, { free(out); out = NULL; }, st = nl_foo(args, &out, &err));
 *
 * runs the call with its 1st allocation failing, then its 2nd, and so on
 * (through nl_alloc_set_hook: the library's own allocations, not GSL's or
 * libc's), until a run in which no allocation was refused. Every refused run
 * must return NL_ENOMEM and the last NL_OK; `cleanup` runs after any run
 * that returned NL_OK (the call comes last: commas in it are its own). A run that aborts, exits or crashes fails the test
 * program; one that leaks fails under the sanitizer suite (LeakSanitizer).
 * nl_test_alloc_runs() is the number of runs of the last loop: a test that
 * expects its call to allocate checks it is above 1, so the loop cannot
 * pass by never refusing anything. The counter is atomic: calls that
 * allocate from nl_parallel_for's threads count every allocation once. */
#ifndef NL_TEST_ALLOC_H
#define NL_TEST_ALLOC_H
#include "base/nl_base.h"
#include "nl_test.h"

static long nl__alloc_count, nl__alloc_fail_at, nl__alloc_runs;
static int nl__alloc_refused;

static int nl__alloc_hook(size_t n, void *ctx)
{
  (void)n; (void)ctx;
  if (__atomic_add_fetch(&nl__alloc_count, 1, __ATOMIC_SEQ_CST) == nl__alloc_fail_at) {
    __atomic_store_n(&nl__alloc_refused, 1, __ATOMIC_SEQ_CST);
    return 0;
  }
  return 1;
}

static inline long nl_test_alloc_runs(void) { return nl__alloc_runs; }

#define NL_FAIL_EACH_ALLOC(status, cleanup, ...) do {                        \
    nl__alloc_runs = 0;                                                      \
    for (long nl__k = 1; nl__k <= 1000000; nl__k++) {                        \
      nl__alloc_count = 0; nl__alloc_fail_at = nl__k; nl__alloc_refused = 0; \
      nl__alloc_runs++;                                                      \
      nl_alloc_set_hook(nl__alloc_hook, NULL);                               \
      __VA_ARGS__;                                                           \
      nl_alloc_set_hook(NULL, NULL);                                         \
      if (!nl__alloc_refused) { NL_CHECK((status) == NL_OK); { cleanup; } break; } \
      if ((status) != NL_ENOMEM) {                                           \
        printf("  allocation %ld refused: status %d, not NL_ENOMEM\n",       \
               nl__k, (int)(status));                                        \
        NL_CHECK((status) == NL_ENOMEM);                                     \
      }                                                                      \
      if ((status) == NL_OK) { cleanup; }                                    \
    }                                                                        \
  } while (0)
#endif
