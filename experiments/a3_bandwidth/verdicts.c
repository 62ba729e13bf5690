/* verdicts.c - A3's verdict rows (report.h). */
#include "report.h"

#include <math.h>
#include <stdio.h>

void a3_verdicts(nl_harness *r, const a3_run *run)
{
  /* F_inf is a bin: within a quarter bin reproduced, within one bin partly. */
  double res = 1.0 / run->base->length;
  char rule_inf[64], kind[32], note[160], what[64];
  snprintf(rule_inf, sizeof rule_inf, "abs %g %g", 0.25 * res, res);
  snprintf(note, sizeof note, "%s, sigma = sd: the text's reading", run->name[0]);
  nl_harness_verdict_rows(r, "bandwidth.tsv", run->bandwidth, "F_inf", "signal", "paper_f_inf",
                          "f_inf", NULL, rule_inf, "independent", note);
  nl_harness_verdict_rows(r, "bandwidth.tsv", run->bandwidth, "F_sup", "signal", "paper_f_sup",
                          "f_sup", "f_sup_sd", "sd 2 4", "independent", note);
  if (!run->win) return; /* the selected reading is the headline */
  const nl_table *t = run->selected;
  snprintf(kind, sizeof kind, "selected 1/%d", run->nh);
  snprintf(note, sizeof note, "%s: the reading with the most of the paper's bounds within",
           run->name[run->win]);
  for (size_t s = 0; s < t->nrows; s++) {
    /* With sigma = RMS and a mean far from 0, (sigma - sqrt T)^2 exceeds the
     * variance, so Gamma^-1 lands on the first bin whatever the noise: where
     * the paper's F_inf is that bin, the match is set by the line's length. */
    double paper = nl_table_value(t, s, "paper_f_inf");
    int built = run->sel->sigma_rms && nl_table_value(t, s, "f_inf_bins") == 1.0 &&
                fabs(paper - res) <= 0.25 * res;
    snprintf(what, sizeof what, "F_inf, signal %s, selected", nl_table_text(t, s, "signal"));
    nl_harness_verdict(r, "bandwidth_selected.tsv", t, s, what, "paper_f_inf", "f_inf", NULL,
                       rule_inf, built ? "by construction" : kind,
                       built ? "sigma = RMS puts F_inf on the first bin of the line" : note);
  }
  nl_harness_verdict_rows(r, "bandwidth_selected.tsv", t, "F_sup, selected", "signal",
                          "paper_f_sup", "f_sup", "f_sup_sd", "sd 2 4", kind, note);
}
