/* test_cheng_fixture.h - what test_cheng.c and test_cheng_repro.c share: a
 * control pattern made from a built-in shape, and a problem on a seeded
 * table (opened and closed in one call each, so a test states only what it
 * varies: grid, config, seed). */
#ifndef TEST_CHENG_FIXTURE_H
#define TEST_CHENG_FIXTURE_H

#include "study/nl_study_cheng.h"
#include "nl_test.h"

/* The flower drawn at size x size pixels, as a grid x grid pattern. */
/* Small problems: the flower drawn at 96 pixels on a 16..32 grid (fast), thesis octaves. */
#define FLOWER_PX 96

/* Relative difference, absolute below 1. */
static inline double rel(double a, double b) { return fabs(a - b) / fmax(1.0, fabs(b)); }

static inline nl_cheng_pattern *test_flower(int size, int grid)
{
  nl_image *im = nl_study_cheng_shape("flower", size);
  nl_cheng_pattern *p = NULL;
  nl_error err;
  NL_CHECK(nl_study_cheng_pattern_from_image(im, grid, &p, &err) == NL_OK);
  nl_image_free(im);
  return p;
}

typedef struct {
  nl_cheng_pattern *pat;
  nl_cheng_config c;
  nl_noise_grad2 *g;          /* c.m angles from `seed` */
  nl_cheng_problem *p;  /* on c, pat and g; NULL when with_problem is 0 */
} test_fixture;

static inline void test_fixture_open(test_fixture *f, int size, int grid, const nl_cheng_config *c,
                                     unsigned long seed, int with_problem)
{
  nl_error err;
  f->pat = test_flower(size, grid);
  f->c = *c;
  f->g = nl_noise_grad2_alloc(c->m);
  nl_noise_grad2_seed(f->g, seed);
  f->p = with_problem ? nl_cheng_problem_alloc(&f->c, f->pat, f->g, &err) : NULL;
  NL_CHECK(!with_problem || f->p);
}

static inline void test_fixture_close(test_fixture *f)
{
  nl_cheng_problem_free(f->p);
  nl_noise_grad2_free(f->g);
  nl_cheng_pattern_free(f->pat);
}

#endif
