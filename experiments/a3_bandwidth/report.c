/* report.c - A3's report prose (report.h). */
#include "report.h"

#include <math.h>
#include <stdio.h>

/* Column col of reading h for signal s in hypotheses.tsv. */
static double hv(const nl_table *t, int h, int s, const char *col)
{
  return nl_table_value(t, (size_t)(h * A3_NSIGNALS + s), col);
}

void a3_report_tables(nl_harness *r, const a3_run *run)
{
  const double(*paper)[2] = run->paper;
  const a3_reading *head = run->base;
  const nl_table *hy = run->hypotheses;
  const char *const *fname = run->name;
  int win = run->win, close = run->close, nsig = A3_NSIGNALS;
  double res = 1.0 / head->length;
  const char *encoding =
      head->shader ? "the shader's encoded value (noise + 1)/2" : "raw noise values";
  const char *line = head->axis ? "along the x axis through the origin"
                                : "along an oblique line (not 256-periodic)";
  nl_harness_text(
      r,
      "**Paper (Table 5.2):** [F_inf, F_sup] = [%.7f, %.7f] (1st octave), [%.7f, %.6f] (2nd), "
      "[%.7f, %.7f] (Fnoise_2), T = (2/255)^2; sample length and rate not given.\n\n**Headline "
      "reading (%s), fixed before any comparison:** the text's own, since it calls the function "
      "Perlin noise citing Perlin's improved noise (2004, and Green's GPU version) and defines "
      "sigma as \"the standard deviation of the signal\" (sec. 5.2.1). %s, %s; a line of length %g "
      "units (frequency resolution 1/%g = %.7f; the paper's F_inf %.7f is 1/%.0f), %g samples per "
      "unit, %s, %s; Gamma(lambda) includes lambda's own bin and Gamma^-1(E) is the lowest "
      "frequency whose Gamma is <= E. %d seeds (permutation tables).\n",
      paper[0][0], paper[0][1], paper[1][0], paper[1][1], paper[2][0], paper[2][1], fname[0],
      a3_noise_text(head->noise), head->sigma_rms ? "sigma = RMS" : "sigma = sd", head->length,
      head->length, res, paper[0][0], 1.0 / paper[0][0], head->rate, encoding, line, run->seeds);
  nl_harness_report_table(
      r, run->bandwidth,
      "Bandwidth: ours (mean and sd over seeds) beside Table 5.2; *_bins = frequency / resolution",
      7);
  const char *none = run->nin[win] == 2 * nsig
                         ? ""
                         : "No reading puts all of them within: the paper's full set of numbers "
                           "appears nowhere in the family tried.";
  nl_harness_text(r,
                  "**Readings (hypotheses.tsv):** %d readings, %d seeds each; z = (paper - mean) / "
                  "max(sd, res/4), within = |z| <= 2. %s puts %d of the paper's %d bounds within "
                  "(F_sup: z = %.2f, %.2f, %.2f; F_inf: z = %.2f, %.2f, %.2f for the 1st octave, "
                  "2nd octave, Fnoise_2)%s; the headline (%s) puts %d within, worst |z| of F_sup "
                  "%.1f. Closest in F_sup over the three signals: %s, worst |z| %.1f. %s\n",
                  run->nh, run->seeds, fname[win], run->nin[win], 2 * nsig, hv(hy, win, 0, "z_sup"),
                  hv(hy, win, 1, "z_sup"), hv(hy, win, 2, "z_sup"), hv(hy, win, 0, "z_inf"),
                  hv(hy, win, 1, "z_inf"), hv(hy, win, 2, "z_inf"),
                  win ? " and is kept as a selected alternative (bandwidth_selected.tsv)" : "",
                  fname[0], run->nin[0], run->worst[0][0], fname[close], run->worst[close][0],
                  none);
  if (win) {
    char cap[160];
    snprintf(cap, sizeof cap,
             "Selected alternative (%s, best of %d readings by closeness to the paper), beside "
             "Table 5.2",
             fname[win], run->nh);
    nl_harness_report_table(r, run->selected, cap, 7);
  }
  char list[2048];
  a3_list(hy, 0, "f_sup", list, sizeof list);
  nl_harness_text(r, "First-octave F_sup by reading (names as in hypotheses.tsv): %s.\n", list);
  nl_harness_report_columns(
      r, hy, "hypotheses.tsv",
      "hypothesis,signal,f_inf,f_sup,f_sup_sd,paper_f_inf,paper_f_sup,z_inf,z_sup,within",
      "Readings of the method: mean and sd over seeds, z = distance of the paper's value in sd", 5);
}

void a3_report_figures(nl_harness *r, const a3_run *run)
{
  const double(*paper)[2] = run->paper;
  const nl_table *hy = run->hypotheses, *sw = run->sweep, *sh = run->sweep_sel, *pt = run->psd;
  const char *const *fname = run->name;
  const double(*m)[7] = run->ms;
  nl_harness_figure(r, "hypotheses.png",
                    "F_sup of each reading (mean +- 2 sd over seeds) against Table 5.2");
  nl_harness_figure(
      r, "psd.png",
      "Fig. 5.5: PSD and Gamma(lambda) of the octaves and their sum (base reading, first seed)");
  char cap[96];
  snprintf(cap, sizeof cap, "Sensitivity: mean F_inf, F_sup over %d seeds when one choice changes",
           run->sweep_seeds);
  nl_harness_report_table(r, sw, cap, 5);
  nl_harness_figure(r, "sweep.png", "F_sup of the three signals against sample length and rate");
  double lo, hi, hlo, hhi, g_at = NAN, from = 256; /* lengths from which F_sup has settled */
  a3_range(sw, from, "oct1_f_sup", &lo, &hi);
  if (sh) {
    a3_range(sh, from, "oct1_f_sup", &hlo, &hhi);
    nl_harness_text(
        r,
        "Under the selected reading (%s) the first octave's F_sup stays within [%.4f, %.4f] over "
        "the sweep's lengths of %g units and more and all its rates (sweep_selected.tsv).\n",
        fname[run->win], hlo, hhi, from);
  }
  for (size_t k = 0; k < pt->nrows && isnan(g_at); k++)
    if (nl_table_value(pt, k, "freq") >= paper[0][1])
      g_at = nl_table_value(pt, k, "gamma_oct1") / NL_BOUNDS_T;
  double rms_inf = hv(hy, A3_SIGMA_RMS, 0, "f_inf");
  double raw_var = pow(hv(hy, A3_RAW, 0, "sigma") / hv(hy, 0, 0, "sigma"), 2);
  nl_harness_text(
      r,
      "Under the headline reading (%s), the first octave's F_sup stays within [%.4f, %.4f] over "
      "the sweep's lengths of %g units and more and all its rates, against the paper's %.4f, so "
      "the unstated sampling does not explain its gap; at the paper's F_sup its tail energy Gamma "
      "is %.3g T (first seed, psd.tsv). The ratio of the octaves' F_sup is %.3f under %s, %.3f "
      "under %s, %.3f in the paper. F_inf with sigma = sd is %.4f (1st octave, %s); with sigma = "
      "RMS (sigma^2 = mean^2 + var, the shader's mean included) %.7f, %.3g bins of 1/length. Raw "
      "values instead of (noise + 1)/2 move the first octave's F_sup from %.4f to %.4f (%.3g times "
      "the variance against the same T).\n",
      fname[0], lo, hi, from, paper[0][1], g_at, hv(hy, 0, 1, "f_sup") / hv(hy, 0, 0, "f_sup"),
      fname[0], m[1][2] / m[0][2], fname[run->win], paper[1][1] / paper[0][1],
      hv(hy, 0, 0, "f_inf"), fname[0], rms_inf, rms_inf * run->base->length, hv(hy, 0, 0, "f_sup"),
      hv(hy, A3_RAW, 0, "f_sup"), raw_var);
}
