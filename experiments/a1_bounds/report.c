/* report.c - A1's report prose (report.h). */
#include "report.h"
#include "noise/nl_noise.h"

#include <math.h>
#include <stdio.h>

void a1_report(nl_harness *r, const a1_run *run)
{
  const nl_table *t = run->bounds;
  nl_harness_text(
      r,
      "**Paper:** |b_i| <= 2^-i (eq. 4.1), |Fnoise_n| <= S_{n-1}, S_n = 2 - 2^-n (eq. 4.2-4.3), "
      "and after k octaves the rest of the sum adds at most S_{Nmax-1} - S_{k-1} (eq. 5.3-5.4, "
      "read as the interval partial +- remainder). All assume |noise| <= 1.\n\n"
      "**Ours:** Perlin's improved 3D noise on %ld random points in [-100, 100)^3 per octave count "
      "and seed, %d seeds. `S` is the paper's bound S_{n-1}; `bound` = %.4f S_{n-1} uses the "
      "analytic bound of improved noise (NL_NOISE3_BOUND, gradients of length sqrt 2). `over_*` "
      "count points whose sum leaves the fractal bound, or some incremental interval.\n",
      run->points, run->seeds, NL_NOISE3_BOUND);
  nl_harness_report_table(r, t, "Observed extremes against the bounds", 4);
  char cap[96];
  snprintf(cap, sizeof cap, "Largest |Fnoise_n| seen against S_{n-1} and %.4f S_{n-1}",
           NL_NOISE3_BOUND);
  nl_harness_figure(r, "bounds.png", cap);
  double m1 = 0;
  long over[4] = { 0, 0, 0, 0 }, first = 0; /* first: octave count of the paper's first failure */
  const char *oc[4] = { "over_paper", "over_paper_incremental", "over_bound",
                        "over_bound_incremental" };
  for (size_t k = 0; k < t->nrows; k++) {
    m1 = fmax(m1, nl_table_value(t, k, "max_noise"));
    for (int c = 0; c < 4; c++) over[c] += (long)nl_table_value(t, k, oc[c]);
    if (!first && over[0] + over[1] > 0) first = (long)nl_table_value(t, k, "octaves");
  }
  char paper[200];
  if (over[0] + over[1] == 0)
    snprintf(paper, sizeof paper,
             "no point left the paper's fractal bound or any of its incremental intervals");
  else
    snprintf(paper, sizeof paper,
             "the paper's fractal bound failed at %ld points and an incremental interval at %ld "
             "(first at %ld octaves)",
             over[0], over[1], first);
  nl_harness_text(
      r,
      "The largest single-octave |noise| seen is %.6f. Improved noise can exceed 1 (its analytic "
      "bound is %.4f), so the paper's unit bound is an assumption, not a theorem, for it. Over the "
      "%d octave counts (%ld points each) %s; with the analytic bound, %ld and %ld points.\n",
      m1, NL_NOISE3_BOUND, run->nmax, run->points * run->seeds, paper, over[2], over[3]);
}
