/* noiselab stat - statistics on tables of numbers (src/stats).
 *
 * Thin layer: parse options, read the table (TSV or whitespace, header
 * optional, '-' = stdin), call the library, print one line per result.
 * Every error is one line on stderr naming the input, and exit status 2.
 */
#include "harness/nl_harness.h"
#include "stats/nl_cluster.h"
#include "stats/nl_gmm.h"
#include "stats/nl_stats.h"
#include "table/nl_table.h"

#include <stdlib.h>
#include <string.h>

#define PROG "noiselab stat"

static const char *usage_text[] = {
  "usage: " PROG " SUBCOMMAND FILE [options]   (FILE: TSV or whitespace table, '-' = stdin)\n"
  "  ks      one-sample Kolmogorov-Smirnov     " PROG " ks --help\n"
  "  ks2     two-sample Kolmogorov-Smirnov     " PROG " ks2 --help\n"
  "  kuiper  Kuiper's test for circular data   " PROG " kuiper --help\n"
  "  chisq   Pearson chi-square on equal bins  " PROG " chisq --help\n"
  "  hclust  hierarchical clustering           " PROG " hclust --help\n"
  "  gmm     Gaussian mixture by EM            " PROG " gmm --help\n",
};

static const char *help_ks =
  "usage: " PROG " ks FILE [--column N] [--uniform A B]\n"
  "One-sample Kolmogorov-Smirnov test of column N (1-based, default 1) against the\n"
  "uniform distribution on [A, B) (default 0 1). Prints D=... p=... n=... method=...\n"
  "p is two-sided and exact for finite n (scipy.stats.kstest); method names the\n"
  "algorithm (durbin-mtw, pomeranz, pelz-good, smirnov, ruben-gambino).\n";
static const char *help_ks2 =
  "usage: " PROG " ks2 FILE1 FILE2 [--column N]\n"
  "Two-sample Kolmogorov-Smirnov test of column N (default 1) of each file.\n"
  "Prints D=... p=... n=N1,N2 method=exact|asymp (scipy.stats.ks_2samp).\n";
static const char *help_kuiper =
  "usage: " PROG " kuiper FILE [--column N] [--uniform A B]\n"
  "Kuiper's test (invariant to where a circle is cut) against the uniform\n"
  "distribution on [A, B) (default 0 1). Prints V=... p=... n=...\n";
static const char *help_chisq =
  "usage: " PROG " chisq FILE --bins K [--column N] [--uniform A B]\n"
  "Pearson chi-square of column N in K >= 2 equal bins of [A, B] (default 0 1)\n"
  "against equal expected counts. Prints chi2=... df=... p=... min_expected=...\n"
  "and warns on stderr when min_expected < 5 (the p-value is then unreliable).\n";
static const char *help_hclust =
  "usage: " PROG " hclust FILE --linkage single|complete|average (--cutoff C | --clusters K)\n"
  "                     [--labels OUT] [--merges OUT]\n"
  "Agglomerative clustering of the rows (Euclidean). --cutoff: points of a cluster\n"
  "have cophenetic distance <= C (scipy fcluster 'distance'); --clusters: at most K\n"
  "clusters ('maxclust'). Prints clusters=K. --labels writes one label (1..K) per\n"
  "row; --merges writes scipy's linkage matrix (a, b, dist, size).\n";
static const char *help_gmm =
  "usage: " PROG " gmm FILE (--k K | --select-aic K0 T) [--covariance full|diag] [--seed N]\n"
  "                  [--tol X] [--max-iter N] [--reg-covar X] [--max-k N] [--params OUT]\n"
  "Gaussian mixture of the rows by EM (scikit-learn's GaussianMixture, k-means++\n"
  "initialisation from --seed, default 0; tol 1e-3, max-iter 100, reg-covar 1e-6).\n"
  "Prints k=... loglik=... aic=... bic=... iterations=... converged=...\n"
  "--select-aic K0 T fits K0, K0+1, ... (at most --max-k, default 100) until the AIC\n"
  "drops by less than T, prints one line per K and then selected=K.\n"
  "--params writes component, param (weight, mean, cov), i, j, value rows.\n";

typedef struct {
  const char *sub;
  const char *files[2];
  int nfiles;
  long column, bins, clusters, k, k0, seed, max_iter, max_k;
  double a, b, cutoff, tol, reg, thresh;
  int have_bins, have_cutoff, have_clusters, have_k, have_select;
  const char *linkage, *labels_out, *merges_out, *params_out, *covariance;
} opts;

static void die(const char *sub, const char *msg)
{
  fprintf(stderr, PROG " %s: %s\n", sub, msg);
  exit(2);
}

static double num_arg(const opts *o, const char *what, const char *s, double lo, double hi)
{
  double v;
  nl_error err;
  if (nl_parse_double(what, s, lo, hi, &v, &err)) die(o->sub, err.msg);
  return v;
}

static long int_arg(const opts *o, const char *what, const char *s, long lo, long hi)
{
  long v;
  nl_error err;
  if (nl_parse_long(what, s, lo, hi, &v, &err)) die(o->sub, err.msg);
  return v;
}

/* Parses argv[2..]; every option takes its values from the following words. */
static void parse(int argc, char **argv, opts *o)
{
  for (int i = 2; i < argc; i++) {
    const char *a = argv[i];
    int left = argc - i - 1;
#define NEED(k) do { if (left < (k)) { char m_[128]; \
      snprintf(m_, sizeof m_, "%s needs %d value(s)", a, (k)); die(o->sub, m_); } } while (0)
    if (a[0] != '-' || strcmp(a, "-") == 0) {
      if (o->nfiles == 2) die(o->sub, "too many file arguments");
      o->files[o->nfiles++] = a;
    } else if (!strcmp(a, "--column")) { NEED(1); o->column = int_arg(o, a, argv[++i], 1, 1000000); }
    else if (!strcmp(a, "--uniform")) {
      NEED(2);
      o->a = num_arg(o, a, argv[++i], -1e300, 1e300);
      o->b = num_arg(o, a, argv[++i], -1e300, 1e300);
      if (!(o->a < o->b)) die(o->sub, "--uniform A B needs A < B");
    }
    else if (!strcmp(a, "--bins")) { NEED(1); o->bins = int_arg(o, a, argv[++i], 2, 100000000); o->have_bins = 1; }
    else if (!strcmp(a, "--linkage")) { NEED(1); o->linkage = argv[++i]; }
    else if (!strcmp(a, "--cutoff")) { NEED(1); o->cutoff = num_arg(o, a, argv[++i], 0, 1e300); o->have_cutoff = 1; }
    else if (!strcmp(a, "--clusters")) { NEED(1); o->clusters = int_arg(o, a, argv[++i], 1, 1000000000); o->have_clusters = 1; }
    else if (!strcmp(a, "--labels")) { NEED(1); o->labels_out = argv[++i]; }
    else if (!strcmp(a, "--merges")) { NEED(1); o->merges_out = argv[++i]; }
    else if (!strcmp(a, "--params")) { NEED(1); o->params_out = argv[++i]; }
    else if (!strcmp(a, "--k")) { NEED(1); o->k = int_arg(o, a, argv[++i], 1, 100000); o->have_k = 1; }
    else if (!strcmp(a, "--select-aic")) {
      NEED(2);
      o->k0 = int_arg(o, a, argv[++i], 1, 100000);
      o->thresh = num_arg(o, a, argv[++i], 0, 1e300);
      o->have_select = 1;
    }
    else if (!strcmp(a, "--covariance")) { NEED(1); o->covariance = argv[++i]; }
    else if (!strcmp(a, "--seed")) { NEED(1); o->seed = int_arg(o, a, argv[++i], 0, 4294967295L); }
    else if (!strcmp(a, "--tol")) { NEED(1); o->tol = num_arg(o, a, argv[++i], 0, 1e300); }
    else if (!strcmp(a, "--max-iter")) { NEED(1); o->max_iter = int_arg(o, a, argv[++i], 1, 100000000); }
    else if (!strcmp(a, "--max-k")) { NEED(1); o->max_k = int_arg(o, a, argv[++i], 1, 100000); }
    else if (!strcmp(a, "--reg-covar")) { NEED(1); o->reg = num_arg(o, a, argv[++i], 0, 1e300); }
    else {
      char m[160];
      snprintf(m, sizeof m, "unknown option '%s' (see " PROG " %s --help)", a, o->sub);
      die(o->sub, m);
    }
#undef NEED
  }
}

/* How an input is named in messages ('-' is standard input). */
static const char *shown(const char *path) { return strcmp(path, "-") ? path : "<stdin>"; }

static nl_table *read_table(const opts *o, const char *path)
{
  nl_table *t = NULL;
  nl_error err;
  if (nl_table_read(path, NL_TABLE_HEADER_AUTO | NL_TABLE_WHITESPACE, &t, &err)) die(o->sub, err.msg);
  if (t->nrows < 2) {
    char m[NL_ERROR_LEN + 64];
    snprintf(m, sizeof m, "%s: %zu data row(s); at least 2 are needed", shown(path), t->nrows);
    die(o->sub, m);
  }
  return t;
}

/* Column o->column of the table as a new array. */
static double *column(const opts *o, const nl_table *t, const char *path)
{
  if ((size_t)o->column > t->ncols) {
    char m[NL_ERROR_LEN];
    snprintf(m, sizeof m, "%s: no column %ld (the table has %zu)", shown(path), o->column, t->ncols);
    die(o->sub, m);
  }
  double *x = nl_xmalloc(t->nrows * sizeof(double));
  for (size_t i = 0; i < t->nrows; i++) x[i] = nl_table_get(t, i, (size_t)o->column - 1);
  return x;
}

static void fail_lib(const opts *o, const char *path, const nl_error *err)
{
  char m[NL_ERROR_LEN + 256];
  snprintf(m, sizeof m, "%s: %s", shown(path), err->msg);
  die(o->sub, m);
}

static const char *fmt(char *buf, double v) { nl_table_format_double(buf, v); return buf; }

static void run_ks(const opts *o, int kuiper)
{
  nl_table *t = read_table(o, o->files[0]);
  double *x = column(o, t, o->files[0]);
  nl_error err;
  char b1[32], b2[32];
  if (kuiper) {
    nl_stats_kuiper_result r;
    if (nl_stats_kuiper_test_uniform(x, t->nrows, o->a, o->b, &r, &err)) fail_lib(o, o->files[0], &err);
    printf("V=%s p=%s n=%zu\n", fmt(b1, r.v), fmt(b2, r.p), r.n);
  } else {
    nl_stats_ks_result r;
    if (nl_stats_ks_test_uniform(x, t->nrows, o->a, o->b, &r, &err)) fail_lib(o, o->files[0], &err);
    printf("D=%s p=%s n=%zu method=%s\n", fmt(b1, r.d), fmt(b2, r.p), r.n,
           nl_stats_ks_method_name(r.method));
  }
  free(x);
  nl_table_free(t);
}

static void run_ks2(const opts *o)
{
  if (o->nfiles != 2) die(o->sub, "needs two files (see " PROG " ks2 --help)");
  nl_table *t1 = read_table(o, o->files[0]), *t2 = read_table(o, o->files[1]);
  double *x = column(o, t1, o->files[0]), *y = column(o, t2, o->files[1]);
  nl_stats_ks_result r;
  nl_error err;
  char b1[32], b2[32];
  if (nl_stats_ks2_test(x, t1->nrows, y, t2->nrows, &r, &err)) fail_lib(o, o->files[0], &err);
  printf("D=%s p=%s n=%zu,%zu method=%s\n", fmt(b1, r.d), fmt(b2, r.p), r.n, r.n2,
         nl_stats_ks_method_name(r.method));
  free(x); free(y);
  nl_table_free(t1); nl_table_free(t2);
}

static void run_chisq(const opts *o)
{
  if (!o->have_bins) die(o->sub, "--bins K is required");
  nl_table *t = read_table(o, o->files[0]);
  double *x = column(o, t, o->files[0]);
  nl_stats_chisq_result r;
  nl_error err;
  char b1[32], b2[32], b3[32];
  if (nl_stats_chisq_test_uniform(x, t->nrows, (size_t)o->bins, o->a, o->b, &r, &err))
    fail_lib(o, o->files[0], &err);
  printf("chi2=%s df=%zu p=%s min_expected=%s\n", fmt(b1, r.chi2), r.df, fmt(b2, r.p),
         fmt(b3, r.min_expected));
  if (r.low_expected)
    fprintf(stderr, PROG " chisq: note: expected counts %s < 5; the chi-square p-value is unreliable\n",
            b3);
  free(x);
  nl_table_free(t);
}

static void write_or_die(const opts *o, nl_table *t, const char *path)
{
  nl_error err;
  if (nl_table_write(t, path, &err)) die(o->sub, err.msg);
  nl_table_free(t);
}

static void run_hclust(const opts *o)
{
  nl_cluster_linkage_method m;
  nl_error err;
  if (!o->linkage) die(o->sub, "--linkage single|complete|average is required");
  if (nl_cluster_linkage_method_parse(o->linkage, &m, &err)) die(o->sub, err.msg);
  if (o->have_cutoff == o->have_clusters) die(o->sub, "give exactly one of --cutoff C and --clusters K");
  nl_table *t = read_table(o, o->files[0]);
  size_t n = t->nrows;
  double *Z = nl_xmalloc((n - 1) * 4 * sizeof(double));
  int *lab = nl_xmalloc(n * sizeof(int));
  size_t k;
  if (nl_cluster_linkage(t->num, n, t->ncols, m, Z, &err)) fail_lib(o, o->files[0], &err);
  nl_status s = o->have_cutoff ? nl_cluster_fcluster_distance(Z, n, o->cutoff, lab, &k, &err)
                               : nl_cluster_fcluster_maxclust(Z, n, (size_t)o->clusters, lab, &k, &err);
  if (s) fail_lib(o, o->files[0], &err);
  if (o->labels_out) {
    const char *cols[] = {"label"};
    nl_table *lt = nl_table_alloc(1, cols);
    for (size_t i = 0; i < n; i++) nl_table_append(lt, "i", lab[i]);
    write_or_die(o, lt, o->labels_out);
  }
  if (o->merges_out) {
    const char *cols[] = {"a", "b", "dist", "size"};
    nl_table *mt = nl_table_alloc(4, cols);
    for (size_t i = 0; i + 1 < n; i++) nl_table_append_doubles(mt, Z + 4 * i);
    write_or_die(o, mt, o->merges_out);
  }
  printf("clusters=%zu\n", k);
  free(Z); free(lab);
  nl_table_free(t);
}

static void print_fit(size_t k, double ll, double aic, double bic, size_t it, int conv)
{
  char b1[32], b2[32], b3[32];
  printf("k=%zu loglik=%s aic=%s bic=%s iterations=%zu converged=%d\n", k, fmt(b1, ll),
         fmt(b2, aic), fmt(b3, bic), it, conv);
}

static void write_params(const opts *o, const nl_gmm *g)
{
  const char *cols[] = {"component", "param", "i", "j", "value"};
  nl_table *t = nl_table_alloc(5, cols);
  size_t d = g->d;
  for (size_t k = 0; k < g->k; k++) {
    nl_table_append(t, "isiid", (int)k + 1, "weight", 0, 0, g->weights[k]);
    for (size_t i = 0; i < d; i++) nl_table_append(t, "isiid", (int)k + 1, "mean", (int)i + 1, 0, g->means[k * d + i]);
    for (size_t i = 0; i < d; i++)
      for (size_t j = 0; j < d; j++) {
        if (g->covariance == NL_GMM_DIAG && i != j) continue;
        double v = g->covariance == NL_GMM_FULL ? g->covs[(k * d + i) * d + j] : g->covs[k * d + i];
        nl_table_append(t, "isiid", (int)k + 1, "cov", (int)i + 1, (int)j + 1, v);
      }
  }
  write_or_die(o, t, o->params_out);
}

/* Constant columns are legal (reg_covar keeps their variance finite), but
 * the user should know the fit leans on reg_covar there. */
static void note_constant_columns(const opts *o, const nl_table *t)
{
  for (size_t j = 0; j < t->ncols; j++) {
    size_t i = 1;
    while (i < t->nrows && nl_table_get(t, i, j) == nl_table_get(t, 0, j)) i++;
    if (i == t->nrows)
      fprintf(stderr, PROG " gmm: note: %s: column %zu is constant; its variance is reg_covar = %g\n",
              shown(o->files[0]), j + 1, o->reg);
  }
}

static void run_gmm(const opts *o)
{
  if (o->have_k == o->have_select) die(o->sub, "give exactly one of --k K and --select-aic K0 T");
  nl_gmm_options go;
  nl_gmm_options_default(&go);
  if (!strcmp(o->covariance, "diag")) go.covariance = NL_GMM_DIAG;
  else if (strcmp(o->covariance, "full")) die(o->sub, "--covariance must be full or diag");
  go.seed = (unsigned long)o->seed;
  go.tol = o->tol;
  go.max_iter = (size_t)o->max_iter;
  go.reg_covar = o->reg;
  nl_table *t = read_table(o, o->files[0]);
  size_t n = t->nrows, d = t->ncols;
  nl_error err;
  nl_gmm *g;
  if (o->have_k) {
    if ((size_t)o->k > n) {
      char m[NL_ERROR_LEN];
      snprintf(m, sizeof m, "%s: %ld components but only %zu rows", shown(o->files[0]), o->k, n);
      die(o->sub, m);
    }
    if (nl_gmm_check_size(n, d, (size_t)o->k, go.covariance, &err)) fail_lib(o, o->files[0], &err);
    g = nl_gmm_alloc((size_t)o->k, d, go.covariance);
    if (nl_gmm_fit(g, t->num, n, &go, &err)) fail_lib(o, o->files[0], &err);
    print_fit(g->k, g->loglik, g->aic, g->bic, g->iterations, g->converged);
  } else {
    if ((size_t)o->k0 > n) {
      char m[NL_ERROR_LEN];
      snprintf(m, sizeof m, "%s: K0 = %ld components but only %zu rows", shown(o->files[0]), o->k0, n);
      die(o->sub, m);
    }
    size_t kmax = (size_t)(o->max_k > o->k0 ? o->max_k : o->k0), np;
    nl_gmm_step *path = nl_xmalloc((kmax - (size_t)o->k0 + 1) * sizeof *path);
    if (nl_gmm_select_aic(t->num, n, d, (size_t)o->k0, o->thresh, kmax, &go, &g, path, &np, &err))
      fail_lib(o, o->files[0], &err);
    for (size_t i = 0; i < np; i++)
      print_fit(path[i].k, path[i].loglik, path[i].aic, path[i].bic, path[i].iterations,
                path[i].converged);
    printf("selected=%zu\n", g->k);
    free(path);
  }
  note_constant_columns(o, t);
  if (o->params_out) write_params(o, g);
  nl_gmm_free(g);
  nl_table_free(t);
}

static const char *sub_help(const char *sub)
{
  const char *names[] = {"ks", "ks2", "kuiper", "chisq", "hclust", "gmm"};
  const char *texts[] = {help_ks, help_ks2, help_kuiper, help_chisq, help_hclust, help_gmm};
  for (int i = 0; i < 6; i++) if (!strcmp(sub, names[i])) return texts[i];
  return NULL;
}

int main(int argc, char **argv)
{
  nl_set_oom_handler(nl_harness_oom_exit);
  if (argc < 2 || !strcmp(argv[1], "--help") || !strcmp(argv[1], "-h")) {
    fputs(usage_text[0], argc < 2 ? stderr : stdout);
    return argc < 2 ? 2 : 0;
  }
  opts o = {.sub = argv[1], .column = 1, .a = 0.0, .b = 1.0, .tol = 1e-3, .reg = 1e-6,
            .max_iter = 100, .max_k = 100, .covariance = "full"};
  const char *help = sub_help(o.sub);
  if (!help) {
    fprintf(stderr, PROG ": unknown subcommand '%s' (ks, ks2, kuiper, chisq, hclust, gmm)\n", o.sub);
    return 2;
  }
  for (int i = 2; i < argc; i++)
    if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) { fputs(help, stdout); return 0; }
  parse(argc, argv, &o);
  if (o.nfiles == 0) die(o.sub, "no input file (see --help)");
  if (strcmp(o.sub, "ks2") && o.nfiles > 1) die(o.sub, "takes one input file");
  if (!strcmp(o.sub, "ks")) run_ks(&o, 0);
  else if (!strcmp(o.sub, "kuiper")) run_ks(&o, 1);
  else if (!strcmp(o.sub, "ks2")) run_ks2(&o);
  else if (!strcmp(o.sub, "chisq")) run_chisq(&o);
  else if (!strcmp(o.sub, "hclust")) run_hclust(&o);
  else run_gmm(&o);
  return 0;
}
