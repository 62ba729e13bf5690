/* C6's sign test of "often below the original's" (below.h). */
#include "below.h"

#include <gsl/gsl_cdf.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

nl_table *c6_below_alloc(void)
{
  const char *cols[] = { "texture", "kind", "error", "n", "below", "frac_below", "p_sign" };
  return nl_table_alloc(sizeof cols / sizeof *cols, cols);
}

double c6_sign_p(unsigned k, unsigned n) { return k >= n ? 1.0 : gsl_cdf_binomial_P(k, 0.5, n); }

void c6_below_add(nl_table *b, const nl_table *sum)
{
  const char *err[2] = { "E_ks", "E_con" }, *frac[2] = { "below_ks", "below_con" };
  for (size_t q = 0; q < sum->nrows; q++) {
    if (strcmp(nl_table_text(sum, q, "kind"), "original") == 0) continue;
    double n = nl_table_value(sum, q, "n");
    for (int e = 0; e < 2; e++) {
      double k = round(nl_table_value(sum, q, frac[e]) * n); /* the fraction is k / n */
      nl_table_append(b, "sssdddd", nl_table_text(sum, q, "texture"), nl_table_text(sum, q, "kind"),
                      err[e], n, k, k / n, c6_sign_p((unsigned)k, (unsigned)n));
    }
  }
}

void c6_below_text(nl_harness *r, const nl_table *b, double swap, const nl_table *ctl)
{
  char want[48];
  snprintf(want, sizeof want, "reproduced_swap_%g", swap);
  nl_harness_text(
      r,
      "**\"Often below the original's\"**, headline reading: if a reproduction were as good as "
      "the original optimised table, its error would be below the original's half the time, so "
      "the count below is Binomial(n, 1/2) and a one-sided sign test (p = P(X <= count)) rejects "
      "\"often below\" when reproductions are below less often than that; the reading comes from "
      "the text's wording, as the thesis prints no count.\n");
  nl_harness_report_table(r, b,
                          "Reproductions below the original per texture, error and swap: count, "
                          "fraction and the sign test's one-sided p",
                          4);
  for (size_t q = 0; q < b->nrows; q++) {
    if (strcmp(nl_table_text(b, q, "kind"), want)) continue;
    char quantity[96];
    int con = strcmp(nl_table_text(b, q, "error"), "E_con") == 0;
    snprintf(quantity, sizeof quantity, "%s of reproductions below the original's, %s",
             con ? "E_Con" : "E_KS", nl_table_text(b, q, "texture"));
    nl_harness_verdict_p(r, "below.tsv", b, q, quantity, "often below the original's", "frac_below",
                         "p_sign", "fit 0.05 0.01", "independent",
                         "one-sided sign test of the count below against Binomial(n, 1/2), "
                         "the thesis's swap of the high entries");
    for (size_t c = 0; c < ctl->nrows; c++)
      if (!strcmp(nl_table_text(ctl, c, "texture"), nl_table_text(b, q, "texture")) &&
          !strcmp(nl_table_text(ctl, c, "error"), nl_table_text(b, q, "error")))
        nl_harness_verdict_control(r, "random (unoptimised) tables in place of reproductions",
                                   "below_ctl.tsv", ctl, c);
  }
  /* rejections at 0.05 per swap (the thesis's first) and error */
  int rej[2][2] = { { 0, 0 }, { 0, 0 } }, ntex[2] = { 0, 0 };
  for (size_t q = 0; q < b->nrows; q++) {
    int w = strcmp(nl_table_text(b, q, "kind"), want) != 0;
    int e = strcmp(nl_table_text(b, q, "error"), "E_con") == 0;
    rej[w][e] += nl_table_value(b, q, "p_sign") < 0.05;
    ntex[w] += e;
  }
  nl_harness_text(r,
                  "The sign test rejects \"often below\" at 0.05 for E_KS in %d of %d textures "
                  "and for E_Con in %d with the swap of the high entries (the thesis's method); "
                  "without the swap in %d and %d of %d.\n",
                  rej[0][0], ntex[0], rej[0][1], rej[1][0], rej[1][1], ntex[1]);
  const char *tex[3] = { "erosion", "marble", "cloud" }, *fig[3] = { "4.9", "4.11", "4.13" };
  for (int t = 0; t < 3; t++) {
    char quantity[96], claim[96], file[64];
    snprintf(quantity, sizeof quantity, "reproduced %s textures against the original", tex[t]);
    snprintf(claim, sizeof claim, "reproductions look like the original (Fig %s)", fig[t]);
    snprintf(file, sizeof file, "textures_%s.png", tex[t]);
    nl_harness_verdict_figure(r, quantity, claim, file, NULL);
  }
  nl_harness_verdict_figure(r, "CDF of reproduced gradient angles",
                            "reproduced CDFs lie on the original's (Fig 4.10, 4.12, 4.14)",
                            "cdf.png", "ks2_D in summary.tsv measures the distance");
}
