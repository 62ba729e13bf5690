/* Simulated annealing: the schedule against callbacks (nl_cheng_sa_run, which
 * the 3D model runs too), one 2D level on it, propagation (eq. 3.13) and the
 * multi-level loop of sec. 3.4.2; the schedule is documented in nl_cheng.h. */
#include "cheng/nl_cheng_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define TRIAL_MOVES 200

/* ---- the schedule, against callbacks ----------------------------------- */

/* T0 so that an average uphill move of the widest step (sigma = pi) is
 * accepted with probability p0; trial moves are undone. */
static double initial_temperature(const nl_cheng_sa_ops *o, gsl_rng *rng, double p0)
{
  double sum = 0, e = o->energy(o->ctx);
  int up = 0;
  for (int t = 0; t < TRIAL_MOVES; t++) {
    double de = o->move(o->ctx, gsl_rng_uniform_int(rng, o->n_vars), NL_PI, rng) - e;
    o->undo(o->ctx);
    if (de > 0) { sum += de; up++; }
  }
  return up ? sum / up / log(1.0 / p0) : 1e-12 * (fabs(e) > 0 ? fabs(e) : 1.0);
}

void nl_cheng_sa_run(const nl_cheng_sa_ops *o, const nl_cheng_schedule *s, gsl_rng *rng,
                     nl_cheng_level_stats *st)
{
  size_t nv = o->n_vars;
  nl_cheng_level_stats z = {.level = 1, .n_vars = nv, .e_start = o->energy(o->ctx)};
  z.e_best = z.e_start;
  double t_start = nl_time_now();
  if (nv == 0) { if (st) *st = z; return; }
  double t0 = initial_temperature(o, rng, s->p0), T = t0;
  double alpha = pow(10.0, -s->t_decades / s->n_temps);
  long per_temp = (long)ceil(s->moves_per_var * (double)nv);
  double *best = nl_xmalloc(o->state_size * sizeof *best), ebest = o->energy(o->ctx);
  o->save(o->ctx, best);
  int stall = 0;
  z.t0 = t0;
  for (z.temps = 0; z.temps < s->n_temps && stall < s->stall; z.temps++) {
    double sigma = NL_PI * fmax(T / t0, 0.01);
    for (long m = 0; m < per_temp; m++) {
      double e0 = o->energy(o->ctx);
      double de = o->move(o->ctx, gsl_rng_uniform_int(rng, nv), sigma, rng) - e0;
      if (de <= 0 || gsl_rng_uniform(rng) < exp(-de / T)) z.accepted++;
      else o->undo(o->ctx);
    }
    z.moves += per_temp;
    o->resum(o->ctx);   /* E_Con's running sum back to an exact sum */
    double e = o->energy(o->ctx);
    if (e < ebest - 1e-12 * fabs(ebest)) { ebest = e; o->save(o->ctx, best); stall = 0; }
    else if (T < 1e-2 * t0) stall++;   /* only once the walk has cooled */
    T *= alpha;
  }
  o->restore(o->ctx, best);
  z.t_end = T;
  z.e_best = o->energy(o->ctx);
  z.seconds = nl_time_now() - t_start;
  if (st) *st = z;
  free(best);
}

/* ---- the 2D levels as callbacks -------------------------------------------
 * Variable q of the annealer is the level's variable vars[q] (a gradient
 * angle, or a gain with X6): a move proposes a step of width sigma (an angle
 * wrapped into [0, 2 pi)) and applies it incrementally. */
typedef struct {
  nl_cheng_problem *p;
  const size_t *vars;
} level_ctx;

static double propose(const nl_cheng_problem *p, gsl_rng *rng, size_t k, double sigma)
{
  if (k >= p->m) return nl_cheng__amp_propose(p, rng, k - p->m, sigma);   /* a gain (X6) */
  return nl_wrap_angle(p->g->angle[k] + sigma * (2.0 * gsl_rng_uniform(rng) - 1.0));
}

static double op_energy(void *ctx) { return ((level_ctx *)ctx)->p->e; }
static double op_move(void *ctx, size_t var, double sigma, gsl_rng *rng)
{
  level_ctx *c = ctx;
  size_t k = c->vars[var];
  return nl_cheng_move(c->p, k, propose(c->p, rng, k, sigma));
}
static void op_undo(void *ctx) { nl_cheng_undo(((level_ctx *)ctx)->p); }
static void op_save(void *ctx, double *state)
{
  level_ctx *c = ctx;
  size_t nv;
  nl_cheng_vars(c->p, &nv);
  for (size_t q = 0; q < nv; q++) state[q] = nl_cheng__var_value(c->p, c->vars[q]);
}
/* Moves the variables back to a saved state through the incremental path,
 * so every structure follows, then an exact resum. */
static void op_restore(void *ctx, const double *state)
{
  level_ctx *c = ctx;
  size_t nv;
  nl_cheng_vars(c->p, &nv);
  for (size_t q = 0; q < nv; q++) {
    size_t k = c->vars[q];
    if (nl_cheng__var_value(c->p, k) != state[q]) nl_cheng_move(c->p, k, state[q]);
  }
  nl_cheng_resum(c->p);
}
/* Only the top octave can have moved within a level: nl_cheng_resum's
 * result at a fraction of its cost. */
static void op_resum(void *ctx) { nl_cheng__resum_top(((level_ctx *)ctx)->p); }

void nl_cheng_anneal(nl_cheng_problem *p, gsl_rng *rng, nl_cheng_level_stats *st)
{
  size_t nv;
  level_ctx c = {p, nl_cheng_vars(p, &nv)};
  nl_cheng_sa_ops ops = {&c, nv, nv, op_energy, op_move, op_undo, op_save, op_restore, op_resum};
  nl_cheng_sa_run(&ops, &p->c.sched, rng, st);
  if (st) st->level = p->level;
}

void nl_cheng_propagate(nl_cheng_problem *p)
{
  int L = p->level;
  if (L < 2) return;
  long lo, hi;
  nl_cheng__lattice_range(p->freq[L - 1], p->c.origin, &lo, &hi);
  unsigned char *done = nl_xcalloc(p->m, 1);
  for (long J = lo; J <= hi; J++)
    for (long I = lo; I <= hi; I++) {
      size_t k = nl_noise_grad2_index(p->g, I, J);
      if (p->first_level[k] != L || done[k]) continue;
      /* eq. 3.13: the lattice point at half the frequency (f_l = 2 f_{l-1}),
       * which lies on octave l-1's lattice over the same domain (indices >= 0) */
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
