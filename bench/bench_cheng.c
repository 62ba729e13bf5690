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
 *     CPU time, propagation and the per-temperature resums included), for
 *     the plain (cloud) texture and again for marble, whose control value
 *     c = (1 + sin(pi V)) / 2 costs a sine per point a move touches;
 *   - CPU time of one full 4-level optimisation (problem set-up included),
 *     best and median of `reps` runs on seeds 1..reps, and its wall time;
 *   - moves per level, with per-level rates from the levels' wall times;
 *   - raw incremental move + undo pairs per CPU second at level 1 and 4;
 *   - CPU seconds per solution-pool run (C5's work: E_R over every octave,
 *     annealed on the low entries, then the cold tail; nl_cheng_pool.c),
 *     from the optimised table of seed 1, for cloud and for marble.
 * Targets: >= 2.5 M moves/s, a full optimisation <= 0.25 s CPU.
 *
 *   build/bench/bench_cheng [--reps N] [--grid G] [--stat ks|chisq|kuiper] [--tsv]
 *   build/bench/bench_cheng --dump quick|full
 *
 * --tsv: '#' lines (setting, pinning, load), then a header and one line:
 * bench (cheng_<stat>, cheng_<stat>_marble), moves_per_s (per CPU second of
 * nl_cheng_optimise), cpu_s_per_opt (median CPU seconds of set-up +
 * optimisation), one line each; then cheng_<stat>_pool and
 * cheng_<stat>_pool_marble with moves_per_s NA and cpu_s_per_opt the CPU
 * seconds of one pool run (the mean over POOL_RUNS runs).
 *
 * --dump: the bit-identity record of the annealer (a speed change must not
 * move it): for each configuration the moves, accepts, temperatures, T0,
 * T_end and E of every level, the final E terms, the E returned by a random
 * move/undo/resum sequence on every level, and the final angles (some in
 * hex, all through a hash). quick: 144 short schedules (two patterns x three
 * statistics x four textures x six variants: literal formulas, gains as
 * variables, no propagation, other F/f1/a1/M/weights); full: six thesis-scale
 * optimisations. Public API only, so this file built against another
 * version of the library dumps that version (compare the md5 of the output).
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

static void dump_run(const char *tag, nl_cheng_config c, const nl_cheng_pattern *pat, unsigned long seed)
{
  nl_error err;
  nl_noise_grad2 *g = nl_noise_grad2_alloc(c.m);
  nl_noise_grad2_seed(g, seed);
  nl_cheng_problem *p = nl_cheng_problem_alloc(&c, pat, g, &err);
  if (!p) { printf("%s: %s\n", tag, err.msg); nl_noise_grad2_free(g); return; }
  nl_cheng_level_stats st[NL_CHENG_MAX_OCTAVES];
  nl_cheng_optimise(p, seed, st);
  printf("%s seed %lu\n", tag, seed);
  for (int L = 0; L < c.octaves; L++)
    printf("  L%d nv %zu moves %ld acc %ld temps %d t0 %a tend %a es %a eb %a\n", st[L].level, st[L].n_vars,
           st[L].moves, st[L].accepted, st[L].temps, st[L].t0, st[L].t_end, st[L].e_start, st[L].e_best);
  double es, ec, e = nl_cheng_energy(p, &es, &ec);
  printf("  E %a %a %a\n", e, es, ec);
  gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(r, seed + 7);
  for (int L = 1; L <= c.octaves; L++) {   /* moves, undos and resums on every level */
    nl_cheng_set_level(p, L);
    size_t nv;
    const size_t *v = nl_cheng_vars(p, &nv);
    double acc = 0;
    unsigned long h = 0;
    for (int i = 0; i < 300 && nv; i++) {
      size_t k = v[gsl_rng_uniform_int(r, nv)];
      double th = k < c.m ? NL_TWO_PI * gsl_rng_uniform(r) : 2.0 * gsl_rng_uniform(r) - 1.0;
      double em = nl_cheng_move(p, k, th);
      unsigned long b;
      memcpy(&b, &em, sizeof b);
      h = h * 31 + b;
      if (gsl_rng_uniform(r) < 0.5) nl_cheng_undo(p);
      if (i % 50 == 0) nl_cheng_resum(p);
      acc += em;
    }
    e = nl_cheng_energy(p, &es, &ec);
    printf("  seq L%d %a h=%016lx E %a %a %a\n", L, acc, h, e, es, ec);
  }
  gsl_rng_free(r);
  unsigned long h = 1469598103934665603UL;   /* FNV-1a of every angle's bytes */
  for (size_t k = 0; k < g->m; k++) {
    unsigned char b[sizeof(double)];
    memcpy(b, &g->angle[k], sizeof b);
    for (size_t i = 0; i < sizeof b; i++) { h ^= b[i]; h *= 1099511628211UL; }
    if (k < 8 || k % 61 == 0) printf(" %a", g->angle[k]);
  }
  printf(" fnv=%016lx\n", h);
  nl_cheng_problem_free(p);
  nl_noise_grad2_free(g);
}

static int dump(int full)
{
  nl_error err;
  const char *shapes[] = {"flower", "x", NULL};
  for (int sh = 0; shapes[sh] && (!full || sh == 0); sh++) {
    nl_image *im = nl_study_cheng_shape(shapes[sh], full ? 128 : 64);
    nl_cheng_pattern *pat;
    if (nl_study_cheng_pattern_from_image(im, full ? 64 : sh ? 16 : 24, &pat, &err)) {
      fprintf(stderr, "bench_cheng: %s\n", err.msg);
      return 1;
    }
    nl_image_free(im);
    if (full) {
      for (int con = 0; con < 4; con++) {
        nl_cheng_config c = nl_cheng_config_default();
        c.con = (nl_cheng_con)con;
        dump_run("full", c, pat, 1 + (unsigned long)con);
      }
      nl_cheng_config c = nl_cheng_config_default();
      c.stat = NL_CHENG_STAT_CHISQ;
      dump_run("full-chisq", c, pat, 11);
      c = nl_cheng_config_default();
      c.stat = NL_CHENG_STAT_KUIPER;
      dump_run("full-kuiper", c, pat, 12);
    }
    for (int stat = 0; stat < 3 && !full; stat++)
      for (int con = 0; con < 4; con++)
        for (int var = 0; var < 6; var++) {
          nl_cheng_config c = nl_cheng_config_default();
          c.stat = (nl_cheng_stat)stat;
          c.con = (nl_cheng_con)con;
          c.sched.n_temps = 12; c.sched.moves_per_var = 3; c.sched.stall = 3;
          if (var == 1) c.literal = 1;
          if (var == 2) c.amp_vary = 1;
          if (var == 3) c.propagate = 0;
          if (var == 4) { c.octaves = 3; c.f1 = 4; c.a1 = 2; c.m = 256; c.log_gain[1] = 0.3; }
          if (var == 5) { c.octaves = 5; c.f1 = 2; c.w1 = 0.5; c.w2 = 0.5; c.chisq_bins = 50; c.amp_vary = 1; c.literal = 1; }
          char tag[64];
          snprintf(tag, sizeof tag, "%s st%d con%d var%d", shapes[sh], stat, con, var);
          dump_run(tag, c, pat, 100 + (unsigned long)(stat * 31 + con * 7 + var));
        }
    nl_cheng_pattern_free(pat);
  }
  return 0;
}

/* `reps` whole optimisations on seeds 1..reps: moves per CPU second of
 * nl_cheng_optimise, and the sorted CPU and wall times of set-up +
 * optimisation; per-level moves and wall seconds summed into lvl_*. */
static double optimisations(nl_cheng_config c, const nl_cheng_pattern *pat, long reps, double *wall,
                            double *cpu, double *lvl_moves, double *lvl_s)
{
  nl_error err;
  long moves = 0;
  double opt_cpu = 0;
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
  return (double)moves / opt_cpu;
}

#define POOL_RUNS 4
#define POOL_KEEP 20

/* CPU seconds per pool run: the table optimised from seed 1, then a pool of
 * POOL_RUNS runs (N = POOL_KEEP kept states each) on one thread. */
static double pool_seconds(nl_cheng_config c, const nl_cheng_pattern *pat)
{
  nl_error err;
  nl_noise_grad2 *g = nl_noise_grad2_alloc(c.m);
  nl_noise_grad2_seed(g, nl_seed_replicate(1, 0));
  nl_cheng_problem *p = nl_cheng_problem_alloc(&c, pat, g, &err);
  if (!p) { fprintf(stderr, "bench_cheng: %s\n", err.msg); exit(1); }
  nl_cheng_optimise(p, nl_seed_replicate(1, 0), NULL);
  nl_cheng_problem_free(p);
  nl_cheng_pool_options o;
  nl_cheng_pool_options_default(&o);
  o.runs = POOL_RUNS;
  o.keep = POOL_KEEP;
  o.threads = 1;
  nl_cheng_pool *pool;
  double c0 = nl_bench_cpu_now();
  if (nl_cheng_pool_collect(g, &c, pat, &o, 1, &pool, &err)) {
    fprintf(stderr, "bench_cheng: %s\n", err.msg);
    exit(1);
  }
  double t = (nl_bench_cpu_now() - c0) / POOL_RUNS;
  nl_cheng_pool_free(pool);
  nl_noise_grad2_free(g);
  return t;
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
    } else if (!strcmp(argv[i], "--dump") && i + 1 < argc) {
      const char *what = argv[++i];
      if (strcmp(what, "quick") && strcmp(what, "full")) { fprintf(stderr, "bench_cheng: --dump quick|full, not '%s'\n", what); return 2; }
      return dump(!strcmp(what, "full"));
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
  double lvl_moves[NL_CHENG_MAX_OCTAVES] = {0}, lvl_s[NL_CHENG_MAX_OCTAVES] = {0};
  double rate = optimisations(c, pat, reps, wall, cpu, lvl_moves, lvl_s);
  /* Marble, separately: its control value's sine is most of its time. */
  nl_cheng_config cm = c;
  cm.con = NL_CHENG_CON_SIN;
  double *wall_m = malloc((size_t)reps * sizeof *wall_m);
  double *cpu_m = malloc((size_t)reps * sizeof *cpu_m);
  double lvl_mm[NL_CHENG_MAX_OCTAVES] = {0}, lvl_ms[NL_CHENG_MAX_OCTAVES] = {0};
  double rate_m = optimisations(cm, pat, reps, wall_m, cpu_m, lvl_mm, lvl_ms);
  double pool_s = pool_seconds(c, pat), pool_m = pool_seconds(cm, pat);
  if (tsv) {
    nl_bench_report(stdout, "end");
    printf("bench\tmoves_per_s\tcpu_s_per_opt\n");
    printf("cheng_%s\t%.0f\t%.4f\n", nl_cheng_stat_name(c.stat), rate, cpu[reps / 2]);
    printf("cheng_%s_marble\t%.0f\t%.4f\n", nl_cheng_stat_name(c.stat), rate_m, cpu_m[reps / 2]);
    printf("cheng_%s_pool\tNA\t%.4f\n", nl_cheng_stat_name(c.stat), pool_s);
    printf("cheng_%s_pool_marble\tNA\t%.4f\n", nl_cheng_stat_name(c.stat), pool_m);
    nl_cheng_pattern_free(pat);
    free(wall); free(cpu); free(wall_m); free(cpu_m);
    return 0;
  }
  for (int L = 0; L < c.octaves; L++)
    printf("  level %d: %.0f moves per optimisation, %.2f M moves per wall second\n", L + 1, lvl_moves[L] / reps,
           lvl_moves[L] / lvl_s[L] / 1e6);
  printf("annealing: %.2f M moves per CPU second overall (whole optimisations, cloud)\n",
         rate / 1e6);
  printf("full 4-level optimisation (set-up included): CPU time best %.3f s, median %.3f s over %ld runs "
         "(wall time: best %.3f s, median %.3f s)\n", cpu[0], cpu[reps / 2], reps, wall[0], wall[reps / 2]);
  printf("annealing, marble: %.2f M moves per CPU second; full optimisation CPU time best %.3f s, "
         "median %.3f s\n", rate_m / 1e6, cpu_m[0], cpu_m[reps / 2]);
  printf("solution pool (E_R, %d runs of N = %d): CPU time per run %.3f s cloud, %.3f s marble\n",
         POOL_RUNS, POOL_KEEP, pool_s, pool_m);

  nl_noise_grad2 *g = nl_noise_grad2_alloc(c.m);
  nl_noise_grad2_seed(g, 1);
  nl_cheng_problem *p = nl_cheng_problem_alloc(&c, pat, g, &err);
  printf("raw move + undo (uniform new angle): level 1 %.2f M pairs per CPU second, level 4 %.2f M\n",
         raw_moves_per_second(p, 1) / 1e6, raw_moves_per_second(p, c.octaves) / 1e6);
  nl_cheng_problem_free(p);
  nl_noise_grad2_free(g);
  nl_cheng_pattern_free(pat);
  free(wall); free(cpu); free(wall_m); free(cpu_m);
  nl_bench_report(stdout, "end");
  return 0;
}
