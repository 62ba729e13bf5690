/* report.c - A4's report prose (report.h). */
#include "report.h"

#include <stdio.h>

void a4_figure_title(const a4_run *run, char *buf, size_t size)
{
  snprintf(buf, size, "Fig. 5.7: %g samples per unit", run->rate);
}

void a4_report(nl_harness *r, const a4_run *run)
{
  nl_harness_text(
      r,
      "**Paper (Fig. 5.7):** the original and the spectrally normalised Perlin noise Nnoise(x) = "
      "noise(x / F_sup), sampled at 2 x 2 pixels per unit^2: aliasing patterns in (a), none in (b) "
      "(images only in the paper). **Ours:** the plane z = 0.5 of improved noise at %g samples per "
      "unit, F_sup measured per seed as in A3's headline (the stored value (noise + 1) / 2, an "
      "oblique line of %g units at %g samples per unit, T = (2/255)^2): mean %.4f over %d seeds. The table gives the fraction of "
      "the variance above the Nyquist frequency %g of that sampling, i.e. what aliases.\n",
      run->rate, run->length, run->fine_rate, run->f_sup, run->seeds, 0.5 * run->rate);
  nl_harness_report_table(
      r, run->aliasing,
      "Energy above Nyquist before and after normalisation (mean and sd over seeds)", 5);
  char cap[128];
  snprintf(cap, sizeof cap,
           "Fig. 5.7: (a) noise, (b) noise(x / F_sup), F_sup = %.7f (Table 5.2), %g samples per unit",
           run->paper_f_sup, run->rate);
  nl_harness_figure(r, "normalised.png", cap);
}

void a4_report_energy(nl_harness *r, const a4_run *run, const nl_table *et, const nl_table *et2,
                      double nyquist)
{
  nl_harness_text(r,
                  "**The claim as a number:** the paper's T = (2/255)^2 is the energy of a barely "
                  "visible change of the stored 8-bit value (noise + 1)/2, so what aliases at this "
                  "sampling is the stored value's energy above the Nyquist frequency %g, in units "
                  "of T (%d seeds; one-sided t tests of its mean against 1). Fig. 5.7 claims it is "
                  "above T for noise(x), panel (a), and below T for Nnoise(x) = noise(x / F_sup), "
                  "panel (b), with the paper's F_sup = %.7f (Table 5.2); our own F_sup (as above) "
                  "is shown beside it. Fig. 5.7 is a 2D image: the headline measures the plane "
                  "z = 0.5 over %g x %g units at %g samples per unit (Hann tapered), the power "
                  "outside the square |f_x|, |f_y| <= %g that a grid of 2 samples per unit folds "
                  "back. On the line the same energy restates the F_sup it was divided by: the "
                  "stored value's energy above 1 cycle per unit of noise(x / F) is the tail "
                  "Gamma(F) that defines F_sup, about T at our F_sup, so the line's rows say "
                  "whether the divisor lies above or below our F_sup (A3's F_sup rows).\n",
                  nyquist, (int)nl_table_value(et, 0, "seeds"), nl_table_value(et, 2, "divisor"),
                  run->extent, run->extent, run->plane_rate, nyquist);
  nl_harness_report_table(r, et2, "Energy above Nyquist of the stored value on the 2D plane, in T",
                          4);
  nl_harness_report_table(r, et, "The same along the line (1D), in T", 4);
  nl_harness_text(
      r,
      "On the plane noise(x) puts %.3g T above Nyquist (sd %.2g; p = %.2g that it is not above "
      "T); divided by our F_sup %.4f, %.3g T (p = %.2g that it is not below T); by the paper's, "
      "%.3g T (p = %.2g). Along the line: %.3g, %.3g and %.3g T.\n",
      nl_table_value(et2, 0, "energy_over_t"), nl_table_value(et2, 0, "energy_over_t_sd"),
      nl_table_value(et2, 0, "p_above"), nl_table_value(et2, 1, "divisor"),
      nl_table_value(et2, 1, "energy_over_t"), nl_table_value(et2, 1, "p_below"),
      nl_table_value(et2, 2, "energy_over_t"), nl_table_value(et2, 2, "p_below"),
      nl_table_value(et, 0, "energy_over_t"), nl_table_value(et, 1, "energy_over_t"),
      nl_table_value(et, 2, "energy_over_t"));
  const char *test = "one-sided t test over seeds of the stored value's energy above Nyquist on "
                     "the plane, in units of T, against 1";
  /* The controls: for (a), the normalised noise the paper says does not
   * alias; for (b), the noise without the normalisation. */
  nl_harness_verdict_p(r, "aliased_energy_2d.tsv", et2, 0,
                       "noise(x) at 2 samples per unit aliases: 2D energy above Nyquist, Fig. 5.7 (a)",
                       "above T", "energy_over_t", "p_above", "p 0.01 0.05", "independent", test);
  nl_harness_verdict_control(r, "Nnoise with the paper's F_sup", "aliased_energy_2d.tsv", et2, 2);
  nl_harness_verdict_p(
      r, "aliased_energy_2d.tsv", et2, 2,
      "Nnoise with the paper's F_sup does not alias: 2D energy above Nyquist, Fig. 5.7 (b)",
      "below T", "energy_over_t", "p_below", "p 0.01 0.05", "independent", test);
  nl_harness_verdict_control(r, "noise(x), not normalised", "aliased_energy_2d.tsv", et2, 0);
  nl_harness_verdict_p(
      r, "aliased_energy_2d.tsv", et2, 1,
      "Nnoise with our F_sup does not alias: 2D energy above Nyquist", "below T", "energy_over_t",
      "p_below", "p 0.01 0.05", "independent", test);
  nl_harness_verdict_control(r, "noise(x), not normalised", "aliased_energy_2d.tsv", et2, 0);
  /* On the line the rows restate F_sup's definition (Gamma(F) <= T for F
   * at or above ours): A3's F_sup rows decide them. */
  const char *line = "on the line: Gamma at the divisor, which A3's F_sup rows decide";
  nl_harness_verdict_p(r, "aliased_energy.tsv", et, 0,
                       "noise(x) at 2 samples per unit aliases: energy above Nyquist, Fig. 5.7 (a)",
                       "above T", "energy_over_t", "p_above", "p 0.01 0.05", "by construction", line);
  nl_harness_verdict_p(
      r, "aliased_energy.tsv", et, 2,
      "Nnoise with the paper's F_sup does not alias: energy above Nyquist, Fig. 5.7 (b)", "below T",
      "energy_over_t", "p_below", "p 0.01 0.05", "by construction", line);
  nl_harness_verdict_figure(r, "Fig. 5.7: Nnoise looks closer to the ideal noise than noise",
                            "aliasing patterns in (a), none in (b)", "normalised.png",
                            "the images; the energy rows above decide the aliasing");
}
