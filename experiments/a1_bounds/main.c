/* A1 - Arnerin 2009 eq. 4.1-4.3 and 5.1-5.4: the octave bound 2^-i, the
 * fractal bound S_{n-1} = 2 - 2^-(n-1) and the incremental bound, checked on
 * random points of Perlin's improved 3D noise, under the paper's assumption
 * |noise| <= 1 and under the noise's analytic bound. */
#include "bounds/nl_bounds.h"
#include "harness/nl_harness.h"

#include <gsl/gsl_statistics_double.h>
#include <math.h>

int main(int argc, char **argv)
{
  nl_harness *r = nl_harness_begin("a1_bounds", "A1 - Octave, fractal and incremental bounds", argc, argv);
  int nmax = (int)nl_harness_param_int(r, "octaves", nl_harness_quick(r) ? 8 : 12, 1, 30,
                                       "largest octave count n the bounds are evaluated at (quick 8)");
  long points = nl_harness_param_int(r, "points", nl_harness_quick(r) ? 5000 : 100000, 1, 100000000,
                                     "random evaluation points per octave count the bounds are checked against (quick 5000)");
  nl_harness_params_done(r);
  int seeds = nl_harness_seeds(r);
  unsigned long seed0 = nl_harness_seed(r);

  const char *cols[] = {"octaves", "S", "bound", "max_abs", "max_abs_mean", "max_abs_sd",
                        "max_noise", "points", "over_paper", "over_paper_incremental",
                        "over_bound", "over_bound_incremental"};
  nl_table *t = nl_table_alloc(12, cols);
  double *maxes = nl_xmalloc((size_t)seeds * sizeof *maxes);
  for (int n = 1; n <= nmax; n++) {
    nl_noise_octaves o = nl_noise_octaves_fractal(n);
    long over_p = 0, over_pi = 0, over_b = 0, over_bi = 0;
    double max_noise = 0;
    for (int s = 0; s < seeds; s++) {
      nl_noise_perm3 p;
      nl_noise_perm3_seed(&p, nl_seed_replicate(seed0, s));
      nl_bounds_check paper, ours;
      nl_bounds_check_random(&p, &o, 1.0, points, nl_seed_stream(nl_seed_replicate(seed0, s), "a1.points", (unsigned long)n), &paper);
      nl_bounds_check_random(&p, &o, NL_NOISE3_BOUND, points, nl_seed_stream(nl_seed_replicate(seed0, s), "a1.points", (unsigned long)n), &ours);
      maxes[s] = ours.max_abs_sum;
      max_noise = fmax(max_noise, ours.max_abs_noise);
      over_p += paper.over_fractal; over_pi += paper.over_incremental;
      over_b += ours.over_fractal; over_bi += ours.over_incremental;
    }
    double mx = gsl_stats_max(maxes, 1, (size_t)seeds);
    double mean = gsl_stats_mean(maxes, 1, (size_t)seeds);
    double sd = seeds > 1 ? gsl_stats_sd(maxes, 1, (size_t)seeds) : 0.0;
    nl_table_append(t, "iddddddiiiii", n, nl_bounds_fractal(n), NL_NOISE3_BOUND * nl_bounds_fractal(n),
                    mx, mean, sd, max_noise, (int)(points * seeds), (int)over_p, (int)over_pi,
                    (int)over_b, (int)over_bi);
    nl_harness_progress(r, (double)n / nmax, "octaves");
  }
  nl_harness_write_table(r, t, "bounds.tsv");

  nl_harness_text(r, "**Paper:** |b_i| <= 2^-i (eq. 4.1), |Fnoise_n| <= S_{n-1}, S_n = 2 - 2^-n "
                     "(eq. 4.2-4.3), and after k octaves the rest of the sum adds at most "
                     "S_{Nmax-1} - S_{k-1} (eq. 5.3-5.4, read as the interval partial +- remainder). "
                     "All assume |noise| <= 1.\n\n"
                     "**Ours:** Perlin's improved 3D noise on %ld random points in [-100, 100)^3 "
                     "per octave count and seed, %d seeds. `S` is the paper's bound S_{n-1}; "
                     "`bound` = %.4f S_{n-1} uses the analytic bound of improved noise "
                     "(NL_NOISE3_BOUND, gradients of length sqrt 2). `over_*` count points whose sum "
                     "leaves the fractal bound, or some incremental interval.\n",
                  points, seeds, NL_NOISE3_BOUND);
  nl_harness_report_table(r, t, "Observed extremes against the bounds", 4);
  char cap[96];
  snprintf(cap, sizeof cap, "Largest |Fnoise_n| seen against S_{n-1} and %.4f S_{n-1}", NL_NOISE3_BOUND);
  nl_harness_figure(r, "bounds.png", cap);
  double m1 = 0;
  long over[4] = {0, 0, 0, 0}, first = 0;   /* first: octave count of the paper's first failure */
  const char *oc[4] = {"over_paper", "over_paper_incremental", "over_bound", "over_bound_incremental"};
  for (size_t k = 0; k < t->nrows; k++) {
    m1 = fmax(m1, nl_table_value(t, k, "max_noise"));
    for (int c = 0; c < 4; c++) over[c] += (long)nl_table_value(t, k, oc[c]);
    if (!first && over[0] + over[1] > 0) first = (long)nl_table_value(t, k, "octaves");
  }
  char paper[200];
  if (over[0] + over[1] == 0)
    snprintf(paper, sizeof paper, "no point left the paper's fractal bound or any of its incremental intervals");
  else
    snprintf(paper, sizeof paper, "the paper's fractal bound failed at %ld points and an incremental interval at %ld "
             "(first at %ld octaves)", over[0], over[1], first);
  nl_harness_text(r, "The largest single-octave |noise| seen is %.6f. Improved noise can exceed 1 "
                     "(its analytic bound is %.4f), so the paper's unit bound is an assumption, not a "
                     "theorem, for it. Over the %d octave counts (%ld points each) %s; with the analytic "
                     "bound, %ld and %ld points.\n",
                  m1, NL_NOISE3_BOUND, nmax, points * seeds, paper, over[2], over[3]);
  free(maxes);
  nl_table_free(t);
  nl_harness_check_measured(r, "*", 100);   /* measured tolerances (nl_harness.h) */
  return nl_harness_end(r);
}
