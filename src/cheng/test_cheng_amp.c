/* X6: octave gains as variables (nl_cheng_amp.c). */
#include "cheng/nl_cheng_internal.h"
#include "cheng/test_cheng_fixture.h"

#include <gsl/gsl_rng.h>
#include <stdlib.h>
#include <string.h>

/* Angle and gain moves mixed (random undos), every control variant and both
 * formulas, every level: incremental E == full recomputation to 1e-12, undo
 * exact, and gains stay where they were put. */
NL_TEST(gain_moves_incremental_equals_full)
{
  nl_cheng_pattern *pat = test_flower(FLOWER_PX, 24);
  double worst = 0;
  for (int lit = 0; lit < 2; lit++)
    for (int con = 0; con < 4; con++) {
      nl_cheng_config c = nl_cheng_config_default();
      c.con = (nl_cheng_con)con;
      c.literal = lit;
      c.amp_vary = 1;
      c.w1 = 0.6; c.w2 = 0.4;
      nl_noise_grad2 *g = nl_noise_grad2_alloc(512);
      nl_noise_grad2_seed(g, nl_seed_stream(7, "test.amp", (unsigned long)(lit * 4 + con)));
      nl_error err;
      nl_cheng_problem *p = nl_cheng_problem_alloc(&c, pat, g, &err);
      NL_CHECK(p != NULL);
      gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
      gsl_rng_set(r, 5);
      for (int L = 1; L <= 4; L++) {
        nl_cheng_set_level(p, L);
        size_t nv;
        const size_t *vars = nl_cheng_vars(p, &nv);
        NL_CHECK(nv > 0 && vars[nv - 1] == 512 + (size_t)(L - 1));   /* the level's gain is its last variable */
        for (int m = 0; m < 200; m++) {
          double before = nl_cheng_energy(p, NULL, NULL);
          if (gsl_rng_uniform(r) < 0.3) {   /* any octave's gain, within [-ln 4, ln 4] */
            size_t l = gsl_rng_uniform_int(r, 4);
            double u = log(4.0) * (2 * gsl_rng_uniform(r) - 1);
            nl_cheng_move(p, 512 + l, u);
            NL_CHECK(nl_cheng__var_value(p, 512 + l) == u);
          } else
            nl_cheng_move(p, gsl_rng_uniform_int(r, 512), NL_TWO_PI * gsl_rng_uniform(r));
          if (gsl_rng_uniform(r) < 0.5) {
            nl_cheng_undo(p);
            NL_CHECK(nl_cheng_energy(p, NULL, NULL) == before);
          }
          double si, ci, sf, cf;
          double ei = nl_cheng_energy(p, &si, &ci), ef = nl_cheng_energy_full(p, &sf, &cf);
          worst = fmax(worst, fmax(rel(ei, ef), fmax(rel(si, sf), rel(ci, cf))));
        }
      }
      /* at level F the problem's E_Con equals the evaluation's, computed with the
       * noise kernel and nl_cheng_octaves from the gains (an independent path) */
      nl_cheng_config ce = c;
      nl_cheng_log_gains(p, ce.log_gain);
      nl_cheng_eval ev;
      double con_p;
      nl_cheng_resum(p);
      nl_cheng_energy(p, NULL, &con_p);
      NL_CHECK(nl_cheng_evaluate(g, &ce, pat, &ev, &err) == NL_OK);
      worst = fmax(worst, rel(ev.e_con, con_p));
      gsl_rng_free(r);
      nl_cheng_problem_free(p);
      nl_noise_grad2_free(g);
    }
  NL_CHECK_NEAR(worst, 0.0, 1e-12);
  nl_cheng_pattern_free(pat);
}

/* The scale follows the gains: a common gain on every octave changes nothing
 * (V = F_sum over its bound), and the optimiser keeps gains within bounds. */
NL_TEST(gains_scale_invariant_and_bounded)
{
  nl_cheng_pattern *pat = test_flower(FLOWER_PX, 16);
  nl_cheng_config c = nl_cheng_config_default(), c2;
  c.amp_vary = 1;
  c.sched.n_temps = 8;
  c.sched.moves_per_var = 5;
  c2 = c;
  for (int l = 0; l < 4; l++) c2.log_gain[l] = log(2.0);
  nl_noise_grad2 *g = nl_noise_grad2_alloc(512);
  nl_noise_grad2_seed(g, 3);
  nl_cheng_eval a, b;
  nl_error err;
  NL_CHECK(nl_cheng_evaluate(g, &c, pat, &a, &err) == NL_OK);
  NL_CHECK(nl_cheng_evaluate(g, &c2, pat, &b, &err) == NL_OK);
  NL_CHECK_NEAR(a.e_con, b.e_con, 1e-12 * a.e_con);
  nl_noise_grad2_free(g);
  nl_cheng_eval ev;
  NL_CHECK(nl_cheng_run(&c, pat, 9, &ev, NULL, NULL, &err) == NL_OK);
  int moved = 0;
  for (int l = 0; l < 4; l++) {
    NL_CHECK(fabs(ev.log_gain[l]) <= log(4.0));
    moved += ev.log_gain[l] != 0;
  }
  NL_CHECK(moved == 4);   /* every level moved its gain */
  /* fixed amplitudes: no gain variable, gains stay 0 */
  c.amp_vary = 0;
  NL_CHECK(nl_cheng_run(&c, pat, 9, &ev, NULL, NULL, &err) == NL_OK);
  for (int l = 0; l < 4; l++) NL_CHECK(ev.log_gain[l] == 0);
  nl_cheng_pattern_free(pat);
}

NL_TEST(bad_gain_configuration)
{
  nl_cheng_config c = nl_cheng_config_default();
  nl_error err;
  c.amp_vary = 1;
  NL_CHECK(nl_cheng_config_check(&c, &err) == NL_OK);
  c.amp_range = 0.5;
  NL_CHECK(nl_cheng_config_check(&c, &err) == NL_EINVAL);
  c.amp_range = 4;
  c.log_gain[2] = 2;   /* > ln 4 */
  NL_CHECK(nl_cheng_config_check(&c, &err) == NL_EINVAL);
  NL_CHECK(strstr(err.msg, "octave 3") != NULL);
  c.amp_vary = 2;
  c.log_gain[2] = 0;
  NL_CHECK(nl_cheng_config_check(&c, &err) == NL_EINVAL);
}

int main(void) { return nl_test_run(); }
