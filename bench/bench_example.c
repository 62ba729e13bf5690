/* bench_example - speed of noise by example (issue targets: analysis of a
 * 512 x 512 RGB exemplar < 0.5 s, synthesis of 1024 x 1024 RGB < 1 s, on
 * one core) and the wavelet-noise evaluation rate. Best of 5 runs each. */
#define _GNU_SOURCE   /* sched_getaffinity in nl_bench.h */
#include "nl_bench.h"
#include "byexample/nl_byexample.h"

#include <stdio.h>
#include <stdlib.h>

int main(void)
{
  nl_image *ex = nl_byexample_exemplar("granite", 512, 1), *out;
  nl_byexample_params p;
  double best_a = 1e30, best_s = 1e30, best_w = 1e30, best_cold = 0, cpu_a = 0, cpu_s = 0;
  nl_bench_report(stdout, "start");
  /* First analysis includes measuring sigma_N^2 (4 tiles), as a fresh
   * `noiselab example analyse` process does. */
  double t0 = nl_time_now();
  nl_byexample_analyse(ex, NULL, &p, NULL);
  best_cold = nl_time_now() - t0;
  for (int i = 0; i < 5; i++) {
    t0 = nl_time_now();
    double c0 = nl_bench_cpu_now();
    nl_byexample_analyse(ex, NULL, &p, NULL);
    double t = nl_time_now() - t0, c = nl_bench_cpu_now() - c0;
    if (c < cpu_a || i == 0) { best_a = t; cpu_a = c; }   /* the fastest in CPU time */
    t0 = nl_time_now();
    c0 = nl_bench_cpu_now();
    nl_byexample_synthesize(&p, 1024, 1024, (unsigned long)i + 1, NULL, &out, NULL);
    t = nl_time_now() - t0;
    c = nl_bench_cpu_now() - c0;
    if (c < cpu_s || i == 0) { best_s = t; cpu_s = c; }
    nl_image_free(out);
  }
  nl_wavelet_tile *tile = nl_wavelet_tile_alloc(2, NL_BYEXAMPLE_TILE);
  nl_wavelet_tile_seed(tile, 1);
  size_t n = 1 << 20;
  double *row = calloc(n, sizeof *row), sink = 0;
  for (int i = 0; i < 5; i++) {
    t0 = nl_bench_cpu_now();
    for (int y = 0; y < 16; y++) nl_wavelet_row(tile, 0.37, 0.73, y * 1.3, 0, n / 16, 1.0, row + (size_t)y * (n / 16));
    double t = nl_bench_cpu_now() - t0;
    if (t < best_w) best_w = t;
    sink += row[12345];
  }
  double best_p = 1e30;
  for (int i = 0; i < 5; i++) {
    t0 = nl_bench_cpu_now();
    for (size_t k = 0; k < n / 8; k++) sink += nl_wavelet_eval2(tile, 0.37 + k * 0.73, 1.3 * (double)(k & 63));
    double t = nl_bench_cpu_now() - t0;
    if (t < best_p) best_p = t;
  }
  printf("analysis 512x512 RGB:        %.3f s, CPU %.3f s (target < 0.5 s; first call incl. sigma_N^2: %.3f s)\n", best_a, cpu_a, best_cold);
  printf("synthesis 1024x1024 RGB:     %.3f s, CPU %.3f s (target < 1 s; %d bands x 3 channels)\n", best_s, cpu_s, p.nbands);
  printf("wavelet noise 2D, rows:      %.1f M samples/s (per CPU second)\n", n / best_w / 1e6);
  printf("wavelet noise 2D, points:    %.1f M samples/s (per CPU second)\n", (n / 8) / best_p / 1e6);
  printf("(checksum %g)\n", sink);
  nl_bench_report(stdout, "end");
  free(row);
  nl_wavelet_tile_free(tile);
  nl_image_free(ex);
  return 0;
}
