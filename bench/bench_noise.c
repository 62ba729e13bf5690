/* bench_noise - samples per second of our noises against stb_perlin.
 *
 * Single thread, a 1024 x 1024 grid over [0, 16)^2 (64 samples per lattice
 * cell at the base frequency) on the plane z = 0.5; 9 rounds over all the
 * kernels, stb's included, each kernel repeated in a round until at least
 * 0.1 s of CPU time has passed, and each kernel's fastest round reported
 * (rounds rather than one stretch per kernel: on a shared machine every
 * kernel then meets the same spells of contention). Time is the thread's CPU time
 * (CLOCK_THREAD_CPUTIME_ID: on a shared machine, time spent descheduled
 * does not count), wall time beside it. stb_perlin_noise3 and
 * stb_perlin_fbm_noise3 (Debian's libstb-dev) run on the same points in the
 * same run, so the ratio is machine-independent to first order; vs_stb of
 * the fBm rows is against stb_perlin_fbm_noise3 (4 octaves), of the others
 * against stb_perlin_noise3. The points kernels take random, incoherent
 * points in [0, 16)^2 (2D) or [0, 16)^3 (3D) through the batch API
 * (nl_noise_grad2_points, nl_noise_perm3_points): no row reuse; vs_stb of
 * the 3D points is against stb_perlin_noise3 on the same points.
 * noise3_row_sparse: rows of the same grid's y with 0.7 lattice cells per
 * sample (x = 0.35 + 0.7 k, z = 0.5), where a row holds fewer samples than
 * cells; vs_stb against stb_perlin_noise3 on the same samples.
 * wavelet_row: nl_wavelet_row over a 256^2 2D tile on the same grid.
 * cellular_row: nl_cellular_row, F1..F4 (Worley 1996; Qin & Yang 2000) on the
 * same grid at lambda = 4, M = 50, inverse-CDF counts, seed 1 (as
 * bench_cellular); a sample is one point's four distances, and vs_stb is
 * against stb_perlin_noise3 on the same points (stb has no cellular noise).
 * The program pins itself to the processor it starts on (sched_setaffinity)
 * unless already given one, and prints the load average.
 *
 *   build/bench/bench_noise [--size N] [--tsv]
 *   NL_NOISE_SIMD=scalar|sse2|avx2|avx512 picks the noise kernels' level.
 *
 * --tsv: lines starting with '#' (load, level, CPU), then a header line and
 * one tab-separated line per kernel: kernel, msamples_per_s (per CPU
 * second), cpu_ms and wall_ms (of one 1024^2 grid), vs_stb.
 */
#define _GNU_SOURCE
#include "nl_bench.h"
#include "noise/nl_noise.h"
#include "wavelet/nl_wavelet.h"
#include "cellular/nl_cellular.h"
#include "base/nl_base.h"

#include <sched.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wsign-compare"
#define STB_PERLIN_IMPLEMENTATION
#include <stb/stb_perlin.h>
#pragma GCC diagnostic pop

static int N = 1024;
static const double EXTENT = 16.0;
enum { ROUNDS = 9 };   /* rounds of >= 0.1 s CPU per kernel */

static void g_noise2(const void *ctx, double *out)
{
  double dx = EXTENT / N;
  for (int r = 0; r < N; r++) nl_noise_grad2_row(ctx, 0.5 * dx, dx, (r + 0.5) * dx, (size_t)N, out + (size_t)r * N);
}

static void g_noise3(const void *ctx, double *out)
{
  double dx = EXTENT / N;
  for (int r = 0; r < N; r++) nl_noise_perm3_row(ctx, 0.5 * dx, dx, (r + 0.5) * dx, 0.5, (size_t)N, out + (size_t)r * N);
}

static void g_fbm(const void *ctx, double *out)
{
  const nl_noise_basis *b = ctx;
  nl_noise_octaves o = nl_noise_octaves_fbm(4, 0.5, 2.0);
  nl_noise_window w = {0, 0, 0.5, EXTENT, N, N};
  nl_noise_fractal_grid(b, &o, &w, out);
}

static void g_stb3(const void *ctx, double *out)
{
  (void)ctx;
  float dx = (float)(EXTENT / N);
  for (int r = 0; r < N; r++)
    for (int c = 0; c < N; c++)
      out[(size_t)r * N + c] = stb_perlin_noise3((c + 0.5f) * dx, (r + 0.5f) * dx, 0.5f, 0, 0, 0);
}

static void g_stbfbm(const void *ctx, double *out)
{
  (void)ctx;
  float dx = (float)(EXTENT / N);
  for (int r = 0; r < N; r++)
    for (int c = 0; c < N; c++)
      out[(size_t)r * N + c] = stb_perlin_fbm_noise3((c + 0.5f) * dx, (r + 0.5f) * dx, 0.5f, 2.0f, 0.5f, 4);
}

/* Sparse rows: 0.7 lattice cells per sample. */
static const double SPARSE_DX = 0.7, SPARSE_X0 = 0.35;

static void g_noise3_sparse(const void *ctx, double *out)
{
  double dy = EXTENT / N;
  for (int r = 0; r < N; r++)
    nl_noise_perm3_row(ctx, SPARSE_X0, SPARSE_DX, (r + 0.5) * dy, 0.5, (size_t)N,
                       out + (size_t)r * N);
}

static void g_stb3_sparse(const void *ctx, double *out)
{
  (void)ctx;
  double dy = EXTENT / N;
  for (int r = 0; r < N; r++)
    for (int c = 0; c < N; c++) {
      float x = (float)(SPARSE_X0 + c * SPARSE_DX), y = (float)((r + 0.5) * dy);
      out[(size_t)r * N + c] = stb_perlin_noise3(x, y, 0.5f, 0, 0, 0);
    }
}

static double *rx, *ry, *rz;
static void g_stb3_points(const void *ctx, double *out)
{
  (void)ctx;
  for (size_t k = 0; k < (size_t)N * N; k++)
    out[k] = stb_perlin_noise3((float)rx[k], (float)ry[k], (float)rz[k], 0, 0, 0);
}

static void g_noise2_points(const void *ctx, double *out)
{
  nl_noise_grad2_points(ctx, rx, ry, (size_t)N * N, out);
}

static void g_noise3_points(const void *ctx, double *out)
{
  nl_noise_perm3_points(ctx, rx, ry, rz, (size_t)N * N, out);
}

/* Wavelet noise (Cook and DeRose 2005) from a 256^2 2D tile, the same grid:
 * nl_wavelet_row adds into the row, so each row starts at 0. */
static void g_wavelet(const void *ctx, double *out)
{
  double dx = EXTENT / N;
  memset(out, 0, (size_t)N * N * sizeof *out);
  for (int r = 0; r < N; r++) nl_wavelet_row(ctx, 0.5 * dx, dx, (r + 0.5) * dx, 0, (size_t)N, 1.0, out + (size_t)r * N);
}

/* F1..F4 rows: the output holds 4 N^2 doubles, F[k*4 + i] per row. */
static void g_cellular(const void *ctx, double *out)
{
  double dx = EXTENT / N;
  for (int r = 0; r < N; r++)
    nl_cellular_row(ctx, 0.5 * dx, dx, (r + 0.5) * dx, 0.5, (size_t)N, 4, out + 4 * (size_t)r * N);
}

typedef struct { double rate, cpu_ms, wall_ms; } timing;
static volatile double sink;

/* One round of a kernel: repeated for at least 0.1 s of CPU time; the
 * fastest round is kept. The rate is per CPU second. */
static void round_of(void (*f)(const void *, double *), const void *ctx, double *out, timing *best)
{
  size_t npoints = (size_t)N * N, iters = 0;
  double c0 = nl_bench_cpu_now(), w0 = nl_time_now(), c, w;
  do { f(ctx, out); sink = out[iters % npoints]; iters++; c = nl_bench_cpu_now() - c0; } while (c < 0.1);
  w = nl_time_now() - w0;
  double rate = (double)iters * (double)npoints / c / 1e6;
  if (rate > best->rate) { best->rate = rate; best->cpu_ms = 1e3 * c / (double)iters; best->wall_ms = 1e3 * w / (double)iters; }
}



/* ---- threads: fbm6 on a 4096^2 grid, 1 thread and 2 ----------------------
 *
 * nl_noise_fractal_grid_threads with 1 and 2 threads, alternately, best
 * wall time of 3 each (a thread's CPU time would not show the split), on
 * the processors the program was given before it pinned itself (all, or
 * taskset's list: under taskset -c 1 the two threads share one), and
 * whether the two grids have the same bytes. One line, after the table. */
static void threads_figure(const cpu_set_t *given, int tsv)
{
  enum { TN = 4096, TREPS = 3 };
  cpu_set_t pinned;
  sched_getaffinity(0, sizeof pinned, &pinned);
  sched_setaffinity(0, sizeof *given, given);
  nl_noise_perm3 p;
  nl_noise_perm3_reference(&p);
  nl_noise_basis b = nl_noise_basis_perm3(&p);
  nl_noise_octaves o = nl_noise_octaves_fbm(6, 0.5, 2.0);
  nl_noise_window w = {0, 0, 0.5, EXTENT, TN, TN};
  size_t n = (size_t)TN * TN;
  double *g[2] = {nl_xmalloc(n * sizeof(double)), nl_xmalloc(n * sizeof(double))};
  double best[2] = {1e300, 1e300};
  for (int r = 0; r < TREPS; r++)
    for (int t = 0; t < 2; t++) {
      double w0 = nl_time_now();
      nl_noise_fractal_grid_threads(&b, &o, &w, t + 1, g[t]);
      double dt = nl_time_now() - w0;
      best[t] = dt < best[t] ? dt : best[t];
    }
  char load[128];
  nl_bench_loadavg(load, sizeof load);
  printf("%sfbm6 4096^2 grid, 1 thread / 2 threads: %.1f / %.1f ms wall, %.2fx, same bytes: %s"
         " (%d processors allowed, load %s)\n", tsv ? "# " : "", 1e3 * best[0], 1e3 * best[1],
         best[0] / best[1], memcmp(g[0], g[1], n * sizeof(double)) ? "NO" : "yes", CPU_COUNT(given),
         load);
  free(g[0]);
  free(g[1]);
  sched_setaffinity(0, sizeof pinned, &pinned);
}

int main(int argc, char **argv)
{
  int tsv = 0;
  for (int a = 1; a < argc; a++) {
    if (strcmp(argv[a], "--size") == 0 && a + 1 < argc) N = atoi(argv[++a]);
    else if (strcmp(argv[a], "--tsv") == 0) tsv = 1;
    else { fprintf(stderr, "usage: bench_noise [--size N] [--tsv]\n"); return 2; }
  }
  if (N < 16 || N > 8192) { fprintf(stderr, "bench_noise: --size must be in [16, 8192]\n"); return 2; }
  char where[64], load0[128], load1[128];
  cpu_set_t given;   /* before the pin: the threads figure's processors */
  sched_getaffinity(0, sizeof given, &given);
  nl_bench_pin(where, sizeof where);
  nl_bench_loadavg(load0, sizeof load0);
  double *out = nl_xmalloc(4 * (size_t)N * N * sizeof *out);   /* 4: cellular's F1..F4 */
  rx = nl_xmalloc((size_t)N * N * sizeof *rx);
  ry = nl_xmalloc((size_t)N * N * sizeof *ry);
  rz = nl_xmalloc((size_t)N * N * sizeof *rz);
  srand(1);
  for (size_t k = 0; k < (size_t)N * N; k++) {
    rx[k] = EXTENT * rand() / RAND_MAX; ry[k] = EXTENT * rand() / RAND_MAX; rz[k] = EXTENT * rand() / RAND_MAX;
  }
  nl_noise_grad2 *t = nl_noise_grad2_alloc(512);
  nl_noise_grad2_seed(t, 1);
  nl_noise_perm3 p;
  nl_noise_perm3_reference(&p);
  nl_noise_basis b2 = nl_noise_basis_grad2(t), b3 = nl_noise_basis_perm3(&p);
  nl_wavelet_tile *wt = nl_wavelet_tile_alloc(2, 256);
  nl_wavelet_tile_seed(wt, 1);
  nl_cellular *cell;
  nl_error err;
  if (nl_cellular_alloc(4.0, 50, NL_COUNT_INVERSE_CDF, 1, &cell, &err)) {
    fprintf(stderr, "bench_noise: %s\n", err.msg);
    return 1;
  }

  /* fbm: the peer of vs_stb: 1 stb's fBm; 0 and 2 stb_perlin_noise3 on the
   * grid, 3 on the sparse rows' samples, 4 on the random points */
  struct { const char *name, *label; void (*f)(const void *, double *); const void *ctx; int fbm; timing tm; } k[] = {
    {"noise3_row", "nl_noise_perm3_row (improved 3D)", g_noise3, &p, 0, {0, 0, 0}},
    {"noise3_row_sparse", "nl_noise_perm3_row, 0.7 cells/sample", g_noise3_sparse, &p, 3,
     {0, 0, 0}},
    {"noise3_points", "nl_noise_perm3_points, random", g_noise3_points, &p, 4, {0, 0, 0}},
    {"noise2_row", "nl_noise_grad2_row (2D table, M=512)", g_noise2, t, 0, {0, 0, 0}},
    {"noise2_points", "nl_noise_grad2_points, random", g_noise2_points, t, 0, {0, 0, 0}},
    {"fbm4_3d_row", "fbm 4 oct, improved 3D", g_fbm, &b3, 1, {0, 0, 0}},
    {"fbm4_2d_row", "fbm 4 oct, 2D table", g_fbm, &b2, 1, {0, 0, 0}},
    {"cellular_row", "nl_cellular_row (F1..F4, lambda=4)", g_cellular, cell, 2, {0, 0, 0}},
    {"wavelet_row", "nl_wavelet_row (2D tile, 256^2)", g_wavelet, wt, 2, {0, 0, 0}},
  };
  /* Rounds over all the kernels, stb's among them, so that each meets the
   * same spells of a shared machine; the fastest round of each counts. */
  timing stb = {0, 0, 0}, stbf = {0, 0, 0}, stbs = {0, 0, 0}, stbp = {0, 0, 0};
  for (int r = 0; r < ROUNDS; r++) {
    round_of(g_stb3, NULL, out, &stb);
    round_of(g_stbfbm, NULL, out, &stbf);
    round_of(g_stb3_sparse, NULL, out, &stbs);
    round_of(g_stb3_points, NULL, out, &stbp);
    for (size_t i = 0; i < sizeof k / sizeof *k; i++) round_of(k[i].f, k[i].ctx, out, &k[i].tm);
  }
  int nk = (int)(sizeof k / sizeof *k);
  const timing *peer[] = {&stb, &stbf, &stb, &stbs, &stbp};   /* by the field fbm */
  nl_bench_loadavg(load1, sizeof load1);
  const char *level = nl_noise_simd_name(nl_noise_simd_get());
  if (tsv) {
    printf("# bench_noise: %d x %d grid over [0,%g)^2, single thread, %s, best of %d rounds, noise kernels: %s\n",
           N, N, EXTENT, where, (int)ROUNDS, level);
    printf("# loadavg before: %s\n# loadavg after: %s\n", load0, load1);
    printf("# stb_perlin_noise3 %.1f Msamples/s, stb_perlin_fbm_noise3 (4 oct) %.1f Msamples/s\n", stb.rate, stbf.rate);
    printf("# stb_perlin_noise3 on the sparse rows' samples %.1f Msamples/s, on the random"
           " points %.1f\n", stbs.rate, stbp.rate);
    printf("kernel\tmsamples_per_s\tcpu_ms\twall_ms\tvs_stb\n");
    for (int i = 0; i < nk; i++)
      printf("%s\t%.1f\t%.2f\t%.2f\t%.2f\n", k[i].name, k[i].tm.rate, k[i].tm.cpu_ms, k[i].tm.wall_ms,
             k[i].tm.rate / peer[k[i].fbm]->rate);
  } else {
    printf("# %d x %d grid over [0,%g)^2, single thread (%s), Msamples per CPU second (best of %d rounds), kernels: %s\n",
           N, N, EXTENT, where, (int)ROUNDS, level);
    printf("# load average: %s (before), %s (after)\n", load0, load1);
    printf("%-34s %10s %10s %10s %8s\n", "noise", "Msample/s", "cpu ms", "wall ms", "vs stb");
    /* each peer's line above the rows compared with it (scripts/noiselab bench reads them so) */
    static const char *peer_name[] = {"stb_perlin_noise3", "stb_perlin_fbm_noise3 (4 oct)",
                                      "stb_perlin_noise3", "stb_perlin_noise3, same samples",
                                      "stb_perlin_noise3, same points"};
    for (int i = 0; i < nk; i++) {
      const timing *pe = peer[k[i].fbm];
      if (i == 0 || pe != peer[k[i - 1].fbm])
        printf("%-34s %10.1f %10.2f %10.2f %8s\n", peer_name[k[i].fbm], pe->rate, pe->cpu_ms,
               pe->wall_ms, "1.00");
      printf("%-34s %10.1f %10.2f %10.2f %8.2f\n", k[i].label, k[i].tm.rate, k[i].tm.cpu_ms, k[i].tm.wall_ms,
             k[i].tm.rate / pe->rate);
    }
  }
  threads_figure(&given, tsv);
  nl_noise_grad2_free(t);
  nl_wavelet_tile_free(wt);
  nl_cellular_free(cell);
  free(out); free(rx); free(ry); free(rz);
  return 0;
}
