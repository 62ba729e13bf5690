/* Tests of nl_basis.h: each entry builds the noise its module's own calls
 * build (same values for the same seed), the names and aliases resolve,
 * bad options are refused with the option's name, and the sums evaluate as
 * nl_noise_fractal_grid does. */
#include "basis/nl_basis.h"
#include "nl_test.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static const nl_noise_window win = {0.25, -1.5, 0.5, 3.0, 9, 7};

static double *grid_of(const nl_noise_basis *b, const nl_noise_octaves *o)
{
  double *v = nl_xmalloc((size_t)win.w * win.h * sizeof *v);
  nl_noise_fractal_grid(b, o, &win, v);
  return v;
}

NL_TEST(every_entry_builds_and_frees)
{
  size_t n;
  const nl_basis_kind *k = nl_basis_kinds(&n);
  NL_CHECK(n == 4 && !strcmp(nl_basis_default()->name, "improved"));
  for (size_t i = 0; i < n; i++) {
    nl_basis *b;
    nl_error err;
    NL_CHECK(nl_basis_make(k[i].name, NULL, 3, &b, &err) == NL_OK);
    NL_CHECK(b->kind == &k[i] && b->noise.bound > 0);
    NL_CHECK(nl_basis_find(k[i].under) == &k[i]);
    nl_basis_free(b);
  }
}

NL_TEST(same_seed_same_noise_as_the_modules_own_calls)
{
  nl_basis *b, *t;
  nl_error err;
  nl_noise_octaves o = nl_noise_octaves_fractal(3);
  NL_CHECK(nl_basis_make("improved", NULL, 7, &b, &err) == NL_OK);
  nl_noise_perm3 p;
  nl_noise_perm3_seed(&p, 7);
  nl_noise_basis direct = nl_noise_basis_perm3(&p);
  double *u = grid_of(&b->noise, &o), *v = grid_of(&direct, &o);
  NL_CHECK(memcmp(u, v, (size_t)win.w * win.h * sizeof *u) == 0);
  free(u);
  free(v);
  nl_basis_free(b);
  /* noise2 and its name under a sum, "table", are one noise. */
  NL_CHECK(nl_basis_make("noise2", NULL, 7, &b, &err) == NL_OK);
  NL_CHECK(nl_basis_make("table", NULL, 7, &t, &err) == NL_OK);
  nl_noise_grad2 *g = nl_noise_grad2_alloc(512);
  nl_noise_grad2_seed(g, 7);
  direct = nl_noise_basis_grad2(g);
  u = grid_of(&b->noise, &o);
  v = grid_of(&direct, &o);
  double *w = grid_of(&t->noise, &o);
  NL_CHECK(memcmp(u, v, (size_t)win.w * win.h * sizeof *u) == 0);
  NL_CHECK(memcmp(u, w, (size_t)win.w * win.h * sizeof *u) == 0);
  free(u);
  free(v);
  free(w);
  nl_noise_grad2_free(g);
  nl_basis_free(b);
  nl_basis_free(t);
  /* Another seed, another table. */
  NL_CHECK(nl_basis_make("noise2", NULL, 8, &b, &err) == NL_OK);
  NL_CHECK(nl_basis_make("noise2", NULL, 7, &t, &err) == NL_OK);
  u = grid_of(&b->noise, &o);
  v = grid_of(&t->noise, &o);
  NL_CHECK(memcmp(u, v, (size_t)win.w * win.h * sizeof *u) != 0);
  free(u);
  free(v);
  nl_basis_free(b);
  nl_basis_free(t);
}

static int make_fails_with(const char *name, const nl_basis_options *o, const char *needle)
{
  nl_basis *b = (nl_basis *)1;
  nl_error err = {{0}};
  int ok = nl_basis_make(name, o, 1, &b, &err) != NL_OK && b == NULL
           && strstr(err.msg, needle) != NULL;
  if (!ok)
    fprintf(stderr, "  %s: got '%s'\n", name, err.msg);
  return ok;
}

NL_TEST(bad_names_and_options_are_refused)
{
  nl_basis_options o = nl_basis_defaults();
  NL_CHECK(make_fails_with("perlin", NULL, "perlin: unknown noise basis"));
  o.tile = 9;
  NL_CHECK(make_fails_with("wavelet", &o, "--tile: the wavelet tile period must be even"));
  /* outside the tile's range: refused, not a NULL tile seeded */
  long tiles[] = {4, 0, -2, 258, 1L << 40};
  for (size_t k = 0; k < sizeof tiles / sizeof *tiles; k++) {
    o.tile = tiles[k];
    NL_CHECK(make_fails_with("wavelet", &o, "in 8..256"));
  }
  o = nl_basis_defaults();
  o.terms = "F5";
  NL_CHECK(make_fails_with("gctbf", &o, "--terms: "));
  NL_CHECK(make_fails_with("gctbf", &o, "1..4"));
}

/* The render command's ranges, in the library so that its Python binding
 * refuses the same values with the same words. */
NL_TEST(sum_and_window_ranges_are_render_s)
{
  nl_error err;
  nl_basis_sum_options so = nl_basis_sum_defaults();
  NL_CHECK(nl_basis_sum_check(&so, &err) == NL_OK);
  so.lacunarity = 0;
  NL_CHECK(nl_basis_sum_check(&so, &err) == NL_EINVAL && !strcmp(err.msg, "--lacunarity: 0 is outside [1e-06, 1e+06]"));
  so = nl_basis_sum_defaults();
  so.gain = NAN;
  NL_CHECK(nl_basis_sum_check(&so, &err) == NL_EINVAL && !strcmp(err.msg, "--gain: nan is not a finite number"));
  so = nl_basis_sum_defaults();
  so.octaves = 31;
  NL_CHECK(nl_basis_sum_check(&so, &err) == NL_EINVAL && !strcmp(err.msg, "--octaves: 31 is outside [1, 30]"));
  so = nl_basis_sum_defaults();
  so.stripes = 0;
  NL_CHECK(nl_basis_sum_check(&so, &err) == NL_EINVAL && !strncmp(err.msg, "--stripes: ", 11));
  so = nl_basis_sum_defaults();
  so.amplitude = -2e6;
  NL_CHECK(nl_basis_sum_check(&so, &err) == NL_EINVAL && !strncmp(err.msg, "--amplitude: ", 13));
  nl_noise_window w = {0, 0, 0.5, 4, 512, 512};
  NL_CHECK(nl_basis_window_check(&w, &err) == NL_OK);
  w.x0 = 1e10;
  NL_CHECK(nl_basis_window_check(&w, &err) == NL_EINVAL && !strcmp(err.msg, "--x0: 1e+10 is outside [-1e+09, 1e+09]"));
  w.x0 = 0;
  w.size = INFINITY;
  NL_CHECK(nl_basis_window_check(&w, &err) == NL_EINVAL && !strcmp(err.msg, "--extent: inf is not a finite number"));
  w.size = 4;
  w.h = 65537;
  NL_CHECK(nl_basis_window_check(&w, &err) == NL_EINVAL && !strcmp(err.msg, "--size: 65537 is outside [1, 65536]"));
  nl_basis_options bo = nl_basis_defaults();
  nl_basis *b;
  bo.table_size = NL_BASIS_MAX_TABLE + 1;
  NL_CHECK(nl_basis_make("noise2", &bo, 1, &b, &err) == NL_EINVAL && !strncmp(err.msg, "--table-size: ", 14));
  NL_CHECK(nl_basis_options_check(&bo, &err) == NL_EINVAL && !strcmp(err.msg, "--table-size: 1048577 is outside [4, 1048576]"));
  bo = nl_basis_defaults();
  NL_CHECK(nl_basis_options_check(&bo, &err) == NL_OK);
  bo.tile = 7;   /* refused whatever the basis, as render refuses it */
  NL_CHECK(nl_basis_options_check(&bo, &err) == NL_EINVAL && !strcmp(err.msg, "--tile: 7 is outside [8, 256]"));
  bo = nl_basis_defaults();
  bo.lambda = NAN;
  NL_CHECK(nl_basis_options_check(&bo, &err) == NL_EINVAL && !strcmp(err.msg, "--lambda: nan is not a finite number"));
  bo = nl_basis_defaults();
  bo.points = 65;
  NL_CHECK(nl_basis_options_check(&bo, &err) == NL_EINVAL && !strcmp(err.msg, "--points: 65 is outside [1, 64]"));
}

NL_TEST(sums_are_the_octaves_of_their_rule)
{
  nl_basis_sum_options so = nl_basis_sum_defaults();
  const nl_basis_sum *fbm = nl_basis_sum_find("fbm"), *turb = nl_basis_sum_find("turbulence");
  NL_CHECK(fbm && turb && !nl_basis_sum_find("improved") && nl_basis_sum_find("marble"));
  so.octaves = 4;
  so.gain = 0.7;
  so.lacunarity = 1.9;
  nl_noise_octaves a = fbm->octaves(&so), b = nl_noise_octaves_fbm(4, 0.7, 1.9);
  NL_CHECK(a.n == 4 && a.freq[3] == b.freq[3] && a.amp[3] == b.amp[3]);
  NL_CHECK(turb->octaves(&so).turbulence == 1);
  nl_basis *nb;
  nl_error err;
  nl_basis_make("improved", NULL, 2, &nb, &err);
  double lo, hi, *v = nl_xmalloc((size_t)win.w * win.h * sizeof *v);
  nl_noise_octaves t = turb->octaves(&so);
  turb->grid(&nb->noise, &t, &so, &win, v, &lo, &hi);
  NL_CHECK(lo == 0 && hi == nl_noise_octaves_bound(&t, nb->noise.bound));
  for (int k = 0; k < win.w * win.h; k++)
    NL_CHECK(v[k] >= lo && v[k] <= hi);
  nl_noise_octaves one = nl_basis_single.octaves(&so);
  nl_basis_single.grid(&nb->noise, &one, &so, &win, v, &lo, &hi);
  NL_CHECK(lo == -nb->noise.bound && hi == nb->noise.bound);
  free(v);
  nl_basis_free(nb);
}

int main(void)
{
  return nl_test_run();
}
