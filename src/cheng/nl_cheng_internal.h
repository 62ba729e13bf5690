/* nl_cheng_internal.h - the problem's state, shared by the module's sources
 * (not installed; users see nl_cheng.h and nl_cheng_repro.h only). */
#ifndef NL_CHENG_INTERNAL_H
#define NL_CHENG_INTERNAL_H

#include "math/nl_math.h"
#include "cheng/nl_cheng.h"
#include "cheng/nl_cheng_repro.h"
#include "stats/nl_stats.h"

#include <math.h>
#include <stdint.h>

/* Undo record of one point of a one-octave move: its index, previous octave
 * value and previous term (one line of memory for the three). */
typedef struct { size_t i; double v, t; } nl_cheng__touch;

/* The statistic term over a sample of angles, kept incrementally: KS and
 * Kuiper through nl_stats_ks_incr, chi-square through bin counts. */
typedef struct {
  nl_cheng_stat kind;
  size_t k;          /* chi-square bins */
  size_t n;
  nl_stats_ks_incr *ks;
  long *count;       /* k bins */
  long sumsq;        /* sum of count^2 */
  double range[2];   /* {0, 2 pi}, the uniform CDF's params */
} nl_cheng_statstate;

void nl_cheng__stat_init(nl_cheng_statstate *s, nl_cheng_stat kind, size_t bins);
void nl_cheng__stat_clear(nl_cheng_statstate *s);
void nl_cheng__stat_reset(nl_cheng_statstate *s, const double *x, size_t n);
void nl_cheng__stat_replace(nl_cheng_statstate *s, double old_value, double new_value);
void nl_cheng__stat_undo(nl_cheng_statstate *s, double old_value, double new_value);
double nl_cheng__stat_value(const nl_cheng_statstate *s);
/* The same statistic from scratch through nl_stats' tests. */
double nl_cheng__stat_full(nl_cheng_stat kind, size_t bins, const double *x, size_t n);
/* Bin of v in k equal bins of [0, 2 pi]: nl_stats' rule, so the incremental
 * counts bin exactly as nl_stats_chisq_test_uniform does. */
static inline size_t nl_cheng__bin(double v, size_t k) { return nl_stats_chisq_bin(v, k, 0.0, NL_TWO_PI); }

struct nl_cheng_problem {
  nl_cheng_config c;
  const nl_cheng_pattern *pat;
  nl_noise_grad2 *g;
  size_t m, np;
  int F, level;
  double freq[NL_CHENG_MAX_OCTAVES], amp[NL_CHENG_MAX_OCTAVES], s;
  uint32_t *ck;          /* np * F * 4 corner entries */
  double *cw;            /* np * F * 4 * 2 corner weight vectors */
  double *nv;            /* np * F octave values */
  double *term;          /* np terms (c_i - D_i)^2 */
  unsigned char *used;   /* F * m: entry used by octave l's lattice */
  int *first_level;      /* m: lowest level using the entry, 0 = none */
  size_t *lstart;        /* F * (m + 1) list offsets */
  uint32_t *litem;       /* point indices */
  double *lw;            /* 2 per item: the point's summed corner weight vector for the entry */
  size_t *vars, nvars;
  size_t *sample, nsample;
  unsigned char *in_sample;
  nl_cheng_statstate st;
  double e_stat, e_con, e;
  /* undo record of the last move */
  int has_undo;
  size_t uk;
  double utheta, ugx, ugy, u_stat, u_con, u_e;
  int tlev;              /* >= 0: only octave tlev changed (records in tu), -1: F values (tp, tnv, tterm) */
  size_t *tp, ntouch;
  double *tnv, *tterm;
  nl_cheng__touch *tu;
  double *sv;            /* np: points' octave sums (then marble's sines) in a move or resum */
  double *spre;          /* np: the sums below the top octave in a resum */
  unsigned *mark, stamp;
  /* pd[2i]: point i's octave sum over octaves 0..level-2 (nl_cheng__octave_sum's
   * first level-1 steps, formed at each resum). A move of the top octave
   * adds only its own term to it, the same additions in the same order; valid
   * while pre_ok and amp[0..level-2] still equal pre_amp (a move of a lower
   * octave or a lower gain makes it stale until the next resum); pd[2i+1]:
   * its target D_i, beside it so a move reads one line a point. */
  double *pd;
  int pre_ok, pre_level;
  double pre_amp[NL_CHENG_MAX_OCTAVES];
  /* octave gains (X6, nl_cheng_amp.c): amp[l] = amp0[l] e^lg[l]; a gain move's
   * undo keeps the previous gain, s and every term */
  double amp0[NL_CHENG_MAX_OCTAVES], lg[NL_CHENG_MAX_OCTAVES];
  double u_lg, u_amp, u_s;
  double *uterm;         /* np terms, allocated with amp_vary */
};

/* Variable k of nl_cheng_vars: k < M a table entry's angle, k = M + l octave
 * l's log gain (amp_vary). */
static inline double nl_cheng__var_value(const nl_cheng_problem *p, size_t k)
{
  return k < p->m ? p->g->angle[k] : p->lg[k - p->m];
}
/* Gain moves (nl_cheng_amp.c): set octave l's log gain to u and return the new
 * E (every term re-evaluated); undo; a proposal for the annealer. */
double nl_cheng__amp_move(nl_cheng_problem *p, size_t l, double u);
void nl_cheng__amp_undo(nl_cheng_problem *p);
double nl_cheng__amp_propose(const nl_cheng_problem *p, gsl_rng *rng, size_t l, double sigma);
/* s = 1 / (sqrt(2)/2 sum amp): V = F_sum over its analytic bound. */
double nl_cheng__amp_scale(const double *amp, int n);

/* nl_cheng_resum for the annealer's temperature steps: the same result,
 * re-evaluating only the top octave when the lower ones cannot have moved
 * (nl_cheng_problem.c). */
void nl_cheng__resum_top(nl_cheng_problem *p);

/* The lattice indices lo..hi (each axis) that octave f's cells over the
 * domain [origin, origin + 1]^2 touch: floor(f o) .. ceil(f (o + 1)). */
void nl_cheng__lattice_range(double f, double origin, long *lo, long *hi);
/* The control value c of nl_cheng.h from a point's octave values (the first
 * `levels` of them); inline because every move evaluates it per point. In two
 * steps: the octave sum (left to right; fire sums |Noise_l|), with nv[rl]
 * read as rv when rl >= 0 (a move's new value, kept in a register: reading
 * it back right after storing it would stall the store forwarding), then
 * the texture's function of the sum. */
static inline double nl_cheng__octave_sum(nl_cheng_con con, const double *nv, const double *amp,
                                          int levels, int rl, double rv)
{
  double v = 0;
  if (con == NL_CHENG_CON_FIRE)
    for (int l = 0; l < levels; l++) v += amp[l] * fabs(l == rl ? rv : nv[l]);
  else
    for (int l = 0; l < levels; l++) v += amp[l] * (l == rl ? rv : nv[l]);
  return v;
}

/* Marble's sin(pi V) is nl_math_sinpi: the same bits under every libm, and
 * 0.7 of glibc's sin's time. The literal reading's sin V of the raw sum
 * stays libm's: sinpi(V / pi) would round V / pi first, which is not the
 * printed function, and a sine of a general argument of our own would need
 * its own reduction by 2 pi. */
static inline double nl_cheng__control_of_sum(nl_cheng_con con, double v, double s, int literal)
{
  if (literal)   /* eq. 3.8, 4.1-4.3 as printed: the raw fractal sum, sin V, |V| */
    return con == NL_CHENG_CON_SIN ? sin(v) : con == NL_CHENG_CON_ABS ? fabs(v) : v;
  if (con == NL_CHENG_CON_FIRE) return s * v;
  v *= s;   /* V in [-1, 1] */
  return con == NL_CHENG_CON_SIN ? 0.5 * (1.0 + nl_math_sinpi(v))
       : con == NL_CHENG_CON_ABS ? fabs(v) : 0.5 * (1.0 + v);
}

/* The octave sums of n points of F = 4 octaves at level 4 (every point's
 * first 4 values, nv + 4 tp[t], or nv + 4 t if tp is NULL) into sv, and
 * if pre is not NULL the sums of their first three into pre:
 * nl_cheng__octave_sum's doubles, four points a vector
 * (nl_cheng_simd_avx2.c; x86 with AVX2 only). */
void nl_cheng__sums4_avx2(size_t n, const size_t *tp, const double *nv, const double *amp,
                          int fire, double *sv, double *pre);

static inline double nl_cheng__control_value(nl_cheng_con con, const double *nv, const double *amp,
                                             int levels, double s, int literal)
{
  return nl_cheng__control_of_sum(con, nl_cheng__octave_sum(con, nv, amp, levels, -1, 0.0), s, literal);
}

#endif
