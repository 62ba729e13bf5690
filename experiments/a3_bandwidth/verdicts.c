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
  /* Each headline row's control: the same samples shuffled (control_shuffled.tsv). */
  const char *ctl = "the same samples shuffled: same values, no band";
  const nl_table *b = run->bandwidth;
  for (size_t s = 0; s < b->nrows; s++) {
    snprintf(what, sizeof what, "F_inf, signal %s", nl_table_text(b, s, "signal"));
    nl_harness_verdict(r, "bandwidth.tsv", b, s, what, "paper_f_inf", "f_inf", NULL, rule_inf,
                       "independent", note);
    nl_harness_verdict_control(r, ctl, "control_shuffled.tsv", run->control, s);
  }
  for (size_t s = 0; s < b->nrows; s++) {
    snprintf(what, sizeof what, "F_sup, signal %s", nl_table_text(b, s, "signal"));
    nl_harness_verdict(r, "bandwidth.tsv", b, s, what, "paper_f_sup", "f_sup", "f_sup_sd",
                       "sd 2 4", "independent", note);
    nl_harness_verdict_control(r, ctl, "control_shuffled.tsv", run->control, s);
  }
  /* Table 5.2 puts the sum's F_sup 14.8% above the 2nd octave's: the
   * printed ratio, against ours with the sds of both means. */
  nl_harness_verdict(r, "sum_over_octave.tsv", run->ratio, 0,
                     "F_sup of Fnoise_2 / F_sup of the 2nd octave", "paper", "ratio", "ratio_sd",
                     "sd 2 4", "independent", note);
  nl_harness_verdict_control(r, ctl, "sum_over_octave.tsv", run->ratio, 1);
  nl_harness_text(r,
                  "**The sum against its 2nd octave:** Table 5.2 puts F_sup of Fnoise_2 %.1f%% "
                  "above the 2nd octave's; ours is %.2f%% above (sd %.2g): the sum's highest "
                  "frequencies are its 2nd octave's. **Controls:** the same samples in a random "
                  "order (control_shuffled.tsv) have F_sup %.3g, %.3g, %.3g, near Nyquist, and "
                  "fail every rule.\n",
                  100.0 * (nl_table_value(run->ratio, 0, "paper") - 1.0),
                  100.0 * (nl_table_value(run->ratio, 0, "ratio") - 1.0),
                  nl_table_value(run->ratio, 0, "ratio_sd"),
                  nl_table_value(run->control, 0, "f_sup"), nl_table_value(run->control, 1, "f_sup"),
                  nl_table_value(run->control, 2, "f_sup"));
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
