#define _GNU_SOURCE   /* RTLD_DEFAULT, dladdr */
#include "harness/nl_harness.h"
#include "harness/nl_build_info.h"
#include "base/nl_parallel.h"
#include "spectrum/nl_spectrum.h"
#include "stats/nl_stats.h"

#include <gsl/gsl_version.h>
#include <dirent.h>
#include <dlfcn.h>
#include <errno.h>
#ifdef __GLIBC__
#include <gnu/libc-version.h>
#include <malloc.h>
#endif
#if defined(__GLIBC__) && defined(__x86_64__) && defined(__has_include)
#if __has_include(<sys/platform/x86.h>)
#include <sys/platform/x86.h>
#ifdef CPU_FEATURE_ACTIVE   /* glibc 2.33 on; 2.32 named it CPU_FEATURE_USABLE */
#define NL_HAVE_X86_FEATURES 1
#endif
#endif
#endif
#include <math.h>
#include <pthread.h>
#include <signal.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/utsname.h>
#include <time.h>
#include <unistd.h>

#define SHARD_DIR ".shards"   /* the shard files' folder in OUT without --shards */

struct nl_harness {
  const char *name, *title;
  char *out;
  unsigned long seed;
  int seeds, quick;
  int images;             /* 0: --no-images (nl_harness_write_image writes nothing) */
  int threads;            /* --threads, default nl_parallel_cores() */
  double t0;
  char started[32];
  int nset;
  char **set_key, **set_val;
  int *set_used;
  int listing;            /* 0; 1 --help, 2 --params: print at nl_harness_params_done, exit 0 */
  size_t nparam;          /* the parameters declared so far, for --params, --help, errors */
  nl_harness_param_info *param;
  int params_checked;     /* nl_harness_params_done ran */
  int prepared;           /* the output folder exists and its old manifest is gone */
  nl_table *manifest;     /* key, value (text) */
  nl_table *checks;       /* table, column, rule (text): regression rules */
  nl_table *verdicts;     /* quantity, source, paper, ours, ours_sd, rule, verdict, reason, control... */
  struct {                /* the verdict declared last, for its control */
    enum { LAST_NONE, LAST_VALUE, LAST_EQUIV, LAST_P, LAST_LESS } type;
    char rule[64], col[128], sd_col[128], n_col[128];
    double paper, alpha;
    int has_control;
  } last;
  char **outputs;         /* files this run writes (nl_harness_path), and its figures */
  size_t noutputs;
  char **figures;         /* nl_harness_figure's files */
  size_t nfigures;
  char **previous;        /* outputs of earlier runs in the folder (prepare) */
  size_t nprevious;
  char *md;               /* report section being built */
  size_t md_len, md_cap;
  /* progress (nl_harness_stage): the current stage's share of the bar and
   * its part (substage); the furthest fraction shown, the last label printed
   * off a terminal, and whether a terminal line is left open */
  double stage_from, stage_to, part_from, part_to, shown;
  char stage_what[64], last_what[64];
  int staged, line_open;
  /* nl_harness_time_column: the time columns (file, column) and the values
   * taken out of the written tables, for times.tsv */
  char **time_file, **time_col;
  size_t ntime;
  nl_table *times;
  /* shards (nl_harness_units): --shard K/N (shard_n 0: none), --merge; the
   * units' stored values, the unit being computed (-1: none) */
  int shard_k, shard_n, merge, units_query;
  char *shard_dir;        /* --shards, default OUT/.shards */
  long nunits;            /* -1 until nl_harness_units */
  double shards_cpu, shards_rss;   /* --merge: the shards' CPU seconds (sum) and peak RSS MB (max) */
  struct unit_entry *ue;
  size_t nue, cue;
  long unit_cur;
};

/* The compiler by name and version: gcc's __VERSION__ is the bare number
 * ("12.2.0"), clang's already names itself ("Debian Clang 14.0.6"). */
#if defined(__clang__)
#define NL_COMPILER __VERSION__
#elif defined(__GNUC__)
#define NL_COMPILER "gcc " __VERSION__
#else
#define NL_COMPILER __VERSION__
#endif

static void usage(const char *name, const char *title)
{
  printf("%s - %s\n\n"
         "usage: %s [--out DIR] [--seed N] [--seeds K] [--quick] [--threads N] [--no-images]\n"
         "       [--set NAME=VALUE]...\n\n"
         "  --out DIR     output folder (default results/%s)\n"
         "  --seed N      base seed, 0..4294967295 (default 1)\n"
         "  --seeds K     seeds for means and spreads (default 10; 3 with --quick)\n"
         "  --quick       small sizes, for tests and CI\n"
         "  --threads N   threads for independent work, 1..64 (default: the number of\n"
         "                cores); the tables are the same for any N\n"
         "  --no-images   tables, manifest and report text only, no image files (for\n"
         "                sweeps and reruns that compare tables; manifest: images no)\n"
         "  --set K=V     set an experiment parameter (listed below)\n"
         "  --shard K/N   compute only the units u with u mod N = K - 1 into\n"
         "                DIR/.shards/K-of-N.tsv (experiments that declare units)\n"
         "  --merge       read DIR/.shards/*-of-N.tsv (all N) and write the run\n"
         "                exactly as an unsharded run writes it\n"
         "  --shards D    the shard files' folder (default DIR/.shards)\n"
         "  --units       print one line a unit, its relative cost, and exit\n"
         "  --params      list the parameters as TSV (name, default, min, max, meaning)\n\n"
         "Nothing in the output folder changes until every option and parameter\n"
         "is accepted; a folder with a manifest.tsv is a finished run.\n",
         name, title, name, name);
}

/* The number as --set accepts it and the manifest records it. */
static void param_text(char buf[32], double v, int is_int)
{
  if (is_int) snprintf(buf, 32, "%ld", (long)v);
  else nl_table_format_double(buf, v);
}

void nl_harness_params_print(const nl_harness *r, FILE *fp, int readable)
{
  char d[32], lo[32], hi[32];
  if (readable) fprintf(fp, "\nparameters (--set NAME=VALUE; default, range):\n");
  else fprintf(fp, "name\tdefault\tmin\tmax\tmeaning\n");
  if (readable && !r->nparam) fprintf(fp, "  (none)\n");
  for (size_t k = 0; k < r->nparam; k++) {
    const nl_harness_param_info *p = &r->param[k];
    param_text(d, p->def, p->is_int);
    param_text(lo, p->lo, p->is_int);
    param_text(hi, p->hi, p->is_int);
    if (readable) fprintf(fp, "  %-16s %s%s in [%s, %s]: %s\n", p->name, p->is_int ? "integer " : "",
                          d, lo, hi, p->meaning);
    else fprintf(fp, "%s\t%s\t%s\t%s\t%s\n", p->name, d, lo, hi, p->meaning);
  }
}

const nl_harness_param_info *nl_harness_params(const nl_harness *r, size_t *n)
{
  *n = r->nparam;
  return r->param;
}

void nl_harness_die(nl_harness *r, int code, const char *fmt, ...)
{
  va_list ap;
  va_start(ap, fmt);
  fprintf(stderr, "%s: ", r ? r->name : "noiselab");
  nl_vmessage(stderr, fmt, ap);   /* one line whatever input it quotes */
  va_end(ap);
  exit(code);
}

static int unit_note(nl_harness *r, const char *key, const char *value);

static void note(nl_harness *r, const char *key, const char *value)
{
  if (unit_note(r, key, value)) return;   /* inside a unit: stored with its values */
  nl_table_append(r->manifest, "ss", key, value);
}

void nl_harness_note(nl_harness *r, const char *key, const char *fmt, ...)
{
  char buf[1024];
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(buf, sizeof buf, fmt, ap);
  va_end(ap);
  note(r, key, buf);
}

/* ---- options ------------------------------------------------------------ */

void nl_harness_options_free(nl_harness_options *o)
{
  if (!o) return;
  for (int k = 0; k < o->nset; k++) { free(o->set_key[k]); free(o->set_val[k]); }
  free(o->set_key); free(o->set_val); free(o->out); free(o->shard_dir);
  memset(o, 0, sizeof *o);
}

nl_status nl_harness_parse(nl_harness_options *o, int argc, char **argv, nl_error *err)
{
  /* GNU style through the tools' parser: --seed 3, --seed=3, unique prefixes. */
  static const nl_opt_spec spec[] = {{"help", 'h', 0}, {"params", 0, 0}, {"quick", 0, 0}, {"out", 0, 1},
                                     {"seed", 0, 1}, {"seeds", 0, 1}, {"set", 0, 1}, {"threads", 0, 1},
                                     {"no-images", 0, 0}, {"shard", 0, 1}, {"merge", 0, 0},
                                     {"shards", 0, 1}, {"units", 0, 0}, {0}};
  memset(o, 0, sizeof *o);
  o->seed = 1;
  o->seeds = -1;
  nl_opt_parser p;
  nl_status st = NL_OK;
  nl_opt_begin(&p, argc, argv, 1, spec);
  for (int k; !st && (k = nl_opt_next(&p, err)) != NL_OPT_END;) {
    const char *v = p.value[0];
    long n;
    if (k == NL_OPT_ERROR) {
      st = nl_fail(err, NL_EINVAL, "%s (see --help)", err->msg);
    } else if (k == NL_OPT_POSITIONAL) st = nl_fail(err, NL_EINVAL, "%s: unexpected argument (see --help)", v);
    else if (!strcmp(spec[k].name, "help")) o->help = 1;
    else if (!strcmp(spec[k].name, "params")) o->params = 1;
    else if (!strcmp(spec[k].name, "quick")) o->quick = 1;
    else if (!strcmp(spec[k].name, "no-images")) o->no_images = 1;
    else if (!strcmp(spec[k].name, "merge")) o->merge = 1;
    else if (!strcmp(spec[k].name, "units")) o->units = 1;
    else if (!strcmp(spec[k].name, "shards")) {
      if (!*v) st = nl_fail(err, NL_EINVAL, "--shards: empty folder name");
      else { free(o->shard_dir); o->shard_dir = nl_xstrdup(v); }
    }
    else if (!strcmp(spec[k].name, "shard")) {
      int kk, nn, used = 0;
      if (sscanf(v, "%d/%d%n", &kk, &nn, &used) != 2 || v[used] || nn < 1 || nn > 10000 || kk < 1 || kk > nn)
        st = nl_fail(err, NL_EINVAL, "--shard: '%s' is not K/N with 1 <= K <= N <= 10000", v);
      else { o->shard_k = kk; o->shard_n = nn; }
    }
    else if (!strcmp(spec[k].name, "out")) {
      if (!*v) st = nl_fail(err, NL_EINVAL, "--out: empty folder name");
      else { free(o->out); o->out = nl_xstrdup(v); }
    } else if (!strcmp(spec[k].name, "seed")) {
      if (!(st = nl_parse_long("--seed", v, 0, 4294967295L, &n, err))) o->seed = (unsigned long)n;
    } else if (!strcmp(spec[k].name, "threads")) {
      if (!(st = nl_parse_long("--threads", v, 1, NL_PARALLEL_MAX, &n, err))) o->threads = (int)n;
    } else if (!strcmp(spec[k].name, "seeds")) {
      if (!(st = nl_parse_long("--seeds", v, 1, 10000, &n, err))) o->seeds = (int)n;
    } else {   /* --set NAME=VALUE */
      const char *eq = strchr(v, '=');
      if (!eq || eq == v) st = nl_fail(err, NL_EINVAL, "--set: '%s' is not NAME=VALUE", v);
      else {
        o->set_key = nl_xrealloc(o->set_key, (size_t)(o->nset + 1) * sizeof *o->set_key);
        o->set_val = nl_xrealloc(o->set_val, (size_t)(o->nset + 1) * sizeof *o->set_val);
        o->set_key[o->nset] = nl_xstrdup(v);
        o->set_key[o->nset][eq - v] = '\0';
        o->set_val[o->nset++] = nl_xstrdup(eq + 1);
      }
    }
  }
  nl_opt_end(&p);
  if (!st && o->merge && o->shard_n) st = nl_fail(err, NL_EINVAL, "--merge: not with --shard (merge after every shard ran)");
  if (st) nl_harness_options_free(o);
  return st;
}

void nl_harness_oom_exit(size_t n)
{
  (void)n;   /* base has printed the message */
  exit(3);
}

/* ---- a program's end: its open temporaries removed -------------------
 *
 * At exit() (so a tool may die() between an output's open and its commit)
 * and on SIGINT, SIGTERM and SIGHUP: the handler removes the temporaries,
 * puts back what the signal did before (the default: end the process; or
 * the program's own handler) and raises it again; it is blocked in here, so
 * it arrives when the handler returns. An ignored signal stays ignored
 * (nohup, a shell's background job). */
static const int end_signals[3] = {SIGINT, SIGTERM, SIGHUP};
static struct sigaction end_previous[3];
static pthread_once_t end_once = PTHREAD_ONCE_INIT;

static void end_on_signal(int sig)
{
  int saved = errno;
  nl_atomic_unlink_open();
  for (int k = 0; k < 3; k++)
    if (end_signals[k] == sig) sigaction(sig, &end_previous[k], NULL);
  raise(sig);
  errno = saved;
}

static void end_install(void)
{
  atexit(nl_atomic_unlink_open);
  for (int k = 0; k < 3; k++) {
    struct sigaction sa;
    if (sigaction(end_signals[k], NULL, &end_previous[k]) != 0) continue;
    if (!(end_previous[k].sa_flags & SA_SIGINFO) && end_previous[k].sa_handler == SIG_IGN)
      continue;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = end_on_signal;
    sigfillset(&sa.sa_mask);
    sigaction(end_signals[k], &sa, NULL);
  }
}

void nl_harness_program_start(void)
{
  pthread_once(&end_once, end_install);
  nl_set_oom_handler(nl_harness_oom_exit);
  nl_parallel_blas_idle();
}

nl_harness *nl_harness_begin(const char *name, const char *title, int argc, char **argv)
{
  nl_harness_program_start();
#ifdef __GLIBC__
  /* Speed only: glibc returns every freed block above 128 KB to
   * the kernel (mmap'ed or trimmed), so a loop that allocates and frees
   * image-sized buffers or EM's K d^2 arrays faults and zeroes their pages
   * again each time (60% of a one-thread L2 run's CPU). Blocks up to 64 MB
   * stay in the heap and freed memory is kept up to 256 MB. Results do not
   * depend on it. */
  mallopt(M_MMAP_THRESHOLD, 64 << 20);
  mallopt(M_TRIM_THRESHOLD, 256 << 20);
#endif
  nl_harness_options o;
  nl_error err;
  if (nl_harness_parse(&o, argc, argv, &err)) {
    fprintf(stderr, "%s: %s\n", name, err.msg);
    exit(2);
  }
  nl_harness *r = nl_xcalloc(1, sizeof *r);
  /* --help and --params are answered at nl_harness_params_done, once the
   * experiment has declared its parameters; nothing is done before. */
  r->listing = o.help ? 1 : o.params ? 2 : 0;
  r->name = name;
  r->title = title;
  r->seed = o.seed;
  r->seeds = o.seeds < 0 ? (o.quick ? 3 : 10) : o.seeds;
  r->quick = o.quick;
  r->images = !o.no_images;
  r->threads = o.threads > 0 ? o.threads : nl_parallel_cores();
  r->t0 = nl_time_now();
  r->out = o.out ? o.out : nl_path_join("results", name);
  r->nset = o.nset;
  r->set_key = o.set_key;
  r->set_val = o.set_val;
  r->set_used = nl_xcalloc((size_t)o.nset + 1, sizeof *r->set_used);
  r->shard_k = o.shard_k;
  r->shard_n = o.shard_n;
  r->merge = o.merge;
  r->shard_dir = o.shard_dir ? o.shard_dir : nl_path_join(r->out, SHARD_DIR);
  r->units_query = o.units;
  r->nunits = -1;
  r->unit_cur = -1;
  /* The output folder is not touched here: see prepare(). */
  time_t now = time(NULL);
  strftime(r->started, sizeof r->started, "%Y-%m-%dT%H:%M:%SZ", gmtime(&now));
  const char *cols[] = {"key", "value"};
  r->manifest = nl_table_alloc(2, cols);
  const char *ccols[] = {"table", "column", "rule"};
  r->checks = nl_table_alloc(3, ccols);
  note(r, "experiment", name);
  nl_harness_note(r, "seed", "%lu", r->seed);
  nl_harness_note(r, "seeds", "%d", r->seeds);
  note(r, "quick", r->quick ? "yes" : "no");
  nl_harness_note(r, "threads", "%d", r->threads);   /* speed only: the tables do not depend on it */
  note(r, "images", r->images ? "yes" : "no");        /* --no-images: tables only */
  nl_harness_text(r, "## %s\n", title);
  r->stage_to = r->part_to = 1.0;
  return r;
}

/* The file name the manifest is written under: manifest.tsv, or
 * NL_MANIFEST_NAME when it is a plain hidden file name. The entry script sets
 * it to a pending name and renames the file to manifest.tsv once the run's
 * figures are made, so a folder is complete only when its figures are. */
static const char *manifest_name(void)
{
  const char *s = getenv("NL_MANIFEST_NAME");
  if (s && s[0] == '.' && strlen(s) > 1 && !strchr(s, '/') && strcmp(s, "..")) return s;
  return "manifest.tsv";
}

/* ---- outputs: what a run wrote, so that the next run removes its stale ones
 *
 * The manifest lists every file the run wrote ("output" lines): the paths
 * handed out by nl_harness_path (tables, images, report.md, checks.tsv,
 * verdicts.tsv) and the figures named by nl_harness_figure (a PNG the
 * program did not write is drawn by the entry script, with its SVG beside
 * it). A run that completes removes the files an earlier run listed and it
 * did not write: a table the code no longer makes would otherwise stay
 * beside the new ones and be read by the regression check and REPORT.md.
 * Files no run listed (a user's notes) are never touched. Between the
 * removal of the old manifest (prepare) and the new one, the list waits in
 * OUTPUTS_PENDING, so an interrupted run does not lose it. */
#define OUTPUTS_PENDING ".outputs-previous.tsv"

static int listed(char **names, size_t n, const char *name)
{
  for (size_t i = 0; i < n; i++)
    if (!strcmp(names[i], name)) return 1;
  return 0;
}

static void list_add(char ***names, size_t *n, const char *name)
{
  if (listed(*names, *n, name)) return;
  *names = nl_xrealloc(*names, (*n + 1) * sizeof **names);
  (*names)[(*n)++] = nl_xstrdup(name);
}

/* Adds to r->previous the names in column `col` of DIR/FILE whose key
 * (column 0, when key is not NULL) is `key`; a missing file adds nothing. */
static void previous_read(nl_harness *r, const char *file, const char *key, size_t col)
{
  char *p = nl_path_join(r->out, file);
  nl_table *t;
  nl_error err;
  if (access(p, F_OK) == 0 && nl_table_read(p, NL_TABLE_TEXT, &t, &err) == NL_OK) {
    for (size_t i = 0; i < t->nrows && col < t->ncols; i++) {
      char ka[32], va[32];
      if (key && strcmp(nl_table_cell_text(t, i, 0, ka), key)) continue;
      list_add(&r->previous, &r->nprevious, nl_table_cell_text(t, i, col, va));
    }
    nl_table_free(t);
  }
  free(p);
}

/* The outputs of earlier runs, kept in OUTPUTS_PENDING before their
 * manifest goes. */
static void previous_keep(nl_harness *r)
{
  previous_read(r, "manifest.tsv", "output", 1);
  previous_read(r, manifest_name(), "output", 1);
  previous_read(r, OUTPUTS_PENDING, NULL, 0);
  if (!r->nprevious) return;
  const char *cols[] = {"output"};
  nl_table *t = nl_table_alloc(1, cols);
  for (size_t i = 0; i < r->nprevious; i++)
    nl_table_append(t, "s", r->previous[i]);
  char *p = nl_path_join(r->out, OUTPUTS_PENDING);
  nl_error err;
  nl_status st = nl_table_write(t, p, &err);
  nl_table_free(t);
  free(p);
  if (st) nl_harness_die(r, 1, "%s", err.msg);
}

/* At the end: the manifest's "output" lines, and the earlier outputs this
 * run did not write removed (plain names only: nothing outside the folder,
 * no hidden file, never the manifest). */
static void outputs_settle(nl_harness *r)
{
  size_t written = r->noutputs;
  for (size_t i = 0; i < r->nfigures; i++) {
    const char *f = r->figures[i];
    size_t len = strlen(f);
    if (listed(r->outputs, written, f)) continue;   /* an image the program wrote */
    list_add(&r->outputs, &r->noutputs, f);
    if (len > 4 && !strcmp(f + len - 4, ".png")) {   /* the entry script's SVG of it */
      char *svg = nl_xstrdup(f);
      strcpy(svg + len - 4, ".svg");
      list_add(&r->outputs, &r->noutputs, svg);
      free(svg);
    }
  }
  for (size_t i = 0; i < r->noutputs; i++)
    note(r, "output", r->outputs[i]);
  for (size_t i = 0; i < r->nprevious; i++) {
    const char *f = r->previous[i];
    if (listed(r->outputs, r->noutputs, f) || strchr(f, '/') || f[0] == '.' || !f[0]
        || !strcmp(f, "manifest.tsv"))
      continue;
    char *p = nl_path_join(r->out, f);
    struct stat st;
    if (lstat(p, &st) == 0 && !S_ISDIR(st.st_mode) && unlink(p) && errno != ENOENT)
      nl_harness_die(r, 1, "%s: cannot remove this output of an earlier run: %s", p,
                     strerror(errno));
    free(p);
  }
}

/* The run is about to write: every parameter has been accepted (unknown
 * --set names are refused here at the latest), so now the folder is made and
 * the previous run's manifest removed (a folder with a manifest is a
 * finished run; this one is not, yet). Called by every function that writes
 * into the folder or hands out a path in it. */
static void units_refuse(nl_harness *r);
static void units_clear(nl_harness *r);
static void shards_remove(nl_harness *r);

static void prepare(nl_harness *r)
{
  if (r->prepared) return;
  if (!r->params_checked) nl_harness_params_done(r);
  units_refuse(r);
  nl_error err;
  if (nl_mkdir_p(r->out, &err)) nl_harness_die(r, 1, "%s", err.msg);
  previous_keep(r);
  const char *names[2] = {"manifest.tsv", manifest_name()};
  for (int k = 0; k < 2; k++) {
    char *m = nl_path_join(r->out, names[k]);
    if (unlink(m) && errno != ENOENT) nl_harness_die(r, 1, "%s: cannot remove: %s", m, strerror(errno));
    free(m);
  }
  r->prepared = 1;
}

unsigned long nl_harness_seed(const nl_harness *r) { return r->seed; }
int nl_harness_seeds(const nl_harness *r) { return r->seeds; }
int nl_harness_quick(const nl_harness *r) { return r->quick; }
int nl_harness_threads(const nl_harness *r) { return r->threads; }
const char *nl_harness_dir(const nl_harness *r) { prepare((nl_harness *)r); return r->out; }
const char *nl_harness_name(const nl_harness *r) { return r->name; }

static const char *set_value(nl_harness *r, const char *name)
{
  const char *v = NULL;
  for (int k = 0; k < r->nset; k++)
    if (!strcmp(r->set_key[k], name)) { v = r->set_val[k]; r->set_used[k] = 1; }
  return v;
}

/* Records the declaration (for --params, --help and the unknown-name error)
 * and returns the --set value for name (NULL if none) with its label. */
static const char *param_value(nl_harness *r, const char *name, double def, double lo, double hi,
                               int is_int, const char *meaning, char *what, size_t n)
{
  r->param = nl_xrealloc(r->param, (r->nparam + 1) * sizeof *r->param);
  r->param[r->nparam++] = (nl_harness_param_info){name, def, lo, hi, is_int, meaning ? meaning : ""};
  snprintf(what, n, "--set %s", name);
  return set_value(r, name);
}

double nl_harness_param(nl_harness *r, const char *name, double def, double lo, double hi, const char *meaning)
{
  char what[128], buf[32];
  const char *s = param_value(r, name, def, lo, hi, 0, meaning, what, sizeof what);
  double v = def;
  nl_error err;
  if (s && nl_parse_double(what, s, lo, hi, &v, &err)) nl_harness_die(r, 2, "%s", err.msg);
  nl_table_format_double(buf, v);
  nl_harness_note(r, "param", "%s=%s", name, buf);
  return v;
}

long nl_harness_param_int(nl_harness *r, const char *name, long def, long lo, long hi, const char *meaning)
{
  char what[128];
  const char *s = param_value(r, name, (double)def, (double)lo, (double)hi, 1, meaning, what, sizeof what);
  long v = def;
  nl_error err;
  if (s && nl_parse_long(what, s, lo, hi, &v, &err)) nl_harness_die(r, 2, "%s", err.msg);
  nl_harness_note(r, "param", "%s=%ld", name, v);
  return v;
}

long nl_harness_param_fft_size(nl_harness *r, const char *name, long def, long lo, long hi,
                               const char *meaning)
{
  long v = nl_harness_param_int(r, name, def, lo, hi, meaning);
  nl_error err;
  if (nl_spectrum_check_size((int)v, (int)v, &err))
    nl_harness_die(r, 2, "--set %s=%ld: %s", name, v, err.msg);
  return v;
}

void nl_harness_params_done(nl_harness *r)
{
  r->params_checked = 1;
  for (int k = 0; k < r->nset; k++) {
    if (r->set_used[k]) continue;
    /* One line that names the valid parameters, so a typo is fixed at once. */
    size_t len = 0;
    for (size_t p = 0; p < r->nparam; p++) len += strlen(r->param[p].name) + 2;
    char *names = nl_xmalloc(len + 8);
    names[0] = '\0';
    for (size_t p = 0; p < r->nparam; p++) {
      if (p) strcat(names, ", ");
      strcat(names, r->param[p].name);
    }
    nl_harness_die(r, 2, "--set %s: unknown parameter for %s (valid: %s)", r->set_key[k], r->name,
                   r->nparam ? names : "none");
  }
  /* --help or --params: the list, and nothing else. Any --set given was
   * checked like a run's, so `--params --set ...` validates a sweep's values
   * without doing the work. */
  if (r->listing) {
    if (r->listing == 1) usage(r->name, r->title);
    nl_harness_params_print(r, stdout, r->listing == 1);
    /* A list lost on a full disk or a closed pipe is a failed output: one
     * line and exit 2, as the tools say it (tools/nl_tool.c). */
    nl_error err;
    if (nl_stream_close(stdout, "standard output", &err)) nl_harness_die(r, 2, "%s", err.msg);
    exit(0);
  }
}

char *nl_harness_path(const nl_harness *r, const char *file)
{
  nl_harness *w = (nl_harness *)r;   /* r is always a heap nl_harness */
  prepare(w);   /* the folder must exist for the caller */
  if (strcmp(file, "manifest.tsv") && strcmp(file, manifest_name()))
    list_add(&w->outputs, &w->noutputs, file);
  return nl_path_join(r->out, file);
}

static int is_time(const nl_harness *r, const char *file, const char *col)
{
  for (size_t i = 0; i < r->ntime; i++)
    if ((!file || !strcmp(r->time_file[i], file)) && !strcmp(r->time_col[i], col)) return 1;
  return 0;
}

static void drop_rule(nl_harness *r, const char *table, const char *column)
{
  nl_table *c = r->checks;
  for (size_t i = 0; i < c->nrows; i++) {
    char **row = c->text + i * c->ncols;
    if (strcmp(row[0], table) || strcmp(row[1], column)) continue;
    for (size_t k = 0; k < c->ncols; k++) free(row[k]);
    memmove(row, row + c->ncols, (c->nrows - i - 1) * c->ncols * sizeof *row);
    memmove(c->num + i * c->ncols, c->num + (i + 1) * c->ncols, (c->nrows - i - 1) * c->ncols * sizeof *c->num);
    c->nrows--;
    return;
  }
}

void nl_harness_time_column(nl_harness *r, const char *file, const char *column)
{
  if (is_time(r, file, column)) return;
  r->time_file = nl_xrealloc(r->time_file, (r->ntime + 1) * sizeof *r->time_file);
  r->time_col = nl_xrealloc(r->time_col, (r->ntime + 1) * sizeof *r->time_col);
  r->time_file[r->ntime] = nl_xstrdup(file);
  r->time_col[r->ntime++] = nl_xstrdup(column);
  drop_rule(r, file, column);   /* nothing left to compare */
}

/* t without FILE's time columns (NULL when it has none); their cells go to
 * r->times, one row each: table, row (from 1), the row's first cell, column,
 * value. */
static nl_table *without_times(nl_harness *r, const nl_table *t, const char *file)
{
  size_t nkeep = 0;
  for (size_t c = 0; c < t->ncols; c++) nkeep += !is_time(r, file, t->names[c]);
  if (nkeep == t->ncols) return NULL;
  const char **names = nl_xmalloc((nkeep + 1) * sizeof *names);
  size_t k = 0;
  for (size_t c = 0; c < t->ncols; c++)
    if (!is_time(r, file, t->names[c])) names[k++] = t->names[c];
  nl_table *v = nl_table_alloc(nkeep, names);
  free(names);
  if (!r->times) {
    const char *cols[] = {"table", "row", "key", "column", "value"};
    r->times = nl_table_alloc(5, cols);
  }
  char a[64], b[64];
  for (size_t row = 0; row < t->nrows; row++) {
    size_t i = nl_table_append_empty(v);
    for (size_t c = 0; c < t->ncols; c++) {
      const char *tx = t->text ? t->text[row * t->ncols + c] : NULL;
      if (is_time(r, file, t->names[c])) {
        nl_table_append(r->times, "sdsss", file, (double)(row + 1),
                        nl_table_cell_text(t, row, 0, a), t->names[c], nl_table_cell_text(t, row, c, b));
        continue;
      }
      if (tx) nl_table_set_text(v, i, t->names[c], tx);
      else nl_table_set(v, i, t->names[c], nl_table_get(t, row, c));
    }
  }
  return v;
}

void nl_harness_write_table(nl_harness *r, const nl_table *t, const char *file)
{
  char *p = nl_harness_path(r, file);
  nl_error err;
  nl_table *v = without_times(r, t, file);
  if (nl_table_write(v ? v : t, p, &err)) nl_harness_die(r, 1, "%s", err.msg);
  nl_table_free(v);
  free(p);
}

void nl_harness_write_image(nl_harness *r, const nl_image *im, const char *file)
{
  if (!r->images) return;
  char *p = nl_harness_path(r, file);
  nl_error err;
  if (nl_image_write(im, p, 8, &err)) nl_harness_die(r, 1, "%s", err.msg);
  free(p);
}

static void progress_print(nl_harness *r, double f, const char *what)
{
  int tty = isatty(2);
  /* a finished bar stays finished: a later loop that reports 100% again
   * would print one more line each time */
  if (tty && r->shown >= 1.0 && !r->line_open) return;
  if (f < r->shown) f = r->shown;   /* one bar: never back */
  r->shown = f;
  char label[160];
  if (r->staged && what && strcmp(what, r->stage_what))
    snprintf(label, sizeof label, "%s: %s", r->stage_what, what);
  else
    snprintf(label, sizeof label, "%s", what ? what : r->stage_what);
  fprintf(stderr, "%s[%s] %3.0f%% %s (%.1f s)%s", tty ? "\r\033[K" : "", r->name, 100 * f, label,
          nl_time_now() - r->t0, tty ? "" : "\n");
  r->line_open = tty;
  if (tty && f >= 1.0) {
    fputc('\n', stderr);
    r->line_open = 0;
  }
  fflush(stderr);
}

void nl_harness_stage(nl_harness *r, double from, double to, const char *what)
{
  r->staged = 1;
  r->stage_from = r->part_from = from;
  r->stage_to = r->part_to = to;
  snprintf(r->stage_what, sizeof r->stage_what, "%s", what ? what : "");
  progress_print(r, from, NULL);
}

void nl_harness_substage(nl_harness *r, int k, int n)
{
  double w = (r->stage_to - r->stage_from) / (n > 0 ? n : 1);
  r->part_from = r->stage_from + k * w;
  r->part_to = r->part_from + w;
}

void nl_harness_progress(nl_harness *r, double fraction, const char *what)
{
  double f = r->part_from + (fraction < 0 ? 0 : fraction > 1 ? 1 : fraction) * (r->part_to - r->part_from);
  if (!isatty(2)) {
    /* off a terminal: a line per stage; a declared stage printed its own */
    if (r->staged || !strcmp(what ? what : "", r->last_what)) {
      if (f > r->shown) r->shown = f;
      return;
    }
    snprintf(r->last_what, sizeof r->last_what, "%s", what ? what : "");
  }
  progress_print(r, f, what);
}

/* ---- report section --------------------------------------------------- */

static void md_append(nl_harness *r, const char *s)
{
  size_t n = strlen(s);
  if (r->md_len + n + 1 > r->md_cap) {
    r->md_cap = 2 * (r->md_len + n + 1) + 1024;
    r->md = nl_xrealloc(r->md, r->md_cap);
  }
  memcpy(r->md + r->md_len, s, n + 1);
  r->md_len += n;
}

void nl_harness_text(nl_harness *r, const char *fmt, ...)
{
  va_list ap;
  va_start(ap, fmt);
  int n = vsnprintf(NULL, 0, fmt, ap);
  va_end(ap);
  char *buf = nl_xmalloc((size_t)n + 1);
  va_start(ap, fmt);
  vsnprintf(buf, (size_t)n + 1, fmt, ap);
  va_end(ap);
  md_append(r, buf);
  md_append(r, "\n");
  free(buf);
}

/* A number for a report table: `digits` significant digits, unless the value
 * is exactly a number of at most digits + 2 (a paper's 0.99999, a weight
 * 0.00001), which is printed exactly. A sweep's 9.99990000099999e-06 reads
 * 1e-05, a measured 0.058087919778 reads 0.05809. */
static void report_number(char *buf, size_t len, double v, int digits)
{
  /* snprintf's result is tested: a 64-byte buffer holds any %.19g. */
  for (int d = digits; d <= digits + 2; d++)
    if (snprintf(buf, len, "%.*g", d, v) < (int)len && strtod(buf, NULL) == v) return;
  if (snprintf(buf, len, "%.*g", digits, v) >= (int)len) buf[len - 1] = 0;
}

void nl_harness_report_table(nl_harness *r, const nl_table *t, const char *caption, int digits)
{
  char cell[64];
  if (caption) nl_harness_text(r, "*%s*\n", caption);
  /* time columns (nl_harness_time_column) are in times.tsv, not here */
  for (size_t c = 0; c < t->ncols; c++) {
    if (is_time(r, NULL, t->names[c])) continue;
    md_append(r, "| "); md_append(r, t->names[c]); md_append(r, " ");
  }
  md_append(r, "|\n");
  for (size_t c = 0; c < t->ncols; c++) if (!is_time(r, NULL, t->names[c])) md_append(r, "|---");
  md_append(r, "|\n");
  for (size_t row = 0; row < t->nrows; row++) {
    for (size_t c = 0; c < t->ncols; c++) {
      if (is_time(r, NULL, t->names[c])) continue;
      size_t k = row * t->ncols + c;
      /* Text cells that are whole numbers (labels such as a sweep's w1) are
       * rounded like the numbers. */
      const char *s = t->text && t->text[k] ? t->text[k] : cell;
      char *end;
      double v = s == cell ? t->num[k] : strtod(s, &end);
      if (s == cell || (*s && !*end && end != s && isfinite(v))) { report_number(cell, sizeof cell, v, digits); s = cell; }
      md_append(r, "| "); md_append(r, s); md_append(r, " ");
    }
    md_append(r, "|\n");
  }
  md_append(r, "\n");
}

void nl_harness_report_columns(nl_harness *r, const nl_table *t, const char *file, const char *columns,
                               const char *caption, int digits)
{
  char *list = nl_xstrdup(columns), *save = NULL;
  size_t n = 0, idx[256];
  const char *names[256];
  for (char *c = strtok_r(list, ",", &save); c; c = strtok_r(NULL, ",", &save)) {
    long k = nl_table_column(t, c);
    if (k < 0) nl_harness_die(r, 1, "report of %s: no column '%s'", file, c);
    if (is_time(r, file, c)) continue;   /* in times.tsv */
    if (n == 256) nl_harness_die(r, 1, "report of %s: more than 256 columns", file);
    names[n] = t->names[k];
    idx[n++] = (size_t)k;
  }
  nl_table *v = nl_table_alloc(n, names);
  for (size_t row = 0; row < t->nrows; row++) {
    size_t i = nl_table_append_empty(v);
    for (size_t c = 0; c < n; c++) {
      const char *tx = t->text ? t->text[row * t->ncols + idx[c]] : NULL;
      if (tx) nl_table_set_text(v, i, names[c], tx);
      else nl_table_set(v, i, names[c], nl_table_get(t, row, idx[c]));
    }
  }
  nl_harness_report_table(r, v, caption, digits);
  size_t ncols = 0;
  for (size_t c = 0; c < t->ncols; c++) ncols += !is_time(r, file, t->names[c]);
  nl_harness_text(r, "Shown: %zu of the table's %zu columns; all of them in [%s](%s/%s).\n", n, ncols, file, r->name, file);
  nl_table_free(v);
  free(list);
}

void nl_harness_figure(nl_harness *r, const char *file, const char *caption)
{
  list_add(&r->figures, &r->nfigures, file);
  nl_harness_text(r, "![%s](%s/%s)\n\n*%s*\n", caption, r->name, file, caption);
}

/* ---- regression rules ----------------------------------------------------- */

static nl_status rule_number(const char *rule, const char *tok, double lo, double hi, double *v, nl_error *err)
{
  char *end;
  if (!tok) return nl_fail(err, NL_EINVAL, "rule '%s': missing number", rule);
  *v = strtod(tok, &end);
  if (*end || end == tok || !(*v >= lo && *v <= hi))
    return nl_fail(err, NL_EINVAL, "rule '%s': '%s' is not a number in [%g, %g]", rule, tok, lo, hi);
  return NL_OK;
}

nl_status nl_harness_rule_parse(const char *s, nl_harness_rule *rule, nl_error *err)
{
  char buf[256], *save = NULL;
  if (strlen(s) >= sizeof buf) return nl_fail(err, NL_EINVAL, "rule '%.40s...': too long", s);
  strcpy(buf, s);
  const char *kind = strtok_r(buf, " ", &save);
  memset(rule, 0, sizeof *rule);
  nl_status st = NL_OK;
  if (!kind) return nl_fail(err, NL_EINVAL, "empty rule");
  if (!strcmp(kind, "exact")) rule->kind = NL_CHECK_EXACT;
  else if (!strcmp(kind, "ignore")) rule->kind = NL_CHECK_IGNORE;
  else if (!strcmp(kind, "abs") || !strcmp(kind, "rel")) {
    rule->kind = kind[0] == 'a' ? NL_CHECK_ABS : NL_CHECK_REL;
    st = rule_number(s, strtok_r(NULL, " ", &save), 0, 1e300, &rule->tol, err);
  } else if (!strcmp(kind, "welch")) {
    const char *col = strtok_r(NULL, " ", &save);
    if (!col || strlen(col) >= sizeof rule->sdcol) return nl_fail(err, NL_EINVAL, "rule '%s': welch needs SDCOL ALPHA", s);
    strcpy(rule->sdcol, col);
    rule->kind = NL_CHECK_WELCH;
    st = rule_number(s, strtok_r(NULL, " ", &save), 1e-300, 0.5, &rule->tol, err);
  } else if (!strcmp(kind, "ftest")) {
    rule->kind = NL_CHECK_FTEST;
    st = rule_number(s, strtok_r(NULL, " ", &save), 1e-300, 0.5, &rule->tol, err);
  } else return nl_fail(err, NL_EINVAL, "rule '%s': unknown (exact, abs, rel, ignore, welch, ftest)", s);
  if (st == NL_OK && strtok_r(NULL, " ", &save)) return nl_fail(err, NL_EINVAL, "rule '%s': extra words", s);
  return st;
}

void nl_harness_check(nl_harness *r, const char *table, const char *column, const char *rule)
{
  nl_harness_rule parsed;
  nl_error err;
  if (nl_harness_rule_parse(rule, &parsed, &err)) nl_harness_die(r, 1, "%s: %s: %s", table, column, err.msg);
  if (is_time(r, table, column)) return;   /* not in the table written */
  nl_table *c = r->checks;
  for (size_t i = 0; i < c->nrows; i++) {
    char **row = c->text + i * c->ncols;
    if (!strcmp(row[0], table) && !strcmp(row[1], column)) {   /* the later rule wins */
      free(row[2]);
      row[2] = nl_xstrdup(rule);
      return;
    }
  }
  nl_table_append(c, "sss", table, column, rule);
}

const char *nl_harness_check_rule(const nl_harness *r, const char *table, const char *column)
{
  const char *star = NULL;
  for (size_t i = 0; i < r->checks->nrows; i++) {
    char **row = r->checks->text + i * r->checks->ncols;
    if (strcmp(row[0], table)) continue;
    if (!strcmp(row[1], column)) return row[2];
    if (!strcmp(row[1], "*")) star = row[2];
  }
  return star;
}

/* ---- verdicts ------------------------------------------------------------ */

/* One row of verdicts.tsv, every cell as text (numbers in the table's own
 * round-trip format; sd "-" when there is none). The kind caps the outcome
 * (nl_harness_verdict_word). */
static void verdict_row(nl_harness *r, const char *quantity, const char *source, const char *paper,
                        const char *ours, const char *sd, const char *rule, const char *kind,
                        nl_harness_outcome v, const char *reason)
{
  nl_error err;
  if (nl_harness_verdict_kind_check(kind, &err)) nl_harness_die(r, 1, "verdict '%s': %s", quantity, err.msg);
  if (!r->verdicts) {
    const char *vcols[] = {"quantity", "source", "paper",  "ours",    "ours_sd",      "rule",
                           "kind",     "verdict", "reason", "control", "control_ours", "control_verdict"};
    r->verdicts = nl_table_alloc(12, vcols);
  }
  nl_table_append(r->verdicts, "ssssssssssss", quantity, source, paper, ours, sd ? sd : "-", rule, kind,
                  nl_harness_verdict_word(v, kind), reason, "-", "-", "-");
  r->last.type = LAST_NONE;   /* the caller says what it was */
  r->last.has_control = 0;
}

/* Remembers the columns the verdict just declared read, for its control. */
static void remember(nl_harness *r, int type, const char *rule, double paper, const char *col,
                     const char *sd_col, const char *n_col, double alpha)
{
  r->last.type = type;
  snprintf(r->last.rule, sizeof r->last.rule, "%s", rule);
  snprintf(r->last.col, sizeof r->last.col, "%s", col);
  snprintf(r->last.sd_col, sizeof r->last.sd_col, "%s", sd_col ? sd_col : "");
  snprintf(r->last.n_col, sizeof r->last.n_col, "%s", n_col ? n_col : "");
  r->last.paper = paper;
  r->last.alpha = alpha;
}

static void append_note(char *reason, size_t len, const char *note)
{
  if (note && *note) {
    size_t n = strlen(reason);
    snprintf(reason + n, len - n, "; %s", note);
  }
}

static void need_columns(nl_harness *r, const char *quantity, const char *file, const nl_table *t,
                         const char *const *cols, int n)
{
  for (int k = 0; k < n; k++)
    if (cols[k] && nl_table_column(t, cols[k]) < 0)
      nl_harness_die(r, 1, "verdict '%s': %s has no column '%s'", quantity, file, cols[k]);
}

void nl_harness_verdict(nl_harness *r, const char *file, const nl_table *t, size_t row,
                        const char *quantity, const char *paper_col, const char *ours_col,
                        const char *sd_col, const char *rule, const char *kind, const char *note)
{
  if (row >= t->nrows) nl_harness_die(r, 1, "verdict '%s': %s has no row %zu", quantity, file, row + 1);
  const char *cols[] = {paper_col, ours_col, sd_col};
  need_columns(r, quantity, file, t, cols, 3);
  double paper = nl_table_value(t, row, paper_col), ours = nl_table_value(t, row, ours_col);
  double sd = sd_col ? nl_table_value(t, row, sd_col) : NAN;
  nl_harness_outcome v;
  char reason[320], source[256];
  nl_error err;
  if (!strncmp(rule, "p ", 2) || !strncmp(rule, "fit ", 4))
    nl_harness_die(r, 1, "verdict '%s': rule '%s' decides a p-value: use nl_harness_verdict_p", quantity, rule);
  if (nl_harness_verdict_decide(rule, paper, ours, sd, &v, reason, sizeof reason, &err))
    nl_harness_die(r, 1, "verdict '%s': %s", quantity, err.msg);
  append_note(reason, sizeof reason, note);
  char pt[32], ot[32], st[32];
  nl_table_format_double(pt, paper);
  nl_table_format_double(ot, ours);
  if (sd_col) nl_table_format_double(st, sd);
  snprintf(source, sizeof source, "%s:%s", file, ours_col);
  verdict_row(r, quantity, source, pt, ot, sd_col ? st : NULL, rule, kind, v, reason);
  remember(r, LAST_VALUE, rule, paper, ours_col, sd_col, NULL, NAN);
}

void nl_harness_verdict_equiv(nl_harness *r, const char *file, const nl_table *t, size_t row,
                              const char *quantity, const char *paper_col, const char *ours_col,
                              const char *se_col, const char *n_col, const char *rule, const char *kind,
                              const char *note)
{
  if (row >= t->nrows) nl_harness_die(r, 1, "verdict '%s': %s has no row %zu", quantity, file, row + 1);
  const char *cols[] = {paper_col, ours_col, se_col, n_col};
  need_columns(r, quantity, file, t, cols, 4);
  double paper = nl_table_value(t, row, paper_col), ours = nl_table_value(t, row, ours_col);
  double se = nl_table_value(t, row, se_col), df = n_col ? nl_table_value(t, row, n_col) - 1 : 0;
  nl_harness_outcome v;
  char reason[320], source[256], pt[32], ot[32], st[32];
  nl_error err;
  if (nl_harness_verdict_decide_equiv(rule, paper, ours, se, df, &v, reason, sizeof reason, &err))
    nl_harness_die(r, 1, "verdict '%s': %s", quantity, err.msg);
  append_note(reason, sizeof reason, note);
  nl_table_format_double(pt, paper);
  nl_table_format_double(ot, ours);
  nl_table_format_double(st, se);
  snprintf(source, sizeof source, "%s:%s", file, ours_col);
  verdict_row(r, quantity, source, pt, ot, st, rule, kind, v, reason);
  remember(r, LAST_EQUIV, rule, paper, ours_col, se_col, n_col, NAN);
}

void nl_harness_verdict_less(nl_harness *r, const char *file, const nl_table *t, size_t row_a,
                             size_t row_b, const char *quantity, const char *claim,
                             const char *col, const char *sd_col, const char *n_col,
                             double alpha, const char *kind)
{
  if (row_a >= t->nrows || row_b >= t->nrows)
    nl_harness_die(r, 1, "verdict '%s': %s has %zu rows", quantity, file, t->nrows);
  const char *cols[] = {col, sd_col, n_col};
  need_columns(r, quantity, file, t, cols, 3);
  double a = nl_table_value(t, row_a, col), b = nl_table_value(t, row_b, col);
  double sa = nl_table_value(t, row_a, sd_col), sb = nl_table_value(t, row_b, sd_col);
  double na = nl_table_value(t, row_a, n_col), nb = nl_table_value(t, row_b, n_col), p = NAN;
  nl_error err;
  if (nl_stats_welch_p(a, sa, (size_t)na, b, sb, (size_t)nb, &p, &err)) p = a == b ? 1 : 0;   /* both sds 0 */
  nl_harness_outcome v = !(a < b) ? NL_VERDICT_NOT : p < alpha ? NL_VERDICT_REPRODUCED : NL_VERDICT_PARTLY;
  char ours[128], reason[256], rule[64], source[256];
  snprintf(ours, sizeof ours, "%.4g +- %.2g vs %.4g +- %.2g", a, sa, b, sb);
  snprintf(reason, sizeof reason, "%s; Welch p = %.2g (%g vs %g seeds)",
           a < b ? "lower" : "not lower", p, na, nb);
  snprintf(rule, sizeof rule, "less welch %g", alpha);
  snprintf(source, sizeof source, "%s:%s", file, col);
  verdict_row(r, quantity, source, claim, ours, NULL, rule, kind, v, reason);
  remember(r, LAST_LESS, rule, NAN, col, sd_col, n_col, alpha);
}

void nl_harness_verdict_p(nl_harness *r, const char *file, const nl_table *t, size_t row,
                          const char *quantity, const char *claim, const char *stat_col,
                          const char *p_col, const char *rule, const char *kind, const char *note)
{
  if (row >= t->nrows) nl_harness_die(r, 1, "verdict '%s': %s has no row %zu", quantity, file, row + 1);
  const char *cols[] = {stat_col, p_col};
  need_columns(r, quantity, file, t, cols, 2);
  if (strncmp(rule, "p ", 2) && strncmp(rule, "fit ", 4))
    nl_harness_die(r, 1, "verdict '%s': rule '%s': wanted 'p A B' or 'fit A B'", quantity, rule);
  double stat = nl_table_value(t, row, stat_col), p = nl_table_value(t, row, p_col);
  nl_harness_outcome v;
  char reason[320], source[256], ours[96];
  nl_error err;
  if (nl_harness_verdict_decide(rule, NAN, p, NAN, &v, reason, sizeof reason, &err))
    nl_harness_die(r, 1, "verdict '%s': %s", quantity, err.msg);
  append_note(reason, sizeof reason, note);
  snprintf(ours, sizeof ours, "%s %.4g, p = %.2g", stat_col, stat, p);
  snprintf(source, sizeof source, "%s:%s", file, p_col);
  verdict_row(r, quantity, source, claim, ours, NULL, rule, kind, v, reason);
  remember(r, LAST_P, rule, NAN, p_col, stat_col, NULL, NAN);
}

void nl_harness_verdict_figure(nl_harness *r, const char *quantity, const char *claim,
                               const char *figure, const char *note)
{
  /* the kind and the verdict ("see figure") already say no number decides */
  char reason[320] = "";
  snprintf(reason, sizeof reason, "%s", note && *note ? note : "the figure decides");
  verdict_row(r, quantity, figure, claim, figure, NULL, "-", "qualitative", NL_VERDICT_NOT, reason);
}

/* Writes the control's cells on the last verdict row; an independent row
 * whose control passes is no evidence (nl_harness.h). */
static void control_row(nl_harness *r, const char *control, const char *ours, nl_harness_outcome v,
                        const char *why)
{
  size_t i = r->verdicts->nrows - 1;
  const char *word = nl_harness_verdict_word(v, "independent");
  nl_table_set_text(r->verdicts, i, "control", control);
  nl_table_set_text(r->verdicts, i, "control_ours", ours);
  nl_table_set_text(r->verdicts, i, "control_verdict", word);
  r->last.has_control = 1;
  /* Only a row that passes (reproduced or partly) is turned: a row that
   * fails where its baseline passes already says "not reproduced". */
  const char *own = nl_table_text(r->verdicts, i, "verdict");
  if (v == NL_VERDICT_REPRODUCED && !strcmp(nl_table_text(r->verdicts, i, "kind"), "independent") &&
      (!strcmp(own, "reproduced") || !strcmp(own, "partly"))) {
    char reason[512];
    snprintf(reason, sizeof reason, "%s; its control (%s) passes the same rule: %s",
             nl_table_text(r->verdicts, i, "reason"), control, why);
    nl_table_set_text(r->verdicts, i, "kind", "by construction");
    nl_table_set_text(r->verdicts, i, "verdict", nl_harness_verdict_word(v, "by construction"));
    nl_table_set_text(r->verdicts, i, "reason", reason);
  }
}

static void control_start(nl_harness *r, const char *control, const char *file, const nl_table *t,
                          size_t row)
{
  const char *q = r->verdicts && r->verdicts->nrows ? nl_table_text(r->verdicts, r->verdicts->nrows - 1, "quantity") : "";
  if (r->last.type == LAST_NONE || r->last.has_control)
    nl_harness_die(r, 1, "control '%s': no verdict declared just before it (or it has one)", control);
  if (row >= t->nrows) nl_harness_die(r, 1, "control '%s' of '%s': %s has no row %zu", control, q, file, row + 1);
  const char *cols[] = {r->last.col, r->last.sd_col[0] ? r->last.sd_col : NULL,
                        r->last.n_col[0] ? r->last.n_col : NULL};
  need_columns(r, q, file, t, cols, 3);
}

void nl_harness_verdict_control(nl_harness *r, const char *control, const char *file, const nl_table *t,
                                size_t row)
{
  control_start(r, control, file, t, row);
  if (r->last.type == LAST_LESS)
    nl_harness_die(r, 1, "control '%s': the verdict compares two rows: nl_harness_verdict_control_less", control);
  double x = nl_table_value(t, row, r->last.col);
  double sd = r->last.sd_col[0] ? nl_table_value(t, row, r->last.sd_col) : NAN;
  nl_harness_outcome v;
  char reason[320], ours[192];
  nl_error err;
  nl_status st;
  if (r->last.type == LAST_P) {
    st = nl_harness_verdict_decide(r->last.rule, NAN, x, NAN, &v, reason, sizeof reason, &err);
    snprintf(ours, sizeof ours, "%s %.4g, p = %.2g", r->last.sd_col, sd, x);
  } else if (r->last.type == LAST_EQUIV) {
    double df = r->last.n_col[0] ? nl_table_value(t, row, r->last.n_col) - 1 : 0;
    st = nl_harness_verdict_decide_equiv(r->last.rule, r->last.paper, x, sd, df, &v, reason, sizeof reason, &err);
    snprintf(ours, sizeof ours, "%.4g +- %.2g", x, sd);
  } else {
    if (!strncmp(r->last.rule, "factor ", 7) && !(x > 0)) {
      st = NL_OK;   /* a ratio's rule cannot hold for a value <= 0 */
      v = NL_VERDICT_NOT;
      snprintf(reason, sizeof reason, "%g is not a positive value", x);
    } else {
      st = nl_harness_verdict_decide(r->last.rule, r->last.paper, x, sd, &v, reason, sizeof reason, &err);
    }
    nl_table_format_double(ours, x);
  }
  if (st) nl_harness_die(r, 1, "control '%s': %s", control, err.msg);
  control_row(r, control, ours, v, reason);
  (void)file;
}

void nl_harness_verdict_control_less(nl_harness *r, const char *control, const char *file,
                                     const nl_table *t, size_t row_a, size_t row_b)
{
  control_start(r, control, file, t, row_a);
  if (r->last.type != LAST_LESS)
    nl_harness_die(r, 1, "control '%s': the verdict is not a comparison of two rows", control);
  if (row_b >= t->nrows) nl_harness_die(r, 1, "control '%s': %s has no row %zu", control, file, row_b + 1);
  const char *col = r->last.col, *sd_col = r->last.sd_col, *n_col = r->last.n_col;
  double a = nl_table_value(t, row_a, col), b = nl_table_value(t, row_b, col);
  double sa = nl_table_value(t, row_a, sd_col), sb = nl_table_value(t, row_b, sd_col);
  double na = nl_table_value(t, row_a, n_col), nb = nl_table_value(t, row_b, n_col), p = NAN;
  nl_error err;
  if (nl_stats_welch_p(a, sa, (size_t)na, b, sb, (size_t)nb, &p, &err)) p = a == b ? 1 : 0;
  nl_harness_outcome v = !(a < b) ? NL_VERDICT_NOT : p < r->last.alpha ? NL_VERDICT_REPRODUCED : NL_VERDICT_PARTLY;
  char ours[128], reason[128];
  snprintf(ours, sizeof ours, "%.4g +- %.2g vs %.4g +- %.2g", a, sa, b, sb);
  snprintf(reason, sizeof reason, "%s; Welch p = %.2g", a < b ? "lower" : "not lower", p);
  control_row(r, control, ours, v, reason);
}

void nl_harness_verdict_rows(nl_harness *r, const char *file, const nl_table *t, const char *what,
                             const char *label_col, const char *paper_col, const char *ours_col,
                             const char *sd_col, const char *rule, const char *kind,
                             const char *note)
{
  long lc = nl_table_column(t, label_col);
  if (lc < 0) nl_harness_die(r, 1, "verdict '%s': %s has no column '%s'", what, file, label_col);
  for (size_t i = 0; i < t->nrows; i++) {
    char buf[32], q[256];
    snprintf(q, sizeof q, "%s, %s %s", what, label_col, nl_table_cell_text(t, i, (size_t)lc, buf));
    nl_harness_verdict(r, file, t, i, q, paper_col, ours_col, sd_col, rule, kind, note);
  }
}

/* ---- the end ------------------------------------------------------------ */

static void write_text(nl_harness *r, const char *file, const char *text)
{
  char *p = nl_harness_path(r, file);
  nl_atomic_file af;
  nl_error err;
  if (nl_atomic_open(&af, p, &err)) nl_harness_die(r, 1, "%s", err.msg);
  fputs(text, af.fp);
  if (nl_atomic_commit(&af, &err)) nl_harness_die(r, 1, "%s", err.msg);
  free(p);
}

/* ---- where the run was made --------------------------------------------- */

/* /proc/cpuinfo's first "model name" (x86) or "Model"/"cpu model", else "unknown". */
static void cpu_model(char *buf, size_t n)
{
  snprintf(buf, n, "unknown");
  FILE *fp = fopen("/proc/cpuinfo", "r");
  if (!fp) return;
  char line[512];
  while (fgets(line, sizeof line, fp)) {
    char *colon = strchr(line, ':');
    if (!colon) continue;
    if (strncmp(line, "model name", 10) && strncmp(line, "Model", 5) && strncmp(line, "cpu model", 9)) continue;
    char *v = colon + 1;
    while (*v == ' ' || *v == '\t') v++;
    v[strcspn(v, "\r\n")] = '\0';
    if (*v) { snprintf(buf, n, "%s", v); break; }
  }
  fclose(fp);
}

/* glibc's libm picks its exp, log, pow, sin, atan... among FMA, FMA4, AVX and
 * SSE2 versions by the CPU features glibc takes as usable (the ifunc
 * selectors of sysdeps/x86_64/fpu/multiarch), and
 * GLIBC_TUNABLES=glibc.cpu.hwcaps=-AVX2,-FMA can turn features off: so the
 * variant is named from glibc's view of the features, not from cpuid, and a
 * feature the CPU has but glibc does not use is said. Their last bits differ.
 * On aarch64 glibc's libm is its own code (sysdeps/aarch64/fpu and the
 * generic functions), the same on every CPU: named "aarch64". */
static void libm_variant(char *buf, size_t n)
{
#ifdef __GLIBC__
  const char *variant = "", *off = "";
#ifdef NL_HAVE_X86_FEATURES
  int fma = CPU_FEATURE_ACTIVE(FMA) && CPU_FEATURE_ACTIVE(AVX2);
  if (fma) variant = " fma";
  else if (CPU_FEATURE_ACTIVE(FMA4)) variant = " fma4";
  else if (CPU_FEATURE_ACTIVE(AVX)) variant = " avx";
  else variant = " sse2";
  if (!fma && CPU_FEATURE_PRESENT(FMA) && CPU_FEATURE_PRESENT(AVX2))
    off = " (CPU's fma turned off)";
#elif defined(__aarch64__)
  variant = " aarch64";   /* one code path on every arm64 CPU: no per-CPU variants */
#endif
  snprintf(buf, n, "glibc %s%s%s", gnu_get_libc_version(), variant, off);
#else
  snprintf(buf, n, "unknown");
#endif
}

/* Where the run was made: CPU, architecture, libm variant and the BLAS the
 * process runs with, what moves a value's last bits across machines (the
 * regression check names them on drift). OpenBLAS's own functions are looked
 * up at run time (dlsym), so the library builds and runs without OpenBLAS. */
static void note_platform(nl_harness *r)
{
  char buf[512];
  cpu_model(buf, sizeof buf);
  note(r, "cpu", buf);
  struct utsname u;
  note(r, "arch", uname(&u) == 0 ? u.machine : "unknown");
  libm_variant(buf, sizeof buf);
  note(r, "libm", buf);
  void *sym = dlsym(RTLD_DEFAULT, "openblas_get_config");
  if (!sym) sym = dlsym(RTLD_DEFAULT, "cblas_dgemm");
  Dl_info info;
  const char *lib = sym && dladdr(sym, &info) && info.dli_fname ? info.dli_fname : "unknown";
  char *(*corename)(void) = (char *(*)(void))dlsym(RTLD_DEFAULT, "openblas_get_corename");
  char *(*config)(void) = (char *(*)(void))dlsym(RTLD_DEFAULT, "openblas_get_config");
  int threads = nl_parallel_blas_threads();
  if (config) {
    nl_harness_note(r, "blas", "OpenBLAS (%s)", lib);
    const char *core = corename ? corename() : NULL, *cfg = config();
    note(r, "blas_core", core && *core ? core : "unknown");
    note(r, "blas_config", cfg && *cfg ? cfg : "unknown");
    if (threads >= 0) nl_harness_note(r, "blas_threads", "%d", threads);
    else note(r, "blas_threads", "unknown");
  } else {
    nl_harness_note(r, "blas", "%s", lib);
    note(r, "blas_core", "none");
    note(r, "blas_config", "none");
    note(r, "blas_threads", "1");
  }
}

/* When and how long the run took, in run.tsv beside the manifest: the
 * manifest identifies the run and is committed with the results, so that a
 * rerun of the same commit writes it byte for byte; these values differ on
 * every run and go to a file that is not tracked (.gitignore) and not an
 * "output" (the regression check would count it as a table the reference
 * lacks). Written through nl_table_write, i.e. by rename: the entry script
 * stages a run in hard links of the previous folder. */
static void run_times_write(nl_harness *r)
{
  const char *cols[] = {"key", "value"};
  nl_table *t = nl_table_alloc(2, cols);
  char buf[128];
  nl_table_append(t, "ss", "started", r->started);
  snprintf(buf, sizeof buf, "%.3f", nl_time_now() - r->t0);
  nl_table_append(t, "ss", "seconds", buf);
  struct rusage ru;
  getrusage(RUSAGE_SELF, &ru);
  /* CPU time of all threads (user + sys, the process start included): with
   * `seconds` it says how well a run used the cores. */
  double user = ru.ru_utime.tv_sec + ru.ru_utime.tv_usec * 1e-6;
  double sys = ru.ru_stime.tv_sec + ru.ru_stime.tv_usec * 1e-6;
  snprintf(buf, sizeof buf, "%.3f (user %.3f + sys %.3f)", user + sys, user, sys);
  nl_table_append(t, "ss", "cpu_seconds", buf);
  snprintf(buf, sizeof buf, "%.1f", ru.ru_maxrss / 1024.0);
  nl_table_append(t, "ss", "peak_rss_mb", buf);
  if (r->merge) {   /* the shards this run merged: their CPU (sum) and largest peak */
    snprintf(buf, sizeof buf, "%.3f", r->shards_cpu);
    nl_table_append(t, "ss", "shards_cpu_seconds", buf);
    snprintf(buf, sizeof buf, "%.1f", r->shards_rss);
    nl_table_append(t, "ss", "shards_peak_rss_mb", buf);
  }
  char *p = nl_path_join(r->out, "run.tsv");
  nl_error err;
  nl_status st = nl_table_write(t, p, &err);
  nl_table_free(t);
  free(p);
  if (st) nl_harness_die(r, 1, "%s", err.msg);
  if (r->times) {   /* the time columns of the tables, likewise */
    p = nl_path_join(r->out, "times.tsv");
    st = nl_table_write(r->times, p, &err);
    free(p);
    if (st) nl_harness_die(r, 1, "%s", err.msg);
  }
}

int nl_harness_end(nl_harness *r)
{
  if (r->line_open) {   /* a progress bar that stopped short of 100% */
    fputc('\n', stderr);
    r->line_open = 0;
  }
  write_text(r, "report.md", r->md ? r->md : "");
  const char *commit = getenv("NL_COMMIT");
  note(r, "commit", commit && *commit ? commit : "unknown");
  nl_harness_note(r, "gsl", "%s", GSL_VERSION);
  nl_harness_note(r, "openimageio", "%s", nl_image_library_version());
  nl_harness_note(r, "compiler", "%s", NL_COMPILER);
  note(r, "cflags", NL_BUILD_CFLAGS);
  note_platform(r);
  run_times_write(r);
  if (r->verdicts) {
    nl_harness_write_table(r, r->verdicts, "verdicts.tsv");
    nl_harness_check(r, "verdicts.tsv", "*", "ignore");   /* copies of compared values */
  }
  /* Always written: an experiment without declarations is all `exact`. */
  nl_harness_write_table(r, r->checks, "checks.tsv");
  outputs_settle(r);
  nl_harness_write_table(r, r->manifest, manifest_name());
  char *pending = nl_path_join(r->out, OUTPUTS_PENDING);
  if (unlink(pending) && errno != ENOENT)
    nl_harness_die(r, 1, "%s: cannot remove: %s", pending, strerror(errno));
  free(pending);
  shards_remove(r);
  units_clear(r);
  free(r->shard_dir);
  for (size_t i = 0; i < r->noutputs; i++) free(r->outputs[i]);
  for (size_t i = 0; i < r->nfigures; i++) free(r->figures[i]);
  for (size_t i = 0; i < r->nprevious; i++) free(r->previous[i]);
  free(r->outputs); free(r->figures); free(r->previous);
  for (size_t i = 0; i < r->ntime; i++) { free(r->time_file[i]); free(r->time_col[i]); }
  free(r->time_file); free(r->time_col);
  nl_table_free(r->times);
  for (int k = 0; k < r->nset; k++) { free(r->set_key[k]); free(r->set_val[k]); }
  free(r->set_key); free(r->set_val); free(r->set_used); free(r->param);
  nl_table_free(r->manifest);
  nl_table_free(r->checks);
  nl_table_free(r->verdicts);
  free(r->md); free(r->out); free(r);
  return 0;
}

static int by_name(const void *a, const void *b) { return strcmp(*(char *const *)a, *(char *const *)b); }

char **nl_harness_tables(const char *dir, size_t *n, nl_error *err)
{
  DIR *d = opendir(dir);
  *n = 0;
  if (!d) { nl_fail(err, NL_EIO, "%s: cannot open folder: %s", dir, strerror(errno)); return NULL; }
  char **names = nl_xmalloc(sizeof *names);   /* non-NULL even when empty */
  struct dirent *e;
  while ((e = readdir(d))) {
    size_t len = strlen(e->d_name);
    if (e->d_name[0] == '.' || len < 5 || strcmp(e->d_name + len - 4, ".tsv")) continue;
    if (!strcmp(e->d_name, "manifest.tsv") || !strcmp(e->d_name, "checks.tsv") ||
        !strcmp(e->d_name, "run.tsv") || !strcmp(e->d_name, "times.tsv"))
      continue;   /* the run's identity and rules, and its times (not tracked) */
    names = nl_xrealloc(names, (*n + 1) * sizeof *names);
    names[(*n)++] = nl_xstrdup(e->d_name);
  }
  closedir(d);
  if (*n) qsort(names, *n, sizeof *names, by_name);
  return names;
}

/* ---- shards: the units' stored values (nl_harness.h) -------------------- */

struct unit_entry {
  long u;
  char kind;        /* 'v' values, 't' table rows, 'n' a manifest note */
  char *key;
  size_t n, ncols;  /* values: count; table: rows and columns */
  double *v;        /* values; table: cells, row-major (NaN in text cells) */
  char **text;      /* table: ncols names then n * ncols cells (NULL: numeric); note: its value */
};


static struct unit_entry *unit_add(nl_harness *r, long u, char kind, const char *key)
{
  if (r->nue == r->cue) {
    r->cue = r->cue ? 2 * r->cue : 64;
    r->ue = nl_xrealloc(r->ue, r->cue * sizeof *r->ue);
  }
  struct unit_entry *e = &r->ue[r->nue++];
  memset(e, 0, sizeof *e);
  e->u = u;
  e->kind = kind;
  e->key = nl_xstrdup(key);
  return e;
}

static void units_clear(nl_harness *r)
{
  for (size_t i = 0; i < r->nue; i++) {
    struct unit_entry *e = &r->ue[i];
    size_t nt = e->kind == 't' ? e->ncols + e->n * e->ncols : e->kind == 'n' ? 1 : 0;
    for (size_t k = 0; k < nt; k++) free(e->text[k]);
    free(e->text); free(e->v); free(e->key);
  }
  free(r->ue);
  r->ue = NULL;
  r->nue = r->cue = 0;
}

/* A writer ran: with --shard or --merge the experiment must have declared
 * its units, and a shard writes nothing but its shard file. */
static void units_refuse(nl_harness *r)
{
  const char *opt = r->merge ? "--merge" : r->shard_n ? "--shard" : "--units";
  if (!r->merge && !r->shard_n && !r->units_query) return;
  if (r->nunits < 0)
    nl_harness_die(r, 2, "%s: %s declares no units to shard; run it whole", opt, r->name);
  if (r->shard_n) nl_harness_die(r, 1, "--shard: a write before nl_harness_units_done (a bug)");
}

static int unit_note(nl_harness *r, const char *key, const char *value)
{
  if (r->unit_cur < 0) return 0;
  struct unit_entry *e = unit_add(r, r->unit_cur, 'n', key);
  e->text = nl_xmalloc(sizeof *e->text);
  e->text[0] = nl_xstrdup(value);
  return 1;
}

long nl_harness_units_weighted(nl_harness *r, long n, const double *cost)
{
  if (!r->params_checked) nl_harness_params_done(r);
  if (n < 0 || r->nunits >= 0) nl_harness_die(r, 1, "nl_harness_units: called twice or with n < 0 (a bug)");
  r->nunits = n;
  if (r->units_query) {   /* --units: one line a unit, its cost, for a scheduler; nothing run or written */
    for (long u = 0; u < n; u++) printf("%g\n", cost ? cost[u] : 1.0);
    exit(0);
  }
  return n;
}

long nl_harness_units(nl_harness *r, long n) { return nl_harness_units_weighted(r, n, NULL); }

int nl_harness_shard_mode(const nl_harness *r) { return r->merge ? 2 : r->shard_n ? 1 : 0; }

int nl_harness_unit_mine(const nl_harness *r, long u)
{
  if (r->merge) return 0;
  if (!r->shard_n) return 1;
  return u % r->shard_n == r->shard_k - 1;
}

void nl_harness_unit_begin(nl_harness *r, long u)
{
  if (r->nunits < 0 || u < 0 || u >= r->nunits || r->unit_cur >= 0 || !nl_harness_unit_mine(r, u))
    nl_harness_die(r, 1, "nl_harness_unit_begin(%ld): not a unit of this run (a bug)", u);
  r->unit_cur = u;
}

void nl_harness_unit_end(nl_harness *r) { r->unit_cur = -1; }

void nl_harness_unit_put(nl_harness *r, const char *key, const double *v, size_t n)
{
  if (r->unit_cur < 0) nl_harness_die(r, 1, "nl_harness_unit_put(%s): outside a unit (a bug)", key);
  struct unit_entry *e = unit_add(r, r->unit_cur, 'v', key);
  e->n = n;
  e->v = nl_xmalloc((n ? n : 1) * sizeof *e->v);
  if (n) memcpy(e->v, v, n * sizeof *v);
}

void nl_harness_unit_put_table(nl_harness *r, const char *key, const nl_table *t)
{
  if (r->unit_cur < 0) nl_harness_die(r, 1, "nl_harness_unit_put_table(%s): outside a unit (a bug)", key);
  struct unit_entry *e = unit_add(r, r->unit_cur, 't', key);
  e->n = t->nrows;
  e->ncols = t->ncols;
  e->v = nl_xmalloc((t->nrows * t->ncols + 1) * sizeof *e->v);
  e->text = nl_xcalloc(t->ncols + t->nrows * t->ncols + 1, sizeof *e->text);
  for (size_t c = 0; c < t->ncols; c++) e->text[c] = nl_xstrdup(t->names[c]);
  for (size_t i = 0; i < t->nrows * t->ncols; i++) {
    e->v[i] = t->num[i];
    if (t->text[i]) e->text[t->ncols + i] = nl_xstrdup(t->text[i]);
  }
}

static const struct unit_entry *unit_find(nl_harness *r, long u, char kind, const char *key)
{
  for (size_t i = 0; i < r->nue; i++)
    if (r->ue[i].u == u && r->ue[i].kind == kind && !strcmp(r->ue[i].key, key)) return &r->ue[i];
  nl_harness_die(r, 1, "unit %ld stored no %s '%s' (a bug in the experiment)", u,
                 kind == 'v' ? "values" : "table", key);
}

const double *nl_harness_unit_get(nl_harness *r, long u, const char *key, size_t *n)
{
  const struct unit_entry *e = unit_find(r, u, 'v', key);
  if (n) *n = e->n;
  return e->v;
}

void nl_harness_unit_get_rows(nl_harness *r, long u, const char *key, nl_table *t)
{
  const struct unit_entry *e = unit_find(r, u, 't', key);
  if (e->ncols != t->ncols)
    nl_harness_die(r, 1, "unit %ld table '%s': %zu columns, not %zu (a bug)", u, key, e->ncols, t->ncols);
  for (size_t c = 0; c < t->ncols; c++)
    if (strcmp(e->text[c], t->names[c]))
      nl_harness_die(r, 1, "unit %ld table '%s': column %s, not %s (a bug)", u, key, e->text[c], t->names[c]);
  for (size_t i = 0; i < e->n; i++) {
    size_t q = nl_table_append_empty(t);
    for (size_t c = 0; c < t->ncols; c++) {
      const char *s = e->text[e->ncols + i * e->ncols + c];
      if (s) nl_table_set_text(t, q, t->names[c], s);
      else t->num[q * t->ncols + c] = e->v[i * e->ncols + c];
    }
  }
}

void nl_harness_unit_notes(nl_harness *r, long u)
{
  for (size_t i = 0; i < r->nue; i++)
    if (r->ue[i].u == u && r->ue[i].kind == 'n') nl_table_append(r->manifest, "ss", r->ue[i].key, r->ue[i].text[0]);
}

/* Text in a shard file: tab, newline and backslash escaped. */
static void put_text(FILE *fp, const char *s)
{
  for (; *s; s++) {
    if (*s == '\t') fputs("\\t", fp);
    else if (*s == '\n') fputs("\\n", fp);
    else if (*s == '\\') fputs("\\\\", fp);
    else fputc(*s, fp);
  }
}

static char *get_text(const char *s)
{
  char *o = nl_xmalloc(strlen(s) + 1), *p = o;
  for (; *s; s++) {
    if (*s == '\\' && s[1]) {
      s++;
      *p++ = *s == 't' ? '\t' : *s == 'n' ? '\n' : *s;
    } else *p++ = *s;
  }
  *p = '\0';
  return o;
}

/* What every shard of one run shares: the experiment, its seeds, scale,
 * parameters and unit count; a shard made otherwise is not merged. */
static char *shard_settings(const nl_harness *r)
{
  size_t cap = 256, len = 0;
  char *s = nl_xmalloc(cap);
  const char *commit = getenv("NL_COMMIT");   /* a shard of other code is another run */
  len = (size_t)snprintf(s, cap, "%s; units %ld; commit %s", r->name, r->nunits,
                         commit && *commit ? commit : "unknown");
  for (size_t i = 0; i < r->manifest->nrows; i++) {
    const char *k = r->manifest->text[i * 2], *v = r->manifest->text[i * 2 + 1];
    if (strcmp(k, "seed") && strcmp(k, "seeds") && strcmp(k, "quick") && strcmp(k, "param")) continue;
    size_t need = len + strlen(k) + strlen(v) + 4;
    if (need > cap) { cap = 2 * need; s = nl_xrealloc(s, cap); }
    len += (size_t)snprintf(s + len, cap - len, "; %s %s", k, v);
  }
  return s;
}

static char *shard_path(const nl_harness *r, int k, int n)
{
  char name[64];
  snprintf(name, sizeof name, "%d-of-%d.tsv", k, n);
  return nl_path_join(r->shard_dir, name);
}

static void shard_write(nl_harness *r)
{
  nl_error err;
  char *path = shard_path(r, r->shard_k, r->shard_n);
  if (nl_mkdir_p(r->shard_dir, &err)) nl_harness_die(r, 1, "%s", err.msg);
  nl_atomic_file af;
  if (nl_atomic_open(&af, path, &err)) nl_harness_die(r, 1, "%s", err.msg);
  char *set = shard_settings(r);
  fprintf(af.fp, "# noiselab shard %d of %d\t", r->shard_k, r->shard_n);
  put_text(af.fp, set);
  fputc('\n', af.fp);
  free(set);
  { /* what this shard cost, for the merge's run.tsv (CPU-hours of a sharded run) */
    struct rusage ru;
    getrusage(RUSAGE_SELF, &ru);
    fprintf(af.fp, "#cost\t%.3f\t%.1f\n",
            ru.ru_utime.tv_sec + ru.ru_utime.tv_usec * 1e-6 + ru.ru_stime.tv_sec + ru.ru_stime.tv_usec * 1e-6,
            ru.ru_maxrss / 1024.0);
  }
  for (size_t i = 0; i < r->nue; i++) {
    const struct unit_entry *e = &r->ue[i];
    fprintf(af.fp, "%ld\t%c\t", e->u, e->kind);
    put_text(af.fp, e->key);
    if (e->kind == 'n') {
      fputc('\t', af.fp);
      put_text(af.fp, e->text[0]);
    } else if (e->kind == 'v') {
      fprintf(af.fp, "\t%zu", e->n);
      for (size_t k = 0; k < e->n; k++) fprintf(af.fp, "\t%a", e->v[k]);
    } else {
      fprintf(af.fp, "\t%zu\t%zu", e->n, e->ncols);
      for (size_t c = 0; c < e->ncols; c++) { fputc('\t', af.fp); put_text(af.fp, e->text[c]); }
      for (size_t k = 0; k < e->n * e->ncols; k++) {
        const char *s = e->text[e->ncols + k];
        fputc('\t', af.fp);
        if (s) { fputc('=', af.fp); put_text(af.fp, s); }
        else fprintf(af.fp, "#%a", e->v[k]);
      }
    }
    fputc('\n', af.fp);
  }
  if (nl_atomic_commit(&af, &err)) nl_harness_die(r, 1, "%s", err.msg);
  free(path);
}

/* Splits line (modified) at tabs into at most max fields; returns the count. */
static size_t split_tabs(char *line, char **f, size_t max)
{
  size_t n = 0;
  for (char *p = line; n < max;) {
    f[n++] = p;
    p = strchr(p, '\t');
    if (!p) break;
    *p++ = '\0';
  }
  return n;
}

static void shard_read(nl_harness *r, const char *path, int k, int n, const char *set)
{
  FILE *fp = fopen(path, "r");
  if (!fp) nl_harness_die(r, 2, "--merge: shard %d of %d missing (%s)", k, n, path);
  char *line = NULL, **f = NULL;
  size_t cap = 0, fcap = 0, lineno = 0;
  ssize_t len;
  while ((len = getline(&line, &cap, fp)) > 0) {
    lineno++;
    if (line[len - 1] == '\n') line[--len] = '\0';
    size_t nf = 1;
    for (char *p = line; *p; p++) nf += *p == '\t';
    if (nf > fcap) { fcap = nf; f = nl_xrealloc(f, fcap * sizeof *f); }
    nf = split_tabs(line, f, nf);
    if (lineno == 1) {
      char *s = nf == 2 ? get_text(f[1]) : NULL;
      int ok = s && !strcmp(s, set);
      free(s);
      if (!ok) nl_harness_die(r, 2, "--merge: %s was made by another run (other settings or units)", path);
      continue;
    }
    if (!strcmp(f[0], "#cost") && nf == 3) {
      double rss = strtod(f[2], NULL);
      r->shards_cpu += strtod(f[1], NULL);
      if (rss > r->shards_rss) r->shards_rss = rss;
      continue;
    }
    char *end;
    long u = nf >= 3 ? strtol(f[0], &end, 10) : -1;
    if (nf < 3 || u < 0 || u >= r->nunits || strlen(f[1]) != 1 || u % n != k - 1)
      nl_harness_die(r, 2, "--merge: %s:%zu: not a line of this shard", path, lineno);
    char *key = get_text(f[2]);
    struct unit_entry *e = unit_add(r, u, f[1][0], key);
    free(key);
    int bad = 0;
    if (e->kind == 'n') {
      e->text = nl_xmalloc(sizeof *e->text);
      e->text[0] = get_text(nf > 3 ? f[3] : "");
    } else if (e->kind == 'v') {
      e->n = nf > 3 ? strtoul(f[3], NULL, 10) : 0;
      bad = nf != 4 + e->n;
      e->v = nl_xmalloc((e->n + 1) * sizeof *e->v);
      for (size_t q = 0; !bad && q < e->n; q++) e->v[q] = strtod(f[4 + q], NULL);
    } else if (e->kind == 't') {
      e->n = nf > 4 ? strtoul(f[3], NULL, 10) : 0;
      e->ncols = nf > 4 ? strtoul(f[4], NULL, 10) : 0;
      bad = nf != 5 + e->ncols + e->n * e->ncols;
      e->v = nl_xmalloc((e->n * e->ncols + 1) * sizeof *e->v);
      e->text = nl_xcalloc(e->ncols + e->n * e->ncols + 1, sizeof *e->text);
      for (size_t c = 0; !bad && c < e->ncols; c++) e->text[c] = get_text(f[5 + c]);
      for (size_t q = 0; !bad && q < e->n * e->ncols; q++) {
        const char *s = f[5 + e->ncols + q];
        if (*s == '=') { e->text[e->ncols + q] = get_text(s + 1); e->v[q] = NAN; }
        else if (*s == '#') e->v[q] = strtod(s + 1, NULL);
        else bad = 1;
      }
      if (bad) { e->n = 0; e->ncols = 0; }   /* nothing for units_clear to free past */
    } else bad = 1;
    if (bad) nl_harness_die(r, 2, "--merge: %s:%zu: malformed", path, lineno);
  }
  int rerr = ferror(fp);
  fclose(fp);
  free(line);
  free(f);
  if (rerr || lineno == 0) nl_harness_die(r, 2, "--merge: %s: unreadable or empty", path);
}

static void shards_merge(nl_harness *r)
{
  const char *dir = r->shard_dir;
  DIR *d = opendir(dir);
  if (!d) nl_harness_die(r, 2, "--merge: no shards in %s (%s)", dir, strerror(errno));
  int n = 0, other = 0;
  struct dirent *de;
  while ((de = readdir(d))) {
    int k, nn, used = 0;
    if (sscanf(de->d_name, "%d-of-%d.tsv%n", &k, &nn, &used) == 2 && !de->d_name[used] && nn > 0) {
      if (n && nn != n) other = nn > other ? nn : other;
      if (!n) n = nn;
    }
  }
  closedir(d);
  if (!n) nl_harness_die(r, 2, "--merge: no shard files (K-of-N.tsv) in %s", dir);
  if (other) nl_harness_die(r, 2, "--merge: %s holds shards of two runs (N = %d and %d)", dir, n, other);
  char *set = shard_settings(r);
  for (int k = 1; k <= n; k++) {
    char *p = shard_path(r, k, n);
    shard_read(r, p, k, n, set);
    free(p);
  }
  free(set);
}

void nl_harness_units_done(nl_harness *r)
{
  if (r->nunits < 0) nl_harness_die(r, 1, "nl_harness_units_done before nl_harness_units (a bug)");
  if (r->shard_n) {
    shard_write(r);
    if (r->line_open) fputc('\n', stderr);
    exit(0);
  }
  if (r->merge) shards_merge(r);
}

/* After a merge's manifest: the shards are spent, the folder is the run's. */
static void shards_remove(nl_harness *r)
{
  if (!r->merge) return;
  const char *dir = r->shard_dir;
  DIR *d = opendir(dir);
  struct dirent *de;
  while (d && (de = readdir(d))) {
    if (!strcmp(de->d_name, ".") || !strcmp(de->d_name, "..")) continue;
    char *p = nl_path_join(dir, de->d_name);
    unlink(p);
    free(p);
  }
  if (d) closedir(d);
  rmdir(dir);
}
