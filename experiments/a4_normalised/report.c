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
      "unit, F_sup measured per seed as in A3 (raw values, an oblique line of %g units at %g "
      "samples per unit, T = (2/255)^2): mean %.4f over %d seeds. The table gives the fraction of "
      "the variance above the Nyquist frequency %g of that sampling, i.e. what aliases.\n",
      run->rate, run->length, run->fine_rate, run->f_sup, run->seeds, 0.5 * run->rate);
  nl_harness_report_table(
      r, run->aliasing,
      "Energy above Nyquist before and after normalisation (mean and sd over seeds)", 5);
  char cap[128];
  snprintf(cap, sizeof cap, "Fig. 5.7: (a) noise, (b) noise(x / F_sup), %g samples per unit",
           run->rate);
  nl_harness_figure(r, "normalised.png", cap);
}

void a4_report_energy(nl_harness *r, const nl_table *et, double nyquist)
{
  nl_harness_text(r,
                  "**The claim as a number:** the paper's T = (2/255)^2 is the energy of a barely "
                  "visible change of the stored 8-bit value (noise + 1)/2, so what aliases at this "
                  "sampling is the stored value's energy above the Nyquist frequency %g, in units "
                  "of T (the same line, %d seeds; one-sided t tests of its mean against 1). Fig. "
                  "5.7 claims it is above T for noise(x), panel (a), and below T for Nnoise(x) = "
                  "noise(x / F_sup), panel (b), with the paper's F_sup = %.7f (Table 5.2); our own "
                  "F_sup (raw values, as above) is shown beside it.\n",
                  nyquist, (int)nl_table_value(et, 0, "seeds"), nl_table_value(et, 2, "divisor"));
  nl_harness_report_table(r, et, "Energy above Nyquist of the stored value, in units of T", 4);
  nl_harness_text(
      r,
      "noise(x) puts %.3g T above Nyquist (sd %.2g; p = %.2g that it is not above T); divided by "
      "our F_sup %.4f, %.3g T; by the paper's, %.3g T (p = %.2g that it is not below T).\n",
      nl_table_value(et, 0, "energy_over_t"), nl_table_value(et, 0, "energy_over_t_sd"),
      nl_table_value(et, 0, "p_above"), nl_table_value(et, 1, "divisor"),
      nl_table_value(et, 1, "energy_over_t"), nl_table_value(et, 2, "energy_over_t"),
      nl_table_value(et, 2, "p_below"));
  const char *test = "one-sided t test over seeds of the stored value's energy above Nyquist, in "
                     "units of T, against 1";
  nl_harness_verdict_p(r, "aliased_energy.tsv", et, 0,
                       "noise(x) at 2 samples per unit aliases: energy above Nyquist, Fig. 5.7 (a)",
                       "above T", "energy_over_t", "p_above", "p 0.01 0.05", "independent", test);
  nl_harness_verdict_p(
      r, "aliased_energy.tsv", et, 2,
      "Nnoise with the paper's F_sup does not alias: energy above Nyquist, Fig. 5.7 (b)", "below T",
      "energy_over_t", "p_below", "p 0.01 0.05", "independent", test);
  nl_harness_verdict_figure(r, "Fig. 5.7: Nnoise looks closer to the ideal noise than noise",
                            "aliasing patterns in (a), none in (b)", "normalised.png",
                            "the images; the energy rows above decide the aliasing");
}
