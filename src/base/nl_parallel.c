/* nl_parallel.c - see nl_parallel.h. */
#include "base/nl_parallel.h"

#include <dlfcn.h>
#include <pthread.h>
#include <stdatomic.h>
#include <unistd.h>

/* Set in every thread while it runs items: a nested region runs serially. */
static _Thread_local int in_region;

typedef struct {
  size_t n;
  nl_parallel_fn fn;
  void *ctx;
  atomic_size_t next;
} region;

typedef struct {
  region *r;
  int thread;
} worker;

static void run_items(region *r, int thread)
{
  in_region = 1;
  for (;;) {
    size_t i = atomic_fetch_add(&r->next, 1);
    if (i >= r->n) break;
    r->fn(r->ctx, i, thread);
  }
  in_region = 0;
}

static void *worker_main(void *arg)
{
  worker *w = arg;
  run_items(w->r, w->thread);
  return NULL;
}

int nl_parallel_threads(size_t n, int nthreads)
{
  if (in_region || nthreads <= 1 || n <= 1) return 1;
  if (nthreads > NL_PARALLEL_MAX) nthreads = NL_PARALLEL_MAX;
  return (size_t)nthreads < n ? nthreads : (int)n;
}

int nl_parallel_cores(void)
{
  long c = sysconf(_SC_NPROCESSORS_ONLN);
  return c < 1 ? 1 : c > NL_PARALLEL_MAX ? NL_PARALLEL_MAX : (int)c;
}

void nl_parallel_for(size_t n, int nthreads, nl_parallel_fn fn, void *ctx)
{
  int nt = nl_parallel_threads(n, nthreads);
  if (nt == 1) {
    int outer = in_region;   /* a nested call leaves its caller's flag set */
    in_region = 1;
    for (size_t i = 0; i < n; i++) fn(ctx, i, 0);
    in_region = outer;
    return;
  }
  /* OpenBLAS's own threads off while ours run (see the header). */
  int blas = nl_parallel_blas_limit();
  region r = {.n = n, .fn = fn, .ctx = ctx};
  atomic_init(&r.next, 0);
  worker w[NL_PARALLEL_MAX];
  pthread_t th[NL_PARALLEL_MAX];
  int started = 1;
  for (int t = 1; t < nt; t++) {
    w[t] = (worker){.r = &r, .thread = t};
    if (pthread_create(&th[t], NULL, worker_main, &w[t]) != 0) break;   /* fewer threads: same results */
    started++;
  }
  run_items(&r, 0);
  for (int t = 1; t < started; t++) pthread_join(th[t], NULL);
  nl_parallel_blas_restore(blas);
}

typedef int (*blas_get_fn)(void);
typedef void (*blas_set_fn)(int);

int nl_parallel_blas_threads(void)
{
  blas_get_fn get = (blas_get_fn)dlsym(RTLD_DEFAULT, "openblas_get_num_threads");
  return get ? get() : -1;
}

int nl_parallel_blas_limit(void)
{
  blas_get_fn get = (blas_get_fn)dlsym(RTLD_DEFAULT, "openblas_get_num_threads");
  blas_set_fn set = (blas_set_fn)dlsym(RTLD_DEFAULT, "openblas_set_num_threads");
  if (!get || !set) return 0;
  int was = get();
  if (was <= 1) return 0;
  set(1);
  return was;
}

void nl_parallel_blas_restore(int was)
{
  blas_set_fn set = (blas_set_fn)dlsym(RTLD_DEFAULT, "openblas_set_num_threads");
  if (was > 1 && set) set(was);
}

void nl_parallel_blas_idle(void)
{
  int (*shutdown)(void) = (int (*)(void))dlsym(RTLD_DEFAULT, "blas_thread_shutdown_");
  if (shutdown) shutdown();
}
