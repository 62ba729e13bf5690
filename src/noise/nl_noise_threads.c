/* nl_noise_threads.c - grids and checked batches split across threads
 * (nl_noise.h, "threads"), bit-identical to one thread.
 *
 * Every value is made by the one-thread call on a part of the work: a grid
 * row by nl_noise_fractal_row, a block of NL_NOISE_CHECK_BLOCK points by
 * the same kernel call and check as nl_noise_*_points_checked. No value
 * depends on which thread made it or on the others (nl_parallel.h's
 * rules), so the bytes are those of one thread for any count.
 */
#include "noise/nl_noise.h"
#include "base/nl_base.h"
#include "base/nl_parallel.h"

#include <sched.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>

/* Below this many samples (points times octaves) the calls run on one
 * thread: starting and joining a thread costs about as much as making
 * them. Measured on the shared 2-core machine (load 10-12, so a bound from
 * below): an fBm grid of 128^2 x 6 octaves ran 0.96-1.00x on two threads,
 * 256^2 x 6 1.29-1.39x. */
#define NL_NOISE_THREAD_MIN_SAMPLES 131072.0

/* ---- grids ------------------------------------------------------------------ */

typedef struct {
  const nl_noise_basis *b;
  const nl_noise_octaves *o;
  const nl_noise_window *win;
  double dx, dy, *out, *scratch;   /* scratch: w doubles per thread */
} grid_job;

static void grid_row(void *ctx, size_t r, int thread)
{
  const grid_job *g = ctx;
  const nl_noise_window *win = g->win;
  size_t w = (size_t)win->w;
  /* nl_noise_fractal_grid's row r, the same arguments */
  nl_noise_fractal_row(g->b, g->o, win->x0 + 0.5 * g->dx, g->dx, win->y0 + ((double)r + 0.5) * g->dy,
                       win->z, w, g->out + r * w, g->scratch + (size_t)thread * w);
}

void nl_noise_fractal_grid_threads(const nl_noise_basis *b, const nl_noise_octaves *o,
                                   const nl_noise_window *win, int nthreads, double *out)
{
  double work = (double)win->w * win->h * (o->n > 1 ? o->n : 1);
  if (nthreads <= 1 || work < NL_NOISE_THREAD_MIN_SAMPLES) {
    nl_noise_fractal_grid(b, o, win, out);
    return;
  }
  grid_job g = {b, o, win, win->size / win->w, win->size / win->h, out, NULL};
  int nt = nl_parallel_threads((size_t)win->h, nthreads);
  g.scratch = nl_xmalloc((size_t)nt * (size_t)win->w * sizeof *g.scratch);
  nl_parallel_for((size_t)win->h, nt, grid_row, &g);
  free(g.scratch);
}

/* ---- checked batches ---------------------------------------------------------
 *
 * Points go in chunks of NL_NOISE_THREAD_CHUNK blocks, one chunk an item.
 * The one-thread contract leaves out[k1 ..) untouched after a refused
 * point k, so a chunk cannot write out before it knows that no earlier
 * chunk holds a refused point: each chunk is made in its thread's scratch
 * and copied to out in chunk order (a chunk waits for the one before it to
 * be copied; chunks are handed out in increasing order, so the one it waits
 * for is running or done). After a refusal the later chunks copy nothing. */

enum { NL_NOISE_THREAD_CHUNK = 16 };   /* blocks: 8192 points, 64 KiB of scratch, in L2 */
#define CHUNK_POINTS ((size_t)NL_NOISE_THREAD_CHUNK * NL_NOISE_CHECK_BLOCK)

typedef struct {
  const nl_noise_perm3 *p;
  const nl_noise_octaves *o;
  const nl_noise_grad2 *t;
  const double *x, *y, *z;
  size_t n;
  double *out, *scratch;   /* CHUNK_POINTS per thread */
  atomic_size_t copied;    /* chunks copied to out (or passed over after a refusal) */
  atomic_size_t first;     /* the first refused point, n if none so far */
} checked_job;

static void checked_chunk(void *ctx, size_t c, int thread)
{
  checked_job *j = ctx;
  size_t k0 = c * CHUNK_POINTS, m = j->n - k0 < CHUNK_POINTS ? j->n - k0 : CHUNK_POINTS;
  double *s = j->scratch + (size_t)thread * CHUNK_POINTS;
  size_t ok = 0;
  /* not worth making a chunk after a refusal already copied */
  if (atomic_load(&j->first) == j->n) {
    if (j->t) ok = nl_noise_grad2_points_checked(j->t, j->x + k0, j->y + k0, m, s);
    else ok = nl_noise_perm3_points_checked(j->p, j->o, j->x + k0, j->y + k0, j->z + k0, m, s);
  }
  while (atomic_load_explicit(&j->copied, memory_order_acquire) != c) sched_yield();
  if (atomic_load(&j->first) == j->n) {
    /* out[k0 .. k1): the chunk's values up to the end of the refused block */
    size_t end = ok == m ? m : (ok / NL_NOISE_CHECK_BLOCK + 1) * NL_NOISE_CHECK_BLOCK;
    memcpy(j->out + k0, s, (end < m ? end : m) * sizeof *s);
    if (ok < m) atomic_store(&j->first, k0 + ok);
  }
  atomic_store_explicit(&j->copied, c + 1, memory_order_release);
}

static size_t checked_threads(checked_job *j, int nthreads)
{
  size_t nchunk = (j->n + CHUNK_POINTS - 1) / CHUNK_POINTS;
  int nt = nl_parallel_threads(nchunk, nthreads);
  atomic_init(&j->copied, 0);
  atomic_init(&j->first, j->n);
  j->scratch = nl_xmalloc((size_t)nt * CHUNK_POINTS * sizeof *j->scratch);
  nl_parallel_for(nchunk, nt, checked_chunk, j);
  free(j->scratch);
  return atomic_load(&j->first);
}

size_t nl_noise_perm3_points_checked_threads(const nl_noise_perm3 *p, const nl_noise_octaves *o,
                                             const double *x, const double *y, const double *z,
                                             size_t n, double *out, int nthreads)
{
  double work = (double)n * (o && o->n > 1 ? o->n : 1);
  if (nthreads <= 1 || work < NL_NOISE_THREAD_MIN_SAMPLES || n <= CHUNK_POINTS)
    return nl_noise_perm3_points_checked(p, o, x, y, z, n, out);
  checked_job j = {.p = p, .o = o, .x = x, .y = y, .z = z, .n = n, .out = out};
  return checked_threads(&j, nthreads);
}

size_t nl_noise_grad2_points_checked_threads(const nl_noise_grad2 *t, const double *x,
                                             const double *y, size_t n, double *out, int nthreads)
{
  if (nthreads <= 1 || (double)n < NL_NOISE_THREAD_MIN_SAMPLES || n <= CHUNK_POINTS)
    return nl_noise_grad2_points_checked(t, x, y, n, out);
  checked_job j = {.t = t, .x = x, .y = y, .n = n, .out = out};
  return checked_threads(&j, nthreads);
}
