/* oracle_survey - S1, S2 and S3's panels against their captions.
 *
 *   oracle_survey s1|s2|s3 OUTDIR
 *
 * Each panel's caption names a sum of octaves of Perlin's improved noise
 * ("(b) 2 octaves": sum_{j<2} noise(2^j p) / 2^j; "(c) gain 0.5": sum_j
 * 0.5^j noise(2^j p); turbulence sums |noise|) on the slice z of the
 * window [0, extent)^2 at pixel centres, for the run's first seed, shown
 * from its mean - 3 sd to its mean + 3 sd. This computes each panel by
 * another path than the survey (nl_study_survey_series -> the rows of
 * nl_noise_fractal_grid, SIMD where the CPU has it): one point at a time
 * through nl_noise_perm3_eval_general, the octaves summed here, and
 * compares the PNG's panels to 8 bits. A panel that shows another octave,
 * another sum or another seed fails (correlation and grey levels). It also
 * checks that panels whose captions differ do not show one picture.
 * Parameters (size, extent, z, octaves, seed) are read from the run's
 * manifest. Exit 0 when every panel matches, 1 with one line per mismatch.
 */
#include "oracle.h"

#include "base/nl_base.h"
#include "noise/nl_noise.h"
#include "table/nl_table.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
  int n;              /* octaves */
  double gain, lac;
  int turbulence;
} sum_spec;

/* The caption's sum at pixel (i, j) of a w x w raster of [0, extent)^2. */
static void render(const nl_noise_perm3 *p, const sum_spec *s, int w, double extent, double z, double *v)
{
  double d = extent / w;
  for (int j = 0; j < w; j++)
    for (int i = 0; i < w; i++) {
      double x = (i + 0.5) * d, y = (j + 0.5) * d, a = 1, f = 1, sum = 0;
      for (int l = 0; l < s->n; l++, a *= s->gain, f *= s->lac) {
        double nv = nl_noise_perm3_eval_general(p, f * x, f * y, f * z);
        sum += a * (s->turbulence ? fabs(nv) : nv);
      }
      v[(size_t)j * w + i] = sum;
    }
}

static void mean_sd(const double *v, size_t n, double *m, double *sd)
{
  double s = 0, ss = 0;
  for (size_t k = 0; k < n; k++) s += v[k];
  *m = s / n;
  for (size_t k = 0; k < n; k++) ss += (v[k] - *m) * (v[k] - *m);
  *sd = sqrt(ss / (n - 1));
}

/* One montage: n panels with these captions and sums. Returns failures. */
static int check_montage(const char *dir, const char *file, const char *title, int n, const char *const *labels,
                         const sum_spec *specs, const nl_table *man)
{
  int w = (int)oracle_param(man, "size", 128);
  double extent = oracle_param(man, "extent", 4), z = oracle_param(man, "z", 64.0 / 3);
  const char *seed_text = oracle_manifest_value(man, "seed");
  unsigned long seed = seed_text ? strtoul(seed_text, NULL, 10) : 1;
  int ws[8], hs[8], bad = 0;
  for (int i = 0; i < n; i++) ws[i] = hs[i] = w;
  char path[1024];
  snprintf(path, sizeof path, "%s/%s", dir, file);
  oracle_montage m;
  if (oracle_montage_read(&m, path, ws, hs, labels, n, n, title)) {
    printf("%s: %s\n", file, m.err);
    oracle_montage_free(&m);
    return 1;
  }
  nl_noise_perm3 p;
  nl_noise_perm3_seed(&p, nl_seed_replicate(seed, 0));
  double *v = malloc((size_t)w * w * sizeof *v);
  for (int i = 0; i < n; i++) {
    double mu, sd;
    render(&p, &specs[i], w, extent, z, v);
    mean_sd(v, (size_t)w * w, &mu, &sd);
    oracle_result res = oracle_panel_compare(&m, i, v, w, w, mu - 3 * sd, mu + 3 * sd);
    if (res.max_diff > ORACLE_TOL_8BIT || res.corr < 0.999) {
      printf("%s: panel %s is not its caption: max grey difference %.4f at (%d, %d), correlation %.4f\n",
             file, labels[i], res.max_diff, res.x, res.y, res.corr);
      bad++;
    }
  }
  /* captions that differ show different pictures */
  for (int i = 0; i + 1 < n; i++) {
    double c = oracle_panels_corr(&m, i, i + 1);
    if (c > 0.9999) {
      printf("%s: panels %s and %s show one picture (correlation %.5f)\n", file, labels[i], labels[i + 1], c);
      bad++;
    }
  }
  free(v);
  oracle_montage_free(&m);
  return bad;
}

static int octave_series(const char *dir, const char *prefix, const char *title, int turbulence,
                         const nl_table *man)
{
  const int oct[4] = {1, 2, 3, 8};
  const char *labels[4] = {"(a) 1 octave", "(b) 2 octaves", "(c) 3 octaves", "(d) 8 octaves"};
  sum_spec s[4];
  for (int i = 0; i < 4; i++) s[i] = (sum_spec){oct[i], 0.5, 2.0, turbulence};
  char file[128];
  snprintf(file, sizeof file, "%s_panels.png", prefix);
  return check_montage(dir, file, title, 4, labels, s, man);
}

int main(int argc, char **argv)
{
  if (argc != 3) {
    fprintf(stderr, "usage: oracle_survey s1|s2|s3 OUTDIR\n");
    return 2;
  }
  const char *dir = argv[2];
  nl_table *man = oracle_read_table("oracle_survey", dir, "manifest.tsv");
  if (!man) return 2;
  int bad = 0;
  if (!strcmp(argv[1], "s1")) {
    bad = octave_series(dir, "fractal", "fractal_sum(p) = sum noise(2^j p) / 2^j", 0, man);
  } else if (!strcmp(argv[1], "s2")) {
    bad = octave_series(dir, "turbulence", "turbulence(p) = sum |noise(2^j p)| / 2^j", 1, man);
  } else if (!strcmp(argv[1], "s3")) {
    int oct = (int)oracle_param(man, "octaves", 6);
    const double gains[5] = {0, 0.25, 0.5, 0.75, 1.0}, lacs[5] = {0.5, 1, 2, 4, 8};
    char gl[5][32], ll[5][32];
    const char *gp[5], *lp[5];
    sum_spec g[5], l[5];
    for (int i = 0; i < 5; i++) {
      snprintf(gl[i], 32, "(%c) gain %g", 'a' + i, gains[i]);
      snprintf(ll[i], 32, "(%c) lacunarity %g", 'a' + i, lacs[i]);
      gp[i] = gl[i];
      lp[i] = ll[i];
      g[i] = (sum_spec){oct, gains[i], 2.0, 0};
      l[i] = (sum_spec){oct, 0.5, lacs[i], 0};
    }
    bad = check_montage(dir, "gain_panels.png", "fBm, lacunarity 2: gain 0, 0.25, 0.5, 0.75, 1", 5, gp, g, man) +
          check_montage(dir, "lacunarity_panels.png", "fBm, gain 0.5: lacunarity 0.5, 1, 2, 4, 8", 5, lp, l, man);
  } else {
    fprintf(stderr, "oracle_survey: %s: wanted s1, s2 or s3\n", argv[1]);
    bad = -1;
  }
  nl_table_free(man);
  return bad < 0 ? 2 : bad > 0;
}
