/* Octave amplitudes as variables of the objective (X6, the thesis's ch. 5
 * future work; the rule, bounds and scale are documented in nl_cheng.h under
 * OCTAVE AMPLITUDES AS VARIABLES). Variable M + l of a level is octave l's
 * log gain u_l, 1/a_l = e^u_l / a_l^thesis. */
#include "cheng/nl_cheng_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

nl_noise_octaves nl_cheng_octaves(const nl_cheng_config *c)
{
  nl_noise_octaves o = nl_noise_octaves_cheng(c->octaves, c->f1, c->a1);
  for (int l = 0; l < o.n; l++) o.amp[l] = o.amp[l] * exp(c->log_gain[l]);   /* exp(0) = 1: the thesis's, exactly */
  return o;
}

void nl_cheng_log_gains(const nl_cheng_problem *p, double *out)
{
  memcpy(out, p->lg, (size_t)p->F * sizeof *out);
}

double nl_cheng__amp_scale(const double *amp, int n)
{
  double a = 0;
  for (int l = 0; l < n; l++) a += amp[l];
  return 1.0 / (NL_NOISE2_BOUND * a);
}

/* Every point's term from its stored octave values (a gain and s move every
 * point's value, not its octave values) and E_Con as the plain left-to-right
 * sum, the one nl_cheng_resum forms. */
static void reterm_all(nl_cheng_problem *p)
{
  size_t F = (size_t)p->F;
  double sum = 0;
  for (size_t i = 0; i < p->np; i++) {
    double e = nl_cheng__control_value(p->c.con, p->nv + i * F, p->amp, p->level, p->s, p->c.literal) - p->pat->d[i];
    p->term[i] = e * e;
    sum += p->term[i];
  }
  p->e_con = sum;
  p->e = nl_cheng_objective(&p->c, p->e_stat, p->e_con);
}

static void set_gain(nl_cheng_problem *p, size_t l, double u, double amp)
{
  p->lg[l] = u;
  p->amp[l] = amp;
  p->s = nl_cheng__amp_scale(p->amp, p->F);   /* V stays over its bound with the new amplitudes */
}

double nl_cheng__amp_move(nl_cheng_problem *p, size_t l, double u)
{
  if (!p->uterm) p->uterm = nl_xmalloc(p->np * sizeof *p->uterm);
  p->uk = p->m + l;
  p->u_lg = p->lg[l];
  p->u_amp = p->amp[l];
  p->u_s = p->s;
  p->u_stat = p->e_stat;   /* the angles do not move: E_stat stays */
  p->u_con = p->e_con;
  p->u_e = p->e;
  memcpy(p->uterm, p->term, p->np * sizeof *p->term);
  p->has_undo = 1;
  set_gain(p, l, u, p->amp0[l] * exp(u));   /* nl_cheng_octaves' product, so evaluation agrees exactly */
  reterm_all(p);
  return p->e;
}

void nl_cheng__amp_undo(nl_cheng_problem *p)
{
  size_t l = p->uk - p->m;
  p->lg[l] = p->u_lg;
  p->amp[l] = p->u_amp;
  p->s = p->u_s;
  memcpy(p->term, p->uterm, p->np * sizeof *p->term);
  p->e_stat = p->u_stat;
  p->e_con = p->u_con;
  p->e = p->u_e;
  p->has_undo = 0;
}

/* u + (sigma / pi) ln R U(-1, 1), reflected into [-ln R, ln R]: the angles'
 * step rule (half the range at the hottest sigma = pi), on the gain's range. */
double nl_cheng__amp_propose(const nl_cheng_problem *p, gsl_rng *rng, size_t l, double sigma)
{
  double hi = log(p->c.amp_range), u = p->lg[l] + sigma / NL_PI * hi * (2.0 * gsl_rng_uniform(rng) - 1.0);
  if (u > hi) u = 2 * hi - u;
  if (u < -hi) u = -2 * hi - u;
  return fmin(hi, fmax(-hi, u));
}
