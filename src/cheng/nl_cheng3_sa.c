/* The annealing schedule of nl_cheng.h (ANNEALING) against callbacks, so the
 * 3D problem (and any other incremental problem) runs the same schedule:
 * T0 from trial moves, Metropolis sweeps, geometric cooling, the stall rule,
 * best end-of-temperature state restored. */
#include "cheng/nl_cheng3.h"

#include <math.h>
#include <stdlib.h>

#define TRIAL_MOVES 200

/* T0 so that an average uphill move of the widest step (sigma = pi) is
 * accepted with probability p0; trial moves are undone. */
static double initial_temperature(const nl_cheng3_sa_ops *o, gsl_rng *rng, double p0)
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

void nl_cheng3_sa_run(const nl_cheng3_sa_ops *o, const nl_cheng_schedule *s, gsl_rng *rng,
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
      double e0 = o->energy(o->ctx), de = o->move(o->ctx, gsl_rng_uniform_int(rng, nv), sigma, rng) - e0;
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
