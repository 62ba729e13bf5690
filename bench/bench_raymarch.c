/* bench_raymarch - A2's smoke ball (Arnerin 2009 Table 5.1) at A2's fitted
 * scene (a = -5, f0 = 2, kappa = 120, terms = N + 1), one seed: plain and
 * bounded thread-CPU ms per render (best of `reps`), the time ratio beside
 * the evaluation ratio, and ns per sample with evaluations per sample, so
 * that the fixed per-sample cost and the cost of one evaluation can be
 * read off: a closing '#' line fits ns/sample =
 * fixed + per_eval * evals/sample over the rows, for each march (least
 * squares). Usage: bench_raymarch [size=128] [reps=3]. */
#define _GNU_SOURCE   /* sched_getaffinity in nl_bench.h */
#include "nl_bench.h"
#include "bounds/nl_bounds.h"

#include <stdio.h>
#include <stdlib.h>

int main(int argc, char **argv)
{
  int size = argc > 1 ? atoi(argv[1]) : 128, reps = argc > 2 ? atoi(argv[2]) : 3;
  if (size < 8 || reps < 1) { fprintf(stderr, "usage: bench_raymarch [size >= 8] [reps >= 1]\n"); return 2; }
  nl_noise_perm3 p;
  nl_noise_perm3_seed(&p, 1);
  nl_bounds_smoke s = nl_bounds_smoke_default();
  s.width = s.height = size;
  s.slope = -5; s.freq = 2; s.kappa = 120;
  const int N[] = {0, 1, 2, 5, 7, 10};
  double fx[2][6], fy[2][6];   /* evals/sample, ns/sample per march */
  nl_bench_report(stdout, "start");
  printf("N\tplain_ms\tbounded_ms\ttime_ratio\teval_ratio\tplain_ns_sample\tbounded_ns_sample\tplain_evals_sample\tbounded_evals_sample\n");
  for (int i = 0; i < 6; i++) {
    s.octaves = N[i] + 1;
    double best[2] = {1e30, 1e30};
    nl_bounds_smoke_pair t;
    for (int r = 0; r < reps; r++) {
      if (nl_bounds_smoke_render_pair(&p, s, NULL, NULL, &t, NULL)) return 1;
      for (int k = 0; k < 2; k++) best[k] = t.ms[k] < best[k] ? t.ms[k] : best[k];
    }
    double ns = 1e6 / (double)t.samples;
    printf("%d\t%.2f\t%.2f\t%.2f\t%.2f\t%.2f\t%.2f\t%.2f\t%.2f\n", N[i], best[0], best[1], best[0] / best[1],
           (double)t.evals[0] / (double)t.evals[1], best[0] * ns, best[1] * ns,
           (double)t.evals[0] / (double)t.samples, (double)t.evals[1] / (double)t.samples);
    for (int k = 0; k < 2; k++) { fx[k][i] = (double)t.evals[k] / (double)t.samples; fy[k][i] = best[k] * ns; }
  }
  for (int k = 0; k < 2; k++) {   /* least squares ns = fixed + per_eval * evals */
    double mx = 0, my = 0, sxy = 0, sxx = 0;
    for (int i = 0; i < 6; i++) { mx += fx[k][i] / 6; my += fy[k][i] / 6; }
    for (int i = 0; i < 6; i++) { sxy += (fx[k][i] - mx) * (fy[k][i] - my); sxx += (fx[k][i] - mx) * (fx[k][i] - mx); }
    double e = sxy / sxx;
    printf("# %s: ns/sample = %.2f fixed + %.2f per evaluation (least squares over the rows)\n",
           k ? "bounded" : "plain", my - e * mx, e);
  }
  nl_bench_report(stdout, "end");
  return 0;
}
