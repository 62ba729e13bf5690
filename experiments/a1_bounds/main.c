/* A1 - Arnerin 2009 eq. 4.1-4.3 and 5.1-5.4: the octave bound 2^-i, the
 * fractal bound S_{n-1} = 2 - 2^-(n-1) and the incremental bound, checked on
 * random points of Perlin's improved 3D noise, under the paper's assumption
 * |noise| <= 1 and under the noise's analytic bound; and that assumption
 * itself, by the largest |noise| a local maximiser finds (maxnoise.h). */
#include "bounds/nl_bounds.h"
#include "harness/nl_harness.h"
#include "maxnoise.h"
#include "report.h"

#include <gsl/gsl_statistics_double.h>
#include <math.h>
#include <stdlib.h>

int main(int argc, char **argv)
{
  nl_harness *r =
      nl_harness_begin("a1_bounds", "A1 - Octave, fractal and incremental bounds", argc, argv);
  int nmax =
      (int)nl_harness_param_int(r, "octaves", nl_harness_quick(r) ? 8 : 12, 1, 30,
                                "largest octave count n the bounds are evaluated at (quick 8)");
  long points = nl_harness_param_int(
      r, "points", nl_harness_quick(r) ? 5000 : 100000, 1, 100000000,
      "random evaluation points per octave count the bounds are checked against (quick 5000)");
  long cands = nl_harness_param_int(
      r, "candidates", nl_harness_quick(r) ? 100000 : 4000000, 1, 100000000,
      "random points per seed in one period whose largest |noise| start the climbs (quick 100000)");
  int starts = (int)nl_harness_param_int(r, "starts", nl_harness_quick(r) ? 100 : 1000, 1, 100000,
                                         "local climbs of |noise| per seed (quick 100)");
  nl_harness_params_done(r);
  int seeds = nl_harness_seeds(r);
  unsigned long seed0 = nl_harness_seed(r);

  const char *cols[] = { "octaves",
                         "S",
                         "bound",
                         "max_abs",
                         "max_abs_mean",
                         "max_abs_sd",
                         "max_noise",
                         "points",
                         "over_paper",
                         "over_paper_incremental",
                         "over_bound",
                         "over_bound_incremental",
                         "over_paper_octave" };
  nl_table *t = nl_table_alloc(13, cols);
  double *maxes = nl_xmalloc((size_t)seeds * sizeof *maxes);
  nl_harness_stage(r, 0.0, 0.5, "octaves");   /* one progress bar over both loops */
  for (int n = 1; n <= nmax; n++) {
    nl_noise_octaves o = nl_noise_octaves_fractal(n);
    long over_p = 0, over_pi = 0, over_b = 0, over_bi = 0, over_o = 0;
    double max_noise = 0;
    for (int s = 0; s < seeds; s++) {
      nl_noise_perm3 p;
      nl_noise_perm3_seed(&p, nl_seed_replicate(seed0, s));
      nl_bounds_check paper, ours;
      /* the same points under the paper's unit bound and the analytic one */
      unsigned long pts =
          nl_seed_stream(nl_seed_replicate(seed0, s), "a1.points", (unsigned long)n);
      nl_bounds_check_random(&p, &o, 1.0, points, pts, &paper);
      nl_bounds_check_random(&p, &o, NL_NOISE3_BOUND, points, pts, &ours);
      maxes[s] = ours.max_abs_sum;
      max_noise = fmax(max_noise, ours.max_abs_noise);
      over_p += paper.over_fractal;
      over_pi += paper.over_incremental;
      over_b += ours.over_fractal;
      over_bi += ours.over_incremental;
      over_o += a1_octave_over(&p, n, points, pts);
    }
    double mx = gsl_stats_max(maxes, 1, (size_t)seeds);
    double mean = gsl_stats_mean(maxes, 1, (size_t)seeds);
    double sd = seeds > 1 ? gsl_stats_sd(maxes, 1, (size_t)seeds) : 0.0;
    nl_table_append(t, "iddddddiiiiii", n, nl_bounds_fractal(n),
                    NL_NOISE3_BOUND * nl_bounds_fractal(n), mx, mean, sd, max_noise,
                    (int)(points * seeds), (int)over_p, (int)over_pi, (int)over_b, (int)over_bi,
                    (int)over_o);
    nl_harness_progress(r, (double)n / nmax, "octaves");
  }
  nl_harness_write_table(r, t, "bounds.tsv");

  /* The premise |noise| <= 1: climbs from the largest of random points;
   * the candidates themselves, unclimbed, are the random-point control. */
  const char *mcols[] = { "seed",       "candidates",      "starts",     "sampled_max",
                          "local_max",  "x",               "y",          "z",
                          "candidates_over", "climbs_over" };
  nl_table *mt = nl_table_alloc(10, mcols);
  /* eq. 4.2: the same climbs on |Fnoise_n| / S_{n-1}, at 2 octaves and at nmax */
  const char *fcols[] = { "seed", "octaves", "sampled_max", "local_max", "candidates_over",
                          "climbs_over" };
  nl_table *ft = nl_table_alloc(6, fcols);
  /* eq. 5.4 as printed on the points of bounds.tsv at nmax octaves */
  const char *pcols[] = { "seed", "octaves", "points", "over_printed", "over_dropped" };
  nl_table *pt = nl_table_alloc(5, pcols);
  int fn[2] = { 2, nmax };
  nl_harness_stage(r, 0.5, 1.0, "climbs");
  for (int s = 0; s < seeds; s++) {
    nl_noise_perm3 p;
    nl_noise_perm3_seed(&p, nl_seed_replicate(seed0, s));
    a1_climbs c;
    a1_climb_sum(&p, 1, cands, starts, nl_seed_replicate(seed0, s), &c);
    nl_table_append(mt, "iiidddddii", s, (int)cands, starts, c.sampled, c.best, c.xyz[0],
                    c.xyz[1], c.xyz[2], (int)c.candidates_over, (int)c.climbs_over);
    for (int k = 0; k < 2 && fn[k] >= 2; k++) {
      if (k == 1 && fn[1] == fn[0]) break;
      a1_climb_sum(&p, fn[k], cands, starts, nl_seed_replicate(seed0, s), &c);
      nl_table_append(ft, "iiddii", s, fn[k], c.sampled, c.best, (int)c.candidates_over,
                      (int)c.climbs_over);
    }
    long printed, dropped;
    unsigned long pts =
        nl_seed_stream(nl_seed_replicate(seed0, s), "a1.points", (unsigned long)nmax);
    a1_printed_over(&p, nmax, points, pts, &printed, &dropped);
    nl_table_append(pt, "iiiii", s, nmax, (int)points, (int)printed, (int)dropped);
    nl_harness_progress(r, (double)(s + 1) / seeds, "climbs");
  }
  nl_harness_write_table(r, mt, "max_noise.tsv");
  nl_harness_write_table(r, ft, "fractal_climbs.tsv");
  nl_harness_write_table(r, pt, "printed.tsv");

  a1_run run = { nmax, points, seeds, t, mt, ft, pt };
  a1_report(r, &run);
  a1_verdicts(r, &run);
  free(maxes);
  nl_table_free(t);
  nl_table_free(mt);
  nl_table_free(ft);
  nl_table_free(pt);
  nl_harness_check_measured(r, "*", 100); /* measured tolerances (nl_harness.h) */
  return nl_harness_end(r);
}
