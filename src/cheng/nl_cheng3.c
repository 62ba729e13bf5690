/* Controllable gradient noise in 3D: patterns, the incremental problem and
 * the proposal over an nl_noise_grad3 table (the model is documented in
 * nl_cheng3.h). */
#include "cheng/nl_cheng3.h"
#include "stats/nl_stats.h"

#include <gsl/gsl_randist.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* ---- patterns ----------------------------------------------------------- */

static int inside(int shape, double x, double y, double z)
{
  x -= 0.5; y -= 0.5;
  if (shape == 0) { double q = sqrt(x * x + y * y) - 0.3, h = z - 0.5; return q * q + h * h < 0.12 * 0.12; }
  if (shape == 1) { double h = z - 0.5; return x * x + y * y + h * h < 0.3 * 0.3; }
  return z >= 0.35 && z < 0.65;
}

static const char *const shape_names[] = {"torus", "ball", "slab"};

nl_status nl_cheng3_pattern_shape(const char *name, int grid, nl_cheng3_pattern **out, nl_error *err)
{
  int shape = -1;
  for (int s = 0; s < 3; s++) if (!strcmp(name, shape_names[s])) shape = s;
  if (shape < 0) return nl_fail(err, NL_EINVAL, "unknown 3D pattern '%s' (torus, ball, slab)", name);
  if (grid < 2 || grid > 256) return nl_fail(err, NL_EINVAL, "3D control grid %d outside 2..256", grid);
  nl_cheng3_pattern *p = nl_xcalloc(1, sizeof *p);
  size_t n = (size_t)grid * grid * grid;
  p->grid = grid;
  p->n = n;
  p->x = nl_xmalloc(n * sizeof *p->x); p->y = nl_xmalloc(n * sizeof *p->y);
  p->z = nl_xmalloc(n * sizeof *p->z); p->d = nl_xmalloc(n * sizeof *p->d);
  for (int k = 0; k < grid; k++)
    for (int j = 0; j < grid; j++)
      for (int i = 0; i < grid; i++) {
        size_t c = ((size_t)k * grid + j) * grid + i;
        int in = 0;
        for (int s = 0; s < 64; s++)   /* 4^3 sub-samples: D = the covered fraction */
          in += inside(shape, (i + (s % 4 + 0.5) / 4) / grid, (j + (s / 4 % 4 + 0.5) / 4) / grid,
                       (k + (s / 16 + 0.5) / 4) / grid);
        p->x[c] = (i + 0.5) / grid; p->y[c] = (j + 0.5) / grid; p->z[c] = (k + 0.5) / grid;
        p->d[c] = in / 64.0;
      }
  *out = p;
  return NL_OK;
}

void nl_cheng3_pattern_free(nl_cheng3_pattern *p)
{
  if (!p) return;
  free(p->x); free(p->y); free(p->z); free(p->d); free(p);
}

nl_cheng3_config nl_cheng3_config_default(void)
{
  nl_cheng3_config c = nl_cheng_config_default();
  c.octaves = 3;   /* f = 4, 8, 16: the top frequency equals the 16^3 grid (nl_cheng3.h) */
  c.f1 = 4;
  c.propagate = 0;
  return c;
}

/* ---- the incremental problem ---------------------------------------------- */

struct nl_cheng3_problem {
  nl_cheng3_config c;
  const nl_cheng3_pattern *pat;
  nl_noise_grad3 *t;
  size_t m, np, nc;      /* nc = F * 8 corners per point */
  double s;              /* 1 / (B3 sum 1/a_l) */
  uint32_t *ck;          /* np * nc entries */
  double *cw;            /* np * nc * 3 weights (amplitude folded in) */
  double *sum;           /* np: F_sum at the point */
  double *term;          /* np: (c_i - D_i)^2 */
  size_t *lstart;        /* m + 1 list offsets */
  uint32_t *litem;       /* points */
  double *lw;            /* 3 per item: summed weight of the entry's corners at the point */
  nl_stats_ks_incr *ksz, *ksp;
  double zr[2], pr[2];   /* uniform ranges */
  double e_stat, e_con, e;
  /* undo */
  int has_undo;
  size_t uk;
  double uv[3], uz, uphi, u_stat, u_con, u_e, *usum, *uterm;
};

static double cvalue(const nl_cheng3_problem *p, double sum) { return 0.5 * (1.0 + p->s * sum); }

static double stat_value(const nl_cheng3_problem *p) { return fmax(p->ksz->d, p->ksp->d); }

typedef struct { uint32_t k, i; double w[3]; } triple;

static int triple_cmp(const void *a, const void *b)
{
  const triple *x = a, *y = b;
  if (x->k != y->k) return x->k < y->k ? -1 : 1;
  return x->i < y->i ? -1 : x->i > y->i;
}

static void build(nl_cheng3_problem *p)
{
  const nl_cheng3_pattern *pat = p->pat;
  int F = p->c.octaves;
  double f = p->c.f1, a = p->c.a1, asum = 0;
  for (int l = 0; l < F; l++, f *= 2, a *= 2) {
    asum += 1 / a;
    for (size_t i = 0; i < p->np; i++) {
      double q[3] = {f * pat->x[i], f * pat->y[i], f * pat->z[i]};
      nl_noise_grad3_corners(p->t, q[0], q[1], q[2], 1 / a, p->ck + i * p->nc + 8 * l,
                             p->cw + 3 * (i * p->nc + 8 * l));
    }
  }
  p->s = 1 / (NL_NOISE_GRAD3_BOUND * asum);
  /* Inverted lists: (entry, point) pairs sorted, duplicates merged. */
  size_t nt = p->np * p->nc, nu = 0;
  triple *tr = nl_xmalloc(nt * sizeof *tr);
  for (size_t q = 0; q < nt; q++) {
    tr[q].k = p->ck[q];
    tr[q].i = (uint32_t)(q / p->nc);
    memcpy(tr[q].w, p->cw + 3 * q, sizeof tr[q].w);
  }
  qsort(tr, nt, sizeof *tr, triple_cmp);
  for (size_t q = 0; q < nt; q++) {
    if (nu && tr[nu - 1].k == tr[q].k && tr[nu - 1].i == tr[q].i) {
      for (int b = 0; b < 3; b++) tr[nu - 1].w[b] += tr[q].w[b];
    } else tr[nu++] = tr[q];
  }
  p->lstart = nl_xcalloc(p->m + 1, sizeof *p->lstart);
  p->litem = nl_xmalloc((nu ? nu : 1) * sizeof *p->litem);
  p->lw = nl_xmalloc((nu ? 3 * nu : 1) * sizeof *p->lw);
  for (size_t q = 0; q < nu; q++) {
    p->lstart[tr[q].k + 1]++;
    p->litem[q] = tr[q].i;
    memcpy(p->lw + 3 * q, tr[q].w, sizeof tr[q].w);
  }
  for (size_t k = 0; k < p->m; k++) p->lstart[k + 1] += p->lstart[k];
  free(tr);
}

static double point_sum(const nl_cheng3_problem *p, size_t i)
{
  double s = 0;
  for (size_t q = i * p->nc; q < (i + 1) * p->nc; q++) {
    const double *g = p->t->v + 3 * p->ck[q], *w = p->cw + 3 * q;
    s += w[0] * g[0] + w[1] * g[1] + w[2] * g[2];
  }
  return s;
}

void nl_cheng3_resum(nl_cheng3_problem *p)
{
  double e = 0;
  for (size_t i = 0; i < p->np; i++) {
    p->sum[i] = point_sum(p, i);
    double d = cvalue(p, p->sum[i]) - p->pat->d[i];
    e += p->term[i] = d * d;
  }
  p->e_con = e;
  p->e_stat = stat_value(p);
  p->e = nl_cheng_objective(&p->c, p->e_stat, p->e_con);
}

nl_cheng3_problem *nl_cheng3_problem_alloc(const nl_cheng3_config *c, const nl_cheng3_pattern *pat,
                                           nl_noise_grad3 *t, nl_error *err)
{
  if (nl_cheng_config_check(c, err) != NL_OK) return NULL;
  if (c->m != t->m) { nl_fail(err, NL_EINVAL, "config M = %zu but table has %zu entries", c->m, t->m); return NULL; }
  nl_cheng3_problem *p = nl_xcalloc(1, sizeof *p);
  p->c = *c; p->pat = pat; p->t = t; p->m = t->m; p->np = pat->n;
  p->nc = 8 * (size_t)c->octaves;
  p->ck = nl_xmalloc(p->np * p->nc * sizeof *p->ck);
  p->cw = nl_xmalloc(3 * p->np * p->nc * sizeof *p->cw);
  p->sum = nl_xmalloc(p->np * sizeof *p->sum);
  p->term = nl_xmalloc(p->np * sizeof *p->term);
  p->usum = nl_xmalloc(p->np * sizeof *p->usum);
  p->uterm = nl_xmalloc(p->np * sizeof *p->uterm);
  build(p);
  p->zr[0] = -1; p->zr[1] = 1; p->pr[0] = 0; p->pr[1] = NL_TWO_PI;
  p->ksz = nl_stats_ks_incr_alloc(t->z, p->m, nl_stats_cdf_uniform, p->zr, err);
  p->ksp = p->ksz ? nl_stats_ks_incr_alloc(t->phi, p->m, nl_stats_cdf_uniform, p->pr, err) : NULL;
  if (!p->ksp) { nl_cheng3_problem_free(p); return NULL; }
  nl_cheng3_resum(p);
  return p;
}

void nl_cheng3_problem_free(nl_cheng3_problem *p)
{
  if (!p) return;
  nl_stats_ks_incr_free(p->ksz); nl_stats_ks_incr_free(p->ksp);
  free(p->ck); free(p->cw); free(p->sum); free(p->term); free(p->usum); free(p->uterm);
  free(p->lstart); free(p->litem); free(p->lw); free(p);
}

double nl_cheng3_energy(const nl_cheng3_problem *p, double *e_stat, double *e_con)
{
  if (e_stat) *e_stat = p->e_stat;
  if (e_con) *e_con = p->e_con;
  return p->e;
}

double nl_cheng3_move(nl_cheng3_problem *p, size_t k, const double u[3])
{
  nl_noise_grad3 *t = p->t;
  double *g = t->v + 3 * k, oz = t->z[k], oph = t->phi[k];
  p->has_undo = 1; p->uk = k; p->u_stat = p->e_stat; p->u_con = p->e_con; p->u_e = p->e;
  memcpy(p->uv, g, sizeof p->uv);
  p->uz = oz; p->uphi = oph;
  nl_noise_grad3_set(t, k, u);
  double dg[3] = {g[0] - p->uv[0], g[1] - p->uv[1], g[2] - p->uv[2]};
  for (size_t q = p->lstart[k]; q < p->lstart[k + 1]; q++) {
    size_t i = p->litem[q];
    const double *w = p->lw + 3 * q;
    p->usum[q - p->lstart[k]] = p->sum[i];
    p->uterm[q - p->lstart[k]] = p->term[i];
    p->sum[i] += w[0] * dg[0] + w[1] * dg[1] + w[2] * dg[2];
    double d = cvalue(p, p->sum[i]) - p->pat->d[i], nt = d * d;
    p->e_con += nt - p->term[i];
    p->term[i] = nt;
  }
  nl_stats_ks_incr_replace(p->ksz, oz, t->z[k], NULL);
  nl_stats_ks_incr_replace(p->ksp, oph, t->phi[k], NULL);
  p->e_stat = stat_value(p);
  p->e = nl_cheng_objective(&p->c, p->e_stat, p->e_con);
  return p->e;
}

void nl_cheng3_undo(nl_cheng3_problem *p)
{
  if (!p->has_undo) return;
  size_t k = p->uk;
  nl_noise_grad3 *t = p->t;
  double nz = t->z[k], nph = t->phi[k];
  memcpy(t->v + 3 * k, p->uv, sizeof p->uv);   /* exactly the saved entry, not renormalised */
  t->z[k] = p->uz; t->phi[k] = p->uphi;
  for (size_t q = p->lstart[k]; q < p->lstart[k + 1]; q++) {
    p->sum[p->litem[q]] = p->usum[q - p->lstart[k]];
    p->term[p->litem[q]] = p->uterm[q - p->lstart[k]];
  }
  nl_stats_ks_incr_replace(p->ksz, nz, t->z[k], NULL);
  nl_stats_ks_incr_replace(p->ksp, nph, t->phi[k], NULL);
  p->e_stat = p->u_stat; p->e_con = p->u_con; p->e = p->u_e;
  p->has_undo = 0;
}

double nl_cheng3_energy_full(const nl_cheng3_problem *p, double *e_stat, double *e_con)
{
  nl_stats_ks_result rz, rp;
  nl_stats_ks_test_uniform(p->t->z, p->m, -1, 1, &rz, NULL);
  nl_stats_ks_test_uniform(p->t->phi, p->m, 0, NL_TWO_PI, &rp, NULL);
  double es = fmax(rz.d, rp.d), ec = 0;
  for (size_t i = 0; i < p->np; i++) {
    double d = cvalue(p, point_sum(p, i)) - p->pat->d[i];
    ec += d * d;
  }
  if (e_stat) *e_stat = es;
  if (e_con) *e_con = ec;
  return nl_cheng_objective(&p->c, es, ec);
}

void nl_cheng3_propose(const double v[3], double sigma, gsl_rng *rng, double out[3])
{
  double u[3], dot, n;
  do {   /* a random tangent: a Gaussian vector minus its component along v */
    for (int a = 0; a < 3; a++) u[a] = gsl_ran_ugaussian(rng);
    dot = u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
    for (int a = 0; a < 3; a++) u[a] -= dot * v[a];
    n = sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
  } while (!(n > 1e-9));
  double ang = sigma * gsl_rng_uniform(rng), c = cos(ang), s = sin(ang) / n, len = 0;
  for (int a = 0; a < 3; a++) { out[a] = c * v[a] + s * u[a]; len += out[a] * out[a]; }
  len = sqrt(len);   /* back to unit length: rounding must not accumulate over a walk */
  for (int a = 0; a < 3; a++) out[a] /= len;
}

/* ---- the problem as the annealer sees it ---------------------------------- */

static double op_energy(void *ctx) { return ((nl_cheng3_problem *)ctx)->e; }
static double op_move(void *ctx, size_t var, double sigma, gsl_rng *rng)
{
  nl_cheng3_problem *p = ctx;
  double u[3];
  nl_cheng3_propose(p->t->v + 3 * var, sigma, rng, u);
  return nl_cheng3_move(p, var, u);
}
static void op_undo(void *ctx) { nl_cheng3_undo(ctx); }
static void op_save(void *ctx, double *state)
{
  nl_cheng3_problem *p = ctx;
  memcpy(state, p->t->v, 3 * p->m * sizeof *state);
}
static void op_restore(void *ctx, const double *state)
{
  nl_cheng3_problem *p = ctx;
  for (size_t k = 0; k < p->m; k++)
    if (memcmp(p->t->v + 3 * k, state + 3 * k, 3 * sizeof *state)) nl_cheng3_move(p, k, state + 3 * k);
  nl_cheng3_resum(p);
}
static void op_resum(void *ctx) { nl_cheng3_resum(ctx); }

void nl_cheng3_optimise(nl_cheng3_problem *p, unsigned long seed, nl_cheng_level_stats *st)
{
  gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(rng, nl_seed_stream(seed, "cheng3.anneal", 0));
  nl_cheng_sa_ops ops = {p, p->m, 3 * p->m, op_energy, op_move, op_undo, op_save, op_restore,
                         op_resum};
  nl_cheng_sa_run(&ops, &p->c.sched, rng, st);
  if (st) st->level = 1;
  gsl_rng_free(rng);
}
