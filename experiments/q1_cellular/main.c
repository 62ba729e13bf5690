/* Q1 - Qin & Yang 2000 sec. 3: F1..F4 over Poisson-distributed feature
 * points (lambda = 4 per unit cube, M = 50, 27 cubes, seeds through a 2^16
 * permutation table), under the paper's count rule ("the m whose p(m) is
 * closest to r") and under inverse-CDF sampling: chi-square of the counts
 * against Poisson(lambda), KS of F1 against 1 - exp(-lambda 4/3 pi r^3). */
#include "cellular/nl_cellular.h"
#include "harness/nl_harness.h"
#include "q1.h"
#include "continuity.h"
#include "seeding.h"
#include "study/nl_study.h"

#include <gsl/gsl_statistics_double.h>
#include <math.h>
#include <string.h>

static nl_cellular *make(nl_harness *r, double lambda, int M, nl_cellular_count_rule rule,
                         unsigned long seed)
{
  nl_cellular *c;
  nl_error err;
  if (nl_cellular_alloc(lambda, M, rule, seed, &c, &err)) nl_harness_die(r, 2, "%s", err.msg);
  return c;
}

/* Per seed: chi-square of the counts and KS of F1; one row of `per_seed`. */
static void one_seed(nl_harness *r, nl_cellular *c, int side, long points, unsigned long seed,
                     nl_table *per_seed, double *hist)
{
  nl_stats_chisq_result cs;
  nl_stats_ks_result ks;
  nl_error err;
  double mean_f1;
  double mean;
  double var;
  nl_cellular_count_histogram(c, 0, side, hist);
  if (nl_cellular_count_chisq(c, hist, &cs, &err)) nl_harness_die(r, 1, "%s", err.msg);
  if (nl_cellular_f1_ks(c, (size_t)points, seed, &ks, &mean_f1, &err))
    nl_harness_die(r, 1, "%s", err.msg);
  nl_cellular_count_moments(hist, c->M, &mean, &var);
  nl_table_append(per_seed, "siddddiddd", nl_cellular_count_rule_name(c->rule), (int)seed, mean,
                  var, cs.chi2, cs.p, (int)cs.df, ks.d, ks.p, mean_f1);
}

static nl_image *f_panel(const nl_cellular *c, const char *expr, int size, double extent)
{
  nl_cellular_gctbf_basis gb = { c, { 0 } };
  nl_cellular_gctbf_parse(expr, &gb.g, NULL);
  nl_noise_basis b = nl_cellular_basis_gctbf(&gb);
  nl_noise_octaves o = nl_noise_octaves_fbm(1, 1.0, 1.0);
  nl_noise_window w = { 0, 0, 0.5, extent, size, size };
  size_t n = (size_t)size * size;
  double *v = nl_xmalloc(n * sizeof *v);
  nl_noise_fractal_grid(&b, &o, &w, v);
  nl_image *im = nl_image_from_values(v, size, size, 0.0, fmax(0.0, gsl_stats_max(v, 1, n)));
  free(v);
  return im;
}

int main(int argc, char **argv)
{
  q1 q = { 0 };
  nl_harness *r = q.r =
      nl_harness_begin("q1_cellular", "Q1 - Cellular F1..F4 and the count rule", argc, argv);
  int quick = nl_harness_quick(r);
  q.lambda = nl_harness_param(r, "lambda", 4.0, 1e-3, 1000.0,
                              "Poisson mean lambda of feature points per unit cube "
                              "(Qin & Yang: 4)");
  q.M = (int)nl_harness_param_int(r, "M", 50, 1, NL_CELLULAR_MAX_M,
                                  "most feature points a cube may hold (Qin & Yang: 50)");
  q.side = (int)nl_harness_param_int(r, "side", quick ? 16 : 32, 2, 256,
                                     "cubes per side of the block whose point counts are tested "
                                     "(side^3 cubes; quick 16)");
  q.points = nl_harness_param_int(r, "points", quick ? 1000 : 5000, 10, 10000000,
                                  "random points at which F1 is tested against the "
                                  "nearest-neighbour law (quick 1000)");
  int size = (int)nl_harness_param_int(r, "size", quick ? 96 : 256, 8, 4096,
                                       "side in pixels of the F1..F4 images (quick 96)");
  nl_harness_params_done(r);
  double lambda = q.lambda;
  int M = q.M;
  int seeds = q.seeds = nl_harness_seeds(r);
  unsigned long seed0 = nl_harness_seed(r);

  /* The three count rules over the seeds: per-seed tests, count histogram. */
  const char *pcols[] = { "rule",   "seed", "mean_count", "var_count", "chi2",
                          "chi2_p", "df",   "ks_d",       "ks_p",      "mean_f1" };
  nl_table *per = nl_table_alloc(10, pcols);
  const char *dcols[] = { "m", "poisson", "closest", "inverse_cdf", "closest_last" };
  q.dist = nl_table_alloc(5, dcols);
  double h[NL_CELLULAR_MAX_M + 1];
  double ncubes = (double)q.side * q.side * q.side;
  for (int rule = 0; rule < NRULE; rule++)
    for (int k = 0; k < seeds; k++) {
      unsigned long seed = nl_seed_replicate(seed0, k);
      nl_cellular *c = make(r, lambda, M, (nl_cellular_count_rule)rule, seed);
      one_seed(r, c, q.side, q.points, seed, per, h);
      for (int m = 0; m <= M; m++) q.hist[rule][m] += h[m] / (ncubes * seeds);
      nl_cellular_free(c);
      nl_harness_progress(r, (rule * seeds + k + 1.0) / ((double)NRULE * seeds), "seeds");
    }
  nl_cellular *ref = make(r, lambda, M, NL_COUNT_INVERSE_CDF, seed0);
  for (int m = 0; m <= (M < 20 ? M : 20); m++)
    nl_table_append(q.dist, "idddd", m, ref->pmf[m], q.hist[0][m], q.hist[1][m], q.hist[2][m]);

  /* Per rule: mean over seeds, and how many seeds reject at p < 0.01. */
  const char *scols[] = { "rule",       "mean_count", "chi2",           "chi2_rejects", "ks_d",
                          "ks_rejects", "mean_f1",    "mean_f1_theory", "seeds" };
  q.sum = nl_table_alloc(9, scols);
  q.theory = tgamma(4.0 / 3.0) * pow(4.0 / 3.0 * NL_PI * lambda, -1.0 / 3.0);
  for (int rule = 0; rule < NRULE; rule++) {
    const char *name = nl_cellular_count_rule_name((nl_cellular_count_rule)rule);
    int rc;
    int rk;
    double mc = nl_study_mean_where(per, "rule", name, "mean_count", NULL, 0, NULL);
    double chi = nl_study_mean_where(per, "rule", name, "chi2", "chi2_p", 0.01, &rc);
    double ksd = nl_study_mean_where(per, "rule", name, "ks_d", "ks_p", 0.01, &rk);
    double mf = nl_study_mean_where(per, "rule", name, "mean_f1", NULL, 0, NULL);
    nl_table_append(q.sum, "sddididdi", name, mc, chi, rc, ksd, rk, mf, q.theory, seeds);
  }
  nl_harness_write_table(r, per, "tests.tsv");
  nl_harness_write_table(r, q.sum, "summary.tsv");
  nl_harness_write_table(r, q.dist, "counts.tsv");

  const char *exprs[] = { "F1", "F2", "F3", "F4", "F2 - F1" };
  nl_image *panels[6];
  for (int k = 0; k < 5; k++) panels[k] = f_panel(ref, exprs[k], size, 4.0);
  nl_cellular *closest = make(r, lambda, M, NL_COUNT_CLOSEST, seed0);
  panels[5] = f_panel(closest, "F1", size, 4.0);
  const char *labels[] = { "F1", "F2", "F3", "F4", "F2 - F1", "F1 paper rule" };
  nl_study_montage(r, (const nl_image *const *)panels, labels, 6, 3, "F_i on z = 0.5",
                   "planes.png");

  q1_report(&q, ref->pmf);
  q1_seeding(&q, seed0);
  q1_continuity(&q, seed0);
  for (int k = 0; k < 6; k++) nl_image_free(panels[k]);
  nl_cellular_free(ref);
  nl_cellular_free(closest);
  nl_table_free(per);
  nl_table_free(q.sum);
  nl_table_free(q.dist);
  nl_harness_check_measured(r, "*", 100); /* measured tolerances (nl_harness.h) */
  return nl_harness_end(r);
}
