/* The incremental objective of eq. 3.9 at one level (see nl_cheng.h). */
#include "cheng/nl_cheng_internal.h"
#include "noise/nl_noise_lattice.h"
#include "simd/nl_simd.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* Corner weight vectors W = w(u) w(v) Delta of eq. 3.2 for a point with
 * fractional offsets (tx, ty) in its cell; corner order (0,0) (1,0) (0,1) (1,1). */
static void corner_weights(double tx, double ty, double *w)
{
  double fx = nl_noise_fade(tx), fy = nl_noise_fade(ty);
  double sx[2] = {1 - fx, fx}, sy[2] = {1 - fy, fy};
  for (int c = 0; c < 4; c++) {
    int di = c & 1, dj = c >> 1;
    double s = sx[di] * sy[dj];
    w[2 * c] = s * (tx - di);
    w[2 * c + 1] = s * (ty - dj);
  }
}

void nl_cheng__lattice_range(double f, double origin, long *lo, long *hi)
{
  *lo = (long)floor(f * origin);
  *hi = (long)ceil(f * (origin + 1));
}

/* Corners of every (point, octave): table entry and weight vector. */
static void build_corners(nl_cheng_problem *p)
{
  const nl_cheng_pattern *pat = p->pat;
  for (size_t i = 0; i < p->np; i++)
    for (int l = 0; l < p->F; l++) {
      double X = p->freq[l] * (p->c.origin + pat->x[i]), Y = p->freq[l] * (p->c.origin + pat->y[i]);
      long ci = (long)floor(X), cj = (long)floor(Y);
      size_t base = (i * (size_t)p->F + (size_t)l) * 4;
      corner_weights(X - (double)ci, Y - (double)cj, p->cw + 2 * base);
      for (int c = 0; c < 4; c++)
        p->ck[base + c] = (uint32_t)nl_noise_grad2_index(p->g, ci + (c & 1), cj + (c >> 1));
    }
}

/* Which entries each octave's lattice over the domain [o, o + 1]^2 uses,
 * and the lowest level that uses each entry (0: none). */
static void build_usage(nl_cheng_problem *p)
{
  for (int l = 0; l < p->F; l++) {
    long lo, hi;
    nl_cheng__lattice_range(p->freq[l], p->c.origin, &lo, &hi);
    for (long j = lo; j <= hi; j++)
      for (long i = lo; i <= hi; i++) {
        size_t k = nl_noise_grad2_index(p->g, i, j);
        p->used[(size_t)l * p->m + k] = 1;
        if (!p->first_level[k]) p->first_level[k] = l + 1;
      }
  }
}

/* Inverted lists: for octave l and entry k, the points whose corners use k,
 * each point once with the sum W of the weight vectors of its corners that
 * use k (a move changes the octave value by W . (G_new - G_old)). */
static void build_lists(nl_cheng_problem *p)
{
  size_t M = p->m, F = (size_t)p->F, M1 = M + 1;
  p->lstart = nl_xcalloc(F * M1, sizeof *p->lstart);
  for (size_t i = 0; i < p->np; i++)
    for (size_t l = 0; l < F; l++) {
      const uint32_t *k = p->ck + (i * F + l) * 4;
      for (int c = 0; c < 4; c++) {
        int dup = 0;
        for (int e = 0; e < c; e++) dup |= k[e] == k[c];
        if (!dup) p->lstart[l * M1 + k[c] + 1]++;
      }
    }
  size_t total = 0;
  for (size_t q = 0; q < F * M1; q++) { total += p->lstart[q]; p->lstart[q] = total; }
  /* One prefix sum over all octaves: list (l, k) is [lstart[l][k], lstart[l][k+1]). */
  p->litem = nl_xmalloc((total ? total : 1) * sizeof *p->litem);
  p->lw = nl_xcalloc(2 * (total ? total : 1), sizeof *p->lw);
  size_t *fill = nl_xmalloc(F * M1 * sizeof *fill);
  memcpy(fill, p->lstart, F * M1 * sizeof *fill);
  for (size_t i = 0; i < p->np; i++)
    for (size_t l = 0; l < F; l++) {
      size_t base = (i * F + l) * 4, pos[4];
      const uint32_t *k = p->ck + base;
      for (int c = 0; c < 4; c++) {
        int first = c;
        for (int e = c - 1; e >= 0; e--) if (k[e] == k[c]) first = e;
        if (first == c) { pos[c] = fill[l * M1 + k[c]]++; p->litem[pos[c]] = (uint32_t)i; }
        else pos[c] = pos[first];
        p->lw[2 * pos[c]] += p->cw[2 * (base + c)];
        p->lw[2 * pos[c] + 1] += p->cw[2 * (base + c) + 1];
      }
    }
  free(fill);
}

nl_cheng_problem *nl_cheng_problem_alloc(const nl_cheng_config *c, const nl_cheng_pattern *pat,
                                         nl_noise_grad2 *table, nl_error *err)
{
  if (nl_cheng_config_check(c, err)) return NULL;
  if (!pat || pat->n == 0) { nl_fail(err, NL_EINVAL, "control pattern has no control points"); return NULL; }
  if (table->m != c->m || table->m < 2 || table->m > UINT32_MAX) {
    nl_fail(err, NL_EINVAL, "table size %zu does not match the configuration's %zu", table->m, c->m);
    return NULL;
  }
  nl_cheng_problem *p = nl_xcalloc(1, sizeof *p);
  p->c = *c;
  p->pat = pat;
  p->g = table;
  p->m = table->m;
  p->np = pat->n;
  p->F = c->octaves;
  nl_noise_octaves o = nl_cheng_octaves(c), o0 = nl_noise_octaves_cheng(c->octaves, c->f1, c->a1);
  double asum = 0;
  for (int l = 0; l < p->F; l++) { p->freq[l] = o.freq[l]; p->amp[l] = o.amp[l]; asum += o.amp[l]; }
  p->s = 1.0 / (NL_NOISE2_BOUND * asum);   /* V = F_sum / its analytic bound */
  for (int l = 0; l < p->F; l++) { p->amp0[l] = o0.amp[l]; p->lg[l] = c->log_gain[l]; }   /* X6: gains */
  size_t F = (size_t)p->F;
  p->ck = nl_xmalloc(p->np * F * 4 * sizeof *p->ck);
  p->cw = nl_xmalloc(p->np * F * 8 * sizeof *p->cw);
  p->nv = nl_xcalloc(p->np * F, sizeof *p->nv);
  p->term = nl_xcalloc(p->np, sizeof *p->term);
  p->used = nl_xcalloc(F * p->m, 1);
  p->first_level = nl_xcalloc(p->m, sizeof *p->first_level);
  p->in_sample = nl_xcalloc(p->m, 1);
  p->vars = nl_xmalloc((p->m + 1) * sizeof *p->vars);   /* + 1: a level's gain (amp_vary) */
  p->sample = nl_xmalloc(p->m * sizeof *p->sample);
  p->mark = nl_xcalloc(p->np, sizeof *p->mark);
  p->tp = nl_xmalloc(p->np * sizeof *p->tp);
  p->tnv = nl_xmalloc(p->np * F * sizeof *p->tnv);
  p->tterm = nl_xmalloc(p->np * sizeof *p->tterm);
  p->pd = nl_xmalloc(2 * p->np * sizeof *p->pd);
  p->tu = nl_xmalloc(p->np * sizeof *p->tu);
  p->sv = nl_xmalloc(p->np * sizeof *p->sv);
  p->spre = nl_xmalloc(p->np * sizeof *p->spre);
  build_corners(p);
  build_usage(p);
  build_lists(p);
  nl_cheng__stat_init(&p->st, c->stat, c->chisq_bins);
  nl_cheng_set_level(p, 1);
  return p;
}

void nl_cheng_problem_free(nl_cheng_problem *p)
{
  if (!p) return;
  nl_cheng__stat_clear(&p->st);
  free(p->ck); free(p->cw); free(p->nv); free(p->term); free(p->used); free(p->first_level);
  free(p->in_sample); free(p->vars); free(p->sample); free(p->mark); free(p->tp);
  free(p->tnv); free(p->tterm); free(p->lstart); free(p->litem); free(p->lw); free(p->uterm);
  free(p->pd);
  free(p->tu);
  free(p->sv);
  free(p->spre);
  free(p);
}

/* Octave l's noise at point i from its stored corners (eq. 3.2). */
static inline double octave_value(const nl_cheng_problem *p, size_t i, size_t l)
{
  size_t base = (i * (size_t)p->F + l) * 4;
  const uint32_t *k = p->ck + base;
  const double *w = p->cw + 2 * base;
  const double *gx = p->g->gx, *gy = p->g->gy;
  return (w[0] * gx[k[0]] + w[1] * gy[k[0]]) + (w[2] * gx[k[1]] + w[3] * gy[k[1]]) +
         (w[4] * gx[k[2]] + w[5] * gy[k[2]]) + (w[6] * gx[k[3]] + w[7] * gy[k[3]]);
}

static inline double point_term(const nl_cheng_problem *p, const double *nv, size_t i)
{
  double e = nl_cheng__control_value(p->c.con, nv, p->amp, p->level, p->s, p->c.literal) - p->pat->d[i];
  return e * e;
}

/* Plain left-to-right sum of the terms: the incremental state and the full
 * recomputation both use it, so a resum makes them agree exactly. */
static double sum_terms(const double *t, size_t n)
{
  double s = 0;
  for (size_t i = 0; i < n; i++) s += t[i];
  return s;
}

/* pre (p->pd) still the lower octaves' sums: nothing below octave l moved
 * since the last full evaluation, and their gains are the same. */
static int pre_valid(const nl_cheng_problem *p, size_t l)
{
  if (!p->pre_ok) return 0;
  for (size_t j = 0; j < l; j++)
    if (p->amp[j] != p->pre_amp[j]) return 0;
  return 1;
}

/* Octave values <= level and terms of every point from the stored corners,
 * and each point's sum of the octaves below the top one (p->pre). For the
 * thesis's F = 4 at level 4 where the CPU has AVX2, the sums of four points
 * a vector and marble's sines at the vector level, as a pool move's
 * (general_terms): the same doubles. */
static void evaluate_points(nl_cheng_problem *p)
{
  size_t F = (size_t)p->F;
  int top = p->level - 1;
#if NL_SIMD_X86
  if (F == 4 && p->level == 4 && nl_simd_get() >= NL_SIMD_AVX2) {
    nl_cheng_con con = p->c.con;
    int literal = p->c.literal;
    double s = p->s, *sv = p->sv, *pre = p->spre;
    const double *dv = p->pat->d;
    for (size_t i = 0; i < p->np; i++)
      for (size_t l = 0; l < 4; l++) p->nv[i * 4 + l] = octave_value(p, i, l);
    nl_cheng__sums4_avx2(p->np, NULL, p->nv, p->amp, con == NL_CHENG_CON_FIRE, sv, pre);
    int marble = con == NL_CHENG_CON_SIN && !literal;
    if (marble) {
      for (size_t i = 0; i < p->np; i++) sv[i] *= s;
      nl_math_sinpi_n(p->np, sv, sv);
    }
    for (size_t i = 0; i < p->np; i++) {
      double c = marble ? 0.5 * (1.0 + sv[i]) : nl_cheng__control_of_sum(con, sv[i], s, literal);
      double e = c - dv[i];
      p->term[i] = e * e;
      p->pd[2 * i] = pre[i];
      p->pd[2 * i + 1] = dv[i];
    }
    memcpy(p->pre_amp, p->amp, sizeof p->amp);
    p->pre_ok = 1;
    p->pre_level = p->level;
    return;
  }
#endif
  for (size_t i = 0; i < p->np; i++) {
    for (size_t l = 0; l < (size_t)p->level; l++) p->nv[i * F + l] = octave_value(p, i, l);
    p->term[i] = point_term(p, p->nv + i * F, i);
    p->pd[2 * i] = nl_cheng__octave_sum(p->c.con, p->nv + i * F, p->amp, top, -1, 0.0);
    p->pd[2 * i + 1] = p->pat->d[i];
  }
  memcpy(p->pre_amp, p->amp, sizeof p->amp);
  p->pre_ok = 1;
  p->pre_level = p->level;
}

void nl_cheng_resum(nl_cheng_problem *p)
{
  evaluate_points(p);
  p->e_con = sum_terms(p->term, p->np);
  p->e = nl_cheng_objective(&p->c, p->e_stat, p->e_con);
  p->has_undo = 0;
}

/* nl_cheng_resum when only the top octave can have moved since the last
 * full evaluation at this level (pre valid: no lower octave and no lower
 * gain moved): the lower octaves' values and sums are what a full
 * evaluation would compute again (the same corners, the same entries), so
 * only the top octave is re-evaluated, and each term from pre + amp * value
 * (the same double as point_term's sum). Otherwise the full resum. */
void nl_cheng__resum_top(nl_cheng_problem *p)
{
  size_t top = (size_t)p->level - 1;
  if (p->pre_level != p->level || !pre_valid(p, top)) { nl_cheng_resum(p); return; }
  size_t F = (size_t)p->F;
  nl_cheng_con con = p->c.con;
  int literal = p->c.literal;
  double al = p->amp[top], s = p->s;
  for (size_t i = 0; i < p->np; i++) {
    double v = octave_value(p, i, top);
    p->nv[i * F + top] = v;
    double e = nl_cheng__control_of_sum(con, p->pd[2 * i] + al * (con == NL_CHENG_CON_FIRE ? fabs(v) : v), s, literal)
               - p->pd[2 * i + 1];
    p->term[i] = e * e;
  }
  p->e_con = sum_terms(p->term, p->np);
  p->e = nl_cheng_objective(&p->c, p->e_stat, p->e_con);
  p->has_undo = 0;
}

void nl_cheng_set_level(nl_cheng_problem *p, int level)
{
  p->level = level < 1 ? 1 : level > p->F ? p->F : level;
  p->nvars = p->nsample = 0;
  for (size_t k = 0; k < p->m; k++) {
    if (p->first_level[k] == p->level) p->vars[p->nvars++] = k;
    p->in_sample[k] = p->used[(size_t)(p->level - 1) * p->m + k];
    if (p->in_sample[k]) p->sample[p->nsample++] = k;
  }
  if (p->c.amp_vary) p->vars[p->nvars++] = p->m + (size_t)(p->level - 1);   /* octave l's gain (X6) */
  double *x = nl_xmalloc((p->nsample ? p->nsample : 1) * sizeof *x);
  for (size_t q = 0; q < p->nsample; q++) x[q] = p->g->angle[p->sample[q]];
  nl_cheng__stat_reset(&p->st, x, p->nsample);
  free(x);
  p->e_stat = nl_cheng__stat_value(&p->st);
  nl_cheng_resum(p);
}

int nl_cheng_level(const nl_cheng_problem *p) { return p->level; }

const size_t *nl_cheng_vars(const nl_cheng_problem *p, size_t *n_vars)
{
  *n_vars = p->nvars;
  return p->vars;
}

double nl_cheng_energy(const nl_cheng_problem *p, double *e_stat, double *e_con)
{
  if (e_stat) *e_stat = p->e_stat;
  if (e_con) *e_con = p->e_con;
  return p->e;
}

/* One point's F <= 8 octave values: a call to memcpy per touched point was
 * 15% of a C5 pool run's samples (E_R moves take the general path below);
 * written as pairs so GCC does not turn it back into that call. */
static inline void copy_octaves(double *restrict to, const double *restrict from, size_t F)
{
  size_t l = 0;
  for (; l + 2 <= F; l += 2) { to[l] = from[l]; to[l + 1] = from[l + 1]; }
  if (l < F) to[l] = from[l];
}

/* The general path's second pass: each touched point's term from its F
 * values (point_term's operations), the change summed in list order. First
 * every point's octave sum V into sv (for F = 4 at level 4, four points a
 * vector where the CPU has AVX2: the same doubles); for marble then all
 * their sines at the vector level (nl_math_sinpi_n: nl_math_sinpi's bits);
 * then the terms. One loop per texture and reading (con, literal
 * constants, as top_loop). */
static inline __attribute__((always_inline)) double
general_terms(const size_t *restrict tp, size_t n, const double *restrict nv, size_t F,
              const double *restrict amp, int levels, double s, const double *restrict dv,
              double *restrict term, const double *restrict tterm, double *restrict sv,
              nl_cheng_con con, int literal)
{
#if NL_SIMD_X86
  if (F == 4 && levels == 4 && nl_simd_get() >= NL_SIMD_AVX2)
    nl_cheng__sums4_avx2(n, tp, nv, amp, con == NL_CHENG_CON_FIRE, sv, NULL);
  else
#endif
    for (size_t t = 0; t < n; t++)
      sv[t] = nl_cheng__octave_sum(con, nv + tp[t] * F, amp, levels, -1, 0.0);
  double d = 0;
  if (con == NL_CHENG_CON_SIN && !literal) {
    for (size_t t = 0; t < n; t++) sv[t] *= s;
    nl_math_sinpi_n(n, sv, sv);
    for (size_t t = 0; t < n; t++) {
      size_t i = tp[t];
      double e = 0.5 * (1.0 + sv[t]) - dv[i];
      double nt = e * e;
      term[i] = nt;
      d += nt - tterm[t];
    }
    return d;
  }
  for (size_t t = 0; t < n; t++) {
    size_t i = tp[t];
    double e = nl_cheng__control_of_sum(con, sv[t], s, literal) - dv[i];
    double nt = e * e;
    term[i] = nt;
    d += nt - tterm[t];
  }
  return d;
}

/* Adds W . (dc, ds) to the octaves < levels of every point listed for entry
 * k, saving each point's previous F values once (in tnv, tterm, tp);
 * returns how many points it touched. */
static inline __attribute__((always_inline)) size_t
general_values(nl_cheng_problem *p, size_t k, double dc, double ds, size_t F, size_t levels)
{
  size_t M1 = p->m + 1, n = 0;
  if (++p->stamp == 0) { memset(p->mark, 0, p->np * sizeof *p->mark); p->stamp = 1; }
  const unsigned stamp = p->stamp;
  unsigned *restrict mark = p->mark;
  const uint32_t *restrict item = p->litem;
  const double *restrict lw = p->lw, *restrict term = p->term;
  double *restrict nv = p->nv, *restrict tnv = p->tnv, *restrict tterm = p->tterm;
  size_t *restrict tp = p->tp;
  for (size_t l = 0; l < levels; l++) {
    const size_t *st = p->lstart + l * M1;
    for (size_t q = st[k]; q < st[k + 1]; q++) {
      size_t i = item[q];
      double *v = nv + i * F;
      if (mark[i] != stamp) {
        mark[i] = stamp;
        copy_octaves(tnv + n * F, v, F);
        tterm[n] = term[i];
        tp[n++] = i;
      }
      v[l] += lw[2 * q] * dc + lw[2 * q + 1] * ds;
    }
  }
  return n;
}

/* update_points_general for F octaves at level `levels`, both constants
 * where the caller passes constants (the thesis's F = 4 at level 4, every
 * move of a solution pool: the copies and sums unrolled). */
static inline __attribute__((always_inline)) double
general_path(nl_cheng_problem *p, size_t k, double dc, double ds, size_t F, size_t levels)
{
  size_t n = general_values(p, k, dc, ds, F, levels);
  p->ntouch = n;
  const size_t *tp = p->tp;
  const double *nv = p->nv, *amp = p->amp, *dv = p->pat->d, *tterm = p->tterm;
  double s = p->s, *sv = p->sv, *term = p->term;
  int lv = (int)levels;
#define TERMS(con, lit) general_terms(tp, n, nv, F, amp, lv, s, dv, term, tterm, sv, con, lit)
  switch (p->c.con * 2 + (p->c.literal != 0)) {
  case NL_CHENG_CON_PLAIN * 2: return TERMS(NL_CHENG_CON_PLAIN, 0);
  case NL_CHENG_CON_PLAIN * 2 + 1: return TERMS(NL_CHENG_CON_PLAIN, 1);
  case NL_CHENG_CON_SIN * 2: return TERMS(NL_CHENG_CON_SIN, 0);
  case NL_CHENG_CON_SIN * 2 + 1: return TERMS(NL_CHENG_CON_SIN, 1);
  case NL_CHENG_CON_ABS * 2: return TERMS(NL_CHENG_CON_ABS, 0);
  case NL_CHENG_CON_ABS * 2 + 1: return TERMS(NL_CHENG_CON_ABS, 1);
  case NL_CHENG_CON_FIRE * 2: return TERMS(NL_CHENG_CON_FIRE, 0);
  default: return TERMS(NL_CHENG_CON_FIRE, 1);
  }
#undef TERMS
}

/* Adds W . (dc, ds) to the octaves <= level of every point listed for entry
 * k, saving each point's previous values once; returns the change of E_Con.
 * The solution pools' moves (E_R over every octave, nl_cheng_pool.c) all
 * come here. The problem's arrays are read into restrict locals, so the
 * stores to the octave values do not force reloads of the rest. */
static double update_points_general(nl_cheng_problem *p, size_t k, double dc, double ds)
{
  p->tlev = -1;
  p->pre_ok = 0;   /* lower octaves may change */
  if (p->F == 4 && p->level == 4) return general_path(p, k, dc, ds, 4, 4);
  return general_path(p, k, dc, ds, (size_t)p->F, (size_t)p->level);
}

/* The annealer's case: entry k is in one octave's lists only (a level's
 * variables are used by no lower octave), so each listed point appears once
 * and only octave l changes. Same operations in the same order as the
 * general path (each point's value updated, its term recomputed, the change
 * summed in list order), one pass, one saved value a point. */
static double update_points_one(nl_cheng_problem *p, size_t k, size_t l, double dc, double ds)
{
  size_t F = (size_t)p->F, M1 = p->m + 1;
  const size_t *st = p->lstart + l * M1;
  const uint32_t *item = p->litem;
  const double *lw = p->lw, *amp = p->amp, *dv = p->pat->d;
  double *nv = p->nv, *term = p->term, s = p->s;
  nl_cheng__touch *tu = p->tu;
  size_t t = 0;
  nl_cheng_con con = p->c.con;
  int levels = p->level, literal = p->c.literal;
  double d = 0;
  for (size_t q = st[k]; q < st[k + 1]; q++, t++) {
    size_t i = item[q];
    double *v = nv + i * F;
    tu[t].i = i;
    tu[t].v = v[l];
    tu[t].t = term[i];
    double vl = v[l] + (lw[2 * q] * dc + lw[2 * q + 1] * ds);
    v[l] = vl;
    double e = nl_cheng__control_of_sum(con, nl_cheng__octave_sum(con, v, amp, levels, (int)l, vl), s, literal) - dv[i];
    term[i] = e * e;
    d += term[i] - tu[t].t;
  }
  p->ntouch = t;
  p->tlev = (int)l;
  return d;
}

/* The top octave's move (l = level - 1, the annealer's every move): the
 * octave sum is pre[i] + amp[l] Noise_l, the last step of
 * nl_cheng__octave_sum on its first l steps, so the same double. One loop per
 * texture and reading (con, literal constants: no branch on them per point).
 * restrict: the arrays are distinct allocations. */
static inline __attribute__((always_inline)) double
top_loop(const uint32_t *restrict item, const double *restrict lw, size_t q0, size_t q1, double *restrict nvl,
         size_t F, const double *restrict pd, double *restrict term, nl_cheng__touch *restrict tu, double al,
         double s, double dc, double ds, nl_cheng_con con, int literal)
{
  double d = 0;
  for (size_t q = q0; q < q1; q++) {
    size_t i = item[q];
    double *v = nvl + i * F, old = *v, ot = term[i];
    double vl = old + (lw[2 * q] * dc + lw[2 * q + 1] * ds);
    *v = vl;
    nl_cheng__touch *r = tu + (q - q0);
    r->i = i;
    r->v = old;
    r->t = ot;
    double e = nl_cheng__control_of_sum(con, pd[2 * i] + al * (con == NL_CHENG_CON_FIRE ? fabs(vl) : vl), s, literal)
               - pd[2 * i + 1];
    double nt = e * e;
    term[i] = nt;
    d += nt - ot;
  }
  return d;
}

/* Marble's top-octave move (non-literal c = (1 + sin(pi V)) / 2) in three
 * passes: each point's value and its V = s (pre + amp Noise_l), as
 * top_loop; the sines of all of them at the vector level (nl_math_sinpi_n,
 * which gives nl_math_sinpi's bits, so the same doubles as one at a time);
 * then the terms and their change, summed in list order. The sine is most
 * of a marble move's time, and one point's does not wait on another's. */
static double top_loop_marble(const uint32_t *restrict item, const double *restrict lw, size_t q0,
                              size_t q1, double *restrict nvl, size_t F, const double *restrict pd,
                              double *restrict term, nl_cheng__touch *restrict tu,
                              double *restrict sv, double al, double s, double dc, double ds)
{
  size_t n = q1 - q0;
  for (size_t q = q0; q < q1; q++) {
    size_t i = item[q];
    double *v = nvl + i * F, old = *v;
    double vl = old + (lw[2 * q] * dc + lw[2 * q + 1] * ds);
    *v = vl;
    nl_cheng__touch *r = tu + (q - q0);
    r->i = i;
    r->v = old;
    r->t = term[i];
    double V = pd[2 * i] + al * vl;
    V *= s;
    sv[q - q0] = V;
  }
  nl_math_sinpi_n(n, sv, sv);
  double d = 0;
  for (size_t t = 0; t < n; t++) {
    size_t i = tu[t].i;
    double e = 0.5 * (1.0 + sv[t]) - pd[2 * i + 1];
    double nt = e * e;
    term[i] = nt;
    d += nt - tu[t].t;
  }
  return d;
}

static double update_points_top(nl_cheng_problem *p, size_t k, size_t l, double dc, double ds)
{
  const size_t *st = p->lstart + l * (p->m + 1);
  size_t q0 = st[k], q1 = st[k + 1], F = (size_t)p->F;
  const uint32_t *item = p->litem;
  const double *lw = p->lw, *pd = p->pd;
  double *nvl = p->nv + l, *term = p->term, al = p->amp[l], s = p->s, d;
  nl_cheng__touch *tu = p->tu;
#define TOP(con, lit) top_loop(item, lw, q0, q1, nvl, F, pd, term, tu, al, s, dc, ds, con, lit)
  switch (p->c.con * 2 + (p->c.literal != 0)) {
  case NL_CHENG_CON_PLAIN * 2: d = TOP(NL_CHENG_CON_PLAIN, 0); break;
  case NL_CHENG_CON_PLAIN * 2 + 1: d = TOP(NL_CHENG_CON_PLAIN, 1); break;
  case NL_CHENG_CON_SIN * 2:
    d = top_loop_marble(item, lw, q0, q1, nvl, F, pd, term, tu, p->sv, al, s, dc, ds);
    break;
  case NL_CHENG_CON_SIN * 2 + 1: d = TOP(NL_CHENG_CON_SIN, 1); break;
  case NL_CHENG_CON_ABS * 2: d = TOP(NL_CHENG_CON_ABS, 0); break;
  case NL_CHENG_CON_ABS * 2 + 1: d = TOP(NL_CHENG_CON_ABS, 1); break;
  case NL_CHENG_CON_FIRE * 2: d = TOP(NL_CHENG_CON_FIRE, 0); break;
  default: d = TOP(NL_CHENG_CON_FIRE, 1); break;
  }
#undef TOP
  p->ntouch = q1 - q0;
  p->tlev = (int)l;
  return d;
}

static double update_points(nl_cheng_problem *p, size_t k, double dc, double ds)
{
  size_t M1 = p->m + 1, only = 0;
  int lists = 0;
  for (size_t l = 0; l < (size_t)p->level; l++) {
    const size_t *st = p->lstart + l * M1;
    if (st[k] < st[k + 1]) { lists++; only = l; }
  }
  if (lists <= 1 && only + 1 == (size_t)p->level && pre_valid(p, only))
    return update_points_top(p, k, only, dc, ds);
  if (lists == 1 && only + 1 < (size_t)p->level) p->pre_ok = 0;   /* a lower octave changes */
  return lists <= 1 ? update_points_one(p, k, only, dc, ds) : update_points_general(p, k, dc, ds);
}

double nl_cheng_move(nl_cheng_problem *p, size_t k, double theta)
{
  if (k >= p->m) return nl_cheng__amp_move(p, k - p->m, theta);   /* a gain (nl_cheng_amp.c) */
  p->uk = k;
  p->utheta = p->g->angle[k];
  p->u_stat = p->e_stat;
  p->u_con = p->e_con;
  p->u_e = p->e;
  p->has_undo = 1;
  if (p->in_sample[k]) {
    nl_cheng__stat_replace(&p->st, p->utheta, theta);
    p->e_stat = nl_cheng__stat_value(&p->st);
  }
  double gx = p->g->gx[k], gy = p->g->gy[k];
  p->ugx = gx;
  p->ugy = gy;
  nl_noise_grad2_set_angle(p->g, k, theta);
  p->e_con += update_points(p, k, p->g->gx[k] - gx, p->g->gy[k] - gy);
  p->e = nl_cheng_objective(&p->c, p->e_stat, p->e_con);
  return p->e;
}

void nl_cheng_undo(nl_cheng_problem *p)
{
  if (!p->has_undo) return;
  if (p->uk >= p->m) { nl_cheng__amp_undo(p); return; }
  size_t k = p->uk, F = (size_t)p->F;
  if (p->in_sample[k]) nl_cheng__stat_undo(&p->st, p->utheta, p->g->angle[k]);
  /* the saved cos and sin: what nl_noise_grad2_set_angle(utheta) computed */
  p->g->angle[k] = p->utheta;
  p->g->gx[k] = p->ugx;
  p->g->gy[k] = p->ugy;
  if (p->tlev >= 0) {
    double *nvl = p->nv + p->tlev, *term = p->term;
    const nl_cheng__touch *tu = p->tu;
    for (size_t t = 0; t < p->ntouch; t++) {
      nvl[tu[t].i * F] = tu[t].v;
      term[tu[t].i] = tu[t].t;
    }
  } else {
    for (size_t t = 0; t < p->ntouch; t++) {
      size_t i = p->tp[t];
      copy_octaves(p->nv + i * F, p->tnv + t * F, F);
      p->term[i] = p->tterm[t];
    }
  }
  p->e_stat = p->u_stat;
  p->e_con = p->u_con;
  p->e = p->u_e;
  p->has_undo = 0;
}

double nl_cheng_energy_full(const nl_cheng_problem *p, double *e_stat, double *e_con)
{
  size_t F = (size_t)p->F;
  double nv[NL_CHENG_MAX_OCTAVES];
  double *terms = nl_xmalloc(p->np * sizeof *terms);
  for (size_t i = 0; i < p->np; i++) {
    for (size_t l = 0; l < F; l++) nv[l] = octave_value(p, i, l);
    terms[i] = point_term(p, nv, i);
  }
  double con = sum_terms(terms, p->np);
  free(terms);
  double *x = nl_xmalloc((p->nsample ? p->nsample : 1) * sizeof *x);
  for (size_t q = 0; q < p->nsample; q++) x[q] = p->g->angle[p->sample[q]];
  double st = nl_cheng__stat_full(p->c.stat, p->c.chisq_bins, x, p->nsample);
  free(x);
  if (e_stat) *e_stat = st;
  if (e_con) *e_con = con;
  return nl_cheng_objective(&p->c, st, con);
}
