/* bench_cellular - cellular F1..F4 evaluations per second beside Perlin's
 * improved noise on the same points.
 *
 * Single thread, a N x N grid over [0, 16)^2 on the plane z = 0.5 (lambda = 4:
 * about 4 feature points per unit cube), evaluated row by row, repeated until
 * 0.5 s of the thread's CPU time has passed; best of 3; pinned to the core it
 * starts on (unless given one). Also: F1..F4 at random points (no row reuse,
 * 27 cubes generated per point) and one GCTBF row (F2 - F1 - F1F1).
 *
 *   build/bench/bench_cellular [--size N]
 */
#define _GNU_SOURCE   /* sched_getaffinity in nl_bench.h */
#include "cellular/nl_cellular.h"
#include "noise/nl_noise.h"

#include "nl_bench.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int N = 512;
static const double EXTENT = 16.0;
static double *rx, *ry, *rz;


static void g_noise3(const void *ctx, double *out)
{
  double dx = EXTENT / N;
  for (int r = 0; r < N; r++)
    nl_noise_perm3_row(ctx, 0.5 * dx, dx, (r + 0.5) * dx, 0.5, (size_t)N, out + (size_t)r * N);
}

static void g_noise3_random(const void *ctx, double *out)
{
  for (size_t k = 0; k < (size_t)N * N; k++) out[k] = nl_noise_perm3_eval(ctx, rx[k], ry[k], rz[k]);
}

/* out holds 4 N^2 doubles. */
static void g_cell_rows(const void *ctx, double *out)
{
  double dx = EXTENT / N;
  for (int r = 0; r < N; r++)
    nl_cellular_row(ctx, 0.5 * dx, dx, (r + 0.5) * dx, 0.5, (size_t)N, 4, out + 4 * (size_t)r * N);
}

static void g_cell_random(const void *ctx, double *out)
{
  for (size_t k = 0; k < (size_t)N * N; k++) {
    double p[3] = {rx[k], ry[k], rz[k]};
    nl_cellular_eval(ctx, p, 4, out + 4 * k);
  }
}

static void g_gctbf(const void *ctx, double *out)
{
  const nl_cellular_gctbf_basis *b = ctx;
  double dx = EXTENT / N;
  for (int r = 0; r < N; r++)
    nl_cellular_gctbf_row(b->cell, &b->g, 0.5 * dx, dx, (r + 0.5) * dx, 0.5, (size_t)N, out + (size_t)r * N);
}


int main(int argc, char **argv)
{
  if (argc == 3 && strcmp(argv[1], "--size") == 0) N = atoi(argv[2]);
  if (N < 16 || N > 4096) { fprintf(stderr, "bench_cellular: --size must be in [16, 4096]\n"); return 2; }
  size_t np = (size_t)N * N;
  double *out = nl_xmalloc(4 * np * sizeof *out);
  rx = nl_xmalloc(np * sizeof *rx); ry = nl_xmalloc(np * sizeof *ry); rz = nl_xmalloc(np * sizeof *rz);
  srand(1);
  for (size_t k = 0; k < np; k++) {
    rx[k] = EXTENT * rand() / RAND_MAX; ry[k] = EXTENT * rand() / RAND_MAX; rz[k] = EXTENT * rand() / RAND_MAX;
  }
  nl_noise_perm3 p;
  nl_noise_perm3_reference(&p);
  nl_cellular *ci, *cc;
  if (nl_cellular_alloc(4.0, 50, NL_COUNT_INVERSE_CDF, 1, &ci, NULL) ||
      nl_cellular_alloc(4.0, 50, NL_COUNT_CLOSEST, 1, &cc, NULL)) return 1;
  nl_cellular_gctbf_basis gb = {ci, {0}};
  nl_cellular_gctbf_parse("F2 - F1 - F1F1", &gb.g, NULL);

  char where[64];
  nl_bench_pin(where, sizeof where);
  nl_bench_report(stdout, "start");
  double n3 = nl_bench_rate(g_noise3, &p, out, (size_t)N * N), n3r = nl_bench_rate(g_noise3_random, &p, out, (size_t)N * N);
  double ri = nl_bench_rate(g_cell_rows, ci, out, (size_t)N * N), rc = nl_bench_rate(g_cell_rows, cc, out, (size_t)N * N);
  double pr = nl_bench_rate(g_cell_random, ci, out, (size_t)N * N), gr = nl_bench_rate(g_gctbf, &gb, out, (size_t)N * N);
  printf("# %d x %d grid over [0,%g)^2 at z = 0.5 (random points: [0,%g)^3), single thread (%s),\n"
         "# Mpoints per CPU second (best of 3); cellular: lambda = 4, M = 50, all of F1..F4 per point\n",
         N, N, EXTENT, EXTENT, where);
  printf("%-40s %10s %10s\n", "function", "Mpoint/s", "vs noise3");
  printf("%-40s %10.2f %10s\n", "nl_noise_perm3_row (improved 3D)", n3, "1.000");
  printf("%-40s %10.2f %10.3f\n", "nl_cellular_row F1..F4 (inverse CDF)", ri, ri / n3);
  printf("%-40s %10.2f %10.3f\n", "nl_cellular_row F1..F4 (closest-p rule)", rc, rc / n3);
  printf("%-40s %10.2f %10.3f\n", "nl_cellular_gctbf_row F2 - F1 - F1F1", gr, gr / n3);
  printf("%-40s %10.2f %10s\n", "nl_noise_perm3_eval random points", n3r, "1.000");
  printf("%-40s %10.2f %10.3f\n", "nl_cellular_eval F1..F4 random points", pr, pr / n3r);
  nl_bench_report(stdout, "end");
  nl_cellular_free(ci); nl_cellular_free(cc);
  free(out); free(rx); free(ry); free(rz);
  return 0;
}
