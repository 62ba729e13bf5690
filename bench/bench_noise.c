/* bench_noise - samples per second of our noises against stb_perlin.
 *
 * Single thread, a 1024 x 1024 grid over [0, 16)^2 (64 samples per lattice
 * cell at the base frequency) on the plane z = 0.5; 9 rounds over all the
 * kernels, stb's included, each kernel repeated in a round until at least
 * 0.1 s of CPU time has passed, and each kernel's fastest round reported
 * (rounds rather than one stretch per kernel: on a shared machine every
 * kernel then meets the same spells of contention). Time is the thread's CPU time
 * (CLOCK_THREAD_CPUTIME_ID: on a shared machine, time spent descheduled
 * does not count), wall time beside it. stb_perlin_noise3 and
 * stb_perlin_fbm_noise3 (Debian's libstb-dev) run on the same points in the
 * same run, so the ratio is machine-independent to first order; vs_stb of
 * the fBm rows is against stb_perlin_fbm_noise3 (4 octaves), of the others
 * against stb_perlin_noise3. The points kernels take random, incoherent
 * points in [0, 16)^2 (2D) or [0, 16)^3 (3D) through the batch API
 * (nl_noise_grad2_points, nl_noise_perm3_points): no row reuse; vs_stb of
 * the 3D points is against stb_perlin_noise3 on the same points.
 * noise3_row_sparse: rows of the same grid's y with 0.7 lattice cells per
 * sample (x = 0.35 + 0.7 k, z = 0.5), where a row holds fewer samples than
 * cells; vs_stb against stb_perlin_noise3 on the same samples.
 * wavelet_row: nl_wavelet_row over a 256^2 2D tile on the same grid.
 * cellular_row: nl_cellular_row, F1..F4 (Worley 1996; Qin & Yang 2000) on the
 * same grid at lambda = 4, M = 50, inverse-CDF counts, seed 1 (as
 * bench_cellular); a sample is one point's four distances, and vs_stb is
 * against stb_perlin_noise3 on the same points (stb has no cellular noise).
 * The program pins itself to the processor it starts on (sched_setaffinity)
 * unless already given one, and prints the load average.
 *
 * FastNoise2 (the float32 peer, fn2_* below) runs in the same rounds on the
 * same grids and points when its library loads: Perlin 3D and 2D by grid
 * rows (fnGenUniformGrid3D/2D) and at the random points (fnGenPositionArray
 * 3D/2D), and FractalFBm of 4 octaves over it on both grids; its lines
 * ("fn2: ...") give our rate, its rate and their ratio.
 *
 *   build/bench/bench_noise [--size N] [--tsv] [--fastnoise2 LIBRARY]
 *   NL_NOISE_SIMD=scalar|sse2|avx2|avx512 picks the noise kernels' level
 *   (avx2 also caps FastNoise2 at AVX2).
 *   --fastnoise2: FastNoise2's shared library (default: build/fastnoise2/
 *   lib/libFastNoise.so beside this program's build/bench, used if present;
 *   otherwise "# FastNoise2: not built" and no peer rows).
 *
 * --tsv: lines starting with '#' (load, level, CPU), then a header line and
 * one tab-separated line per kernel: kernel, msamples_per_s (per CPU
 * second), cpu_ms and wall_ms (of one 1024^2 grid), vs_stb; FastNoise2's
 * kernels as fastnoise2_<our kernel>.
 */
#define _GNU_SOURCE
#include "nl_bench.h"
#include "noise/nl_noise.h"
#include "wavelet/nl_wavelet.h"
#include "cellular/nl_cellular.h"
#include "base/nl_base.h"

#include <sched.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
/* FastNoise2, the peer loaded at run time */
#include <ctype.h>
#include <dlfcn.h>
#include <stdbool.h>
#include <unistd.h>

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wsign-compare"
#define STB_PERLIN_IMPLEMENTATION
#include <stb/stb_perlin.h>
#pragma GCC diagnostic pop

static int N = 1024;
static const double EXTENT = 16.0;
enum { ROUNDS = 9 };   /* rounds of >= 0.1 s CPU per kernel */

static void g_noise2(const void *ctx, double *out)
{
  double dx = EXTENT / N;
  for (int r = 0; r < N; r++) nl_noise_grad2_row(ctx, 0.5 * dx, dx, (r + 0.5) * dx, (size_t)N, out + (size_t)r * N);
}

static void g_noise3(const void *ctx, double *out)
{
  double dx = EXTENT / N;
  for (int r = 0; r < N; r++) nl_noise_perm3_row(ctx, 0.5 * dx, dx, (r + 0.5) * dx, 0.5, (size_t)N, out + (size_t)r * N);
}

static void g_fbm(const void *ctx, double *out)
{
  const nl_noise_basis *b = ctx;
  nl_noise_octaves o = nl_noise_octaves_fbm(4, 0.5, 2.0);
  nl_noise_window w = {0, 0, 0.5, EXTENT, N, N};
  nl_noise_fractal_grid(b, &o, &w, out);
}

static void g_stb3(const void *ctx, double *out)
{
  (void)ctx;
  float dx = (float)(EXTENT / N);
  for (int r = 0; r < N; r++)
    for (int c = 0; c < N; c++)
      out[(size_t)r * N + c] = stb_perlin_noise3((c + 0.5f) * dx, (r + 0.5f) * dx, 0.5f, 0, 0, 0);
}

static void g_stbfbm(const void *ctx, double *out)
{
  (void)ctx;
  float dx = (float)(EXTENT / N);
  for (int r = 0; r < N; r++)
    for (int c = 0; c < N; c++)
      out[(size_t)r * N + c] = stb_perlin_fbm_noise3((c + 0.5f) * dx, (r + 0.5f) * dx, 0.5f, 2.0f, 0.5f, 4);
}

/* Sparse rows: 0.7 lattice cells per sample. */
static const double SPARSE_DX = 0.7, SPARSE_X0 = 0.35;

static void g_noise3_sparse(const void *ctx, double *out)
{
  double dy = EXTENT / N;
  for (int r = 0; r < N; r++)
    nl_noise_perm3_row(ctx, SPARSE_X0, SPARSE_DX, (r + 0.5) * dy, 0.5, (size_t)N,
                       out + (size_t)r * N);
}

static void g_stb3_sparse(const void *ctx, double *out)
{
  (void)ctx;
  double dy = EXTENT / N;
  for (int r = 0; r < N; r++)
    for (int c = 0; c < N; c++) {
      float x = (float)(SPARSE_X0 + c * SPARSE_DX), y = (float)((r + 0.5) * dy);
      out[(size_t)r * N + c] = stb_perlin_noise3(x, y, 0.5f, 0, 0, 0);
    }
}

static double *rx, *ry, *rz;
static void g_stb3_points(const void *ctx, double *out)
{
  (void)ctx;
  for (size_t k = 0; k < (size_t)N * N; k++)
    out[k] = stb_perlin_noise3((float)rx[k], (float)ry[k], (float)rz[k], 0, 0, 0);
}

static void g_noise2_points(const void *ctx, double *out)
{
  nl_noise_grad2_points(ctx, rx, ry, (size_t)N * N, out);
}

static void g_noise3_points(const void *ctx, double *out)
{
  nl_noise_perm3_points(ctx, rx, ry, rz, (size_t)N * N, out);
}

/* Wavelet noise (Cook and DeRose 2005) from a 256^2 2D tile, the same grid:
 * nl_wavelet_row adds into the row, so each row starts at 0. */
static void g_wavelet(const void *ctx, double *out)
{
  double dx = EXTENT / N;
  memset(out, 0, (size_t)N * N * sizeof *out);
  for (int r = 0; r < N; r++) nl_wavelet_row(ctx, 0.5 * dx, dx, (r + 0.5) * dx, 0, (size_t)N, 1.0, out + (size_t)r * N);
}

/* F1..F4 rows: the output holds 4 N^2 doubles, F[k*4 + i] per row. */
static void g_cellular(const void *ctx, double *out)
{
  double dx = EXTENT / N;
  for (int r = 0; r < N; r++)
    nl_cellular_row(ctx, 0.5 * dx, dx, (r + 0.5) * dx, 0.5, (size_t)N, 4, out + 4 * (size_t)r * N);
}

typedef struct { double rate, cpu_ms, wall_ms; } timing;
static volatile double sink;

/* The float32 path (nl_noise.h) on the same grid, sparse rows and random
 * points (rounded to float), into float buffers made at the first call. */
static float *f32_out, *f32_x, *f32_y, *f32_z;
static float *f32_buf(void)
{
  if (!f32_out) {
    size_t n = (size_t)N * N;
    f32_out = nl_xmalloc(n * sizeof *f32_out);
    f32_x = nl_xmalloc(n * sizeof *f32_x);
    f32_y = nl_xmalloc(n * sizeof *f32_y);
    f32_z = nl_xmalloc(n * sizeof *f32_z);
    for (size_t k = 0; k < n; k++) {
      f32_x[k] = (float)rx[k];
      f32_y[k] = (float)ry[k];
      f32_z[k] = (float)rz[k];
    }
  }
  return f32_out;
}
static void g_noise3_f32(const void *ctx, double *out)
{
  (void)out;
  float *o = f32_buf(), dx = (float)(EXTENT / N);
  for (int r = 0; r < N; r++)
    nl_noise_perm3_row_f32(ctx, 0.5f * dx, dx, (float)((r + 0.5) * dx), 0.5f, (size_t)N, o + (size_t)r * N);
}
static void g_noise3_sparse_f32(const void *ctx, double *out)
{
  (void)out;
  float *o = f32_buf();
  double dy = EXTENT / N;
  for (int r = 0; r < N; r++)
    nl_noise_perm3_row_f32(ctx, (float)SPARSE_X0, (float)SPARSE_DX, (float)((r + 0.5) * dy), 0.5f, (size_t)N,
                           o + (size_t)r * N);
}
static void g_noise2_f32(const void *ctx, double *out)
{
  (void)out;
  float *o = f32_buf(), dx = (float)(EXTENT / N);
  for (int r = 0; r < N; r++)
    nl_noise_grad2_row_f32(ctx, 0.5f * dx, dx, (float)((r + 0.5) * dx), (size_t)N, o + (size_t)r * N);
}
static void g_noise3_points_f32(const void *ctx, double *out)
{
  (void)out;
  float *o = f32_buf();
  nl_noise_perm3_points_f32(ctx, f32_x, f32_y, f32_z, (size_t)N * N, o);
}
static void g_noise2_points_f32(const void *ctx, double *out)
{
  (void)out;
  float *o = f32_buf();
  nl_noise_grad2_points_f32(ctx, f32_x, f32_y, (size_t)N * N, o);
}
static void g_fbm3_f32(const void *ctx, double *out)
{
  (void)out;
  nl_noise_octaves o = nl_noise_octaves_fbm(4, 0.5, 2.0);
  nl_noise_window w = {0, 0, 0.5, EXTENT, N, N};
  nl_noise_fractal_grid_f32(NULL, ctx, &o, &w, f32_buf());
}
static void g_fbm2_f32(const void *ctx, double *out)
{
  (void)out;
  nl_noise_octaves o = nl_noise_octaves_fbm(4, 0.5, 2.0);
  nl_noise_window w = {0, 0, 0.5, EXTENT, N, N};
  nl_noise_fractal_grid_f32(ctx, NULL, &o, &w, f32_buf());
}

/* One round of a kernel: repeated for at least 0.1 s of CPU time; the
 * fastest round is kept. The rate is per CPU second. */
static void round_of(void (*f)(const void *, double *), const void *ctx, double *out, timing *best)
{
  size_t npoints = (size_t)N * N, iters = 0;
  double c0 = nl_bench_cpu_now(), w0 = nl_time_now(), c, w;
  do { f(ctx, out); sink = out[iters % npoints]; iters++; c = nl_bench_cpu_now() - c0; } while (c < 0.1);
  w = nl_time_now() - w0;
  double rate = (double)iters * (double)npoints / c / 1e6;
  if (rate > best->rate) { best->rate = rate; best->cpu_ms = 1e3 * c / (double)iters; best->wall_ms = 1e3 * w / (double)iters; }
}

/* ---- FastNoise2, the float32 peer (loaded with dlopen) -------------------
 * FastNoise2 (Auburn, MIT; bench/third_party/FastNoise2, built by
 * `scripts/noiselab bench` into build/fastnoise2) through its C API. Its
 * Perlin node is set to our frequency ("Feature Scale" 1: a sample at x
 * reads lattice cell floor(x), as ours), one octave; its FractalFBm over
 * that node is 4 octaves, gain 0.5, lacunarity 2, as ours. It computes in
 * float (32-bit) in its widest SIMD level (fnGetActiveFeatureSet; capped at
 * AVX2 when NL_NOISE_SIMD=avx2, so that both sides run at one level); ours in
 * double. Same points (the random points rounded to float), same rounds. */
typedef struct {
  void *lib, *perlin, *fbm;
  unsigned level;
  int (*meta_count)(void);
  const char *(*meta_name)(int);
  void *(*new_node)(int, unsigned);
  void (*del_node)(void *);
  unsigned (*active_level)(const void *);
  int (*var_count)(int);
  const char *(*var_name)(int, int);
  bool (*set_float)(void *, int, float);
  bool (*set_int)(void *, int, int);
  int (*lookup_count)(int);
  const char *(*lookup_name)(int, int);
  bool (*set_lookup)(void *, int, const void *);
  int (*hybrid_count)(int);
  const char *(*hybrid_name)(int, int);
  bool (*set_hybrid)(void *, int, float);
  void (*grid2)(const void *, float *, float, float, int, int, float, float, int, float *);
  void (*grid3)(const void *, float *, float, float, float, int, int, int, float, float, float, int, float *);
  void (*pos2)(const void *, float *, int, const float *, const float *, float, float, int, float *);
  void (*pos3)(const void *, float *, int, const float *, const float *, const float *, float, float, float, int,
               float *);
} fn2_api;

static fn2_api fn2;
static float *fx, *fy, *fz;
enum { FN2_SEED = 1337 };

static int fn2_meta_id(const char *name)
{
  for (int i = 0; i < fn2.meta_count(); i++)
    if (strcmp(fn2.meta_name(i), name) == 0) return i;
  return -1;
}

/* Index of the variable, node lookup or hybrid called name of node type id
 * (the name compared without spaces and case: the C API formats them). */
static int fn2_same(const char *a, const char *b)
{
  for (;; a++, b++) {
    while (*a == ' ') a++;
    while (*b == ' ') b++;
    if (tolower((unsigned char)*a) != tolower((unsigned char)*b)) return 0;
    if (!*a) return 1;
  }
}

static int fn2_index(int (*count)(int), const char *(*name)(int, int), int id, const char *want)
{
  for (int i = 0; i < count(id); i++)
    if (fn2_same(name(id, i), want)) return i;
  return -1;
}

static const char *fn2_level_name(unsigned fs)
{
  /* FastSIMD::FeatureFlag bits: SSE2 3, SSE41 6, AVX2 9, AVX512_F 10 */
  if (fs & (1u << 10)) return "AVX512";
  if (fs & (1u << 9)) return "AVX2";
  if (fs & (1u << 6)) return "SSE4.1";
  if (fs & (1u << 3)) return "SSE2";
  return "scalar";
}

/* Loads path; on failure says why in why and returns 0. */
static int fn2_load(const char *path, char *why, size_t len)
{
  fn2.lib = dlopen(path, RTLD_NOW | RTLD_LOCAL);
  if (!fn2.lib) { snprintf(why, len, "%s", dlerror()); return 0; }
  struct { void **fp; const char *name; } sym[] = {
    {(void **)&fn2.meta_count, "fnGetMetadataCount"}, {(void **)&fn2.meta_name, "fnGetMetadataName"},
    {(void **)&fn2.new_node, "fnNewFromMetadata"}, {(void **)&fn2.del_node, "fnDeleteNodeRef"},
    {(void **)&fn2.active_level, "fnGetActiveFeatureSet"},
    {(void **)&fn2.var_count, "fnGetMetadataVariableCount"}, {(void **)&fn2.var_name, "fnGetMetadataVariableName"},
    {(void **)&fn2.set_float, "fnSetVariableFloat"}, {(void **)&fn2.set_int, "fnSetVariableIntEnum"},
    {(void **)&fn2.lookup_count, "fnGetMetadataNodeLookupCount"},
    {(void **)&fn2.lookup_name, "fnGetMetadataNodeLookupName"}, {(void **)&fn2.set_lookup, "fnSetNodeLookup"},
    {(void **)&fn2.hybrid_count, "fnGetMetadataHybridCount"}, {(void **)&fn2.hybrid_name, "fnGetMetadataHybridName"},
    {(void **)&fn2.set_hybrid, "fnSetHybridFloat"},
    {(void **)&fn2.grid2, "fnGenUniformGrid2D"}, {(void **)&fn2.grid3, "fnGenUniformGrid3D"},
    {(void **)&fn2.pos2, "fnGenPositionArray2D"}, {(void **)&fn2.pos3, "fnGenPositionArray3D"},
  };
  for (size_t i = 0; i < sizeof sym / sizeof *sym; i++)
    if (!(*sym[i].fp = dlsym(fn2.lib, sym[i].name))) { snprintf(why, len, "%s: no %s", path, sym[i].name); return 0; }
  /* FastSIMD::FeatureSet AVX2 (x86, SSE..AVX2: bits 1-9), or no limit */
  const char *lv = getenv("NL_NOISE_SIMD");
  unsigned cap = lv && strcmp(lv, "avx2") == 0 ? 0x3FEu : ~0u;
  int pid = fn2_meta_id("Perlin"), fid = fn2_meta_id("FractalFBm");
  if (pid < 0 || fid < 0) { snprintf(why, len, "%s: no Perlin or FractalFBm node", path); return 0; }
  fn2.perlin = fn2.new_node(pid, cap);
  fn2.fbm = fn2.new_node(fid, cap);
  int scale = fn2_index(fn2.var_count, fn2.var_name, pid, "Feature Scale");
  int oct = fn2_index(fn2.var_count, fn2.var_name, fid, "Octaves");
  int lac = fn2_index(fn2.var_count, fn2.var_name, fid, "Lacunarity");
  int src = fn2_index(fn2.lookup_count, fn2.lookup_name, fid, "Source");
  int gain = fn2_index(fn2.hybrid_count, fn2.hybrid_name, fid, "Gain");
  if (!fn2.perlin || !fn2.fbm || scale < 0 || oct < 0 || lac < 0 || src < 0 || gain < 0 ||
      !fn2.set_float(fn2.perlin, scale, 1.0f) || !fn2.set_int(fn2.fbm, oct, 4) ||
      !fn2.set_float(fn2.fbm, lac, 2.0f) || !fn2.set_hybrid(fn2.fbm, gain, 0.5f) ||
      !fn2.set_lookup(fn2.fbm, src, fn2.perlin)) {
    snprintf(why, len, "%s: cannot set Perlin's scale or the fBm's octaves, gain, lacunarity, source", path);
    return 0;
  }
  fn2.level = fn2.active_level(fn2.perlin);
  return 1;
}

static void f_fn2_noise3(const void *ctx, double *out)
{
  (void)ctx;
  float dx = (float)(EXTENT / N);
  fn2.grid3(fn2.perlin, (float *)out, 0.5f * dx, 0.5f * dx, 0.5f, N, N, 1, dx, dx, dx, FN2_SEED, NULL);
}

static void f_fn2_noise2(const void *ctx, double *out)
{
  (void)ctx;
  float dx = (float)(EXTENT / N);
  fn2.grid2(fn2.perlin, (float *)out, 0.5f * dx, 0.5f * dx, N, N, dx, dx, FN2_SEED, NULL);
}

static void f_fn2_fbm3(const void *ctx, double *out)
{
  (void)ctx;
  float dx = (float)(EXTENT / N);
  fn2.grid3(fn2.fbm, (float *)out, 0.5f * dx, 0.5f * dx, 0.5f, N, N, 1, dx, dx, dx, FN2_SEED, NULL);
}

static void f_fn2_fbm2(const void *ctx, double *out)
{
  (void)ctx;
  float dx = (float)(EXTENT / N);
  fn2.grid2(fn2.fbm, (float *)out, 0.5f * dx, 0.5f * dx, N, N, dx, dx, FN2_SEED, NULL);
}

static void f_fn2_points3(const void *ctx, double *out)
{
  (void)ctx;
  fn2.pos3(fn2.perlin, (float *)out, N * N, fx, fy, fz, 0, 0, 0, FN2_SEED, NULL);
}

static void f_fn2_points2(const void *ctx, double *out)
{
  (void)ctx;
  fn2.pos2(fn2.perlin, (float *)out, N * N, fx, fy, 0, 0, FN2_SEED, NULL);
}

/* Each FastNoise2 kernel beside the one of ours it is compared with (by
 * name in main's table k[]). */
static struct { const char *ours, *label; void (*f)(const void *, double *); timing tm; } fn2k[] = {
  {"noise3_row", "Perlin 3D, grid rows", f_fn2_noise3, {0, 0, 0}},
  {"noise3_points", "Perlin 3D, random points", f_fn2_points3, {0, 0, 0}},
  {"noise2_row", "Perlin 2D, grid rows", f_fn2_noise2, {0, 0, 0}},
  {"noise2_points", "Perlin 2D, random points", f_fn2_points2, {0, 0, 0}},
  {"fbm4_3d_row", "FractalFBm 4 oct, 3D grid", f_fn2_fbm3, {0, 0, 0}},
  {"fbm4_2d_row", "FractalFBm 4 oct, 2D grid", f_fn2_fbm2, {0, 0, 0}},
};
enum { NFN2 = sizeof fn2k / sizeof *fn2k };

static void fn2_say(int have, const char *path, const char *why, const char *level)
{
  if (!have) printf("# FastNoise2: %s\n", why);
  else
    printf("# FastNoise2 (%s), SIMD level %s, float32, same points and rounds; ours in double, level %s\n",
           path, fn2_level_name(fn2.level), level);
}

/* The library: --fastnoise2 PATH, else build/fastnoise2/lib/libFastNoise.so
 * beside this program's build/bench. */
static const char *fn2_default_path(char *buf, size_t len)
{
  ssize_t r = readlink("/proc/self/exe", buf, len - 1);
  if (r <= 0) return NULL;
  buf[r] = 0;
  char *slash = strrchr(buf, '/');
  if (!slash) return NULL;
  *slash = 0;
  slash = strrchr(buf, '/');   /* build/bench -> build */
  if (!slash) return NULL;
  *slash = 0;
  size_t used = strlen(buf);
  snprintf(buf + used, len - used, "/fastnoise2/lib/libFastNoise.so");
  return access(buf, R_OK) == 0 ? buf : NULL;
}




/* ---- threads: fbm6 on a 4096^2 grid, 1 thread and 2 ----------------------
 *
 * nl_noise_fractal_grid_threads with 1 and 2 threads, alternately, best
 * wall time of 3 each (a thread's CPU time would not show the split), on
 * the processors the program was given before it pinned itself (all, or
 * taskset's list: under taskset -c 1 the two threads share one), and
 * whether the two grids have the same bytes. One line, after the table. */
static void threads_figure(const cpu_set_t *given, int tsv)
{
  enum { TN = 4096, TREPS = 3 };
  cpu_set_t pinned;
  sched_getaffinity(0, sizeof pinned, &pinned);
  sched_setaffinity(0, sizeof *given, given);
  nl_noise_perm3 p;
  nl_noise_perm3_reference(&p);
  nl_noise_basis b = nl_noise_basis_perm3(&p);
  nl_noise_octaves o = nl_noise_octaves_fbm(6, 0.5, 2.0);
  nl_noise_window w = {0, 0, 0.5, EXTENT, TN, TN};
  size_t n = (size_t)TN * TN;
  double *g[2] = {nl_xmalloc(n * sizeof(double)), nl_xmalloc(n * sizeof(double))};
  double best[2] = {1e300, 1e300};
  for (int r = 0; r < TREPS; r++)
    for (int t = 0; t < 2; t++) {
      double w0 = nl_time_now();
      nl_noise_fractal_grid_threads(&b, &o, &w, t + 1, g[t]);
      double dt = nl_time_now() - w0;
      best[t] = dt < best[t] ? dt : best[t];
    }
  char load[128];
  nl_bench_loadavg(load, sizeof load);
  printf("%sfbm6 4096^2 grid, 1 thread / 2 threads: %.1f / %.1f ms wall, %.2fx, same bytes: %s"
         " (%d processors allowed, load %s)\n", tsv ? "# " : "", 1e3 * best[0], 1e3 * best[1],
         best[0] / best[1], memcmp(g[0], g[1], n * sizeof(double)) ? "NO" : "yes", CPU_COUNT(given),
         load);
  free(g[0]);
  free(g[1]);
  sched_setaffinity(0, sizeof pinned, &pinned);
}

/* What a CPU with AVX2 and no AVX-512 keeps: improved 3D by rows and at
 * random points on the AVX2 level and on the best level, alternately, in
 * the same rounds (best of 5 each), as a share of the best level's rate.
 * One line after the table; nothing when the CPU has no AVX-512. */
static void levels_figure(const nl_noise_perm3 *p, double *out, int tsv)
{
  int best = nl_noise_simd_best(), was = nl_noise_simd_get();
  if (best != NL_NOISE_SIMD_AVX512 || !nl_noise_simd_supported(NL_NOISE_SIMD_AVX2)) return;
  timing t[2][2] = {{{0, 0, 0}}};   /* [level: avx2, best][rows, points] */
  for (int r = 0; r < 5; r++)
    for (int l = 0; l < 2; l++) {
      if (nl_noise_simd_set(l ? best : NL_NOISE_SIMD_AVX2)) return;
      round_of(g_noise3, p, out, &t[l][0]);
      round_of(g_noise3_points, p, out, &t[l][1]);
    }
  nl_noise_simd_set(was);
  printf("%ssimd levels, improved 3D rows / random points: avx2 %.1f / %.1f, %s %.1f / %.1f"
         " Msamples per CPU s, avx2 keeps %.1f%% / %.1f%%\n", tsv ? "# " : "", t[0][0].rate,
         t[0][1].rate, nl_noise_simd_name(best), t[1][0].rate, t[1][1].rate,
         100 * t[0][0].rate / t[1][0].rate, 100 * t[0][1].rate / t[1][1].rate);
}

int main(int argc, char **argv)
{
  int tsv = 0;
  const char *fn2_path = NULL;
  for (int a = 1; a < argc; a++) {
    if (strcmp(argv[a], "--size") == 0 && a + 1 < argc) N = atoi(argv[++a]);
    else if (strcmp(argv[a], "--tsv") == 0) tsv = 1;
    else if (strcmp(argv[a], "--fastnoise2") == 0 && a + 1 < argc) fn2_path = argv[++a];
    else { fprintf(stderr, "usage: bench_noise [--size N] [--tsv] [--fastnoise2 LIBRARY]\n"); return 2; }
  }
  if (N < 16 || N > 8192) { fprintf(stderr, "bench_noise: --size must be in [16, 8192]\n"); return 2; }
  char where[64], load0[128], load1[128];
  cpu_set_t given;   /* before the pin: the threads figure's processors */
  sched_getaffinity(0, sizeof given, &given);
  nl_bench_pin(where, sizeof where);
  nl_bench_loadavg(load0, sizeof load0);
  double *out = nl_xmalloc(4 * (size_t)N * N * sizeof *out);   /* 4: cellular's F1..F4 */
  rx = nl_xmalloc((size_t)N * N * sizeof *rx);
  ry = nl_xmalloc((size_t)N * N * sizeof *ry);
  rz = nl_xmalloc((size_t)N * N * sizeof *rz);
  srand(1);
  for (size_t k = 0; k < (size_t)N * N; k++) {
    rx[k] = EXTENT * rand() / RAND_MAX; ry[k] = EXTENT * rand() / RAND_MAX; rz[k] = EXTENT * rand() / RAND_MAX;
  }
  /* FastNoise2: a library named on the command line must load (exit 2
   * otherwise); the default one is used when it was built. */
  char fn2_buf[4096], fn2_why[512] = "not built (scripts/noiselab bench builds it)";
  int have_fn2 = 0;
  if (!fn2_path) fn2_path = fn2_default_path(fn2_buf, sizeof fn2_buf);
  else if (!fn2_load(fn2_path, fn2_why, sizeof fn2_why)) {
    fprintf(stderr, "bench_noise: --fastnoise2 %s: %s\n", fn2_path, fn2_why);
    return 2;
  } else have_fn2 = 1;
  if (fn2_path && !have_fn2) have_fn2 = fn2_load(fn2_path, fn2_why, sizeof fn2_why);
  if (have_fn2) {
    fx = nl_xmalloc((size_t)N * N * sizeof *fx);
    fy = nl_xmalloc((size_t)N * N * sizeof *fy);
    fz = nl_xmalloc((size_t)N * N * sizeof *fz);
    for (size_t q = 0; q < (size_t)N * N; q++) { fx[q] = (float)rx[q]; fy[q] = (float)ry[q]; fz[q] = (float)rz[q]; }
  }
  nl_noise_grad2 *t = nl_noise_grad2_alloc(512);
  nl_noise_grad2_seed(t, 1);
  nl_noise_perm3 p;
  nl_noise_perm3_reference(&p);
  nl_noise_basis b2 = nl_noise_basis_grad2(t), b3 = nl_noise_basis_perm3(&p);
  nl_wavelet_tile *wt = nl_wavelet_tile_alloc(2, 256);
  nl_wavelet_tile_seed(wt, 1);
  nl_cellular *cell;
  nl_error err;
  if (nl_cellular_alloc(4.0, 50, NL_COUNT_INVERSE_CDF, 1, &cell, &err)) {
    fprintf(stderr, "bench_noise: %s\n", err.msg);
    return 1;
  }

  /* fbm: the peer of vs_stb: 1 stb's fBm; 0 and 2 stb_perlin_noise3 on the
   * grid, 3 on the sparse rows' samples, 4 on the random points */
  struct { const char *name, *label; void (*f)(const void *, double *); const void *ctx; int fbm; timing tm; } k[] = {
    {"noise3_row", "nl_noise_perm3_row (improved 3D)", g_noise3, &p, 0, {0, 0, 0}},
    {"noise3_row_sparse", "nl_noise_perm3_row, 0.7 cells/sample", g_noise3_sparse, &p, 3,
     {0, 0, 0}},
    {"noise3_points", "nl_noise_perm3_points, random", g_noise3_points, &p, 4, {0, 0, 0}},
    {"noise2_row", "nl_noise_grad2_row (2D table, M=512)", g_noise2, t, 0, {0, 0, 0}},
    {"noise2_points", "nl_noise_grad2_points, random", g_noise2_points, t, 0, {0, 0, 0}},
    {"fbm4_3d_row", "fbm 4 oct, improved 3D", g_fbm, &b3, 1, {0, 0, 0}},
    {"fbm4_2d_row", "fbm 4 oct, 2D table", g_fbm, &b2, 1, {0, 0, 0}},
    {"cellular_row", "nl_cellular_row (F1..F4, lambda=4)", g_cellular, cell, 2, {0, 0, 0}},
    {"wavelet_row", "nl_wavelet_row (2D tile, 256^2)", g_wavelet, wt, 2, {0, 0, 0}},
    /* the float32 path, each row's peer as its double kernel's */
    {"noise3_row_f32", "nl_noise_perm3_row_f32 (float32)", g_noise3_f32, &p, 0, {0, 0, 0}},
    {"noise3_row_sparse_f32", "nl_noise_perm3_row_f32, 0.7 cells", g_noise3_sparse_f32, &p, 3, {0, 0, 0}},
    {"noise3_points_f32", "nl_noise_perm3_points_f32, random", g_noise3_points_f32, &p, 4, {0, 0, 0}},
    {"noise2_row_f32", "nl_noise_grad2_row_f32 (float32)", g_noise2_f32, t, 0, {0, 0, 0}},
    {"noise2_points_f32", "nl_noise_grad2_points_f32, random", g_noise2_points_f32, t, 0, {0, 0, 0}},
    {"fbm4_3d_row_f32", "fbm 4 oct, improved 3D, float32", g_fbm3_f32, &p, 1, {0, 0, 0}},
    {"fbm4_2d_row_f32", "fbm 4 oct, 2D table, float32", g_fbm2_f32, t, 1, {0, 0, 0}},
  };
  /* Rounds over all the kernels, stb's among them, so that each meets the
   * same spells of a shared machine; the fastest round of each counts. */
  timing stb = {0, 0, 0}, stbf = {0, 0, 0}, stbs = {0, 0, 0}, stbp = {0, 0, 0};
  for (int r = 0; r < ROUNDS; r++) {
    round_of(g_stb3, NULL, out, &stb);
    round_of(g_stbfbm, NULL, out, &stbf);
    round_of(g_stb3_sparse, NULL, out, &stbs);
    round_of(g_stb3_points, NULL, out, &stbp);
    for (size_t i = 0; i < sizeof k / sizeof *k; i++) round_of(k[i].f, k[i].ctx, out, &k[i].tm);
    for (int i = 0; have_fn2 && i < NFN2; i++) round_of(fn2k[i].f, NULL, out, &fn2k[i].tm);
  }
  int nk = (int)(sizeof k / sizeof *k);
  const timing *peer[] = {&stb, &stbf, &stb, &stbs, &stbp};   /* by the field fbm */
  nl_bench_loadavg(load1, sizeof load1);
  const char *level = nl_noise_simd_name(nl_noise_simd_get());
  if (tsv) {
    printf("# bench_noise: %d x %d grid over [0,%g)^2, single thread, %s, best of %d rounds, noise kernels: %s\n",
           N, N, EXTENT, where, (int)ROUNDS, level);
    printf("# loadavg before: %s\n# loadavg after: %s\n", load0, load1);
    printf("# stb_perlin_noise3 %.1f Msamples/s, stb_perlin_fbm_noise3 (4 oct) %.1f Msamples/s\n", stb.rate, stbf.rate);
    printf("# stb_perlin_noise3 on the sparse rows' samples %.1f Msamples/s, on the random"
           " points %.1f\n", stbs.rate, stbp.rate);
    fn2_say(have_fn2, fn2_path, fn2_why, level);
    printf("kernel\tmsamples_per_s\tcpu_ms\twall_ms\tvs_stb\n");
    for (int i = 0; i < nk; i++)
      printf("%s\t%.1f\t%.2f\t%.2f\t%.2f\n", k[i].name, k[i].tm.rate, k[i].tm.cpu_ms, k[i].tm.wall_ms,
             k[i].tm.rate / peer[k[i].fbm]->rate);
  } else {
    printf("# %d x %d grid over [0,%g)^2, single thread (%s), Msamples per CPU second (best of %d rounds), kernels: %s\n",
           N, N, EXTENT, where, (int)ROUNDS, level);
    printf("# load average: %s (before), %s (after)\n", load0, load1);
    printf("%-34s %10s %10s %10s %8s\n", "noise", "Msample/s", "cpu ms", "wall ms", "vs stb");
    /* each peer's line above the rows compared with it (scripts/noiselab bench reads them so) */
    static const char *peer_name[] = {"stb_perlin_noise3", "stb_perlin_fbm_noise3 (4 oct)",
                                      "stb_perlin_noise3", "stb_perlin_noise3, same samples",
                                      "stb_perlin_noise3, same points"};
    for (int i = 0; i < nk; i++) {
      const timing *pe = peer[k[i].fbm];
      if (i == 0 || pe != peer[k[i - 1].fbm])
        printf("%-34s %10.1f %10.2f %10.2f %8s\n", peer_name[k[i].fbm], pe->rate, pe->cpu_ms,
               pe->wall_ms, "1.00");
      printf("%-34s %10.1f %10.2f %10.2f %8.2f\n", k[i].label, k[i].tm.rate, k[i].tm.cpu_ms, k[i].tm.wall_ms,
             k[i].tm.rate / pe->rate);
    }
  }
  /* FastNoise2 beside ours: ratio = our rate / its rate (> 1: ours faster);
   * with --tsv its '#' line went above the table */
  if (!tsv) fn2_say(have_fn2, fn2_path, fn2_why, level);
  if (have_fn2) {
    if (!tsv) printf("%-44s %10s %10s %8s\n", "ours vs FastNoise2", "ours", "FN2", "ratio");
    for (int i = 0; i < NFN2; i++) {
      const timing *ours = &k[0].tm, *stb_peer = peer[0];
      const char *olabel = "";
      for (int j = 0; j < nk; j++)
        if (strcmp(k[j].name, fn2k[i].ours) == 0) { ours = &k[j].tm; olabel = k[j].label; stb_peer = peer[k[j].fbm]; }
      if (tsv)
        printf("fastnoise2_%s\t%.1f\t%.2f\t%.2f\t%.2f\n", fn2k[i].ours, fn2k[i].tm.rate, fn2k[i].tm.cpu_ms,
               fn2k[i].tm.wall_ms, fn2k[i].tm.rate / stb_peer->rate);
      else
        printf("fn2: %-39s %10.1f %10.1f %8.2f   (%s)\n", olabel, ours->rate, fn2k[i].tm.rate,
               ours->rate / fn2k[i].tm.rate, fn2k[i].label);
      /* and our float32 kernel of the same work, where there is one: the
       * like-for-like comparison (FastNoise2 computes in float) */
      char f32name[64];
      snprintf(f32name, sizeof f32name, "%s_f32", fn2k[i].ours);
      for (int j = 0; !tsv && j < nk; j++)
        if (strcmp(k[j].name, f32name) == 0)
          printf("fn2: %-39s %10.1f %10.1f %8.2f   (%s)\n", k[j].label, k[j].tm.rate, fn2k[i].tm.rate,
                 k[j].tm.rate / fn2k[i].tm.rate, fn2k[i].label);
    }
    fn2.del_node(fn2.fbm);
    fn2.del_node(fn2.perlin);
    free(fx); free(fy); free(fz);
  }
  levels_figure(&p, out, tsv);
  threads_figure(&given, tsv);
  nl_noise_grad2_free(t);
  nl_wavelet_tile_free(wt);
  nl_cellular_free(cell);
  free(out); free(rx); free(ry); free(rz);
  free(f32_out); free(f32_x); free(f32_y); free(f32_z);
  return 0;
}
