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
      "(images only). **Ours:** the plane z = 0.5 of improved noise at %g samples per unit, F_sup "
      "measured per seed as in A3 (raw values, an oblique line of %g units at %g samples per unit, "
      "T = (2/255)^2): mean %.4f over %d seeds. The table gives the fraction of the variance above "
      "the Nyquist frequency %g of that sampling, i.e. what aliases.\n",
      run->rate, run->length, run->fine_rate, run->f_sup, run->seeds, 0.5 * run->rate);
  nl_harness_report_table(
      r, run->aliasing,
      "Energy above Nyquist before and after normalisation (mean and sd over seeds)", 5);
  char cap[128];
  snprintf(cap, sizeof cap, "Fig. 5.7: (a) noise, (b) noise(x / F_sup), %g samples per unit",
           run->rate);
  nl_harness_figure(r, "normalised.png", cap);
  nl_harness_text(r,
                  "Normalising by F_sup stretches the noise by %.2f so that the energy above "
                  "Nyquist is at most T by construction; it also makes the features larger, which "
                  "is the price of the normalisation.\n",
                  run->f_sup);
}
