/* What C5 and C6 share (noise reproduction): the thesis's Tables 4.2-4.4,
 * the --set parameters and the chain original -> pool. */
#include "study/nl_study_cheng.h"

#include <string.h>

const nl_study_cheng_thesis_gmm nl_study_cheng_thesis_gmm_tables[3] = {
  { "erosion", "disc", NL_CHENG_CON_ABS, "Table 4.2", 1000, 10.0, 30, 36, 18.6, -15079449.0743 },
  { "marble", "rings", NL_CHENG_CON_SIN, "Table 4.3", 1000, 10.0, 39, 42, 19.5, -25353476.4511 },
  { "cloud", "flower", NL_CHENG_CON_PLAIN, "Table 4.4", 1000, 10.0, 20, 24, 15.5, -20163091.2097 },
};

void nl_study_cheng_repro_params(nl_harness *r, nl_cheng_pool_options *po,
                                 nl_cheng_model_options *mo)
{
  int q = nl_harness_quick(r);
  nl_cheng_pool_options_default(po);
  nl_cheng_model_options_default(mo);
  po->runs = (int)nl_harness_param_int(
      r, "runs", q ? 6 : po->runs, 1, 100000,
      "Q: annealing runs in the solution pool (Cheng sec. 3.5.2; quick 6)"); /* Q */
  po->keep = (int)nl_harness_param_int(
      r, "keep", q ? 20 : po->keep, 1, 100000,
      "N: solutions kept per run in the pool (Cheng sec. 3.5.2; quick 20)"); /* N */
  po->epsilon = nl_harness_param(
      r, "epsilon", po->epsilon, 0, 1e300,
      "error bound on E_R: pool solutions above the run's best by more than this are left out");
  po->low_levels = (int)nl_harness_param_int(
      r, "low_levels", po->low_levels, 1, NL_CHENG_MAX_OCTAVES - 1,
      "levels 1..low_levels hold the shared low-frequency gradients that are reproduced");
  /* Threads for the pool runs, the fits and EM's steps: the run's --threads
   * (a speed setting, not a parameter: no table depends on it). */
  po->threads = nl_harness_threads(r);
  mo->samples = (size_t)nl_harness_param_int(
      r, "samples", q ? 100 : (long)mo->samples, 0, 1000000,
      "input samples drawn from the pool for clustering and the mixture, 0 = all (quick 100)");
  mo->threshold = nl_harness_param(
      r, "T", mo->threshold, 0, 1e300,
      "AIC threshold T: a mixture component is added only if AIC falls by at least T");
  mo->k_extra =
      (size_t)nl_harness_param_int(r, "k_extra", (long)mo->k_extra, 0, 100000,
                                   "the GMM growth path is capped at K0 + k_extra components");
  mo->rep = (nl_cheng_rep)nl_harness_param_int(
      r, "unwrap", mo->rep == NL_CHENG_REP_UNWRAP, 0, 1,
      "1: angles unwrapped to a line before the mixture; 0: each angle as (cos, sin)");
  mo->gmm.covariance =
      nl_harness_param_int(r, "diag", 0, 0, 1, "1: diagonal GMM covariances; 0: full covariances")
          ? NL_GMM_DIAG
          : NL_GMM_FULL;
  mo->gmm.max_iter = (size_t)nl_harness_param_int(
      r, "max_iter", (long)mo->gmm.max_iter, 1, 1000000,
      "EM iterations allowed per mixture fit before it counts as not converged");
  mo->gmm.threads = po->threads; /* EM's steps; fits run by a threaded caller run theirs serially */
}

nl_status nl_study_cheng_repro_original(const nl_cheng_config *c, const nl_cheng_pattern *pat,
                                        unsigned long seed, nl_study_cheng_repro *out,
                                        nl_error *err)
{
  memset(out, 0, sizeof *out);
  double t0 = nl_time_now();
  nl_status st = nl_cheng_run(c, pat, seed, &out->ev, NULL, &out->opt, err);
  out->seconds_opt = nl_time_now() - t0;
  return st;
}

nl_status nl_study_cheng_repro_pool(nl_study_cheng_repro *rp, const nl_cheng_config *c,
                                    const nl_cheng_pattern *pat, const nl_cheng_pool_options *po,
                                    unsigned long seed, nl_error *err)
{
  double t0 = nl_time_now();
  nl_status st = nl_cheng_pool_collect(rp->opt, c, pat, po, seed, &rp->pool, err);
  rp->seconds_pool = nl_time_now() - t0;
  return st;
}

void nl_study_cheng_repro_clear(nl_study_cheng_repro *rp)
{
  nl_noise_grad2_free(rp->opt);
  nl_cheng_pool_free(rp->pool);
  memset(rp, 0, sizeof *rp);
}
