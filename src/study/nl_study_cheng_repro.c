/* What C5 and C6 share (noise reproduction): the thesis's Tables 4.2-4.4,
 * the --set parameters, and the chain original -> pool -> model. */
#include "study/nl_study_cheng.h"

#include <stdlib.h>
#include <string.h>

const nl_cheng_thesis_gmm nl_cheng_thesis_gmm_tables[3] = {
  {"erosion", "disc", NL_CHENG_CON_ABS, "Table 4.2", 1000, 10.0, 30, 36, 18.6, -15079449.0743},
  {"marble", "rings", NL_CHENG_CON_SIN, "Table 4.3", 1000, 10.0, 39, 42, 19.5, -25353476.4511},
  {"cloud", "flower", NL_CHENG_CON_PLAIN, "Table 4.4", 1000, 10.0, 20, 24, 15.5, -20163091.2097},
};

void nl_cheng_repro_params(nl_run *r, nl_cheng_pool_options *po, nl_cheng_model_options *mo)
{
  int q = nl_run_quick(r);
  nl_cheng_pool_options_default(po);
  nl_cheng_model_options_default(mo);
  po->runs = (int)nl_run_param_int(r, "runs", q ? 6 : po->runs, 1, 100000);          /* Q */
  po->keep = (int)nl_run_param_int(r, "keep", q ? 20 : po->keep, 1, 100000);         /* N */
  po->epsilon = nl_run_param(r, "epsilon", po->epsilon, 0, 1e300);
  po->low_levels = (int)nl_run_param_int(r, "low_levels", po->low_levels, 1, NL_CHENG_MAX_OCTAVES - 1);
  po->threads = (int)nl_run_param_int(r, "threads", po->threads, 1, 64);
  mo->samples = (size_t)nl_run_param_int(r, "samples", q ? 100 : (long)mo->samples, 0, 1000000);
  mo->threshold = nl_run_param(r, "T", mo->threshold, 0, 1e300);
  mo->k_extra = (size_t)nl_run_param_int(r, "k_extra", (long)mo->k_extra, 0, 100000);
  mo->rep = (nl_cheng_rep)nl_run_param_int(r, "unwrap", mo->rep == NL_CHENG_REP_UNWRAP, 0, 1);
  mo->gmm.covariance = nl_run_param_int(r, "diag", 0, 0, 1) ? NL_GMM_DIAG : NL_GMM_FULL;
  mo->gmm.max_iter = (size_t)nl_run_param_int(r, "max_iter", (long)mo->gmm.max_iter, 1, 1000000);
}

nl_status nl_cheng_repro_original(const nl_cheng_config *c, const nl_cheng_pattern *pat,
                                  unsigned long seed, nl_cheng_repro *out, nl_error *err)
{
  memset(out, 0, sizeof *out);
  double t0 = nl_time_now();
  nl_status st = nl_cheng_run(c, pat, seed, &out->ev, NULL, &out->opt, err);
  out->seconds_opt = nl_time_now() - t0;
  return st;
}

nl_status nl_cheng_repro_pool(nl_cheng_repro *rp, const nl_cheng_config *c, const nl_cheng_pattern *pat,
                              const nl_cheng_pool_options *po, unsigned long seed, nl_error *err)
{
  double t0 = nl_time_now();
  nl_status st = nl_cheng_pool_collect(rp->opt, c, pat, po, seed, &rp->pool, err);
  rp->seconds_pool = nl_time_now() - t0;
  return st;
}

void nl_cheng_repro_clear(nl_cheng_repro *rp)
{
  nl_grad2_free(rp->opt);
  nl_cheng_pool_free(rp->pool);
  memset(rp, 0, sizeof *rp);
}
