/* Unit tests of the raw chi-square objective C2 measures beside Cramer's V
 * (NL_CHENG_STAT_CHISQ_RAW, eq. 3.4 as printed): the term is Pearson's chi2
 * itself, V^2 n (K - 1) of the Cramer's V term on the same sample, and its
 * incremental value follows a random sequence of moves exactly. */
#include "study/nl_study_cheng.h"
#include "nl_test.h"

#include <math.h>

static nl_cheng_pattern *flower(void)
{
  nl_image *im = nl_study_cheng_shape("flower", 96);
  nl_cheng_pattern *p = NULL;
  nl_error err;
  NL_CHECK(nl_study_cheng_pattern_from_image(im, 16, &p, &err) == NL_OK);
  nl_image_free(im);
  return p;
}

NL_TEST(raw_chi2_is_pearson_and_follows_moves)
{
  nl_cheng_pattern *pat = flower();
  nl_cheng_config cv = nl_cheng_config_default(), cr = cv;
  cv.stat = NL_CHENG_STAT_CHISQ;
  cr.stat = NL_CHENG_STAT_CHISQ_RAW;
  nl_error err;
  nl_noise_grad2 *g = nl_noise_grad2_alloc(cv.m);
  nl_noise_grad2_seed(g, 7);
  /* over all M angles: the evaluation's chi2 and E = w1 chi2 + w2 E_Con */
  nl_cheng_eval ev;
  NL_CHECK(nl_cheng_evaluate(g, &cr, pat, &ev, &err) == NL_OK);
  NL_CHECK(fabs(ev.e - (cr.w1 * ev.chi2 + cr.w2 * ev.e_con)) <= 1e-9 * ev.e);
  /* at the top level: raw = V^2 n (K - 1) for the level's sample size n,
   * the same n for every V, so two tables give the same ratio */
  nl_noise_grad2 *g2 = nl_noise_grad2_alloc(cv.m);
  nl_noise_grad2_copy(g2, g);
  nl_cheng_problem *pv = nl_cheng_problem_alloc(&cv, pat, g, &err);
  nl_cheng_problem *pr = nl_cheng_problem_alloc(&cr, pat, g2, &err);
  NL_CHECK(pv && pr);
  nl_cheng_set_level(pv, cv.octaves);
  nl_cheng_set_level(pr, cr.octaves);
  double sv, sr;
  nl_cheng_energy(pv, &sv, NULL);
  nl_cheng_energy(pr, &sr, NULL);
  double n_k1 = sr / (sv * sv); /* n (K - 1) */
  NL_CHECK(n_k1 > cv.chisq_bins - 1 && n_k1 <= (double)cv.m * (cv.chisq_bins - 1) * (1 + 1e-12));
  /* moves: incremental == full, and the ratio stays n (K - 1) */
  gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
  size_t nv;
  const size_t *vars = nl_cheng_vars(pr, &nv);
  for (int i = 0; i < 300; i++) {
    size_t k = vars[gsl_rng_uniform_int(rng, nv)];
    double th = NL_TWO_PI * gsl_rng_uniform(rng);
    double er = nl_cheng_move(pr, k, th);
    nl_cheng_move(pv, k, th);
    double fr, fs;
    NL_CHECK(fabs(er - nl_cheng_energy_full(pr, &fs, NULL)) <= 1e-9 * fabs(er));
    nl_cheng_energy(pr, &fr, NULL);
    NL_CHECK(fabs(fr - fs) <= 1e-9 * fmax(1, fs));
    nl_cheng_energy(pv, &sv, NULL);
    NL_CHECK(fabs(fr - sv * sv * n_k1) <= 1e-9 * fmax(1, fr));
  }
  gsl_rng_free(rng);
  nl_cheng_problem_free(pv);
  nl_cheng_problem_free(pr);
  nl_noise_grad2_free(g);
  nl_noise_grad2_free(g2);
  nl_cheng_pattern_free(pat);
}

int main(void) { return nl_test_run(); }
