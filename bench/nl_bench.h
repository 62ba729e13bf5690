/* nl_bench.h - what the benchmarks share: the timing loop, CPU time beside
 * wall time, the machine's load, pinning to one core.
 *
 * nl_bench_rate(f, ctx, out, npoints): calls f(ctx, out) (which computes
 * npoints samples into out) repeatedly for at least 0.5 s of the thread's CPU
 * time, three times, and returns the best rate in millions of samples per
 * CPU second (time descheduled on a shared machine does not count; the best
 * of three discounts what is left: caches another process emptied).
 * nl_bench_cpu_share holds CPU time / wall time of that round (near 1 on an
 * idle core, lower when other work took the core).
 * nl_bench_report(fp, "start"|"end") prints a '#' line with /proc/loadavg and
 * the lowest CPU share seen so far: a number is only as good as its load.
 */
#ifndef NL_BENCH_H
#define NL_BENCH_H

#include "base/nl_base.h"

#include <sched.h>
#include <stdio.h>
#include <string.h>
#include <time.h>

typedef void (*nl_bench_fn)(const void *ctx, double *out);

static volatile double nl_bench_sink;   /* keeps the work observable */

static double nl_bench_cpu_share = 1, nl_bench_cpu_share_min = 1;
static int nl_bench_rounds;   /* nl_bench_rate calls so far */

/* CPU time of the calling thread, seconds. */
static inline double nl_bench_cpu_now(void)
{
  struct timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static inline double nl_bench_rate(nl_bench_fn f, const void *ctx, double *out, size_t npoints)
{
  double best = 0;
  for (int rep = 0; rep < 3; rep++) {
    size_t iters = 0;
    double t0 = nl_time_now(), c0 = nl_bench_cpu_now(), c;
    do { f(ctx, out); nl_bench_sink = out[iters % npoints]; iters++; c = nl_bench_cpu_now() - c0; } while (c < 0.5);
    double r = (double)iters * (double)npoints / c / 1e6, share = c / (nl_time_now() - t0);
    if (r > best) { best = r; nl_bench_cpu_share = share; }
  }
  if (nl_bench_cpu_share < nl_bench_cpu_share_min) nl_bench_cpu_share_min = nl_bench_cpu_share;
  nl_bench_rounds++;
  return best;
}

/* /proc/loadavg's first three numbers, or "unknown". */
static inline void nl_bench_loadavg(char *buf, size_t len)
{
  FILE *f = fopen("/proc/loadavg", "r");
  buf[0] = 0;
  if (!f || !fgets(buf, (int)len, f)) snprintf(buf, len, "unknown\n");
  if (f) fclose(f);
  buf[strcspn(buf, "\n")] = 0;
}

static inline void nl_bench_report(FILE *fp, const char *when)
{
  char load[128];
  nl_bench_loadavg(load, sizeof load);
  fprintf(fp, "# load average at %s: %s", when, load);
  if (nl_bench_rounds) fprintf(fp, "; lowest CPU / wall time of a timed round %.2f", nl_bench_cpu_share_min);
  fputc('\n', fp);
}

/* Keeps the process on the core it runs on (unless it was given one), so
 * timings do not include migrations; says where in buf. */
static inline const char *nl_bench_pin(char *buf, size_t len)
{
  cpu_set_t set;
  if (sched_getaffinity(0, sizeof set, &set) != 0) { snprintf(buf, len, "not pinned (sched_getaffinity failed)"); return buf; }
  int cpu = sched_getcpu();
  if (CPU_COUNT(&set) == 1) {
    for (int c = 0; c < CPU_SETSIZE; c++) if (CPU_ISSET(c, &set)) cpu = c;
    snprintf(buf, len, "cpu %d (given)", cpu);
    return buf;
  }
  if (cpu < 0) { snprintf(buf, len, "not pinned (sched_getcpu failed)"); return buf; }
  CPU_ZERO(&set);
  CPU_SET(cpu, &set);
  if (sched_setaffinity(0, sizeof set, &set) != 0) snprintf(buf, len, "not pinned (sched_setaffinity failed)");
  else snprintf(buf, len, "cpu %d (pinned)", cpu);
  return buf;
}

#endif
