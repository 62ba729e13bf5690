/* Simulated annealing of one level, propagation (eq. 3.13) and the
 * multi-level loop of sec. 3.4.2; the schedule is documented in nl_cheng.h. */
#include "cheng/nl_cheng_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define TRIAL_MOVES 200

static double propose(const nl_cheng_problem *p, gsl_rng *rng, size_t k, double sigma)
{
  if (k >= p->m) return nl_cheng__amp_propose(p, rng, k - p->m, sigma);   /* a gain (X6) */
  return nl_wrap_angle(p->g->angle[k] + sigma * (2.0 * gsl_rng_uniform(rng) - 1.0));
}

/* T0 so that an average uphill move of the widest step is accepted with
 * probability p0; trial moves are undone. */
static double initial_temperature(nl_cheng_problem *p, gsl_rng *rng, const size_t *vars,
                                  size_t nv, double p0)
{
  double sum = 0;
  int up = 0;
  for (int t = 0; t < TRIAL_MOVES; t++) {
    size_t k = vars[gsl_rng_uniform_int(rng, nv)];
    double e0 = p->e, de = nl_cheng_move(p, k, propose(p, rng, k, NL_PI)) - e0;
    nl_cheng_undo(p);
    if (de > 0) { sum += de; up++; }
  }
  double scale = fabs(p->e) > 0 ? fabs(p->e) : 1.0;
  return up ? sum / up / log(1.0 / p0) : 1e-12 * scale;
}

static void save_vars(const nl_cheng_problem *p, const size_t *vars, size_t nv, double *to)
{
  for (size_t q = 0; q < nv; q++) to[q] = nl_cheng__var_value(p, vars[q]);
}

/* Moves the variables back to a saved state, through the incremental path
 * so every structure follows. */
static void restore_vars(nl_cheng_problem *p, const size_t *vars, size_t nv, const double *from)
{
  for (size_t q = 0; q < nv; q++)
    if (nl_cheng__var_value(p, vars[q]) != from[q]) nl_cheng_move(p, vars[q], from[q]);
  nl_cheng_resum(p);
}

/* One temperature: moves_per_temp Metropolis moves; returns accepted moves. */
static long sweep(nl_cheng_problem *p, gsl_rng *rng, const size_t *vars, size_t nv, long moves,
                  double T, double sigma)
{
  long acc = 0;
  for (long m = 0; m < moves; m++) {
    size_t k = vars[gsl_rng_uniform_int(rng, nv)];
    double e0 = p->e, de = nl_cheng_move(p, k, propose(p, rng, k, sigma)) - e0;
    if (de <= 0 || gsl_rng_uniform(rng) < exp(-de / T)) acc++;
    else nl_cheng_undo(p);
  }
  return acc;
}

void nl_cheng_anneal(nl_cheng_problem *p, gsl_rng *rng, nl_cheng_level_stats *st)
{
  const nl_cheng_schedule *s = &p->c.sched;
  size_t nv;
  const size_t *vars = nl_cheng_vars(p, &nv);
  nl_cheng_level_stats z = {.level = p->level, .n_vars = nv, .e_start = p->e, .e_best = p->e};
  double t_start = nl_time_now();
  if (nv == 0) { if (st) *st = z; return; }
  double t0 = initial_temperature(p, rng, vars, nv, s->p0), T = t0;
  double alpha = pow(10.0, -s->t_decades / s->n_temps);
  long per_temp = (long)ceil(s->moves_per_var * (double)nv);
  double *best = nl_xmalloc(nv * sizeof *best), ebest = p->e;
  save_vars(p, vars, nv, best);
  int stall = 0;
  z.t0 = t0;
  for (z.temps = 0; z.temps < s->n_temps && stall < s->stall; z.temps++) {
    z.accepted += sweep(p, rng, vars, nv, per_temp, T, NL_PI * fmax(T / t0, 0.01));
    z.moves += per_temp;
    nl_cheng__resum_top(p);   /* E_Con's running sum back to an exact sum (nl_cheng_resum's result) */
    if (p->e < ebest - 1e-12 * fabs(ebest)) { ebest = p->e; save_vars(p, vars, nv, best); stall = 0; }
    else if (T < 1e-2 * t0) stall++;   /* only once the walk has cooled: hot phases rarely improve */
    T *= alpha;
  }
  restore_vars(p, vars, nv, best);
  z.t_end = T;
  z.e_best = p->e;
  z.seconds = nl_time_now() - t_start;
  if (st) *st = z;
  free(best);
}

void nl_cheng_propagate(nl_cheng_problem *p)
{
  int L = p->level;
  if (L < 2) return;
  long lmax = nl_cheng__lattice_max(p->freq[L - 1]);
  unsigned char *done = nl_xcalloc(p->m, 1);
  for (long J = 0; J <= lmax; J++)
    for (long I = 0; I <= lmax; I++) {
      size_t k = nl_noise_grad2_index(p->g, I, J);
      if (p->first_level[k] != L || done[k]) continue;
      /* eq. 3.13: the lattice point at half the frequency (f_l = 2 f_{l-1}). */
      size_t parent = nl_noise_grad2_index(p->g, I / 2, J / 2);
      nl_noise_grad2_set_angle(p->g, k, p->g->angle[parent]);
      done[k] = 1;
    }
  free(done);
  nl_cheng_set_level(p, L);
}

void nl_cheng_optimise(nl_cheng_problem *p, unsigned long seed, nl_cheng_level_stats *stats)
{
  gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(rng, nl_seed_stream(seed, "cheng.anneal", 0));
  for (int L = 1; L <= p->F; L++) {
    nl_cheng_set_level(p, L);
    if (p->c.propagate) nl_cheng_propagate(p);
    nl_cheng_anneal(p, rng, stats ? &stats[L - 1] : NULL);
  }
  gsl_rng_free(rng);
}
