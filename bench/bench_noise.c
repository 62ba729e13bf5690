/* bench_noise - samples per second of our noises against stb_perlin.
 *
 * Single thread, a 1024 x 1024 grid over [0, 16)^2 (64 samples per lattice
 * cell at the base frequency) on the plane z = 0.5, repeated until at least
 * 0.5 s has passed; the best of 3 repetitions is reported. stb_perlin_noise3
 * and stb_perlin_fbm_noise3 (Debian's libstb-dev) run on the same points in
 * the same run, so the ratio is machine-independent to first order.
 * Also reported: random, incoherent points (no row reuse) for our 2D noise.
 *
 *   build/bench/bench_noise [--size N]
 */
#include "noise/nl_noise.h"
#include "base/nl_base.h"
#include "nl_bench.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wsign-compare"
#define STB_PERLIN_IMPLEMENTATION
#include <stb/stb_perlin.h>
#pragma GCC diagnostic pop

static int N = 1024;
static const double EXTENT = 16.0;


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

static double *rx, *ry;
static void g_noise2_random(const void *ctx, double *out)
{
  for (size_t k = 0; k < (size_t)N * N; k++) out[k] = nl_noise_grad2_eval(ctx, rx[k], ry[k]);
}


int main(int argc, char **argv)
{
  if (argc == 3 && strcmp(argv[1], "--size") == 0) N = atoi(argv[2]);
  if (N < 16 || N > 8192) { fprintf(stderr, "bench_noise: --size must be in [16, 8192]\n"); return 2; }
  double *out = nl_xmalloc((size_t)N * N * sizeof *out);
  rx = nl_xmalloc((size_t)N * N * sizeof *rx);
  ry = nl_xmalloc((size_t)N * N * sizeof *ry);
  srand(1);
  for (size_t k = 0; k < (size_t)N * N; k++) { rx[k] = EXTENT * rand() / RAND_MAX; ry[k] = EXTENT * rand() / RAND_MAX; }
  nl_noise_grad2 *t = nl_noise_grad2_alloc(512);
  nl_noise_grad2_seed(t, 1);
  nl_noise_perm3 p;
  nl_noise_perm3_reference(&p);
  nl_noise_basis b2 = nl_noise_basis_grad2(t), b3 = nl_noise_basis_perm3(&p);

  double stb = nl_bench_rate(g_stb3, NULL, out, (size_t)N * N), stbf = nl_bench_rate(g_stbfbm, NULL, out, (size_t)N * N);
  double n2 = nl_bench_rate(g_noise2, t, out, (size_t)N * N), n3 = nl_bench_rate(g_noise3, &p, out, (size_t)N * N);
  double f2 = nl_bench_rate(g_fbm, &b2, out, (size_t)N * N), f3 = nl_bench_rate(g_fbm, &b3, out, (size_t)N * N);
  double nr = nl_bench_rate(g_noise2_random, t, out, (size_t)N * N);
  printf("# %d x %d grid over [0,%g)^2, single thread, Msamples/s (best of 3)\n", N, N, EXTENT);
  printf("%-34s %10s %10s\n", "noise", "Msample/s", "vs stb");
  printf("%-34s %10.1f %10s\n", "stb_perlin_noise3", stb, "1.00");
  printf("%-34s %10.1f %10.2f\n", "nl_noise_grad2_row (2D table, M=512)", n2, n2 / stb);
  printf("%-34s %10.1f %10.2f\n", "nl_noise_perm3_row (improved 3D)", n3, n3 / stb);
  printf("%-34s %10.1f %10.2f\n", "nl_noise_grad2_eval random points", nr, nr / stb);
  printf("%-34s %10.1f %10s\n", "stb_perlin_fbm_noise3 (4 oct)", stbf, "1.00");
  printf("%-34s %10.1f %10.2f\n", "fbm 4 oct, 2D table", f2, f2 / stbf);
  printf("%-34s %10.1f %10.2f\n", "fbm 4 oct, improved 3D", f3, f3 / stbf);
  nl_noise_grad2_free(t);
  free(out); free(rx); free(ry);
  return 0;
}
