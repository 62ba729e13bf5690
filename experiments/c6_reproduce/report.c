/* C6's report (report.h): the thesis's claims of sec. 4.4 beside ours, every
 * number formatted from the summary table or the run's parameters. */
#include "report.h"
#include "reproduce.h"
#include "study/nl_study_cheng.h"

#include <stdio.h>

void c6_report(nl_harness *r, const nl_table *sum, int nrep, double swap,
               const nl_cheng_pool_options *po, const nl_cheng_config *c)
{
  nl_harness_text(
      r,
      "**Thesis** (sec. 4.4, Fig 4.9-4.14): reproduced erosion, marble and cloud textures look "
      "like the original optimised ones (marble least, through its sine), their E_KS and E_Con are "
      "close to the original's and often below, and the CDFs of the reproduced gradients lie on "
      "the original's; one original and a few reproductions per texture, numbers printed only in "
      "the figures (not legible in our copy). **Ours:** per texture the original table (C5's "
      "setting), its pool (Q = %d, N = %d) and mixture (cutoff matched to the thesis's initial K, "
      "AIC rule), then %d reproductions: low entries drawn from the mixture, a fraction %g of the "
      "high entries permuted at random (sec. 3.5.3), and the same without the swap (swap 0) to "
      "separate the two effects. E_KS and E_Con are over all %zu angles and all %d octaves, as for "
      "the original.\n",
      po->runs, po->keep, nrep, swap, c->m, c->octaves);
  nl_harness_report_table(
      r, sum,
      "Original against reproductions: mean and sd over reproductions; below_* = fraction of "
      "reproductions with a lower error than the original; ks2_D = two-sample KS distance between "
      "a reproduction's angles and the original's",
      4);
  for (size_t q = 0; q + 1 < sum->nrows; q++) {
    if (nl_table_value(sum, q, "n") != 1) continue; /* an original row, its reproductions follow */
    const char *tex = nl_table_text(sum, q, "texture");
    size_t w = q + 1;
    if (w >= sum->nrows || nl_table_value(sum, w, "n") == 1) continue;
    nl_harness_text(
        r,
        "%s: E_KS %.4g (original) vs %.4g +- %.2g (reproduced; %.0f%% below the original); E_Con "
        "%.4g vs %.4g +- %.3g (%.0f%% below). Smallest uniformity p-value of a reproduction %.3g: "
        "%s. Angles differ from the original's by D = %.3g on average. The times of a reproduction "
        "(table, and with a %d^2 texture) and of one optimisation are in times.tsv (they differ "
        "on every run; the real-time claim below is decided on speed.tsv).\n",
        tex, nl_table_value(sum, q, "E_ks"), nl_table_value(sum, w, "E_ks"),
        nl_table_value(sum, w, "E_ks_sd"), 100 * nl_table_value(sum, w, "below_ks"),
        nl_table_value(sum, q, "E_con"), nl_table_value(sum, w, "E_con"),
        nl_table_value(sum, w, "E_con_sd"), 100 * nl_table_value(sum, w, "below_con"),
        nl_table_value(sum, w, "p_ks_min"),
        nl_table_value(sum, w, "p_ks_min") > 0.05 ? "none is rejected as non-uniform at 0.05"
                                                  : "some are rejected as non-uniform at 0.05",
        nl_table_value(sum, w, "ks2_D"), C6_TEXTURE_SIDE);
    if (w + 1 < sum->nrows && nl_table_value(sum, w + 1, "n") != 1)
      nl_harness_text(
          r,
          "%s without the swap (%s): E_KS %.4g +- %.2g (%.0f%% below the original), E_Con %.4g +- "
          "%.3g (%.0f%% below): the swap of the high entries moves E_Con by %+.1f%%.\n",
          tex, nl_table_text(sum, w + 1, "kind"), nl_table_value(sum, w + 1, "E_ks"),
          nl_table_value(sum, w + 1, "E_ks_sd"), 100 * nl_table_value(sum, w + 1, "below_ks"),
          nl_table_value(sum, w + 1, "E_con"), nl_table_value(sum, w + 1, "E_con_sd"),
          100 * nl_table_value(sum, w + 1, "below_con"),
          100 * (nl_table_value(sum, w, "E_con") - nl_table_value(sum, w + 1, "E_con")) /
              nl_table_value(sum, w + 1, "E_con"));
  }
  /* r, contrast and the two baselines, originals and reproductions */
  nl_study_cheng_control_text(r, sum, 2);
  nl_harness_text(r, "The optimisation time above is one multi-level run (nl_cheng_run); building "
                     "the model once costs the pool (Q annealing runs of E_R) and the fits, see "
                     "C5's original.tsv and gmm.tsv.\n");
  const char *tex[3] = { "erosion", "marble", "cloud" }, *fig[3] = { "4.9", "4.11", "4.13" };
  for (int t = 0; t < 3; t++) {
    char f[64], cap[160];
    snprintf(f, sizeof f, "textures_%s.png", tex[t]);
    snprintf(cap, sizeof cap,
             "Fig %s: %s, original (top left) and %d reproductions, each labelled E_KS / E_Con",
             fig[t], tex[t], C6_NSHOW);
    nl_harness_figure(r, f, cap);
  }
  char cap[160];
  snprintf(cap, sizeof cap,
           "Fig 4.10, 4.12, 4.14: CDF of the gradient angles, original and %d reproductions, and "
           "their deviation from the ideal line",
           C6_NSHOW);
  nl_harness_figure(r, "cdf.png", cap);
}
