/* nl_bench.h - the timing loop the benchmarks share.
 *
 * nl_bench_rate(f, ctx, out, npoints): calls f(ctx, out) (which computes
 * npoints samples into out) repeatedly for at least 0.5 s, three times, and
 * returns the best rate in millions of samples per second. The best of
 * three discounts interruptions by other processes on a shared machine.
 */
#ifndef NL_BENCH_H
#define NL_BENCH_H

#include "base/nl_base.h"

typedef void (*nl_bench_fn)(const void *ctx, double *out);

static volatile double nl_bench_sink;   /* keeps the work observable */

static inline double nl_bench_rate(nl_bench_fn f, const void *ctx, double *out, size_t npoints)
{
  double best = 0;
  for (int rep = 0; rep < 3; rep++) {
    size_t iters = 0;
    double t0 = nl_time_now(), t;
    do { f(ctx, out); nl_bench_sink = out[iters % npoints]; iters++; t = nl_time_now() - t0; } while (t < 0.5);
    double r = (double)iters * (double)npoints / t / 1e6;
    if (r > best) best = r;
  }
  return best;
}

#endif
