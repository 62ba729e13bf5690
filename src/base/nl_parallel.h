/* nl_parallel.h - a parallel for over POSIX threads whose results do not
 * depend on the number of threads.
 *
 *   nl_parallel_for(n, nthreads, fn, ctx)
 *
 * calls fn(ctx, i, t) once for every item i in 0..n-1, on up to nthreads
 * threads (the calling thread is thread 0 and works too); t in
 * 0..nl_parallel_threads(n, nthreads)-1 names the thread, for per-thread
 * scratch (workspaces, a model copy), never for results. Items are handed
 * out in increasing order to whichever thread is free, so which thread runs
 * an item, and when, is not fixed. The rules that make the results the same
 * bytes for any thread count (tested in test_base: 1, 2 and 3 threads):
 *  - item i writes only its own output slot (row i of an image, entry i of
 *    an array), never a shared accumulator;
 *  - item i draws its random numbers from its own stream, seeded from
 *    nl_seed_stream(seed, "role", i) (nl_base.h), never from a generator
 *    shared across items or kept per thread across items;
 *  - sums, maxima and the like over items are taken after nl_parallel_for
 *    returns, in item order.
 *
 * The thread count is an argument: library modules never choose it (the
 * experiment harness passes its --threads N, default nl_parallel_cores()).
 * nthreads <= 1, n <= 1, or a call from inside another nl_parallel_for's
 * item (nested regions run on the thread that calls them, so a threaded
 * caller of a threaded module never makes nthreads^2 threads) run every
 * item on the calling thread, in order. While two or more threads run,
 * OpenBLAS (when loaded; found at run time with dlsym) is set to one
 * thread, its count restored at the end: its own threads would only
 * compete with ours for the same cores (a spinning BLAS thread was 36% of
 * C5's samples) and one-thread BLAS results do not vary with its thread
 * count. Returns when every item has finished. Not async-signal-safe;
 * fn must not longjmp or exit.
 */
#ifndef NL_PARALLEL_H
#define NL_PARALLEL_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef void (*nl_parallel_fn)(void *ctx, size_t item, int thread);

void nl_parallel_for(size_t n, int nthreads, nl_parallel_fn fn, void *ctx);

/* The number of threads nl_parallel_for(n, nthreads, ...) will run, called
 * from here: min(nthreads, n), or 1 inside another region; at least 1. For
 * sizing per-thread scratch before the call. */
int nl_parallel_threads(size_t n, int nthreads);

/* The processors online (sysconf), at least 1: the harness's default. */
int nl_parallel_cores(void);

/* Stops OpenBLAS's idle worker threads, if OpenBLAS is loaded (found at
 * run time with dlsym; a no-op otherwise). OpenBLAS starts its workers when
 * it is loaded, and a new worker spins (sched_yield) for its timeout, about
 * 0.1 s of another core's CPU, before it sleeps: in every process that
 * links it, whether or not it calls a threaded BLAS routine (measured: 0.11 s
 * of a 0.3 s process, /proc/PID/task; 0.05 s against 0.19 s of CPU for a
 * process that sleeps 0.3 s). blas_thread_shutdown_ is OpenBLAS's own (its
 * fork handler calls it): it joins the workers, and the next threaded call
 * starts them again with the same count, so no result changes (a 1500^2
 * dgemm after it: the same bytes, two threads again). The programs call it
 * first thing (nl_harness_program_start, harness/nl_harness.h); only from one thread,
 * before any BLAS call is running. */
void nl_parallel_blas_idle(void);

/* OpenBLAS's thread count, one home for its run-time look-up (dlsym of
 * openblas_get_num_threads / openblas_set_num_threads: the library builds
 * and runs without OpenBLAS).
 *   nl_parallel_blas_threads: the count, -1 when OpenBLAS is not loaded.
 *   nl_parallel_blas_limit: sets OpenBLAS to one thread when it runs more,
 *     and returns the count to hand back (0: nothing changed).
 *   nl_parallel_blas_restore: gives it back (a no-op for 0).
 *   int was = nl_parallel_blas_limit();
 *   ...   // our own threads, or BLAS calls too small to split
 *   nl_parallel_blas_restore(was); */
int nl_parallel_blas_threads(void);
int nl_parallel_blas_limit(void);
void nl_parallel_blas_restore(int was);

/* The most threads nl_parallel_for starts. */
#define NL_PARALLEL_MAX 64

#ifdef __cplusplus
}
#endif

#endif
