/* noiselab stat - statistics on tables of numbers (src/stats).
 *
 * Thin layer: parse options (nl_opt: GNU style), read the table (TSV,
 * whitespace or CSV, header optional, '-' = stdin), call the library, print
 * one line per result (key=value, or --format tsv|json).
 * Every error is one line on stderr naming the input, and exit status 2.
 */
#include "harness/nl_harness.h"
#include "nl_tool.h"
#include "stats/nl_cluster.h"
#include "stats/nl_gmm.h"
#include "stats/nl_stats.h"
#include "table/nl_table.h"

#include <math.h>
#include <stdarg.h>
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
  "  gmm     Gaussian mixture by EM            " PROG " gmm --help\n"
  "Options as --name VALUE or --name=VALUE; --format kv|tsv|json (default kv: key=value);\n"
  "--column C: the column tested, by number (1-based) or by the header's name.\n"
  "FILE may be CSV (detected from a first line with commas and no tab, or --csv).\n",
};

static const char *help_ks =
  "usage: " PROG " ks FILE [--column C]\n"
  "                 (--uniform A B | --dist NAME [--shape A[,B]] [--loc L] [--scale S]\n"
  "                  | --cdf TABLE)\n"
  "                 [--alternative two-sided|less|greater] [--csv] [--format kv|tsv|json]\n"
  "One-sample Kolmogorov-Smirnov test of column C (a number, 1-based, default 1, or the\n"
  "name of a header's column) against the null distribution, which is required (as scipy's\n"
  "kstest requires its CDF):\n"
  "  --uniform A B     the uniform distribution on [A, B) (end points)\n"
  "  --dist NAME       a distribution of scipy.stats with its --shape A[,B] (if it has any),\n"
  "                    --loc L (0) and --scale S (1): F((x - L) / S; A, B), so uniform is on\n"
  "                    [L, L + S] (scipy.stats.kstest(x, NAME, (A, B, L, S))). NAME (shapes):\n"
  "                    uniform, norm, expon, gamma (a), beta (a,b), lognorm (s; scale = e^mu),\n"
  "                    t (df), chi2 (df), weibull_min (c), cauchy, logistic, laplace,\n"
  "                    pareto (b), rayleigh\n"
  "  --cdf TABLE       a tabulated CDF: columns x and F (or the first two), linear\n"
  "                    interpolation, constant beyond the ends (numpy.interp)\n"
  "  --alternative A  two-sided (default), less (D- = max(F - F_n): the sample lies\n"
  "                    below F somewhere) or greater (D+ = max(F_n - F)), as kstest's\n"
  "Prints D=... p=... n=... method=... (--format tsv: a header and a row; json: an object).\n"
  "p is exact for finite n (scipy.stats.kstest; one-sided: Smirnov's law, ksone); method\n"
  "names the algorithm (durbin-mtw, pomeranz, pelz-good, smirnov, ruben-gambino).\n";
static const char *help_ks2 =
  "usage: " PROG " ks2 FILE1 FILE2 [--column C [--column C2]]\n"
  "       " PROG " ks2 FILE --column C1 --column C2\n"
  "                  [--alternative two-sided|less|greater] [--csv] [--format kv|tsv|json]\n"
  "Two-sample Kolmogorov-Smirnov test of column C (number or header name, default 1)\n"
  "of each file; a second --column names FILE2's column (C2), or, with one FILE, the\n"
  "two columns of that table compared with each other.\n"
  "--alternative: greater tests F1 > F2 somewhere (D = max(F1 - F2)), less F1 < F2.\n"
  "Prints D=... p=... n=N1,N2 method=exact|asymp (scipy.stats.ks_2samp).\n";
static const char *help_kuiper =
  "usage: " PROG " kuiper FILE [--column C]\n"
  "                     [--uniform A B | --dist NAME [--shape A[,B]] [--loc L] [--scale S]\n"
  "                      | --cdf TABLE]\n"
  "                     [--csv] [--format kv|tsv|json]\n"
  "Kuiper's test (invariant to where a circle is cut) against the uniform\n"
  "distribution on [A, B) (default 0 1), or a distribution as for ks (see ks --help).\n"
  "Prints V=... p=... n=...\n";
static const char *help_chisq =
  "usage: " PROG " chisq FILE --bins K [--column C] [--uniform A B] [--csv]\n"
  "                    [--format kv|tsv|json]\n"
  "Pearson chi-square of column C (number or name) in K >= 2 equal bins of [A, B] (default 0 1)\n"
  "against equal expected counts. Prints chi2=... df=... p=... min_expected=...\n"
  "and warns on stderr when min_expected < 5 (the p-value is then unreliable).\n";
static const char *help_hclust =
  "usage: " PROG " hclust FILE --linkage METHOD [--metric NAME] (--cutoff C | --clusters K)\n"
  "                     [--labels OUT] [--merges OUT] [--csv] [--format kv|tsv|json]\n"
  "Agglomerative clustering of the rows, scipy.cluster.hierarchy.linkage(x, METHOD,\n"
  "NAME) (--method is another name for --linkage). METHOD: single, complete, average,\n"
  "weighted, ward (Ward's minimum variance), centroid or median (scipy's Lance-Williams\n"
  "updates; centroid and median can merge lower than before: Z is in merge order).\n"
  "--metric (pdist's; default euclidean): sqeuclidean, cityblock, chebyshev, cosine,\n"
  "correlation, canberra, braycurtis; ward, centroid and median need euclidean.\n"
  "--cutoff: points of a cluster have cophenetic distance <= C (scipy fcluster\n"
  "'distance'); --clusters: at most K clusters ('maxclust'). Prints clusters=K;\n"
  "--format json adds linkage, Z (scipy's linkage matrix) and labels (one per row).\n"
  "--labels writes one label (1..K) per row; --merges writes scipy's linkage\n"
  "matrix (a, b, dist, size).\n";
static const char *help_gmm =
  "usage: " PROG " gmm FILE (--k K | --select-aic K0 T) [--covariance full|diag|tied|spherical]\n"
  "                  [--seed N] [--tol X] [--max-iter N] [--reg-covar X] [--max-k N]\n"
  "                  [--params OUT] [--labels OUT]\n"
  "                  [--csv] [--format kv|tsv|json]\n"
  "Gaussian mixture of the rows by EM (scikit-learn's GaussianMixture, k-means++\n"
  "initialisation from --seed, default 0; tol 1e-3, max-iter 100, reg-covar 1e-6).\n"
  "Prints k=... loglik=... score=... aic=... bic=... iterations=... converged=...\n"
  "(loglik: the total log-likelihood; score: its mean per row, sklearn's score()).\n"
  "--format json: converged as true/false, and weights, means and covariances\n"
  "(sklearn's weights_, means_, covariances_); --select-aic: selected true on one K.\n"
  "Warns on stderr when the model has more free parameters than the data has numbers.\n"
  "--select-aic K0 T fits K0, K0+1, ... (at most --max-k, default 100) until the AIC\n"
  "drops by less than T, prints one line per K and then selected=K (tsv/json: a\n"
  "column selected, 1 on the chosen K).\n"
  "--covariance (sklearn's covariance_type): full, diag, tied (one matrix for all\n"
  "components) or spherical (one variance per component); AIC/BIC count sklearn's\n"
  "free parameters for each.\n"
  "--params writes component, param (weight, mean, cov), i, j, value rows (each\n"
  "component's matrix: tied repeats the shared one, spherical gives sigma^2 on the diagonal).\n"
  "--labels writes each row's component, 1..K (sklearn's predict, plus one), of the\n"
  "fitted (or selected) model.\n"
  "Every subcommand: options as --name VALUE or --name=VALUE; tables are TSV or\n"
  "blank-separated, or CSV (found from a first line with commas and no tab, or --csv).\n";

typedef enum { OUT_KV, OUT_TSV, OUT_JSON } out_format;

typedef struct {
  const char *sub;
  const char *files[2];
  int nfiles;
  const char *column_name;   /* --column NAME: a header's column; NULL: the number column */
  const char *column2_name;  /* ks2's second --column: FILE2's, or the one table's other */
  long column2;
  int ncolumns;
  long column, bins, clusters, k, k0, seed, max_iter, max_k;
  double a, b, cutoff, tol, reg, thresh, loc, scale, shape[2];
  size_t nshape;
  int have_column, have_bins, have_cutoff, have_clusters, have_k, have_select, have_uniform, have_loc, have_scale;
  int csv;
  out_format format;
  const char *alternative, *metric;
  nl_stats_ks_alternative alt;
  const char *linkage, *labels_out, *merges_out, *params_out, *covariance, *dist, *cdf_file;
} opts;

/* One line on stderr, exit 2: input quoted in it is escaped (nl_message). */
static void die(const char *sub, const char *fmt, ...)
  __attribute__((format(printf, 2, 3), noreturn));
static void die(const char *sub, const char *fmt, ...)
{
  va_list ap;
  va_start(ap, fmt);
  fprintf(stderr, PROG " %s: ", sub);
  nl_vmessage(stderr, fmt, ap);
  va_end(ap);
  exit(2);
}

static double num_arg(const opts *o, const char *what, const char *s, double lo, double hi)
{
  double v;
  nl_error err;
  if (nl_parse_double(what, s, lo, hi, &v, &err)) die(o->sub, "%s", err.msg);
  return v;
}

static long int_arg(const opts *o, const char *what, const char *s, long lo, long hi)
{
  long v;
  nl_error err;
  if (nl_parse_long(what, s, lo, hi, &v, &err)) die(o->sub, "%s", err.msg);
  return v;
}

/* --shape A or A,B: scipy's shape parameters, in its order. */
static void parse_shape(opts *o, const char *v)
{
  const char *comma = strchr(v, ',');
  char first[64];
  if (comma && strchr(comma + 1, ',')) die(o->sub, "--shape: '%s' has more than 2 values", v);
  if (comma && (size_t)(comma - v) >= sizeof first) die(o->sub, "--shape: '%s' is too long", v);
  if (comma) {
    memcpy(first, v, (size_t)(comma - v));
    first[comma - v] = 0;
  }
  o->shape[0] = num_arg(o, "--shape", comma ? first : v, -1e300, 1e300);
  o->nshape = 1;
  if (comma) o->shape[o->nshape++] = num_arg(o, "--shape", comma + 1, -1e300, 1e300);
}

enum {
  O_COLUMN, O_UNIFORM, O_BINS, O_LINKAGE, O_METHOD, O_CUTOFF, O_CLUSTERS, O_LABELS, O_MERGES,
  O_PARAMS, O_K, O_SELECT_AIC, O_COVARIANCE, O_SEED, O_TOL, O_MAX_ITER, O_MAX_K, O_REG_COVAR,
  O_ALTERNATIVE, O_METRIC, O_DIST, O_SHAPE, O_LOC, O_SCALE, O_CDF, O_FORMAT, O_CSV, O_HELP
};
static const nl_opt_spec spec[] = {
  [O_COLUMN] = {"column", 0, 1}, [O_UNIFORM] = {"uniform", 0, 2}, [O_BINS] = {"bins", 0, 1},
  [O_LINKAGE] = {"linkage", 0, 1}, [O_METHOD] = {"method", 0, 1}, [O_CUTOFF] = {"cutoff", 0, 1},
  [O_CLUSTERS] = {"clusters", 0, 1}, [O_LABELS] = {"labels", 0, 1}, [O_MERGES] = {"merges", 0, 1},
  [O_PARAMS] = {"params", 0, 1}, [O_K] = {"k", 0, 1}, [O_SELECT_AIC] = {"select-aic", 0, 2},
  [O_COVARIANCE] = {"covariance", 0, 1}, [O_SEED] = {"seed", 0, 1}, [O_TOL] = {"tol", 0, 1},
  [O_MAX_ITER] = {"max-iter", 0, 1}, [O_MAX_K] = {"max-k", 0, 1}, [O_REG_COVAR] = {"reg-covar", 0, 1},
  [O_ALTERNATIVE] = {"alternative", 0, 1}, [O_METRIC] = {"metric", 0, 1},
  [O_DIST] = {"dist", 0, 1},
  [O_SHAPE] = {"shape", 0, 1}, [O_LOC] = {"loc", 0, 1}, [O_SCALE] = {"scale", 0, 1},
  [O_CDF] = {"cdf", 0, 1}, [O_FORMAT] = {"format", 0, 1}, [O_CSV] = {"csv", 0, 0},
  [O_HELP] = {"help", 'h', 0}, {NULL, 0, 0}};

/* The options each subcommand uses (bit O_x); any other is refused, so a
 * misplaced one (`ks --bins 4`) is not silently ignored. */
#define B(o) (1u << (o))
static const struct { const char *sub; unsigned opts; } sub_opts[] = {
  {"ks", B(O_COLUMN) | B(O_UNIFORM) | B(O_DIST) | B(O_SHAPE) | B(O_LOC) | B(O_SCALE) | B(O_CDF)
         | B(O_ALTERNATIVE)},
  {"ks2", B(O_COLUMN) | B(O_ALTERNATIVE)},
  {"kuiper", B(O_COLUMN) | B(O_UNIFORM) | B(O_DIST) | B(O_SHAPE) | B(O_LOC) | B(O_SCALE) | B(O_CDF)},
  {"chisq", B(O_COLUMN) | B(O_BINS) | B(O_UNIFORM)},
  {"hclust", B(O_LINKAGE) | B(O_METHOD) | B(O_METRIC) | B(O_CUTOFF) | B(O_CLUSTERS) | B(O_LABELS)
             | B(O_MERGES)},
  {"gmm", B(O_K) | B(O_SELECT_AIC) | B(O_COVARIANCE) | B(O_SEED) | B(O_TOL) | B(O_MAX_ITER)
          | B(O_MAX_K) | B(O_REG_COVAR) | B(O_PARAMS) | B(O_LABELS)},
};
enum { N_SUBS = sizeof sub_opts / sizeof sub_opts[0] };
static const unsigned common_opts = B(O_FORMAT) | B(O_CSV) | B(O_HELP);
#undef B

/* Refuses option k (as typed: name) unless o->sub uses it, naming the
 * subcommands that do. */
static void check_option_used(const opts *o, int k, const char *name)
{
  const char *users[N_SUBS];
  int nu = 0, mine = 0;
  if (common_opts & (1u << k)) return;
  for (int i = 0; i < N_SUBS; i++)
    if (sub_opts[i].opts & (1u << k)) {
      users[nu++] = sub_opts[i].sub;
      mine |= !strcmp(sub_opts[i].sub, o->sub);
    }
  if (mine) return;
  char list[128] = "";
  for (int i = 0; i < nu; i++)
    snprintf(list + strlen(list), sizeof list - strlen(list), "%s%s",
             i == 0 ? "" : i + 1 == nu ? " and " : ", ", users[i]);
  const char *why = k == O_COLUMN ? "uses every column" : k == O_ALTERNATIVE ? "has no one-sided form"
                                                                           : "does not use it";
  die(o->sub, "%s is for %s (%s %s); see " PROG " %s --help", name, list, o->sub, why, o->sub);
}

/* Parses argv[2..] (nl_opt: --name VALUE or --name=VALUE, files anywhere). */
static void parse(int argc, char **argv, opts *o)
{
  nl_opt_parser p;
  nl_error err;
  nl_opt_begin(&p, argc, argv, 2, spec);
  for (int k; (k = nl_opt_next(&p, &err)) != NL_OPT_END;) {
    const char *a = p.name, *v = p.value[0];
    if (k == NL_OPT_ERROR) {
      die(o->sub, "%s (see " PROG " %s --help)", err.msg, o->sub);
    }
    if (k != NL_OPT_POSITIONAL) check_option_used(o, k, a);
    switch (k) {
    case NL_OPT_POSITIONAL:
      if (o->nfiles == 2) die(o->sub, "too many file arguments");
      o->files[o->nfiles++] = v;
      break;
    case O_COLUMN: {
      /* A number keeps its meaning (1-based); anything else names a header's column. Only
       * ks2 compares two columns, so only it takes a second --column. */
      if (o->ncolumns == (strcmp(o->sub, "ks2") ? 1 : 2))
        die(o->sub, "--column given %s (see " PROG " %s --help)",
            o->ncolumns == 1 ? "twice" : "three times", o->sub);
      const char **name = o->ncolumns ? &o->column2_name : &o->column_name;
      long *number = o->ncolumns ? &o->column2 : &o->column;
      *name = NULL;
      o->have_column = 1;
      o->ncolumns++;
      if (strspn(v, "0123456789+-") == strlen(v)) *number = int_arg(o, a, v, 1, 1000000);
      else *name = v;
      break;
    }
    case O_UNIFORM:
      o->a = num_arg(o, a, v, -1e300, 1e300);
      o->b = num_arg(o, a, p.value[1], -1e300, 1e300);
      if (!(o->a < o->b)) die(o->sub, "--uniform A B needs A < B");
      o->have_uniform = 1;
      break;
    case O_BINS: o->bins = int_arg(o, a, v, 2, 100000000); o->have_bins = 1; break;
    case O_LINKAGE: case O_METHOD: o->linkage = v; break;
    case O_CUTOFF: o->cutoff = num_arg(o, a, v, 0, 1e300); o->have_cutoff = 1; break;
    case O_CLUSTERS: o->clusters = int_arg(o, a, v, 1, 1000000000); o->have_clusters = 1; break;
    case O_LABELS: o->labels_out = v; break;
    case O_MERGES: o->merges_out = v; break;
    case O_PARAMS: o->params_out = v; break;
    case O_K: o->k = int_arg(o, a, v, 1, 100000); o->have_k = 1; break;
    case O_SELECT_AIC:
      o->k0 = int_arg(o, a, v, 1, 100000);
      o->thresh = num_arg(o, a, p.value[1], 0, 1e300);
      o->have_select = 1;
      break;
    case O_COVARIANCE: o->covariance = v; break;
    case O_SEED: o->seed = int_arg(o, a, v, 0, 4294967295L); break;
    case O_TOL: o->tol = num_arg(o, a, v, 0, NL_GMM_MAX_TOL); break;
    case O_MAX_ITER: o->max_iter = int_arg(o, a, v, 1, NL_GMM_MAX_ITER); break;
    case O_MAX_K: o->max_k = int_arg(o, a, v, 1, 100000); break;
    case O_REG_COVAR: o->reg = num_arg(o, a, v, 0, NL_GMM_MAX_TOL); break;
    case O_ALTERNATIVE: o->alternative = v; break;
    case O_METRIC: o->metric = v; break;
    case O_DIST: o->dist = v; break;
    case O_SHAPE: parse_shape(o, v); break;
    case O_LOC: o->loc = num_arg(o, a, v, -1e300, 1e300); o->have_loc = 1; break;
    case O_SCALE: o->scale = num_arg(o, a, v, -1e300, 1e300); o->have_scale = 1; break;
    case O_CDF: o->cdf_file = v; break;
    case O_CSV: o->csv = 1; break;
    case O_FORMAT:
      if (!strcmp(v, "kv")) o->format = OUT_KV;
      else if (!strcmp(v, "tsv")) o->format = OUT_TSV;
      else if (!strcmp(v, "json")) o->format = OUT_JSON;
      else {
        die(o->sub, "--format: '%s' is not kv, tsv or json", v);
      }
      break;
    default: break;   /* --help was answered before parsing */
    }
  }
  nl_opt_end(&p);
  if (o->alternative && nl_stats_ks_alternative_parse(o->alternative, &o->alt, &err))
    die(o->sub, "--alternative: %s", err.msg);
  if (o->have_uniform + (o->dist != NULL) + (o->cdf_file != NULL) > 1)
    die(o->sub, "give one of --uniform A B, --dist NAME and --cdf TABLE");
  if ((o->have_loc || o->have_scale || o->nshape) && !o->dist)
    die(o->sub, "--shape, --loc and --scale go with --dist NAME (scipy's shape/loc/scale "
        "convention)");
}

/* ---- output: key=value (default), TSV or JSON --------------------------- */

#define MAX_FIELDS 12
typedef struct {
  const char *key[MAX_FIELDS];
  char val[MAX_FIELDS][64];
  int text[MAX_FIELDS];
  int n;
} record;

static void rec_num(record *r, const char *key, double v)
{
  r->key[r->n] = key;
  r->text[r->n] = 0;
  if (isfinite(v)) nl_table_format_double(r->val[r->n], v);
  else snprintf(r->val[r->n], sizeof r->val[0], "%s", isnan(v) ? "nan" : v > 0 ? "inf" : "-inf");
  r->n++;
}

static void rec_size(record *r, const char *key, size_t v)
{
  r->key[r->n] = key;
  r->text[r->n] = 0;
  snprintf(r->val[r->n++], sizeof r->val[0], "%zu", v);
}

/* 1 or 0 in key=value and TSV; true or false in JSON. */
static void rec_bool(record *r, const char *key, int v)
{
  r->key[r->n] = key;
  r->text[r->n] = 2;
  snprintf(r->val[r->n++], sizeof r->val[0], "%d", v != 0);
}

static void rec_text(record *r, const char *key, const char *v)
{
  r->key[r->n] = key;
  r->text[r->n] = 1;
  snprintf(r->val[r->n++], sizeof r->val[0], "%s", v);
}

/* A JSON number (null when not finite: JSON has no NaN or infinity). */
static void json_num(double v)
{
  char buf[64];
  if (!isfinite(v)) {
    fputs("null", stdout);
    return;
  }
  nl_table_format_double(buf, v);
  fputs(buf, stdout);
}

/* "[v0, v1, ...]" of n numbers spaced by stride. */
static void json_list(const double *v, size_t n, size_t stride)
{
  putchar('[');
  for (size_t i = 0; i < n; i++) {
    if (i) fputs(", ", stdout);
    json_num(v[i * stride]);
  }
  putchar(']');
}

/* ", "KEY": [...]": a member after the record's scalars. */
static void json_array(const char *key, const double *v, size_t n, size_t stride)
{
  printf(", \"%s\": ", key);
  json_list(v, n, stride);
}

/* What a single JSON record carries beyond its scalars (arrays), written
 * before its closing brace; NULL: nothing. */
typedef void (*json_more_fn)(const void *ctx);
static void emit_more(const opts *o, const record *r, size_t nr, json_more_fn more,
                      const void *ctx);
static void emit(const opts *o, const record *r, size_t nr) { emit_more(o, r, nr, NULL, NULL); }

/* key=value lines; TSV: one header (the first record's keys) and a row per
 * record; JSON: an object, or an array of objects for several records
 * (non-finite numbers as null, flags as true and false). */
static void emit_more(const opts *o, const record *r, size_t nr, json_more_fn more,
                      const void *ctx)
{
  for (size_t i = 0; i < nr; i++) {
    if (o->format == OUT_TSV && i == 0)
      for (int j = 0; j < r[0].n; j++) printf("%s%s", j ? "\t" : "", r[0].key[j]);
    if (o->format == OUT_TSV && i == 0) putchar('\n');
    if (o->format == OUT_JSON) fputs(nr > 1 ? (i ? ",\n " : "[") : "", stdout);
    if (o->format == OUT_JSON) putchar('{');
    for (int j = 0; j < r[i].n; j++) {
      const char *v = r[i].val[j];
      if (o->format == OUT_KV) printf("%s%s=%s", j ? " " : "", r[i].key[j], v);
      else if (o->format == OUT_TSV) printf("%s%s", j ? "\t" : "", v);
      else if (r[i].text[j] == 2)
        printf("%s\"%s\": %s", j ? ", " : "", r[i].key[j], strcmp(v, "0") ? "true" : "false");
      else if (r[i].text[j]) printf("%s\"%s\": \"%s\"", j ? ", " : "", r[i].key[j], v);
      else {
        int finite = strcmp(v, "nan") && strcmp(v, "inf") && strcmp(v, "-inf");
        printf("%s\"%s\": %s", j ? ", " : "", r[i].key[j], finite ? v : "null");
      }
    }
    if (o->format == OUT_JSON && more) more(ctx);
    if (o->format == OUT_JSON) putchar('}');
    if (o->format != OUT_JSON || i + 1 == nr) {
      if (o->format == OUT_JSON && nr > 1) putchar(']');
      putchar('\n');
    }
  }
}

/* How an input is named in messages ('-' is standard input). */
static const char *shown(const char *path) { return strcmp(path, "-") ? path : "<stdin>"; }

static int table_flags(const opts *o)
{
  return NL_TABLE_HEADER_AUTO | NL_TABLE_WHITESPACE | (o->csv ? NL_TABLE_CSV : NL_TABLE_CSV_AUTO);
}

/* The arrays and tables a command holds until it exits, kept reachable so
 * that an error's exit (die: exit(2) from anywhere) leaves no leak for
 * LeakSanitizer to report, whatever the optimiser did with the locals. */
static void *held[8];
static size_t nheld;
static void *hold(void *p)
{
  held[nheld++ % 8] = p;
  return p;
}

static nl_table *read_table(const opts *o, const char *path)
{
  nl_table *t = NULL;
  nl_error err;
  if (nl_table_read(path, table_flags(o), &t, &err)) die(o->sub, "%s", err.msg);
  hold(t);
  if (t->nrows < 2) {
    die(o->sub, "%s: %zu data row(s); at least 2 are needed", shown(path), t->nrows);
  }
  return t;
}

/* Column NUMBER (1-based) or NAME (a header's, when not NULL) of the table as a new array. */
static double *column_of(const opts *o, const nl_table *t, const char *path, long number,
                         const char *name)
{
  size_t c = (size_t)number - 1;
  if (name) {
    long j = nl_table_column(t, name);
    if (j < 0) {
      /* The table's own names, so the user can copy one; a wide table's list is cut. */
      char list[512];
      size_t len = 0;
      for (size_t i = 0; i < t->ncols && len < sizeof list; i++) {
        int w = i < 16 ? snprintf(list + len, sizeof list - len, "%s%s", i ? ", " : "", t->names[i])
                       : snprintf(list + len, sizeof list - len, ", ... (%zu in all)", t->ncols);
        len += w > 0 ? (size_t)w : 0;
        if (i >= 16) break;
      }
      die(o->sub, "%s: no column '%s' (the table's columns: %s)", shown(path), name, list);
    }
    c = (size_t)j;
  } else if ((size_t)number > t->ncols) {
    die(o->sub, "%s: no column %ld (the table has %zu)", shown(path), number, t->ncols);
  }
  double *x = nl_xmalloc(t->nrows * sizeof(double));
  for (size_t i = 0; i < t->nrows; i++) x[i] = nl_table_get(t, i, c);
  return hold(x);
}

/* Column --column of the table. */
static double *column(const opts *o, const nl_table *t, const char *path)
{
  return column_of(o, t, path, o->column, o->column_name);
}

static void fail_lib(const opts *o, const char *path, const nl_error *err)
{
  die(o->sub, "%s: %s", shown(path), err->msg);
}

/* The null distribution of ks/kuiper: --uniform A B (end points), --dist
 * NAME with loc/scale, or --cdf TABLE (columns x and F, else the first two).
 * *cdf_table holds the tabulated CDF's table (freed by the caller). */
static void null_dist(const opts *o, nl_stats_dist *dist, nl_table **cdf_table, double **xF)
{
  nl_error err;
  *cdf_table = NULL;
  *xF = NULL;
  if (o->cdf_file) {
    nl_table *t = NULL;
    if (nl_table_read(o->cdf_file, table_flags(o), &t, &err)) die(o->sub, "%s", err.msg);
    long cx = nl_table_column(t, "x"), cF = nl_table_column(t, "F");
    if (cx < 0 || cF < 0) { cx = 0; cF = 1; }
    if (t->ncols < 2) {
      die(o->sub, "%s: a CDF table needs columns x and F (it has %zu column)", shown(o->cdf_file),
          t->ncols);
    }
    double *x = nl_xmalloc(2 * t->nrows * sizeof *x), *F = x + t->nrows;
    for (size_t i = 0; i < t->nrows; i++) { x[i] = nl_table_get(t, i, (size_t)cx); F[i] = nl_table_get(t, i, (size_t)cF); }
    if (nl_stats_dist_table(dist, x, F, t->nrows, &err)) fail_lib(o, o->cdf_file, &err);
    *cdf_table = t;
    *xF = x;
  } else if (o->dist) {
    nl_stats_dist_kind kind;
    if (nl_stats_dist_parse(o->dist, &kind, &err)) die(o->sub, "%s", err.msg);
    double scale = o->have_scale ? o->scale : 1.0;
    int want = nl_stats_dist_nshape(kind);
    if ((size_t)want != o->nshape) {
      if (want == 0) die(o->sub, "--dist %s takes no --shape", o->dist);
      die(o->sub, "--dist %s needs --shape %s (%d value%s, scipy's order), got %zu", o->dist,
          want == 1 ? "A" : "A,B", want, want == 1 ? "" : "s", o->nshape);
    }
    if (o->have_scale && !(scale > 0)) die(o->sub, "--scale %g must be positive", scale);
    for (size_t i = 0; i < o->nshape; i++)
      if (!(o->shape[i] > 0)) {
        die(o->sub, "--shape: %s's %s must be positive, got %g", o->dist,
            nl_stats_dist_shape_names(kind), o->shape[i]);
      }
    if (nl_stats_dist_init_shape(dist, kind, o->shape, o->nshape, o->have_loc ? o->loc : 0.0, scale,
                                 &err)) {
      die(o->sub, "--dist %s: %s", o->dist, err.msg);
    }
  } else {
    /* end points: uniform on [a, b) evaluated as (x - a) / (b - a), as before */
    dist->kind = NL_DIST_UNIFORM;
  }
}

static void run_ks(const opts *o, int kuiper)
{
  nl_table *t = read_table(o, o->files[0]);
  double *x = column(o, t, o->files[0]);
  /* scipy's kstest has no default CDF; a silent U(0, 1) tested the wrong law. Kuiper's keeps
   * astropy's default, the uniform on the circle [0, 1). */
  if (!kuiper && !o->have_uniform && !o->dist && !o->cdf_file)
    die(o->sub, "the null distribution is required: --uniform A B, --dist NAME or --cdf TABLE "
        "(see " PROG " ks --help)");
  nl_stats_dist dist;
  nl_table *ct;
  double *xF;
  null_dist(o, &dist, &ct, &xF);
  int named = o->dist || o->cdf_file;
  nl_error err;
  record r = {0};
  if (kuiper) {
    nl_stats_kuiper_result k;
    nl_status s = named ? nl_stats_kuiper_test(x, t->nrows, nl_stats_dist_cdf, &dist, &k, &err)
                        : nl_stats_kuiper_test_uniform(x, t->nrows, o->a, o->b, &k, &err);
    if (s) fail_lib(o, o->files[0], &err);
    rec_num(&r, "V", k.v);
    rec_num(&r, "p", k.p);
    rec_size(&r, "n", k.n);
  } else {
    nl_stats_ks_result k;
    nl_status s = named ? nl_stats_ks_test(x, t->nrows, nl_stats_dist_cdf, &dist, &k, &err)
                        : nl_stats_ks_test_uniform(x, t->nrows, o->a, o->b, &k, &err);
    if (s) fail_lib(o, o->files[0], &err);
    nl_stats_ks_one_sided(&k, o->alt);
    rec_num(&r, "D", k.d);
    rec_num(&r, "p", k.p);
    rec_size(&r, "n", k.n);
    rec_text(&r, "method", nl_stats_ks_method_name(k.method));
  }
  emit(o, &r, 1);
  free(x); free(xF);
  nl_table_free(ct);
  nl_table_free(t);
}

static void run_ks2(const opts *o)
{
  if (o->nfiles == 1 && o->ncolumns != 2)
    die(o->sub, "one file needs two columns to compare: --column C1 --column C2 (see " PROG
        " ks2 --help)");
  if (o->nfiles != 1 && o->nfiles != 2) die(o->sub, "needs two files (see " PROG " ks2 --help)");
  /* One table read once: its two columns are the two samples. */
  nl_table *t1 = read_table(o, o->files[0]);
  nl_table *t2 = o->nfiles == 2 ? read_table(o, o->files[1]) : NULL;
  const nl_table *second = t2 ? t2 : t1;
  const char *second_path = o->files[o->nfiles - 1];
  double *x = column(o, t1, o->files[0]);
  double *y = o->ncolumns == 2 ? column_of(o, second, second_path, o->column2, o->column2_name)
                               : column(o, second, second_path);
  nl_stats_ks_result k;
  nl_error err;
  if (nl_stats_ks2_test(x, t1->nrows, y, second->nrows, &k, &err)) fail_lib(o, o->files[0], &err);
  nl_stats_ks_one_sided(&k, o->alt);
  record r = {0};
  char n12[64];
  snprintf(n12, sizeof n12, "%zu,%zu", k.n, k.n2);
  rec_num(&r, "D", k.d);
  rec_num(&r, "p", k.p);
  if (o->format == OUT_KV) rec_text(&r, "n", n12);
  else { rec_size(&r, "n1", k.n); rec_size(&r, "n2", k.n2); }
  rec_text(&r, "method", nl_stats_ks_method_name(k.method));
  emit(o, &r, 1);
  free(x); free(y);
  nl_table_free(t1); nl_table_free(t2);
}

static void run_chisq(const opts *o)
{
  if (!o->have_bins) die(o->sub, "--bins K is required");
  nl_table *t = read_table(o, o->files[0]);
  double *x = column(o, t, o->files[0]);
  nl_stats_chisq_result c;
  nl_error err;
  if (nl_stats_chisq_test_uniform(x, t->nrows, (size_t)o->bins, o->a, o->b, &c, &err))
    fail_lib(o, o->files[0], &err);
  record r = {0};
  rec_num(&r, "chi2", c.chi2);
  rec_size(&r, "df", c.df);
  rec_num(&r, "p", c.p);
  rec_num(&r, "min_expected", c.min_expected);
  emit(o, &r, 1);
  if (c.low_expected)
    fprintf(stderr, PROG " chisq: note: expected counts %s < 5; the chi-square p-value is unreliable\n",
            r.val[3]);
  free(x);
  nl_table_free(t);
}

typedef struct {
  const char *linkage, *metric;
  const double *Z;
  const int *labels;
  size_t n;
} hclust_json;

/* JSON: the linkage matrix in scipy's layout (n - 1 rows a, b, dist, size)
 * and the flat clusters' labels, one per row of the input. */
static void hclust_more(const void *ctx)
{
  const hclust_json *h = ctx;
  printf(", \"linkage\": \"%s\", \"metric\": \"%s\", \"Z\": [", h->linkage, h->metric);
  for (size_t i = 0; i + 1 < h->n; i++) {
    fputs(i ? ", [" : "[", stdout);
    for (int j = 0; j < 4; j++) {
      if (j) fputs(", ", stdout);
      json_num(h->Z[4 * i + (size_t)j]);
    }
    putchar(']');
  }
  fputs("], \"labels\": [", stdout);
  for (size_t i = 0; i < h->n; i++) printf("%s%d", i ? ", " : "", h->labels[i]);
  putchar(']');
}

static void run_hclust(const opts *o)
{
  nl_cluster_linkage_method m;
  nl_error err;
  nl_cluster_metric metric = NL_METRIC_EUCLIDEAN;
  if (!o->linkage) {
    die(o->sub, "--linkage single|complete|average|weighted|ward|centroid|median is required");
  }
  if (nl_cluster_linkage_method_parse(o->linkage, &m, &err)) die(o->sub, "%s", err.msg);
  if (o->metric && nl_cluster_metric_parse(o->metric, &metric, &err))
    die(o->sub, "--metric: %s", err.msg);
  if (metric != NL_METRIC_EUCLIDEAN
      && (m == NL_LINKAGE_WARD || m == NL_LINKAGE_CENTROID || m == NL_LINKAGE_MEDIAN)) {
    die(o->sub, "--linkage %s needs --metric euclidean, not %s (as scipy's linkage)", o->linkage,
        o->metric);
  }
  if (o->have_cutoff == o->have_clusters) die(o->sub, "give exactly one of --cutoff C and --clusters K");
  /* Both outputs are opened (and so checked) before anything is computed or
   * written, and committed together: a bad --merges leaves --labels' old
   * file as it was. A temporary left by die() is removed at exit. */
  nl_atomic_file af[2] = {{0}, {0}};
  if (o->labels_out && nl_atomic_open(&af[0], o->labels_out, &err)) die(o->sub, "%s", err.msg);
  if (o->merges_out && nl_atomic_open(&af[1], o->merges_out, &err)) die(o->sub, "%s", err.msg);
  nl_table *t = read_table(o, o->files[0]);
  size_t n = t->nrows;
  double *Z = hold(nl_xmalloc((n - 1) * 4 * sizeof(double)));
  int *lab = hold(nl_xmalloc(n * sizeof(int)));
  size_t k;
  if (nl_cluster_linkage_metric(t->num, n, t->ncols, m, metric, Z, &err))
    fail_lib(o, o->files[0], &err);
  nl_status s = o->have_cutoff ? nl_cluster_fcluster_distance(Z, n, o->cutoff, lab, &k, &err)
                               : nl_cluster_fcluster_maxclust(Z, n, (size_t)o->clusters, lab, &k, &err);
  if (s) fail_lib(o, o->files[0], &err);
  nl_table *out[2] = {NULL, NULL};
  if (o->labels_out) {
    const char *cols[] = {"label"};
    out[0] = nl_table_alloc(1, cols);
    for (size_t i = 0; i < n; i++) nl_table_append(out[0], "i", lab[i]);
  }
  if (o->merges_out) {
    const char *cols[] = {"a", "b", "dist", "size"};
    out[1] = nl_table_alloc(4, cols);
    for (size_t i = 0; i + 1 < n; i++) nl_table_append_doubles(out[1], Z + 4 * i);
  }
  for (int i = 0; i < 2; i++)
    if (out[i] && nl_table_write_to(out[i], &af[i], &err)) die(o->sub, "%s", err.msg);
  if (nl_atomic_commit_all(af, 2, &err)) die(o->sub, "%s", err.msg);
  nl_table_free(out[0]);
  nl_table_free(out[1]);
  record r = {0};
  rec_size(&r, "clusters", k);
  hclust_json hj = {nl_cluster_linkage_method_name(m), nl_cluster_metric_name(metric), Z, lab, n};
  emit_more(o, &r, 1, hclust_more, &hj);
  free(Z); free(lab);
  nl_table_free(t);
}

static void fit_record(record *r, size_t n, size_t k, double ll, double aic, double bic, size_t it, int conv)
{
  rec_size(r, "k", k);
  rec_num(r, "loglik", ll);
  rec_num(r, "score", ll / (double)n);   /* sklearn GaussianMixture.score: mean log-likelihood per row */
  rec_num(r, "aic", aic);
  rec_num(r, "bic", bic);
  rec_size(r, "iterations", it);
  rec_bool(r, "converged", conv);
}

/* Into af, opened (and so checked) before the fit: a bad --params is
 * refused before EM runs, as hclust's outputs are. */
static nl_table *params_table(const nl_gmm *g)
{
  const char *cols[] = {"component", "param", "i", "j", "value"};
  nl_table *t = nl_table_alloc(5, cols);
  size_t d = g->d;
  for (size_t k = 0; k < g->k; k++) {
    nl_table_append(t, "isiid", (int)k + 1, "weight", 0, 0, g->weights[k]);
    for (size_t i = 0; i < d; i++) nl_table_append(t, "isiid", (int)k + 1, "mean", (int)i + 1, 0, g->means[k * d + i]);
    for (size_t i = 0; i < d; i++)
      for (size_t j = 0; j < d; j++) {
        /* each component's matrix: tied repeats the shared one, spherical is sigma_k^2 I */
        int full = g->covariance == NL_GMM_FULL || g->covariance == NL_GMM_TIED;
        if (!full && i != j) continue;
        double v = full ? g->covs[(k * d + i) * d + j] : g->covs[k * d + i];
        nl_table_append(t, "isiid", (int)k + 1, "cov", (int)i + 1, (int)j + 1, v);
      }
  }
  return t;
}

/* sklearn's predict on the fitted rows, 0-based (held: freed at exit). */
static int *predict(const opts *o, const nl_gmm *g, const nl_table *t)
{
  int *lab = hold(nl_xmalloc(t->nrows * sizeof(int)));
  nl_error err;
  if (nl_gmm_predict(g, t->num, t->nrows, lab, &err)) fail_lib(o, o->files[0], &err);
  return lab;
}

/* Constant columns are legal (reg_covar keeps their variance finite), but
 * the user should know the fit leans on reg_covar there. */
static void note_constant_columns(const opts *o, const nl_table *t)
{
  for (size_t j = 0; j < t->ncols; j++) {
    size_t i = 1;
    while (i < t->nrows && nl_table_get(t, i, j) == nl_table_get(t, 0, j)) i++;
    if (i == t->nrows)
      nl_message(stderr, PROG " gmm: note: %s: column %zu is constant; its variance is "
                 "reg_covar = %g", shown(o->files[0]), j + 1, o->reg);
  }
}

/* A model with more free parameters than the data has numbers fits
 * anything: EM "converges" on a likelihood that means nothing. One line. */
static void warn_overparameterised(const opts *o, const nl_table *t, size_t k, nl_gmm_covariance cov)
{
  size_t m = nl_gmm_nparams(k, t->ncols, cov), numbers = t->nrows * t->ncols;
  if (m > numbers)
    nl_message(stderr, PROG " gmm: warning: %s: k = %zu components (%s covariance) have %zu free "
               "parameters, more than the %zu numbers of the data (%zu rows x %zu columns); the "
               "fit is not meaningful", shown(o->files[0]), k,
               nl_gmm_covariance_name(cov), m, numbers, t->nrows, t->ncols);
}

/* JSON of one fit: its weights, means (k rows of d) and covariances in
 * sklearn's shapes (full: k matrices d x d; tied: one d x d; diag: k rows of
 * d; spherical: k variances), as weights_, means_ and covariances_, and
 * predict's label (1..k) of every row. */
typedef struct {
  const nl_gmm *g;
  const int *labels;
} gmm_json;

static void gmm_more(const void *ctx)
{
  const gmm_json *j = ctx;
  const nl_gmm *g = j->g;
  size_t d = g->d;
  nl_gmm_covariance c = g->covariance;
  printf(", \"covariance_type\": \"%s\"", nl_gmm_covariance_name(c));
  json_array("weights", g->weights, g->k, 1);
  fputs(", \"means\": [", stdout);
  for (size_t k = 0; k < g->k; k++) {
    fputs(k ? ", " : "", stdout);
    json_list(g->means + k * d, d, 1);
  }
  fputs("], \"covariances\": ", stdout);
  if (c == NL_GMM_SPHERICAL) json_list(g->covs, g->k, d);
  size_t matrices = c == NL_GMM_FULL ? g->k : c == NL_GMM_TIED ? 1 : 0;
  if (c == NL_GMM_DIAG || c == NL_GMM_TIED) putchar('[');
  for (size_t k = 0; c == NL_GMM_DIAG && k < g->k; k++) {
    fputs(k ? ", " : "", stdout);
    json_list(g->covs + k * d, d, 1);
  }
  if (c == NL_GMM_FULL) putchar('[');
  for (size_t k = 0; k < matrices; k++) {
    fputs(k ? ", [" : c == NL_GMM_FULL ? "[" : "", stdout);
    for (size_t i = 0; i < d; i++) {
      fputs(i ? ", " : "", stdout);
      json_list(g->covs + (k * d + i) * d, d, 1);
    }
    if (c == NL_GMM_FULL) putchar(']');
  }
  if (c != NL_GMM_SPHERICAL) putchar(']');
  fputs(", \"labels\": [", stdout);
  for (size_t i = 0; i < g->n; i++) printf("%s%d", i ? ", " : "", j->labels[i] + 1);
  putchar(']');
}

static void run_gmm(const opts *o)
{
  if (o->have_k == o->have_select) die(o->sub, "give exactly one of --k K and --select-aic K0 T");
  nl_gmm_options go;
  nl_gmm_options_default(&go);
  nl_error err;
  if (nl_gmm_covariance_parse(o->covariance, &go.covariance, &err))
    die(o->sub, "--covariance: %s", err.msg);
  go.seed = (unsigned long)o->seed;
  go.tol = o->tol;
  go.max_iter = (size_t)o->max_iter;
  go.reg_covar = o->reg;
  /* Both outputs opened (so checked) before EM runs, committed together.
   * A temporary left by die() is removed at exit. */
  nl_atomic_file af[2] = {{0}, {0}};
  if (o->params_out && nl_atomic_open(&af[0], o->params_out, &err)) die(o->sub, "%s", err.msg);
  if (o->labels_out && nl_atomic_open(&af[1], o->labels_out, &err)) die(o->sub, "%s", err.msg);
  nl_table *t = read_table(o, o->files[0]);
  size_t n = t->nrows, d = t->ncols;
  nl_gmm *g;
  if (o->have_k) {
    if ((size_t)o->k > n) {
      die(o->sub, "%s: %ld components but only %zu rows", shown(o->files[0]), o->k, n);
    }
    if (nl_gmm_check_size(n, d, (size_t)o->k, go.covariance, &err)) fail_lib(o, o->files[0], &err);
    g = hold(nl_gmm_alloc((size_t)o->k, d, go.covariance));
    if (nl_gmm_fit(g, t->num, n, &go, &err)) fail_lib(o, o->files[0], &err);
    record r = {0};
    fit_record(&r, n, g->k, g->loglik, g->aic, g->bic, g->iterations, g->converged);
    gmm_json gj = {g, predict(o, g, t)};
    emit_more(o, &r, 1, gmm_more, &gj);
    warn_overparameterised(o, t, g->k, go.covariance);
  } else {
    if ((size_t)o->k0 > n) {
      die(o->sub, "%s: K0 = %ld components but only %zu rows", shown(o->files[0]), o->k0, n);
    }
    size_t kmax = (size_t)(o->max_k > o->k0 ? o->max_k : o->k0), np;
    nl_gmm_step *path = hold(nl_xmalloc((kmax - (size_t)o->k0 + 1) * sizeof *path));
    if (nl_gmm_select_aic(t->num, n, d, (size_t)o->k0, o->thresh, kmax, &go, &g, path, &np, &err))
      fail_lib(o, o->files[0], &err);
    record *r = nl_xcalloc(np + 1, sizeof *r);
    for (size_t i = 0; i < np; i++) {
      fit_record(&r[i], n, path[i].k, path[i].loglik, path[i].aic, path[i].bic, path[i].iterations,
                 path[i].converged);
      if (o->format != OUT_KV) rec_bool(&r[i], "selected", path[i].k == g->k);
    }
    emit(o, r, np);
    if (o->format == OUT_KV) printf("selected=%zu\n", g->k);
    warn_overparameterised(o, t, path[np - 1].k, go.covariance);
    free(r);
    free(path);
  }
  note_constant_columns(o, t);
  nl_table *out[2] = {o->params_out ? params_table(g) : NULL, NULL};
  if (o->labels_out) {
    const char *cols[] = {"label"};
    int *lab = predict(o, g, t);
    out[1] = nl_table_alloc(1, cols);
    for (size_t i = 0; i < n; i++) nl_table_append(out[1], "i", lab[i] + 1);
  }
  for (int i = 0; i < 2; i++)
    if (out[i] && nl_table_write_to(out[i], &af[i], &err)) die(o->sub, "%s", err.msg);
  if (nl_atomic_commit_all(af, 2, &err)) die(o->sub, "%s", err.msg);
  nl_table_free(out[0]);
  nl_table_free(out[1]);
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
  nl_tool_start("noiselab stat");   /* OOM exit, SIGXFSZ ignored, stdout checked at exit */
  if (argc < 2 || !strcmp(argv[1], "--help") || !strcmp(argv[1], "-h")) {
    fputs(usage_text[0], argc < 2 ? stderr : stdout);
    return argc < 2 ? 2 : 0;
  }
  opts o = {.sub = argv[1], .column = 1, .a = 0.0, .b = 1.0, .tol = 1e-3, .reg = 1e-6,
            .max_iter = 100, .max_k = 100, .covariance = "full"};
  const char *help = sub_help(o.sub);
  if (!help) {
    nl_message(stderr, PROG ": unknown subcommand '%s' (ks, ks2, kuiper, chisq, hclust, gmm)",
               o.sub);
    return 2;
  }
  for (int i = 2; i < argc && strcmp(argv[i], "--"); i++)
    if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) { fputs(help, stdout); return 0; }
  parse(argc, argv, &o);
  /* No output replaces an input or the program's own sources. */
  const char *ins[3] = {o.nfiles > 0 ? o.files[0] : NULL, o.nfiles > 1 ? o.files[1] : NULL,
                        o.cdf_file};
  nl_tool_check_output(o.labels_out, ins, 3);
  nl_tool_check_output(o.merges_out, ins, 3);
  nl_tool_check_output(o.params_out, ins, 3);
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
