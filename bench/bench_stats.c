/* bench_stats - speed of src/stats against scipy / scikit-learn on the same data.
 *
 *   build/bench/bench_stats [DIR]      (DIR for the shared data; default a private
 *                                       /tmp/noiselab_bench_stats.XXXXXX, removed at the end)
 *
 * C side (always): GMM EM on 10,000 x 81, K = 30 full covariance, from k-means
 * labels (time per EM iteration, log-likelihood at convergence); complete,
 * average, Ward and single linkage on the same 10,000 x 81 (time, peak
 * memory of a child process; the merges go to DIR/Z_<method>.tsv, and the
 * Python side counts the rows where scipy's and fastcluster's differ from
 * them); KS with exact p at n = 512 (microseconds per call) and the
 * incremental statistic (moves per second). It writes the data and labels to
 * DIR, then runs bench/bench_stats.py on them when /usr/bin/python3 can import
 * sklearn, so the Python side starts EM from the same labels.
 * FFT: the 2D transform of a 512 x 512 real image, ms of CPU time per call
 * (best of three rounds of >= 0.3 s), GSL's complex strided transform (the baseline),
 * nl_spectrum_fft2 (full spectrum) and nl_spectrum_rfft2 with a plan,
 * beside numpy's rfft2 and fft2 in the same run.
 * OpenBLAS is pinned to one thread on both sides (OPENBLAS_NUM_THREADS=1; this
 * program re-executes itself with it set).
 *
 *   build/bench/bench_stats [--only fft|linkage|gmm|ks] [DIR]   one part only (Python side too)
 *   build/bench/bench_stats --only linkage --scale   complete linkage's CPU ns per n^2 at
 *                                       n = 1k, 2k, 5k, 10k, 20k (bench_linkage_scale; the
 *                                       whole run ends with it too)
 */
#define _GNU_SOURCE   /* sched_getaffinity in nl_bench.h */
#include "nl_bench.h"
#include "spectrum/nl_spectrum.h"
#include "stats/nl_cluster.h"
#include "stats/nl_gmm.h"
#include "stats/nl_stats.h"
#include "table/nl_table.h"

#include <gsl/gsl_fft_complex.h>
#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>
#include <ftw.h>
#include <malloc.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

enum { N = 10000, D = 81, K = 30 };

/* A mixture of K Gaussians with random centres and random covariances
 * A A^T / d + 0.5 I: the clusters overlap a little, as real features do. */
static double *make_data_n(gsl_rng *rng, size_t n)
{
  double *x = nl_xmalloc(n * D * sizeof(double));
  double *A = nl_xmalloc((size_t)K * D * D * sizeof(double)), *mu = nl_xmalloc(K * D * sizeof(double));
  for (size_t i = 0; i < (size_t)K * D * D; i++) A[i] = gsl_ran_gaussian(rng, 1.0) / sqrt((double)D);
  for (size_t i = 0; i < (size_t)K * D; i++) mu[i] = gsl_ran_gaussian(rng, 0.4);
  double z[D];
  for (size_t i = 0; i < n; i++) {
    size_t k = gsl_rng_uniform_int(rng, K);
    for (int j = 0; j < D; j++) z[j] = gsl_ran_gaussian(rng, 1.0);
    for (int r = 0; r < D; r++) {
      double v = mu[k * D + r] + 0.7 * gsl_ran_gaussian(rng, 1.0);
      for (int j = 0; j < D; j++) v += A[(k * D + r) * D + j] * z[j];
      x[i * D + r] = v;
    }
  }
  free(A);
  free(mu);
  return x;
}

static double *make_data(gsl_rng *rng) { return make_data_n(rng, N); }

static void save(const char *dir, const char *name, size_t rows, size_t cols, const double *v)
{
  char **names = nl_xmalloc(cols * sizeof(char *));
  for (size_t j = 0; j < cols; j++) { names[j] = nl_xmalloc(16); snprintf(names[j], 16, "c%zu", j); }
  nl_table *t = nl_table_alloc(cols, (const char *const *)names);
  for (size_t i = 0; i < rows; i++) nl_table_append_doubles(t, v + i * cols);
  char *p = nl_path_join(dir, name);
  nl_error err;
  if (nl_table_write(t, p, &err)) { fprintf(stderr, "%s\n", err.msg); exit(1); }
  free(p);
  nl_table_free(t);
  for (size_t j = 0; j < cols; j++) free(names[j]);
  free(names);
}

static void bench_gmm(const double *x, const int *labels)
{
  nl_gmm_options o;
  nl_gmm_options_default(&o);
  o.init_labels = labels;
  nl_gmm *g = nl_gmm_alloc(K, D, NL_GMM_FULL);
  nl_error err;
  /* the thread's CPU time, as docs/speed.md says (one thread: o.threads = 1,
   * OpenBLAS at one thread); the wall time beside it */
  double t0 = nl_time_thread_cpu(), w0 = nl_time_now();
  if (nl_gmm_fit(g, x, N, &o, &err)) { fprintf(stderr, "gmm: %s\n", err.msg); exit(1); }
  double t = nl_time_thread_cpu() - t0, w = nl_time_now() - w0;
  printf("gmm_em   C    n=%d d=%d K=%d full: %.3f s total thread CPU (%.3f s wall), %zu iterations, "
         "%.4f s/iteration, mean loglik %.10f, converged %d\n", N, D, K, t, w, g->iterations,
         t / (double)g->iterations, g->loglik / N, g->converged);
  nl_gmm_free(g);
}

/* User and system CPU seconds of this process so far. */
static void user_system(double *user, double *sys)
{
  struct rusage ru;
  getrusage(RUSAGE_SELF, &ru);
  *user = (double)ru.ru_utime.tv_sec + 1e-6 * (double)ru.ru_utime.tv_usec;
  *sys = (double)ru.ru_stime.tv_sec + 1e-6 * (double)ru.ru_stime.tv_usec;
}

/* Runs linkage in a child so that its peak RSS is its own; the merges go to
 * DIR/Z_<method>.tsv (digits that read back to the same doubles), which bench_stats.py compares with scipy's.
 * User and system time are printed apart: the system time is the kernel
 * handing over the condensed matrix's pages (400 MB), which fastcluster pays too. */
static void bench_linkage(const char *dir, const double *x, nl_cluster_linkage_method m, const char *name)
{
  fflush(stdout);
  pid_t pid = fork();
  if (pid == 0) {
    double *Z = nl_xmalloc((N - 1) * 4 * sizeof(double));
    double u0, s0, u1, s1;
    user_system(&u0, &s0);
    double t0 = nl_time_now();
    nl_error err;
    if (nl_cluster_linkage(x, N, D, m, Z, &err)) { fprintf(stderr, "%s\n", err.msg); _exit(1); }
    double t = nl_time_now() - t0;
    user_system(&u1, &s1);
    printf("linkage  C     %-8s n=%d d=%d: %.3f s, %.3f s CPU = %.3f s user + %.3f s system, "
           "top merge height %.10g\n", name, N, D, t, (u1 - u0) + (s1 - s0), u1 - u0, s1 - s0,
           Z[4 * (N - 2) + 2]);
    fflush(stdout);
    char zname[64];
    snprintf(zname, sizeof zname, "Z_%s.tsv", name);
    save(dir, zname, N - 1, 4, Z);
    _exit(0);
  }
  int status;
  struct rusage ru;
  wait4(pid, &status, 0, &ru);
  printf("linkage  C     %-8s peak RSS of the process %.0f MiB\n", name, ru.ru_maxrss / 1024.0);
}

static void bench_ks(gsl_rng *rng)
{
  enum { M = 512 };
  double a[M], ab[2] = {0.0, NL_TWO_PI};
  for (int i = 0; i < M; i++) a[i] = NL_TWO_PI * gsl_rng_uniform(rng);
  nl_stats_ks_result r;
  int reps = 20000;
  /* The thread's CPU time (docs/speed.md): on a loaded machine the wall time
   * counts the time this thread waited for a core. */
  double t0 = nl_time_thread_cpu(), sink = 0.0;
  for (int i = 0; i < reps; i++) {
    a[i % M] = NL_TWO_PI * gsl_rng_uniform(rng);
    nl_stats_ks_test_uniform(a, M, 0.0, NL_TWO_PI, &r, NULL);
    sink += r.p;
  }
  double t = (nl_time_thread_cpu() - t0) / reps;
  printf("ks       C    n=%d exact p (sort + D + p): %.2f us/call thread CPU  (last D=%.6f p=%.6f method=%s)\n",
         M, t * 1e6, r.d, r.p, nl_stats_ks_method_name(r.method));
  /* annealer moves: small perturbations and random jumps, half each */
  nl_stats_ks_incr *s = nl_stats_ks_incr_alloc(a, M, nl_stats_cdf_uniform, ab, NULL);
  int moves = 2000000;
  double *steps = nl_xmalloc(2 * (size_t)moves * sizeof(double));
  for (int i = 0; i < moves; i++) {
    steps[2 * i] = (double)gsl_rng_uniform_int(rng, M);
    steps[2 * i + 1] = i % 2 ? 0.02 * (gsl_rng_uniform(rng) - 0.5) : NL_TWO_PI * gsl_rng_uniform(rng);
  }
  t0 = nl_time_thread_cpu();
  for (int i = 0; i < moves; i++) {
    size_t j = (size_t)steps[2 * i];
    double nv = i % 2 ? fmod(a[j] + steps[2 * i + 1] + NL_TWO_PI, NL_TWO_PI) : steps[2 * i + 1];
    nl_stats_ks_incr_replace(s, a[j], nv, NULL);
    a[j] = nv;
    sink += s->d;
  }
  t = nl_time_thread_cpu() - t0;
  printf("ks_incr  C    n=%d: %.0f ns/move, %.2f million moves/s\n", M, t / moves * 1e9, moves / t / 1e6);
  /* the alternative: keep the sorted array but rescan all n terms per move */
  double u[M], dp, dm;
  memcpy(u, s->u, sizeof u);
  t0 = nl_time_thread_cpu();
  for (int i = 0; i < moves; i++) {
    nl_stats_ks_statistic(u, M, &dp, &dm);
    sink += dp + dm;
  }
  t = nl_time_thread_cpu() - t0;
  printf("ks_full  C    n=%d: full O(n) rescan %.0f ns/move (the block scheme above avoids it)\n",
         M, t / moves * 1e9);
  if (sink == 42.0) printf(" ");
  free(steps);
  nl_stats_ks_incr_free(s);
}


/* ---- FFT ---------------------------------------------------------------- */

enum { FW = 512 };

/* The baseline the real-input path is measured against: GSL's complex
 * transform of every row, then of every column in place at a stride of w
 * complex (printed as "before"). */
static void fft2_gsl_strided(const double *img, double *F)
{
  for (size_t k = 0; k < (size_t)FW * FW; k++) { F[2 * k] = img[k]; F[2 * k + 1] = 0; }
  gsl_fft_complex_wavetable *wt = gsl_fft_complex_wavetable_alloc(FW);
  gsl_fft_complex_workspace *ws = gsl_fft_complex_workspace_alloc(FW);
  for (int k = 0; k < FW; k++) gsl_fft_complex_transform(F + 2 * (size_t)FW * k, 1, FW, wt, ws, gsl_fft_forward);
  for (int k = 0; k < FW; k++) gsl_fft_complex_transform(F + 2 * k, FW, FW, wt, ws, gsl_fft_forward);
  gsl_fft_complex_workspace_free(ws);
  gsl_fft_complex_wavetable_free(wt);
}

typedef struct { const double *img; double *out; nl_spectrum_fft2_plan *plan; int which; } fft_ctx;

/* FW is a power of two: a refusal is a bug here. */
static void fft_checked(nl_status st, const nl_error *err)
{
  if (st) { fprintf(stderr, "bench_stats: %s\n", err->msg); exit(1); }
}

static void fft_once(fft_ctx *c)
{
  nl_error err;
  if (c->which == 0) fft2_gsl_strided(c->img, c->out);
  else if (c->which == 1) fft_checked(nl_spectrum_fft2(c->img, FW, FW, c->out, &err), &err);
  else nl_spectrum_rfft2(c->plan, c->img, c->out);
}

/* Best of three rounds of at least 0.3 s: CPU ms and wall ms per call. */
static void fft_time(fft_ctx *c, double *cpu_ms, double *wall_ms)
{
  *cpu_ms = *wall_ms = INFINITY;
  for (int rep = 0; rep < 3; rep++) {
    int iters = 0;
    double t0 = nl_time_now(), c0 = nl_bench_cpu_now(), t;
    do { fft_once(c); iters++; t = nl_time_now() - t0; } while (t < 0.3);
    double cm = (nl_bench_cpu_now() - c0) / iters * 1e3, wm = t / iters * 1e3;
    if (cm < *cpu_ms) { *cpu_ms = cm; *wall_ms = wm; }
  }
}

static void bench_fft(gsl_rng *rng)
{
  size_t n = (size_t)FW * FW;
  double *img = nl_xmalloc(n * sizeof *img), *F = nl_xmalloc(2 * n * sizeof *F), *G = nl_xmalloc(2 * n * sizeof *G);
  for (size_t k = 0; k < n; k++) img[k] = gsl_ran_gaussian(rng, 1.0);
  nl_error err;
  nl_spectrum_fft2_plan *plan = nl_spectrum_fft2_plan_alloc(FW, FW, &err);
  fft_checked(plan ? NL_OK : NL_EINVAL, &err);
  const char *names[3] = {"gsl complex, strided columns (before)", "nl_spectrum_fft2 (full spectrum)",
                          "nl_spectrum_rfft2 (half spectrum, plan)"};
  for (int which = 0; which < 3; which++) {
    fft_ctx c = {img, which == 0 ? F : G, plan, which};
    double cm, wm;
    fft_time(&c, &cm, &wm);
    printf("fft2     C    %dx%d %-40s %7.3f ms CPU/call (%.3f ms wall)\n", FW, FW, names[which], cm, wm);
  }
  /* agreement: the full spectrum against GSL's, relative to the largest |F| */
  fft_checked(nl_spectrum_fft2(img, FW, FW, G, &err), &err);
  double worst = 0, big = 0;
  for (size_t k = 0; k < 2 * n; k++) { worst = fmax(worst, fabs(F[k] - G[k])); big = fmax(big, fabs(F[k])); }
  printf("fft2     C    %dx%d largest |nl_spectrum_fft2 - GSL| %.3g (%.3g of max |F|)\n", FW, FW, worst, worst / big);
  nl_spectrum_fft2_plan_free(plan);
  free(img); free(F); free(G);
}

/* User and system CPU seconds of the calling thread so far. */
static void thread_user_system(double *user, double *sys)
{
  struct rusage ru;
  getrusage(RUSAGE_THREAD, &ru);
  *user = (double)ru.ru_utime.tv_sec + 1e-6 * (double)ru.ru_utime.tv_usec;
  *sys = (double)ru.ru_stime.tv_sec + 1e-6 * (double)ru.ru_stime.tv_usec;
}

/* Complete linkage's cost per n^2 as n grows (--scale): the same mixture
 * (make_data_n, d = 81) at n = 1,000 ... 20,000, calls adding up to at
 * least 0.5 s (one at the largest n) in this thread, timed in its CPU time. An O(n^2) algorithm whose memory traffic
 * stays sequential keeps ns / n^2 flat; one that reads the distance matrix
 * by strided columns pays a cache (and TLB) miss a read once the matrix
 * outgrows the caches, and the figure climbs with n. */
static void bench_linkage_scale(gsl_rng *rng)
{
  static const size_t ns[] = {1000, 2000, 5000, 10000, 20000};
  double first = 0;
  /* Fresh pages for every call, as a program's one linkage gets: glibc
   * would otherwise raise its mmap threshold after the first free, and the
   * repeated small calls would reuse warm heap memory that the single call
   * at n = 20,000 does not have (measured: 1.2 against 5-10 ns per n^2 of
   * system time). */
  mallopt(M_MMAP_THRESHOLD, 128 * 1024);
  for (size_t i = 0; i < sizeof ns / sizeof *ns; i++) {
    size_t n = ns[i];
    double *x = make_data_n(rng, n), *Z = nl_xmalloc((n - 1) * 4 * sizeof *Z);
    char l0[128], l1[128];
    nl_bench_loadavg(l0, sizeof l0);
    nl_error err;
    double u0, s0, u1, s1;
    int calls = 0;
    thread_user_system(&u0, &s0);
    double w0 = nl_time_now(), c0 = nl_time_thread_cpu(), c;
    do {   /* calls adding up to 0.5 s: the user / system split is counted in scheduler ticks */
      if (nl_cluster_linkage(x, n, D, NL_LINKAGE_COMPLETE, Z, &err)) { fprintf(stderr, "%s\n", err.msg); exit(1); }
      calls++;
      c = nl_time_thread_cpu() - c0;
    } while (c < 0.5);
    double w = (nl_time_now() - w0) / calls;
    thread_user_system(&u1, &s1);
    nl_bench_loadavg(l1, sizeof l1);
    c /= calls;
    double nn = (double)n * (double)n * calls, per = c * calls / nn * 1e9;
    if (i == 0) first = per;
    printf("linkage_scale C complete n=%zu d=%d: %.3f s CPU (%.3f s wall) a call, %d call%s, %.2f ns CPU "
           "per n^2 (user %.2f + system %.2f), %.2fx that at n=%zu (load %s .. %s)\n", n, D, c, w, calls,
           calls > 1 ? "s" : "", per, (u1 - u0) / nn * 1e9, (s1 - s0) / nn * 1e9, per / first, ns[0], l0, l1);
    fflush(stdout);
    free(x);
    free(Z);
  }
}

static void run_python(const char *dir, const char *only)
{
  if (system("/usr/bin/python3 -c 'import numpy' >/dev/null 2>&1") != 0) {
    printf("python   numpy not importable by /usr/bin/python3: Python side skipped\n");
    return;
  }
  const char *candidates[] = {"bench/bench_stats.py", "../bench/bench_stats.py", "../../bench/bench_stats.py"};
  for (int i = 0; i < 3; i++) {
    if (access(candidates[i], R_OK) != 0) continue;
    char cmd[1024];
    snprintf(cmd, sizeof cmd, "OPENBLAS_NUM_THREADS=1 /usr/bin/python3 %s %s%s %s", candidates[i],
             only ? "--only " : "", only ? only : "", dir);
    fflush(stdout);
    if (system(cmd) != 0) printf("python   %s failed\n", candidates[i]);
    return;
  }
  printf("python   bench/bench_stats.py not found from here; run it from the source tree:\n"
         "         OPENBLAS_NUM_THREADS=1 /usr/bin/python3 bench/bench_stats.py %s\n", dir);
}

static int remove_entry(const char *path, const struct stat *st, int flag, struct FTW *f)
{
  (void)st; (void)flag; (void)f;
  remove(path);
  return 0;
}

/* The private data folder, removed with what both sides wrote into it. */
static void remove_tree(const char *dir)
{
  nftw(dir, remove_entry, 16, FTW_DEPTH | FTW_PHYS);
}

int main(int argc, char **argv)
{
  const char *env = getenv("OPENBLAS_NUM_THREADS");
  if (!env || strcmp(env, "1") != 0) {   /* OpenBLAS reads it when it loads */
    setenv("OPENBLAS_NUM_THREADS", "1", 1);
    execv("/proc/self/exe", argv);
  }
  const char *only = NULL;
  int a = 1, scale = 0;
  if (argc > 2 && strcmp(argv[1], "--only") == 0) {
    only = argv[2];
    a = 3;
  }
  if (only && strcmp(only, "linkage") == 0 && argc > a && strcmp(argv[a], "--scale") == 0) {
    scale = 1;
    a++;
  }
  /* An option where the data folder goes would become a folder named "--help". */
  if (argc > a + 1 || (argc > a && argv[a][0] == '-')) {
    fprintf(stderr, "usage: bench_stats [--only ks|fft|linkage [--scale]|gmm] [DIR]\n");
    return 2;
  }
  if (only && strcmp(only, "ks") && strcmp(only, "fft") && strcmp(only, "linkage") &&
      strcmp(only, "gmm")) {
    fprintf(stderr, "bench_stats: --only %s: not one of ks, fft, linkage, gmm\n", only);
    return 2;
  }
  /* A private folder by default: two runs at once (or another user's) must
   * not read each other's data files. */
  char own[] = "/tmp/noiselab_bench_stats.XXXXXX";
  const char *dir = argc > a ? argv[a] : mkdtemp(own);
  if (!dir) { perror("bench_stats: mkdtemp"); return 1; }
  if (argc > a) mkdir(dir, 0755);
  gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(rng, 2024);
  char pin[128];
  printf("bench_stats: OPENBLAS_NUM_THREADS=%s, data in %s, %s\n", getenv("OPENBLAS_NUM_THREADS"), dir,
         nl_bench_pin(pin, sizeof pin));
  nl_bench_report(stdout, "start");
  if (scale) {   /* the growth figure alone: no data files, no Python side */
    bench_linkage_scale(rng);
    nl_bench_report(stdout, "end");
    gsl_rng_free(rng);
    if (argc <= a) remove_tree(dir);
    return 0;
  }
  if (!only || !strcmp(only, "ks")) bench_ks(rng);
  if (!only || !strcmp(only, "fft")) bench_fft(rng);
  if (only && strcmp(only, "linkage") && strcmp(only, "gmm")) {
    run_python(dir, only);
    nl_bench_report(stdout, "end");
    gsl_rng_free(rng);
    if (argc <= a) remove_tree(dir);
    return 0;
  }
  double *x = make_data(rng);
  /* k-means labels from our k-means++ (seed 0), shared with the Python side */
  nl_gmm_options o;
  nl_gmm_options_default(&o);
  o.max_iter = 1;
  o.tol = 0;
  nl_gmm *g = nl_gmm_alloc(K, D, NL_GMM_FULL);
  nl_error err;
  nl_gmm_fit(g, x, N, &o, &err);   /* one iteration to get k-means labels via the means */
  int *labels = nl_xmalloc(N * sizeof(int));
  double *lab = nl_xmalloc(N * sizeof(double));
  for (size_t i = 0; i < N; i++) {   /* label = nearest k-means-initialised mean */
    size_t best = 0;
    double bd = INFINITY;
    for (size_t k = 0; k < K; k++) {
      double dd = nl_cluster_euclidean(x + i * D, g->means + k * D, D);
      if (dd < bd) { bd = dd; best = k; }
    }
    labels[i] = (int)best;
    lab[i] = (double)best;
  }
  nl_gmm_free(g);
  save(dir, "X.tsv", N, D, x);
  save(dir, "labels.tsv", N, 1, lab);
  if (!only || !strcmp(only, "gmm")) bench_gmm(x, labels);
  if (!only || !strcmp(only, "linkage")) {
    bench_linkage(dir, x, NL_LINKAGE_COMPLETE, "complete");
    bench_linkage(dir, x, NL_LINKAGE_AVERAGE, "average");
    bench_linkage(dir, x, NL_LINKAGE_WARD, "ward");
    bench_linkage(dir, x, NL_LINKAGE_SINGLE, "single");
  }
  run_python(dir, only);
  /* the growth of linkage's cost with n, last: its own data, up to 4 GB */
  if (!only) bench_linkage_scale(rng);
  nl_bench_report(stdout, "end");
  free(x); free(labels); free(lab);
  gsl_rng_free(rng);
  if (argc <= a) remove_tree(dir);
  return 0;
}
