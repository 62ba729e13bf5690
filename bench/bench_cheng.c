/* bench_cheng - speed of the controllable-noise optimiser (Cheng 2009).
 *
 * Thesis setting: M = 512 angles, F = 4 octaves, f1 = 8, a1 = 4, KS term,
 * w1 = 0.995, w2 = 0.005, the flower pattern (built in, no file) on a 64 x 64
 * control grid, default schedule (nl_cheng.h). Single thread, pinned to the
 * core it starts on (unless given one). Times are CPU time of the thread
 * (the machine is shared: wall time measures the other work too), and the
 * load average is printed before and after. Reports
 *   - annealing moves per CPU second over whole optimisations (move,
 *     Metropolis test, undo when rejected: the real mix; nl_cheng_optimise's
 *     CPU time, propagation and the per-temperature resums included);
 *   - CPU time of one full 4-level optimisation (problem set-up included),
 *     best and median of `reps` runs on seeds 1..reps, and its wall time;
 *   - moves per level, with per-level rates from the levels' wall times;
 *   - raw incremental move + undo pairs per CPU second at level 1 and 4.
 * Targets (issue 17): >= 2.5 M moves/s, a full optimisation <= 0.25 s CPU.
 *
 *   build/bench/bench_cheng [--reps N] [--grid G] [--stat ks|chisq|kuiper] [--tsv]
 *
 * --tsv: '#' lines (setting, pinning, load), then a header and one line:
 * bench (cheng_<stat>), moves_per_s (per CPU second of nl_cheng_optimise),
 * cpu_s_per_opt (median CPU seconds of set-up + optimisation).
 */
#define _GNU_SOURCE   /* sched_getaffinity in nl_bench.h */
#include "nl_bench.h"
#include "study/nl_study_cheng.h"

#include <gsl/gsl_rng.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int cmp_double(const void *a, const void *b)
{
  double x = *(const double *)a, y = *(const double *)b;
  return (x > y) - (x < y);
}

/* Random move + undo pairs on the level's variables for ~0.3 s of CPU. */
static double raw_moves_per_second(nl_cheng_problem *p, int level)
{
  nl_cheng_set_level(p, level);
  size_t nv;
  const size_t *v = nl_cheng_vars(p, &nv);
  gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
  long n = 0;
  double t0 = nl_bench_cpu_now(), t;
  do {
    for (int i = 0; i < 10000; i++) {
      size_t k = v[gsl_rng_uniform_int(r, nv)];
      nl_cheng_move(p, k, NL_TWO_PI * gsl_rng_uniform(r));
      nl_cheng_undo(p);
    }
    n += 10000;
  } while ((t = nl_bench_cpu_now() - t0) < 0.3);
  gsl_rng_free(r);
  return (double)n / t;
}

int main(int argc, char **argv)
{
  long reps = 5, grid = 64;
  int tsv = 0;
  nl_cheng_config c = nl_cheng_config_default();
  nl_error err;
  for (int i = 1; i < argc; i++) {
    if (!strcmp(argv[i], "--reps") && i + 1 < argc) {
      if (nl_parse_long("--reps", argv[++i], 1, 1000, &reps, &err)) { fprintf(stderr, "bench_cheng: %s\n", err.msg); return 2; }
    } else if (!strcmp(argv[i], "--grid") && i + 1 < argc) {
      if (nl_parse_long("--grid", argv[++i], 2, 1024, &grid, &err)) { fprintf(stderr, "bench_cheng: %s\n", err.msg); return 2; }
    } else if (!strcmp(argv[i], "--stat") && i + 1 < argc) {
      if (nl_cheng_stat_parse(argv[++i], &c.stat, &err)) { fprintf(stderr, "bench_cheng: %s\n", err.msg); return 2; }
    } else if (!strcmp(argv[i], "--tsv")) {
      tsv = 1;
    } else { fprintf(stderr, "bench_cheng: unknown argument '%s'\n", argv[i]); return 2; }
  }
  nl_image *im = nl_study_cheng_shape("flower", 128);
  nl_cheng_pattern *pat;
  if (nl_study_cheng_pattern_from_image(im, (int)grid, &pat, &err)) { fprintf(stderr, "bench_cheng: %s\n", err.msg); return 1; }
  nl_image_free(im);
  char where[96];
  nl_bench_pin(where, sizeof where);
  printf("%sbench_cheng: M = %zu, F = %d, f1 = %g, a1 = %g, objective %s, %ld x %ld control grid (%zu points), "
         "schedule %d temps x %g moves/var, single thread (%s)\n", tsv ? "# " : "", c.m, c.octaves, c.f1, c.a1,
         nl_cheng_stat_name(c.stat), grid, grid, pat->n, c.sched.n_temps, c.sched.moves_per_var, where);

  nl_bench_report(stdout, "start");
  double *wall = malloc((size_t)reps * sizeof *wall), *cpu = malloc((size_t)reps * sizeof *cpu);
  long moves = 0;
  double opt_cpu = 0, lvl_moves[NL_CHENG_MAX_OCTAVES] = {0}, lvl_s[NL_CHENG_MAX_OCTAVES] = {0};
  for (long s = 0; s < reps; s++) {
    nl_noise_grad2 *g = nl_noise_grad2_alloc(c.m);
    nl_noise_grad2_seed(g, nl_seed_replicate(1, s));
    nl_cheng_level_stats st[NL_CHENG_MAX_OCTAVES];
    double t0 = nl_time_now(), c0 = nl_bench_cpu_now();
    nl_cheng_problem *p = nl_cheng_problem_alloc(&c, pat, g, &err);
    double c1 = nl_bench_cpu_now();
    nl_cheng_optimise(p, nl_seed_replicate(1, s), st);
    double c2 = nl_bench_cpu_now();
    wall[s] = nl_time_now() - t0;
    cpu[s] = c2 - c0;
    opt_cpu += c2 - c1;
    for (int L = 0; L < c.octaves; L++) {
      moves += st[L].moves;
      lvl_moves[L] += (double)st[L].moves;
      lvl_s[L] += st[L].seconds;
    }
    nl_cheng_problem_free(p);
    nl_noise_grad2_free(g);
  }
  qsort(wall, (size_t)reps, sizeof *wall, cmp_double);
  qsort(cpu, (size_t)reps, sizeof *cpu, cmp_double);
  double rate = (double)moves / opt_cpu;
  if (tsv) {
    nl_bench_report(stdout, "end");
    printf("bench\tmoves_per_s\tcpu_s_per_opt\n");
    printf("cheng_%s\t%.0f\t%.4f\n", nl_cheng_stat_name(c.stat), rate, cpu[reps / 2]);
    nl_cheng_pattern_free(pat);
    free(wall); free(cpu);
    return 0;
  }
  for (int L = 0; L < c.octaves; L++)
    printf("  level %d: %.0f moves per optimisation, %.2f M moves per wall second\n", L + 1, lvl_moves[L] / reps,
           lvl_moves[L] / lvl_s[L] / 1e6);
  printf("annealing: %.2f M moves per CPU second overall (%ld moves in %.2f CPU s of nl_cheng_optimise)\n",
         rate / 1e6, moves, opt_cpu);
  printf("full 4-level optimisation (set-up included): CPU time best %.3f s, median %.3f s over %ld runs "
         "(wall time: best %.3f s, median %.3f s)\n", cpu[0], cpu[reps / 2], reps, wall[0], wall[reps / 2]);

  nl_noise_grad2 *g = nl_noise_grad2_alloc(c.m);
  nl_noise_grad2_seed(g, 1);
  nl_cheng_problem *p = nl_cheng_problem_alloc(&c, pat, g, &err);
  printf("raw move + undo (uniform new angle): level 1 %.2f M pairs per CPU second, level 4 %.2f M\n",
         raw_moves_per_second(p, 1) / 1e6, raw_moves_per_second(p, c.octaves) / 1e6);
  nl_cheng_problem_free(p);
  nl_noise_grad2_free(g);
  nl_cheng_pattern_free(pat);
  free(wall); free(cpu);
  nl_bench_report(stdout, "end");
  return 0;
}
