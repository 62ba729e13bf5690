/* Tests of the experiment harness (report): option parsing and its errors,
 * parameters (lookup, range errors, the unknown-name error, --params and
 * --help), the manifest read back with nl_table_read, regression rules
 * (well-formed and malformed) and the check engine on two tiny folders.
 * What must exit (nl_harness_die, --params) runs in a forked child whose exit
 * status and output are read back. */
#define _GNU_SOURCE   /* open_memstream */
#include "harness/nl_harness.h"
#include "table/nl_table.h"
#include "nl_test.h"

#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

static const char *dir;

/* ---- options -------------------------------------------------------------- */

static nl_status parse(nl_harness_options *o, nl_error *err, int argc, const char *const *args)
{
  return nl_harness_parse(o, argc, (char **)args, err);
}

NL_TEST(options_parse)
{
  nl_harness_options o;
  nl_error err;
  const char *a[] = {"x", "--out", "d", "--seed", "4294967295", "--seeds", "3", "--quick",
                     "--set", "size=64", "--set", "z=0.5=1", "--params", "--help"};
  NL_CHECK(parse(&o, &err, 14, a) == NL_OK);
  NL_CHECK(strcmp(o.out, "d") == 0 && o.seed == 4294967295UL && o.seeds == 3 && o.quick && o.params && o.help);
  NL_CHECK(o.nset == 2 && !strcmp(o.set_key[0], "size") && !strcmp(o.set_val[0], "64"));
  NL_CHECK(!strcmp(o.set_key[1], "z") && !strcmp(o.set_val[1], "0.5=1"));   /* the first '=' splits */
  nl_harness_options_free(&o);
  /* GNU style: --name=value and unique prefixes */
  const char *gnu[] = {"x", "--seed=7", "--out=e", "--set=size=32", "--qu"};
  NL_CHECK(parse(&o, &err, 5, gnu) == NL_OK && o.seed == 7 && !strcmp(o.out, "e") && o.quick);
  NL_CHECK(o.nset == 1 && !strcmp(o.set_key[0], "size") && !strcmp(o.set_val[0], "32"));
  nl_harness_options_free(&o);
  /* shards: --shard K/N (an exact name beats the prefix of --shards), --merge, --units */
  const char *sh[] = {"x", "--shard", "2/5", "--shards", "d/s", "--units"};
  NL_CHECK(parse(&o, &err, 6, sh) == NL_OK && o.shard_k == 2 && o.shard_n == 5 && o.units &&
           !strcmp(o.shard_dir, "d/s") && !o.merge);
  nl_harness_options_free(&o);
  const char *mg[] = {"x", "--merge"};
  NL_CHECK(parse(&o, &err, 2, mg) == NL_OK && o.merge && o.shard_n == 0 && !o.shard_dir);
  nl_harness_options_free(&o);
  const char *amb[] = {"x", "--see", "3"};
  NL_CHECK(parse(&o, &err, 3, amb) == NL_EINVAL && strstr(err.msg, "ambiguous"));
  const char *none[] = {"x"};
  NL_CHECK(parse(&o, &err, 1, none) == NL_OK && o.seed == 1 && o.seeds == -1 && !o.out && !o.quick && !o.params);
  nl_harness_options_free(&o);
}

NL_TEST(option_errors_are_one_line_naming_the_option)
{
  static const struct { int argc; const char *args[3]; const char *want; } bad[] = {
    {2, {"x", "--frobnicate"}, "--frobnicate: unknown option"},
    {2, {"x", "--out"}, "--out: missing value"},
    {3, {"x", "--out", ""}, "--out: empty folder name"},
    {3, {"x", "--seed", "4294967296"}, "--seed"},
    {3, {"x", "--seed", "-1"}, "--seed"},
    {3, {"x", "--seeds", "0"}, "--seeds"},
    {3, {"x", "--seeds", "two"}, "--seeds"},
    {3, {"x", "--set", "=1"}, "is not NAME=VALUE"},
    {3, {"x", "--set", "size"}, "is not NAME=VALUE"},
    {3, {"x", "--shard", "3/2"}, "--shard: '3/2' is not K/N"},
    {3, {"x", "--shard", "0/2"}, "--shard: '0/2' is not K/N"},
    {3, {"x", "--shard", "1/2x"}, "--shard: '1/2x' is not K/N"},
    {3, {"x", "--shards", ""}, "--shards: empty folder name"},
  };
  for (size_t i = 0; i < sizeof bad / sizeof *bad; i++) {
    nl_harness_options o;
    nl_error err = {{0}};
    NL_CHECK(parse(&o, &err, bad[i].argc, bad[i].args) == NL_EINVAL);
    NL_CHECK(strstr(err.msg, bad[i].want) != NULL && !strchr(err.msg, '\n'));
    NL_CHECK(o.nset == 0 && o.out == NULL);   /* nothing to free on error */
  }
}

/* ---- parameters, in a child ------------------------------------------------- */

typedef struct { int status; char out[4096], err[4096]; } child_result;

static void read_into(const char *path, char *buf, size_t n)
{
  FILE *f = fopen(path, "r");
  size_t got = f ? fread(buf, 1, n - 1, f) : 0;
  buf[got] = '\0';
  if (f) fclose(f);
}

/* The little experiment the children run: declares size (int, 16..4096)
 * and z (double, -1..1), calls nl_harness_params_done and says "ran". */
static int little_experiment(int argc, char **argv)
{
  nl_harness *r = nl_harness_begin("t_exp", "T - a test", argc, argv);
  long size = nl_harness_param_int(r, "size", 64, 16, 4096, "image side in pixels");
  double z = nl_harness_param(r, "z", 0.5, -1, 1, "slice height");
  nl_harness_params_done(r);
  printf("ran size=%ld z=%g\n", size, z);
  fflush(stdout);
  _exit(0);   /* the run is never ended (no output): not a leak for LeakSanitizer */
}

/* execv of this program with args[0 .. n - 1]. Under meson's exe_wrapper
 * (qemu-aarch64 for the arm64 cross build; the test's environment names it)
 * the kernel cannot run the program itself, so the wrapper runs it again:
 * WRAPPER -0 ARGV0 PROGRAM ARGS (qemu-user's -0 sets argv[0]). */
static void exec_self(int n, const char **args)
{
  const char *wrap = getenv("MESON_EXE_WRAPPER");
  if (!wrap || !*wrap) {
    execv("/proc/self/exe", (char **)args);
    return;
  }
  static char self[4096];
  ssize_t len = readlink("/proc/self/exe", self, sizeof self - 1);
  if (len <= 0) return;
  self[len] = '\0';
  const char **w = nl_xcalloc((size_t)n + 4, sizeof *w);
  w[0] = wrap;
  w[1] = "-0";
  w[2] = args[0];
  w[3] = self;
  for (int i = 1; i < n; i++) w[i + 3] = args[i];
  execv(wrap, (char **)w);
}

/* Runs this program again (a fresh process: a forked copy would inherit
 * OpenBLAS's threads and this test's exit handlers) as the little
 * experiment with argv[1..], output to files. */
static child_result run_child(int argc, const char **argv)
{
  child_result res;
  char *o = nl_path_join(dir, "child.out"), *e = nl_path_join(dir, "child.err");
  const char **args = nl_xcalloc((size_t)argc + 2, sizeof *args);
  args[0] = "test_report";
  args[1] = "--child";   /* main's switch; the experiment sees it as its argv[0] */
  for (int i = 1; i < argc; i++) args[i + 1] = argv[i];
  fflush(NULL);
  pid_t pid = fork();
  if (pid == 0) {
    if (!freopen(o, "w", stdout) || !freopen(e, "w", stderr)) _exit(99);
    exec_self(argc + 1, args);
    _exit(98);
  }
  waitpid(pid, &res.status, 0);
  res.status = WIFEXITED(res.status) ? WEXITSTATUS(res.status) : -1;
  read_into(o, res.out, sizeof res.out);
  read_into(e, res.err, sizeof res.err);
  free(o); free(e); free(args);
  return res;
}

NL_TEST(parameters_lookup_and_range_errors)
{
  const char *ok[] = {"t", "--set", "size=128", "--set", "z=-1"};
  child_result c = run_child(5, ok);
  NL_CHECK(c.status == 0 && strstr(c.out, "ran size=128 z=-1"));
  const char *def[] = {"t"};
  c = run_child(1, def);
  NL_CHECK(c.status == 0 && strstr(c.out, "ran size=64 z=0.5"));
  const char *outside[] = {"t", "--set", "size=8"};
  c = run_child(3, outside);
  NL_CHECK(c.status == 2 && strstr(c.err, "t_exp: --set size: ") && strstr(c.err, "outside") && !strstr(c.out, "ran"));
  const char *notint[] = {"t", "--set", "size=2.5"};
  c = run_child(3, notint);
  NL_CHECK(c.status == 2 && strstr(c.err, "--set size"));
  const char *nan[] = {"t", "--set", "z=nan"};
  c = run_child(3, nan);
  NL_CHECK(c.status == 2 && strstr(c.err, "--set z"));
  const char *unknown[] = {"t", "--set", "sise=1"};
  c = run_child(3, unknown);
  NL_CHECK(c.status == 2 && !strcmp(c.err, "t_exp: --set sise: unknown parameter for t_exp (valid: size, z)\n"));
}

NL_TEST(params_lists_tsv_and_help_reads_well)
{
  const char *p[] = {"t", "--params", "--out", "never"};
  child_result c = run_child(4, p);
  NL_CHECK(c.status == 0);
  NL_CHECK(!strcmp(c.out, "name\tdefault\tmin\tmax\tmeaning\n"
                          "size\t64\t16\t4096\timage side in pixels\n"
                          "z\t0.5\t-1\t1\tslice height\n"));
  NL_CHECK(access("never", F_OK) != 0);
  const char *bad[] = {"t", "--params", "--set", "z=2"};   /* values given are still checked */
  c = run_child(4, bad);
  NL_CHECK(c.status == 2 && strstr(c.err, "--set z"));
  const char *h[] = {"t", "--help"};
  c = run_child(2, h);
  NL_CHECK(c.status == 0 && strstr(c.out, "usage: t_exp") && strstr(c.out, "--params"));
  NL_CHECK(strstr(c.out, "  size ") && strstr(c.out, "[16, 4096]: image side in pixels"));
  NL_CHECK(strstr(c.out, "  z ") && strstr(c.out, "slice height") && !strstr(c.out, "ran size"));
}

/* ---- the manifest, read back ---------------------------------------------- */

static const char *manifest_value(const nl_table *m, const char *key, int nth)
{
  for (size_t i = 0; i < m->nrows; i++)
    if (m->text[i * 2] && !strcmp(m->text[i * 2], key) && nth-- == 0) return m->text[i * 2 + 1];
  return NULL;
}

NL_TEST(manifest_round_trip)
{
  nl_error err0;
  char *out = nl_path_join(dir, "run");
  const char *argv[] = {"t", "--out", out, "--seed", "7", "--seeds", "2", "--set", "z=0.25"};
  nl_harness *r = nl_harness_begin("t_exp", "T - a test", 9, (char **)argv);
  long size = nl_harness_param_int(r, "size", 64, 16, 4096, "image side in pixels");
  double z = nl_harness_param(r, "z", 0.5, -1, 1, "slice height");
  NL_CHECK(size == 64 && z == 0.25);
  size_t np;
  const nl_harness_param_info *pi = nl_harness_params(r, &np);
  NL_CHECK(np == 2 && !strcmp(pi[0].name, "size") && pi[0].is_int && pi[1].lo == -1 && !strcmp(pi[1].meaning, "slice height"));
  nl_harness_params_done(r);
  nl_harness_note(r, "pool_bytes", "%d", 123);
  nl_harness_check(r, "a.tsv", "x", "rel 1e-9");
  nl_harness_check(r, "a.tsv", "*", "abs 0.5");
  nl_harness_check(r, "a.tsv", "x", "ignore");   /* the later rule wins */
  NL_CHECK(!strcmp(nl_harness_check_rule(r, "a.tsv", "x"), "ignore"));
  NL_CHECK(!strcmp(nl_harness_check_rule(r, "a.tsv", "y"), "abs 0.5"));
  NL_CHECK(nl_harness_check_rule(r, "b.tsv", "x") == NULL);
  /* Report numbers to their significant digits: a sweep's label
   * 9.99990000099999e-06 (text) reads 1e-05, a paper's 0.99999 stays. */
  const char *tc[] = {"w1", "w2", "E", "paper_E"};
  nl_table *t = nl_table_alloc(4, tc);
  nl_table_append(t, "sddd", "9.99990000099999e-06", 0.99999, 0.058087919778, 0.06);
  nl_harness_report_table(r, t, NULL, 4);
  nl_harness_verdict(r, "t.tsv", t, 0, "E", "paper_E", "E", NULL, "rel 0.05 0.25", "independent", "a reading");
  nl_harness_verdict(r, "t.tsv", t, 0, "E fitted", "paper_E", "E", NULL, "rel 0.05 0.25", "fitted 2/3", NULL);
  /* controls: the flat image's E is far off (the row stays independent);
   * a control as good as the method turns the row to "by construction" */
  nl_table_append(t, "sddd", "flat", 0.5, 0.9, 0.06);
  nl_table_append(t, "sddd", "random", 0.5, 0.0601, 0.06);
  nl_harness_verdict(r, "t.tsv", t, 0, "E ctl", "paper_E", "E", NULL, "rel 0.05 0.25", "independent", NULL);
  nl_harness_verdict_control(r, "a flat image", "t.tsv", t, 1);
  nl_harness_verdict(r, "t.tsv", t, 0, "E same", "paper_E", "E", NULL, "rel 0.05 0.25", "independent", NULL);
  nl_harness_verdict_control(r, "random tables", "t.tsv", t, 2);
  /* a row that fails keeps its verdict when its baseline passes */
  nl_harness_verdict(r, "t.tsv", t, 1, "E fails", "paper_E", "E", NULL, "rel 0.05 0.25", "independent", NULL);
  nl_harness_verdict_control(r, "random tables", "t.tsv", t, 2);
  nl_harness_verdict_figure(r, "the look", "looks like marble", "panels.png", NULL);
  nl_table_free(t);
  NL_CHECK(nl_harness_end(r) == 0);
  char *rp = nl_path_join(out, "report.md"), *vp = nl_path_join(out, "verdicts.tsv");
  char md[4096] = "";
  FILE *fp = fopen(rp, "r");
  NL_CHECK(fp && fread(md, 1, sizeof md - 1, fp) > 0);
  if (fp) fclose(fp);
  NL_CHECK(strstr(md, "| 1e-05 | 0.99999 | 0.05809 | 0.06 |"));
  nl_table *vt = NULL;
  NL_CHECK(nl_table_read(vp, NL_TABLE_TEXT, &vt, &err0) == NL_OK);
  if (vt) {
    NL_CHECK(vt->nrows == 6 && !strcmp(nl_table_text(vt, 0, "verdict"), "reproduced"));
    NL_CHECK(!strcmp(nl_table_text(vt, 4, "kind"), "independent") && !strcmp(nl_table_text(vt, 4, "verdict"), "not reproduced"));
    NL_CHECK(!strcmp(nl_table_text(vt, 4, "control_verdict"), "reproduced"));
    NL_CHECK(!strcmp(nl_table_text(vt, 0, "control"), "-") && !strcmp(nl_table_text(vt, 0, "control_verdict"), "-"));
    NL_CHECK(!strcmp(nl_table_text(vt, 2, "kind"), "independent") && !strcmp(nl_table_text(vt, 2, "control"), "a flat image"));
    NL_CHECK(!strcmp(nl_table_text(vt, 2, "control_verdict"), "not reproduced") && nl_table_value(vt, 2, "control_ours") == 0.9);
    NL_CHECK(!strcmp(nl_table_text(vt, 3, "kind"), "by construction") && !strcmp(nl_table_text(vt, 3, "verdict"), "by construction"));
    NL_CHECK(!strcmp(nl_table_text(vt, 3, "control_verdict"), "reproduced") && strstr(nl_table_text(vt, 3, "reason"), "its control (random tables) passes"));
    NL_CHECK(!strcmp(nl_table_text(vt, 0, "kind"), "independent"));
    /* a fitted reading is capped: it cannot be "reproduced" */
    NL_CHECK(!strcmp(nl_table_text(vt, 1, "verdict"), "consistent after fit"));
    NL_CHECK(!strcmp(nl_table_text(vt, 5, "verdict"), "see figure") && !strcmp(nl_table_text(vt, 5, "kind"), "qualitative"));
    /* the reason: the distance and the note, the thresholds left to the rule's column */
    NL_CHECK(!strcmp(nl_table_text(vt, 0, "reason"), "3.19% below the paper; a reading"));
    NL_CHECK(!strcmp(nl_table_text(vt, 5, "reason"), "the figure decides"));
    NL_CHECK(!strcmp(nl_table_text(vt, 0, "source"), "t.tsv:E"));
  }
  nl_table_free(vt);
  free(rp); free(vp);
  char *mp = nl_path_join(out, "manifest.tsv"), *cp = nl_path_join(out, "checks.tsv");
  nl_table *m = NULL, *ck = NULL;
  nl_error err;
  NL_CHECK(nl_table_read(mp, NL_TABLE_TEXT, &m, &err) == NL_OK);
  NL_CHECK(nl_table_read(cp, NL_TABLE_TEXT, &ck, &err) == NL_OK);
  if (m && ck) {
    NL_CHECK(m->ncols == 2 && !strcmp(m->names[0], "key") && !strcmp(m->names[1], "value"));
    NL_CHECK(!strcmp(manifest_value(m, "experiment", 0), "t_exp"));
    char b[32];
    for (size_t i = 0; i < m->nrows; i++)
      if (!strcmp(m->text[i * 2], "seed")) NL_CHECK(!strcmp(nl_table_cell_text(m, i, 1, b), "7"));
    NL_CHECK(!strcmp(manifest_value(m, "quick", 0), "no"));
    NL_CHECK(!strcmp(manifest_value(m, "param", 0), "size=64"));
    NL_CHECK(!strcmp(manifest_value(m, "param", 1), "z=0.25"));
    const char *cc = manifest_value(m, "compiler", 0);
    NL_CHECK(cc && (!strncmp(cc, "gcc ", 4) || strstr(cc, "lang")));   /* names the compiler */
    NL_CHECK(manifest_value(m, "cflags", 0) && manifest_value(m, "blas", 0) && manifest_value(m, "cpu", 0));
    /* what moves last bits across machines: the architecture and libm's variant */
    const char *arch = manifest_value(m, "arch", 0), *libm = manifest_value(m, "libm", 0);
    NL_CHECK(arch && *arch && strcmp(arch, "unknown"));
#ifdef __GLIBC__
    NL_CHECK(libm && !strncmp(libm, "glibc 2.", 8));
#if defined(__x86_64__)
    NL_CHECK(libm && (strstr(libm, " fma") || strstr(libm, " avx") || strstr(libm, " sse2")));
#elif defined(__aarch64__)
    NL_CHECK(libm && strstr(libm, " aarch64") && !strcmp(arch, "aarch64"));
#endif
#else
    NL_CHECK(libm != NULL);
#endif
    NL_CHECK(ck->nrows == 3 && !strcmp(ck->text[0 * 3 + 2], "ignore") && !strcmp(ck->text[1 * 3 + 1], "*"));
    /* verdicts.tsv holds copies of compared values: not compared again */
    NL_CHECK(!strcmp(ck->text[2 * 3], "verdicts.tsv") && !strcmp(ck->text[2 * 3 + 2], "ignore"));
  }
  nl_table_free(m); nl_table_free(ck);
  free(mp); free(cp); free(out);
}

/* ---- rules ----------------------------------------------------------------- */

NL_TEST(rules_parse_and_malformed_ones_are_refused)
{
  nl_harness_rule r;
  nl_error err;
  NL_CHECK(nl_harness_rule_parse("exact", &r, &err) == NL_OK && r.kind == NL_CHECK_EXACT);
  NL_CHECK(nl_harness_rule_parse("ignore", &r, &err) == NL_OK && r.kind == NL_CHECK_IGNORE);
  NL_CHECK(nl_harness_rule_parse("abs 0.5", &r, &err) == NL_OK && r.kind == NL_CHECK_ABS && r.tol == 0.5);
  NL_CHECK(nl_harness_rule_parse("rel 1e-9", &r, &err) == NL_OK && r.kind == NL_CHECK_REL && r.tol == 1e-9);
  NL_CHECK(nl_harness_rule_parse("welch mean_sd 1e-3", &r, &err) == NL_OK && r.kind == NL_CHECK_WELCH
           && !strcmp(r.sdcol, "mean_sd") && r.tol == 1e-3);
  NL_CHECK(nl_harness_rule_parse("ftest 0.01", &r, &err) == NL_OK && r.kind == NL_CHECK_FTEST && r.tol == 0.01);
  static const char *const bad[] = {"", "exactly", "abs", "abs x", "abs -1", "rel 1e-9 extra", "welch 1e-3",
                                    "welch sd", "welch sd 0.7", "ftest 0", "ftest", "exact 1"};
  for (size_t i = 0; i < sizeof bad / sizeof *bad; i++) {
    err.msg[0] = '\0';
    NL_CHECK(nl_harness_rule_parse(bad[i], &r, &err) == NL_EINVAL && err.msg[0]);
  }
  char longrule[400];
  memset(longrule, 'a', sizeof longrule - 1);
  longrule[sizeof longrule - 1] = '\0';
  NL_CHECK(nl_harness_rule_parse(longrule, &r, &err) == NL_EINVAL && strstr(err.msg, "too long"));
}

/* ---- the check engine -------------------------------------------------------- */

static void put(const char *folder, const char *file, const char *text)
{
  nl_error err;
  char *p = nl_path_join(folder, file);
  NL_CHECK(nl_mkdir_p(folder, &err) == NL_OK);
  FILE *f = fopen(p, "w");
  fputs(text, f);
  fclose(f);
  free(p);
}

static const char *MANIFEST = "key\tvalue\nexperiment\tt1\nseed\t1\nseeds\t10\nquick\tno\nparam\tsize=8\ncpu\tX\n";

static nl_status check(const char *a, const char *b, nl_harness_check_state *s, char **report, nl_error *err)
{
  size_t n;
  FILE *fp = open_memstream(report, &n);
  s->out = fp;
  nl_status st = nl_harness_check_experiment(s, a, b, err);
  nl_harness_check_totals(s);
  fclose(fp);
  return st;
}

NL_TEST(check_engine_on_two_folders)
{
  char *ref = nl_path_join(dir, "ref"), *same = nl_path_join(dir, "same"), *moved = nl_path_join(dir, "moved");
  char *badrule = nl_path_join(dir, "badrule");
  const char *checks = "table\tcolumn\trule\nd.tsv\tmean\twelch mean_sd 1e-3\nd.tsv\tmean_sd\tftest 1e-3\n"
                       "d.tsv\tsecs\tignore\n";
  const char *d = "label\tmean\tmean_sd\tsecs\tcount\na\t0.5\t0.1\t3\t17\nb\t1.5\t0\t1\t4\n";
  const char *folders[] = {ref, same, moved};
  for (int k = 0; k < 3; k++) { put(folders[k], "manifest.tsv", MANIFEST); put(folders[k], "checks.tsv", checks); put(folders[k], "d.tsv", d); }
  put(moved, "d.tsv", "label\tmean\tmean_sd\tsecs\tcount\na\t0.53\t0.12\t99\t17\nb\t1.5\t0\t1\t5\n");
  nl_harness_check_state s = {0};
  char *rep = NULL;
  nl_error err;
  NL_CHECK(check(ref, same, &s, &rep, &err) == NL_OK && s.drifted == 0 && s.tables == 1);
  NL_CHECK(strstr(rep, "check: t1: 1 tables, ") && strstr(rep, " 0 drifted"));
  free(rep);
  /* noise under welch passes, the timing is ignored, a count that moved drifts */
  nl_harness_check_state s2 = {0};
  NL_CHECK(check(ref, moved, &s2, &rep, &err) == NL_OK && s2.drifted == 1);
  NL_CHECK(strstr(rep, "experiment\ttable\trow\tcolumn\tcommitted\tnew\trule\n"
                       "t1\td.tsv\t2 [b]\tcount\t4\t5\texact\n"));
  /* what differs or is not recorded comes first, what is the same last */
  NL_CHECK(strstr(rep, "check: t1: 1 drifted; reference vs this run: architecture unknown ("));
  NL_CHECK(strstr(rep, ", libm unknown (reference: not recorded, this run: not recorded), "
                       "CPU same (X)\n"));
  free(rep);
  /* bad input is a status and a message, not an exit */
  put(badrule, "manifest.tsv", MANIFEST);
  put(badrule, "checks.tsv", "table\tcolumn\trule\nd.tsv\tmean\twelch nosuch 1e-3\n");
  put(badrule, "d.tsv", d);
  nl_harness_check_state s3 = {0};
  NL_CHECK(check(badrule, same, &s3, &rep, &err) == NL_EFORMAT && strstr(err.msg, "no column 'nosuch'"));
  free(rep);
  nl_harness_check_state s4 = {0};
  NL_CHECK(check(ref, "/nonexistent/folder", &s4, &rep, &err) != NL_OK && strstr(err.msg, "manifest.tsv"));
  free(rep);
  free(ref); free(same); free(moved); free(badrule);
}

/* Verdicts: each rule's thresholds, the words of the reason, bad rules. */
NL_TEST(verdict_rules)
{
  nl_harness_outcome v;
  char why[256];
  nl_error err;
  NL_CHECK(nl_harness_verdict_decide("rel 0.05 0.25", 2.0, 2.08, NAN, &v, why, sizeof why, &err) == NL_OK);
  /* the thresholds are the rule's column, not repeated in every reason */
  NL_CHECK(v == NL_VERDICT_REPRODUCED && !strcmp(why, "4% above the paper"));
  NL_CHECK(nl_harness_verdict_decide("rel 0.05 0.25", 2.0, 1.6, NAN, &v, why, sizeof why, &err) == NL_OK);
  NL_CHECK(v == NL_VERDICT_PARTLY && strstr(why, "20% below"));
  NL_CHECK(nl_harness_verdict_decide("factor 1.1 1.5", 11.96, 4.08, NAN, &v, why, sizeof why, &err) == NL_OK);
  NL_CHECK(v == NL_VERDICT_NOT && strstr(why, "x2.93 below"));
  NL_CHECK(nl_harness_verdict_decide("sd 2 4", 0.21, 0.196, 0.004, &v, why, sizeof why, &err) == NL_OK);
  NL_CHECK(v == NL_VERDICT_PARTLY && strstr(why, "3.5 sd below"));
  NL_CHECK(nl_harness_verdict_decide("sd 2 4", 1, 1, 0, &v, why, sizeof why, &err) == NL_OK && v == NL_VERDICT_REPRODUCED);
  NL_CHECK(nl_harness_verdict_decide("abs 0.01 0.1", 0.5, 0.45, NAN, &v, why, sizeof why, &err) == NL_OK);
  NL_CHECK(v == NL_VERDICT_PARTLY && !strcmp(nl_harness_verdict_word(v, "independent"), "partly"));
  NL_CHECK(nl_harness_verdict_decide("rel 0.5 0.1", 1, 1, NAN, &v, why, sizeof why, &err) == NL_EINVAL);
  NL_CHECK(nl_harness_verdict_decide("near 0.1 0.2", 1, 1, NAN, &v, why, sizeof why, &err) == NL_EINVAL && strstr(err.msg, "near"));
  NL_CHECK(nl_harness_verdict_decide("sd 1 2", 1, 1, NAN, &v, why, sizeof why, &err) == NL_EINVAL);
  NL_CHECK(nl_harness_verdict_decide("factor 1.1 2", -1, 1, NAN, &v, why, sizeof why, &err) == NL_EINVAL);
  NL_CHECK(nl_harness_verdict_decide("rel 0.1 0.2 x", 1, 1, NAN, &v, why, sizeof why, &err) == NL_EINVAL);
  /* p-value rules: an effect wants a small p, a law a large one */
  NL_CHECK(nl_harness_verdict_decide("p 0.01 0.05", NAN, 0.03, NAN, &v, why, sizeof why, &err) == NL_OK);
  NL_CHECK(v == NL_VERDICT_PARTLY && strstr(why, "p = 0.03"));
  NL_CHECK(nl_harness_verdict_decide("fit 0.05 0.001", NAN, 0.5, NAN, &v, why, sizeof why, &err) == NL_OK);
  NL_CHECK(v == NL_VERDICT_REPRODUCED);
  NL_CHECK(nl_harness_verdict_decide("fit 0.05 0.001", NAN, 1e-5, NAN, &v, why, sizeof why, &err) == NL_OK);
  NL_CHECK(v == NL_VERDICT_NOT);
  NL_CHECK(nl_harness_verdict_decide("fit 0.001 0.05", NAN, 0.5, NAN, &v, why, sizeof why, &err) == NL_EINVAL);
  NL_CHECK(nl_harness_verdict_decide("p 0.01 0.05", NAN, 1.5, NAN, &v, why, sizeof why, &err) == NL_EINVAL);
  /* equivalence by two one-sided tests; p from scipy 1.10:
   * max(t.sf(7, 9), t.cdf(-3, 9)) = 0.007478181955207101 */
  NL_CHECK(nl_harness_verdict_decide_equiv("equiv rel 0.05 0.01 0.05", 1, 1.02, 0.01, 9, &v, why, sizeof why, &err) == NL_OK);
  NL_CHECK(v == NL_VERDICT_REPRODUCED && strstr(why, "TOST p = 0.0075"));
  /* normal: max(norm.sf(3.5), norm.cdf(-1.5)) = 0.06680720126885807 */
  NL_CHECK(nl_harness_verdict_decide_equiv("equiv abs 0.01 0.01 0.1", 0, 0.004, 0.004, 0, &v, why, sizeof why, &err) == NL_OK);
  NL_CHECK(v == NL_VERDICT_PARTLY && strstr(why, "TOST p = 0.067"));
  /* a wide se never shows equality, however close ours is */
  NL_CHECK(nl_harness_verdict_decide_equiv("equiv rel 0.05 0.01 0.05", 1, 1.0, 1.0, 9, &v, why, sizeof why, &err) == NL_OK && v == NL_VERDICT_NOT);
  NL_CHECK(nl_harness_verdict_decide("equiv rel 0.05 0.01 0.05", 1, 1, 0.1, &v, why, sizeof why, &err) == NL_EINVAL);
  NL_CHECK(nl_harness_verdict_decide_equiv("equiv rel 0 0.01 0.05", 1, 1, 0.1, 9, &v, why, sizeof why, &err) == NL_EINVAL);
  /* kinds, and the cap each puts on the word */
  const char *good[] = {"independent", "fitted 1/6", "fitted 4/12", "selected 1/19", "by construction", "qualitative"};
  for (size_t i = 0; i < sizeof good / sizeof *good; i++)
    NL_CHECK(nl_harness_verdict_kind_check(good[i], &err) == NL_OK);
  const char *bad[] = {"fitted", "fitted 0/3", "selected 2/19", "selected 1/1", "fitted 1/6 ", "chosen", ""};
  for (size_t i = 0; i < sizeof bad / sizeof *bad; i++)
    NL_CHECK(nl_harness_verdict_kind_check(bad[i], &err) == NL_EINVAL);
  NL_CHECK(!strcmp(nl_harness_verdict_word(NL_VERDICT_REPRODUCED, "selected 1/19"), "consistent after selection"));
  NL_CHECK(!strcmp(nl_harness_verdict_word(NL_VERDICT_REPRODUCED, "fitted 1/6"), "consistent after fit"));
  NL_CHECK(!strcmp(nl_harness_verdict_word(NL_VERDICT_PARTLY, "fitted 1/6"), "partly consistent after fit"));
  NL_CHECK(!strcmp(nl_harness_verdict_word(NL_VERDICT_NOT, "fitted 4/12"), "not consistent after fit"));
  NL_CHECK(!strcmp(nl_harness_verdict_word(NL_VERDICT_PARTLY, "selected 1/8"), "partly consistent after selection"));
  NL_CHECK(!strcmp(nl_harness_verdict_word(NL_VERDICT_NOT, "selected 1/19"), "not consistent after selection"));
  /* the counted words belong to independent rows only */
  NL_CHECK(!strcmp(nl_harness_verdict_word(NL_VERDICT_PARTLY, "independent"), "partly"));
  NL_CHECK(!strcmp(nl_harness_verdict_word(NL_VERDICT_NOT, "independent"), "not reproduced"));
  NL_CHECK(!strcmp(nl_harness_verdict_word(NL_VERDICT_REPRODUCED, "by construction"), "by construction"));
}

/* In a program started by nl_harness_program_start, a temporary still open
 * when the program exits or is stopped by SIGINT, SIGTERM or SIGHUP is
 * removed; the signal still ends the process. */
NL_TEST(atomic_temporaries_removed_on_exit_and_signals)
{
  static const int sigs[3] = {SIGINT, SIGTERM, SIGHUP};
  char *sub = nl_path_join(dir, "signals");
  nl_error err = {{0}};
  NL_CHECK(nl_mkdir_p(sub, &err) == NL_OK);
  char *p = nl_path_join(sub, "t.tsv");
  for (int k = 0; k <= 3; k++) {
    struct sigaction was;
    /* A signal ignored when the handlers were installed stays ignored
     * (nohup ignores SIGHUP): nothing to test there. */
    if (k < 3 && sigaction(sigs[k], NULL, &was) == 0 && !(was.sa_flags & SA_SIGINFO) &&
        was.sa_handler == SIG_IGN) {
      nl_test_skip("signal %d is ignored in this environment (nohup?): left ignored", sigs[k]);
      continue;
    }
    pid_t pid = fork();
    if (pid == 0) {
      nl_atomic_file af;
      nl_harness_program_start();
      if (nl_atomic_open(&af, p, &err)) _exit(4);
      fputs("half", af.fp);
      fflush(af.fp);
      if (k == 3) exit(5);
      raise(sigs[k]);
      _exit(6);
    }
    int status = -1;
    NL_CHECK(pid > 0 && waitpid(pid, &status, 0) == pid);
    if (k == 3) NL_CHECK(WIFEXITED(status) && WEXITSTATUS(status) == 5);
    else NL_CHECK(WIFSIGNALED(status) && WTERMSIG(status) == sigs[k]);
    NL_CHECK(nl_test_no_hidden_files(sub));
  }
  NL_CHECK(access(p, F_OK) != 0);
  free(sub); free(p);
}

int main(int argc, char **argv)
{
  if (argc > 1 && !strcmp(argv[1], "--child")) return little_experiment(argc - 1, argv + 1);
  dir = nl_test_tmpdir();
  return nl_test_run();
}
