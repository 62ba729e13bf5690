/* bench_point - one call per point, the way a noise library is used:
 * for (...) v = noise(x, y, z);
 *
 * Single thread, 2^14 random points (the same points for every kernel;
 * floats for the float peers, the same values), in three sets:
 *   volume: (x, y, z) uniform in [0, 16)^3;
 *   plane:  (x, y) uniform in [0, 16)^2 on the plane z = 0.5 (a call
 *           compiled into the loop can hoist the z work out of it);
 *   2D:     the plane's (x, y).
 * Kernels and their peers, in the same process:
 *   perm3_volume, perm3_plane      nl_noise_perm3_eval (the reference
 *       permutation)  vs stb_perlin_noise3 (Debian's libstb-dev, float);
 *   grad2                          nl_noise_grad2_eval (M = 512, seed 1) vs
 *       FastNoiseLite's 2D Perlin, fnlGetNoise2D with FNL_NOISE_PERLIN,
 *       frequency 1, no fractal (float; bench/third_party/FastNoiseLite.h,
 *       MIT, used by this benchmark only): the like-for-like kernel, one
 *       gradient per lattice corner and Perlin's quintic fade;
 *   fbm4_volume, fbm4_plane        nl_noise_perm3_fractal_eval, 4 octaves,
 *       gain 1/2, lacunarity 2 vs stb_perlin_fbm_noise3 (same octaves).
 * The point calls also run as the library built them before the header's
 * inline fast path (*_old: old_perm3_eval and old_grad2_eval below, the
 * same bits, out of line and opaque to the caller as exported functions
 * are), so old and new are timed back to back; they run at the speed of
 * bench_point built against main 219f033 (same run: perm3 48, grad2 75
 * Msamples/s).
 *
 * 15 rounds over all the kernels, each kernel repeated in a round until at
 * least 20 ms of CPU time have passed; the fastest round of each is kept
 * (rounds rather than one stretch per kernel: on a shared machine every
 * kernel meets the same spells of contention). Rates are per second of
 * the thread's CPU time (CLOCK_THREAD_CPUTIME_ID); the load average is
 * printed before and after. The program pins itself to the processor it
 * starts on unless already given one.
 *
 *   build/bench/bench_point [--tsv] [--only KERNEL]
 *
 * --only KERNEL times that kernel alone (for perf record); its
 * vs_peer is then not a ratio.
 *
 * --tsv: '#' lines (load, CPU), a header, one line per kernel: kernel,
 * points, msamples_per_s, ns_per_call, peer, vs_peer (rate / peer's rate).
 */
#define _GNU_SOURCE
#include "nl_bench.h"
#include "noise/nl_noise.h"
#include "noise/nl_noise_lattice.h"
#include "base/nl_base.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Waggressive-loop-optimizations"
#define STB_PERLIN_IMPLEMENTATION
#include <stb/stb_perlin.h>
#define FNL_IMPL
#include "third_party/FastNoiseLite.h"
#pragma GCC diagnostic pop

enum { NPOINTS = 1 << 14, ROUNDS = 15 };
static const double EXTENT = 16.0, PLANE_Z = 0.5;

static double px[NPOINTS], py[NPOINTS], pz[NPOINTS], out[NPOINTS];
static float fx[NPOINTS], fy[NPOINTS], fz[NPOINTS];
static nl_noise_perm3 perm;
static nl_noise_grad2 *table;
static fnl_state fnl;

/* ---- the point calls before the inline fast path ---------------------- */

static const double old_grad3[16][3] = {
  {1,1,0},{-1,1,0},{1,-1,0},{-1,-1,0},{1,0,1},{-1,0,1},{1,0,-1},{-1,0,-1},
  {0,1,1},{0,-1,1},{0,1,-1},{0,-1,-1},{1,1,0},{0,-1,1},{-1,1,0},{0,-1,-1}};

static inline double old_blend(double t, double gx0, double a0, double gx1, double a1)
{
  double l = t * gx0 + a0;
  double r = (t - 1) * gx1 + a1;
  return l + nl_noise_fade(t) * (r - l);
}

static inline double old_yz_part(int h, double fy, double fz)
{
  return old_grad3[h][1] * fy + old_grad3[h][2] * fz;
}

static inline double old_lerp(double t, double a, double b) { return a + t * (b - a); }

static inline void old_column3(const nl_noise_perm3 *p, long i, long j, long k, double fy,
                               double fz, double v, double w, double *gxo, double *ao)
{
  int X = (int)(i & 255), Y = (int)(j & 255), Z = (int)(k & 255);
  int A = p->p[X] + Y, AA = p->p[A] + Z, AB = p->p[A + 1] + Z;
  int h00 = p->p[AA] & 15, h10 = p->p[AB] & 15, h01 = p->p[AA + 1] & 15;
  int h11 = p->p[AB + 1] & 15;
  double gx = old_lerp(w, old_lerp(v, old_grad3[h00][0], old_grad3[h10][0]),
                       old_lerp(v, old_grad3[h01][0], old_grad3[h11][0]));
  double a = old_lerp(w, old_lerp(v, old_yz_part(h00, fy, fz), old_yz_part(h10, fy - 1, fz)),
                      old_lerp(v, old_yz_part(h01, fy, fz - 1), old_yz_part(h11, fy - 1, fz - 1)));
  *gxo = gx;
  *ao = a;
}

__attribute__((noipa))
static double old_perm3_eval(const nl_noise_perm3 *p, double x, double y, double z)
{
  long i = nl_noise_lfloor(x), j = nl_noise_lfloor(y), k = nl_noise_lfloor(z);
  double fy = nl_noise_lfrac(y, j), fz = nl_noise_lfrac(z, k);
  double v = nl_noise_fade(fy), w = nl_noise_fade(fz), g0, a0, g1, a1;
  old_column3(p, i, j, k, fy, fz, v, w, &g0, &a0);
  old_column3(p, i + 1, j, k, fy, fz, v, w, &g1, &a1);
  return old_blend(nl_noise_lfrac(x, i), g0, a0, g1, a1);
}

/* Out of line and opaque to the caller, as the library's GCC -O3 build
 * left nl_noise_grad2_index (an exported function: bench_point built
 * against main 219f033 timed its grad2 at 75.5 Msamples/s). */
__attribute__((noipa))
static size_t old_grad2_index(const nl_noise_grad2 *t, long i, long j)
{
  long m = (long)t->m;
  if (m > 0 && (m & (m - 1)) == 0) {
    long k = m - 1;
    return t->perm[((long)t->perm[i & k] + j) & k];
  }
  long pi = (long)t->perm[nl_noise_lmod(i, m)];
  return t->perm[nl_noise_lmod(pi + nl_noise_lmod(j, m), m)];
}

static inline void old_column2(const nl_noise_grad2 *t, long i, long j, double fy, double v,
                               double *gxo, double *ao)
{
  size_t k0 = old_grad2_index(t, i, j), k1 = old_grad2_index(t, i, j + 1);
  double a0 = t->gy[k0] * fy, a1 = t->gy[k1] * (fy - 1);
  *gxo = t->gx[k0] + v * (t->gx[k1] - t->gx[k0]);
  *ao = a0 + v * (a1 - a0);
}

__attribute__((noipa))
static double old_grad2_eval(const nl_noise_grad2 *t, double x, double y)
{
  long i = nl_noise_lfloor(x), j = nl_noise_lfloor(y);
  double fy = nl_noise_lfrac(y, j), v = nl_noise_fade(fy), g0, a0, g1, a1;
  old_column2(t, i, j, fy, v, &g0, &a0);
  old_column2(t, i + 1, j, fy, v, &g1, &a1);
  return old_blend(nl_noise_lfrac(x, i), g0, a0, g1, a1);
}

/* The octaves of stb_perlin_fbm_noise3(x, y, z, 2, 0.5, 4). */
static nl_noise_octaves fbm4;

static void k_perm3_volume(void)
{
  for (int k = 0; k < NPOINTS; k++)
    out[k] = nl_noise_perm3_eval(&perm, px[k], py[k], pz[k]);
}

static void k_perm3_volume_old(void)
{
  for (int k = 0; k < NPOINTS; k++)
    out[k] = old_perm3_eval(&perm, px[k], py[k], pz[k]);
}

static void k_stb_volume(void)
{
  for (int k = 0; k < NPOINTS; k++)
    out[k] = stb_perlin_noise3(fx[k], fy[k], fz[k], 0, 0, 0);
}

static void k_perm3_plane(void)
{
  for (int k = 0; k < NPOINTS; k++)
    out[k] = nl_noise_perm3_eval(&perm, px[k], py[k], PLANE_Z);
}

static void k_perm3_plane_old(void)
{
  for (int k = 0; k < NPOINTS; k++)
    out[k] = old_perm3_eval(&perm, px[k], py[k], PLANE_Z);
}

static void k_stb_plane(void)
{
  for (int k = 0; k < NPOINTS; k++)
    out[k] = stb_perlin_noise3(fx[k], fy[k], (float)PLANE_Z, 0, 0, 0);
}

static void k_grad2(void)
{
  for (int k = 0; k < NPOINTS; k++)
    out[k] = nl_noise_grad2_eval(table, px[k], py[k]);
}

static void k_grad2_old(void)
{
  for (int k = 0; k < NPOINTS; k++)
    out[k] = old_grad2_eval(table, px[k], py[k]);
}

static void k_fnl2(void)
{
  for (int k = 0; k < NPOINTS; k++)
    out[k] = fnlGetNoise2D(&fnl, fx[k], fy[k]);
}

static void k_fbm4_volume(void)
{
  for (int k = 0; k < NPOINTS; k++)
    out[k] = nl_noise_perm3_fractal_eval(&perm, &fbm4, px[k], py[k], pz[k]);
}

static void k_stbfbm_volume(void)
{
  for (int k = 0; k < NPOINTS; k++)
    out[k] = stb_perlin_fbm_noise3(fx[k], fy[k], fz[k], 2.0f, 0.5f, 4);
}

static void k_fbm4_plane(void)
{
  for (int k = 0; k < NPOINTS; k++)
    out[k] = nl_noise_perm3_fractal_eval(&perm, &fbm4, px[k], py[k], PLANE_Z);
}

static void k_stbfbm_plane(void)
{
  for (int k = 0; k < NPOINTS; k++)
    out[k] = stb_perlin_fbm_noise3(fx[k], fy[k], (float)PLANE_Z, 2.0f, 0.5f, 4);
}

typedef struct {
  const char *name;
  void (*f)(void);
  int peer;        /* index of the kernel this one is compared with; -1: none */
  double rate;     /* best Msamples per CPU second */
} kernel;

static kernel ks[] = {
  {"stb_perlin_noise3_volume", k_stb_volume, -1, 0},
  {"perm3_volume", k_perm3_volume, 0, 0},
  {"perm3_volume_old", k_perm3_volume_old, 0, 0},
  {"stb_perlin_noise3_plane", k_stb_plane, -1, 0},
  {"perm3_plane", k_perm3_plane, 3, 0},
  {"perm3_plane_old", k_perm3_plane_old, 3, 0},
  {"fnl_perlin2d", k_fnl2, -1, 0},
  {"grad2", k_grad2, 6, 0},
  {"grad2_old", k_grad2_old, 6, 0},
  {"stb_perlin_fbm_noise3_volume", k_stbfbm_volume, -1, 0},
  {"fbm4_volume", k_fbm4_volume, 9, 0},
  {"stb_perlin_fbm_noise3_plane", k_stbfbm_plane, -1, 0},
  {"fbm4_plane", k_fbm4_plane, 11, 0},
};
enum { NK = sizeof ks / sizeof *ks };

static void round_of(kernel *k)
{
  size_t iters = 0;
  double c0 = nl_bench_cpu_now(), c;
  do {
    k->f();
    nl_bench_sink = out[iters % NPOINTS];
    iters++;
    c = nl_bench_cpu_now() - c0;
  } while (c < 0.02);
  double rate = (double)iters * NPOINTS / c / 1e6;
  if (rate > k->rate) k->rate = rate;
}

int main(int argc, char **argv)
{
  int tsv = 0;
  const char *only = NULL;
  for (int a = 1; a < argc; a++) {
    if (strcmp(argv[a], "--tsv") == 0) {
      tsv = 1;
    } else if (strcmp(argv[a], "--only") == 0 && a + 1 < argc) {
      only = argv[++a];
    } else {
      fprintf(stderr, "bench_point: unknown argument '%s'; usage: bench_point [--tsv] "
              "[--only KERNEL]\n", argv[a]);
      return 2;
    }
  }
  int known = !only;
  for (int i = 0; i < NK; i++) known |= only && strcmp(only, ks[i].name) == 0;
  if (!known) {
    fprintf(stderr, "bench_point: --only '%s': no such kernel (see the kernel column of a full "
            "run)\n", only);
    return 2;
  }
  char where[64], load0[128], load1[128];
  nl_bench_pin(where, sizeof where);
  nl_bench_loadavg(load0, sizeof load0);
  /* Coordinates on a 2^-20 grid, so the floats the peers take are the same values. */
  srand(1);
  for (int k = 0; k < NPOINTS; k++) {
    px[k] = EXTENT * ldexp(rand() % (1 << 20), -20);
    py[k] = EXTENT * ldexp(rand() % (1 << 20), -20);
    pz[k] = EXTENT * ldexp(rand() % (1 << 20), -20);
    fx[k] = (float)px[k];
    fy[k] = (float)py[k];
    fz[k] = (float)pz[k];
  }
  nl_noise_perm3_reference(&perm);
  table = nl_noise_grad2_alloc(512);
  nl_noise_grad2_seed(table, 1);
  fnl = fnlCreateState();
  fnl.noise_type = FNL_NOISE_PERLIN;
  fnl.frequency = 1.0f;
  fnl.fractal_type = FNL_FRACTAL_NONE;
  fbm4 = nl_noise_octaves_fbm(4, 0.5, 2.0);

  for (int r = 0; r < ROUNDS; r++)
    for (int i = 0; i < NK; i++)
      if (!only || strcmp(only, ks[i].name) == 0) round_of(&ks[i]);
  nl_bench_loadavg(load1, sizeof load1);

  const char *fmt = tsv ? "%s\t%d\t%.1f\t%.2f\t%s\t%s\n" : "%-30s %7d %10.1f %8.2f  %-30s %s\n";
  printf("# bench_point: one call per point, %d points a pass, single thread, %s, "
         "best of %d rounds by CPU time\n", NPOINTS, where, (int)ROUNDS);
  printf("# loadavg before: %s\n# loadavg after: %s\n", load0, load1);
  if (tsv) printf("kernel\tpoints\tmsamples_per_s\tns_per_call\tpeer\tvs_peer\n");
  else
    printf("%-30s %7s %10s %8s  %-30s %s\n", "kernel", "points", "Msample/s", "ns/call", "peer",
           "vs peer");
  for (int i = 0; i < NK; i++) {
    char ratio[32] = "-";
    if (only && strcmp(only, ks[i].name) != 0) continue;
    const kernel *peer = ks[i].peer >= 0 ? &ks[ks[i].peer] : NULL;
    if (peer && peer->rate > 0) snprintf(ratio, sizeof ratio, "%.2f", ks[i].rate / peer->rate);
    printf(fmt, ks[i].name, NPOINTS, ks[i].rate, 1e3 / ks[i].rate, peer ? peer->name : "-", ratio);
  }
  nl_noise_grad2_free(table);
  return 0;
}
