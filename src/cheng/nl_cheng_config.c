/* Configuration: the thesis setting, checks and names. */
#include "cheng/nl_cheng_internal.h"

#include <math.h>
#include <string.h>

nl_cheng_config nl_cheng_config_default(void)
{
  nl_cheng_config c = {
    .stat = NL_CHENG_STAT_KS, .con = NL_CHENG_CON_PLAIN,
    .w1 = 0.995, .w2 = 0.005,              /* sec. 3.4.1 */
    .octaves = 4, .f1 = 8, .a1 = 4,        /* eq. 3.10 */
    .m = 512, .chisq_bins = 500,           /* sec. 3.2, 4.2 */
    .propagate = 1,                        /* sec. 3.4.2 */
    .origin = 1,                           /* the domain [1, 2]^2 (nl_cheng.h READINGS) */
    .sched = {.n_temps = 60, .moves_per_var = 20, .t_decades = 4, .p0 = 0.8, .stall = 10},
    .amp_vary = 0, .amp_range = 4,         /* X6: fixed amplitudes; gains within [1/4, 4] when varied */
  };
  return c;
}

nl_status nl_cheng_config_check(const nl_cheng_config *c, nl_error *err)
{
  if (!(c->w1 >= 0 && c->w2 >= 0 && isfinite(c->w1) && isfinite(c->w2)))
    return nl_fail(err, NL_EINVAL, "weights must be finite and >= 0 (w1 = %g, w2 = %g)", c->w1, c->w2);
  if (c->w1 == 0 && c->w2 == 0) return nl_fail(err, NL_EINVAL, "weights w1 and w2 are both 0");
  if (!(c->f1 > 0 && isfinite(c->f1))) return nl_fail(err, NL_EINVAL, "f1 must be > 0, got %g", c->f1);
  if (!(c->a1 > 0 && isfinite(c->a1))) return nl_fail(err, NL_EINVAL, "a1 must be > 0, got %g", c->a1);
  if (c->octaves < 1 || c->octaves > NL_CHENG_MAX_OCTAVES)
    return nl_fail(err, NL_EINVAL, "octaves must be in 1..%d, got %d", NL_CHENG_MAX_OCTAVES, c->octaves);
  if (!(c->origin >= 0 && c->origin <= 1e6))
    return nl_fail(err, NL_EINVAL, "origin must be in [0, 1e6], got %g", c->origin);
  if (c->chisq_bins < 2) return nl_fail(err, NL_EINVAL, "chi-square needs >= 2 bins");
  if ((unsigned)c->stat > NL_CHENG_STAT_CHISQ_RAW) return nl_fail(err, NL_EINVAL, "unknown objective %d", (int)c->stat);
  if (c->literal != 0 && c->literal != 1) return nl_fail(err, NL_EINVAL, "literal must be 0 or 1, got %d", c->literal);
  if ((unsigned)c->con > NL_CHENG_CON_FIRE) return nl_fail(err, NL_EINVAL, "unknown texture type %d", (int)c->con);
  if (c->amp_vary != 0 && c->amp_vary != 1) return nl_fail(err, NL_EINVAL, "amp_vary must be 0 or 1, got %d", c->amp_vary);
  if (c->amp_vary && !(c->amp_range >= 1 && isfinite(c->amp_range)))
    return nl_fail(err, NL_EINVAL, "amp_range must be finite and >= 1, got %g", c->amp_range);
  for (int l = 0; l < c->octaves; l++)
    if (!isfinite(c->log_gain[l]) || (c->amp_vary && fabs(c->log_gain[l]) > log(c->amp_range)))
      return nl_fail(err, NL_EINVAL, "log gain of octave %d is %g, outside [-ln R, ln R] (R = amp_range %g)", l + 1,
                     c->log_gain[l], c->amp_range);
  const nl_cheng_schedule *s = &c->sched;
  if (s->n_temps < 1 || !(s->moves_per_var > 0) || !(s->t_decades > 0) || !(s->p0 > 0 && s->p0 < 1) || s->stall < 1)
    return nl_fail(err, NL_EINVAL, "bad annealing schedule (n_temps %d, moves/var %g, decades %g, p0 %g, stall %d)",
                   s->n_temps, s->moves_per_var, s->t_decades, s->p0, s->stall);
  return NL_OK;
}

static const char *const stat_names[] = {"ks", "chisq", "kuiper", "chisq_raw"};
static const char *const con_names[] = {"cloud", "marble", "erosion", "fire"};
static const char *const con_alias[] = {"plain", "sin", "abs", "fire"};

nl_status nl_cheng_stat_parse(const char *s, nl_cheng_stat *out, nl_error *err)
{
  for (int k = 0; k < 4; k++)
    if (!strcmp(s, stat_names[k])) { *out = (nl_cheng_stat)k; return NL_OK; }
  return nl_fail(err, NL_EINVAL, "unknown objective '%s' (ks, chisq, kuiper, chisq_raw)", s);
}

nl_status nl_cheng_con_parse(const char *s, nl_cheng_con *out, nl_error *err)
{
  for (int k = 0; k < 4; k++)
    if (!strcmp(s, con_names[k]) || !strcmp(s, con_alias[k])) { *out = (nl_cheng_con)k; return NL_OK; }
  return nl_fail(err, NL_EINVAL, "unknown texture type '%s' (cloud, marble, erosion, fire)", s);
}

const char *nl_cheng_stat_name(nl_cheng_stat s) { return (unsigned)s < 4 ? stat_names[s] : "?"; }
const char *nl_cheng_con_name(nl_cheng_con c) { return (unsigned)c < 4 ? con_names[c] : "?"; }

double nl_cheng_objective(const nl_cheng_config *c, double e_stat, double e_con)
{
  return c->w1 * e_stat + c->w2 * e_con;
}
