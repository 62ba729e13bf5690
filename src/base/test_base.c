/* Tests of base: the seed rule (splitmix64 against its published reference,
 * distinct stream ids give different and uncorrelated streams, replicates
 * are consecutive run seeds), directories, writable targets, memory sizes,
 * atomic files (a failed write leaves the old file), range-checked
 * parsing, and nl_parallel_for: the same bytes for 1, 2, 3 and 7 threads. */
#include "base/nl_base.h"
#include "base/nl_parallel.h"
#include "nl_test.h"
#include "nl_test_alloc.h"

#include <dirent.h>
#include <fcntl.h>
#include <gsl/gsl_blas.h>
#include <gsl/gsl_rng.h>
#include <gsl/gsl_statistics_double.h>
#include <stdlib.h>
#include <string.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/wait.h>
#include <dlfcn.h>
#include <unistd.h>

static const char *dir;

NL_TEST(splitmix64_matches_reference)
{
  /* Vigna's splitmix64.c from state 0: the first two outputs are
   * 0xe220a8397b1dcdaf and 0x6e789e6aa1b965f4 (state advanced by the golden
   * increment each call, so output 2 is mix(0x9e3779b97f4a7c15)). */
  NL_CHECK(nl_seed_mix(0) == 0xe220a8397b1dcdafULL);
  NL_CHECK(nl_seed_mix(0x9E3779B97F4A7C15ULL) == 0x6e789e6aa1b965f4ULL);
}

NL_TEST(stream_ids_give_distinct_seeds)
{
  /* Pins the rule itself: a change of derivation changes every result. */
  unsigned long a = nl_seed_stream(1, "noise.grad2", 0);
  NL_CHECK(a == nl_seed_stream(1, "noise.grad2", 0));
  NL_CHECK(a != nl_seed_stream(1, "noise.grad2", 1));
  NL_CHECK(a != nl_seed_stream(1, "noise.perm3", 0));
  NL_CHECK(a != nl_seed_stream(2, "noise.grad2", 0));
  /* Role and index do not trade: ("x", 1) is not ("x1", 0) and the like. */
  NL_CHECK(nl_seed_stream(7, "x", 1) != nl_seed_stream(7, "x1", 0));
  NL_CHECK(nl_seed_stream(0, "", 0) != nl_seed_stream(0, "", 1));
  /* No collision in the low 32 bits (what MT19937 reads) over 2 x 20000 ids. */
  enum { N = 20000 };
  static unsigned int lo[2 * N];
  for (int k = 0; k < N; k++) {
    lo[k] = (unsigned int)nl_seed_stream(1, "pool", (unsigned long)k);
    lo[N + k] = (unsigned int)nl_seed_stream(1, "table", (unsigned long)k);
  }
  int dup = 0;
  for (int i = 0; i < 2 * N && dup < 1; i++)
    for (int j = i + 1; j < 2 * N; j++) if (lo[i] == lo[j]) { dup++; break; }
  /* Birthday bound: P(any duplicate among 40000 32-bit values) ~ 0.17, so
   * a single duplicate would not prove a bug; count none for these ids
   * (measured), which pins the derivation as well. */
  NL_CHECK(dup == 0);
}

NL_TEST(two_streams_of_one_seed_are_uncorrelated)
{
  /* Seeds that differ by one (the old ad hoc rule seed, seed + 1) and two
   * roles of one seed: Pearson correlation of 100000 uniforms each. Under
   * independence r ~ N(0, 1/n), sd 0.0032; bound 5 sd = 0.016. */
  enum { N = 100000 };
  static double x[N], y[N], z[N];
  gsl_rng *a = gsl_rng_alloc(gsl_rng_mt19937), *b = gsl_rng_alloc(gsl_rng_mt19937),
          *c = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(a, nl_seed_stream(5, "cheng.anneal", 0));
  gsl_rng_set(b, nl_seed_stream(5, "noise.grad2", 0));
  gsl_rng_set(c, nl_seed_stream(5, "cheng.anneal", 1));
  int same = 0;
  for (int i = 0; i < N; i++) {
    x[i] = gsl_rng_uniform(a); y[i] = gsl_rng_uniform(b); z[i] = gsl_rng_uniform(c);
    same += x[i] == y[i];
  }
  NL_CHECK(same < 5);
  NL_CHECK(fabs(gsl_stats_correlation(x, 1, y, 1, N)) < 0.016);
  NL_CHECK(fabs(gsl_stats_correlation(x, 1, z, 1, N)) < 0.016);
  /* Lagged: stream b is not stream a shifted by a few draws. */
  for (int lag = 1; lag <= 3; lag++)
    NL_CHECK(fabs(gsl_stats_correlation(x + lag, 1, y, 1, N - lag)) < 0.016);
  gsl_rng_free(a); gsl_rng_free(b); gsl_rng_free(c);
}

NL_TEST(replicates_are_consecutive_run_seeds)
{
  NL_CHECK(nl_seed_replicate(10, 0) == 10);
  NL_CHECK(nl_seed_replicate(10, 3) == 13);
  /* A sweep task with base 13 and K = 2 runs replicates 3, 4 of base 10. */
  NL_CHECK(nl_seed_replicate(nl_seed_replicate(10, 3), 1) == nl_seed_replicate(10, 4));
}



/* An empty --out "" once overflowed a heap buffer in nl_mkdir_p (13.5). */
NL_TEST(mkdir_p_refuses_empty_and_file_parents)
{
  nl_error err = {{0}};
  NL_CHECK(nl_mkdir_p("", &err) == NL_EINVAL && strcmp(err.msg, "'': empty directory name") == 0);
  char *file = nl_path_join(dir, "afile"), *under = nl_path_join(dir, "afile/sub/deeper");
  FILE *f = fopen(file, "w");
  fclose(f);
  NL_CHECK(nl_mkdir_p(under, &err) == NL_EIO && strstr(err.msg, "is not a directory") != NULL);
  NL_CHECK(strncmp(err.msg, under, strlen(under)) == 0);
  NL_CHECK(nl_mkdir_p(file, &err) == NL_EIO);
  char *ok = nl_path_join(dir, "a/b/c/");
  NL_CHECK(nl_mkdir_p(ok, &err) == NL_OK);
  NL_CHECK(nl_mkdir_p("/", &err) == NL_OK);
  free(file); free(under); free(ok);
}

NL_TEST(writable_check_names_the_reason)
{
  nl_error err = {{0}};
  char *file = nl_path_join(dir, "f2"), *under = nl_path_join(dir, "f2/x.png");
  FILE *f = fopen(file, "w");
  fclose(f);
  char want[600];
  snprintf(want, sizeof want, "%s: parent %s is not a directory", under, file);
  NL_CHECK(nl_path_check_writable(under, &err) != NL_OK && strcmp(err.msg, want) == 0);
  NL_CHECK(nl_path_check_writable("", &err) == NL_EINVAL);
  NL_CHECK(nl_path_check_writable("/nonexistent/x.tsv", &err) != NL_OK
           && strcmp(err.msg, "/nonexistent/x.tsv: directory /nonexistent does not exist") == 0);
  NL_CHECK(nl_path_check_writable(dir, &err) != NL_OK);           /* a directory */
  NL_CHECK(nl_path_check_writable("x.tsv", &err) == NL_OK || 1);  /* cwd may be read-only */
  /* The atomic writer gives the same reason and leaves nothing. */
  nl_atomic_file af;
  NL_CHECK(nl_atomic_open(&af, under, &err) != NL_OK && strcmp(err.msg, want) == 0);
  free(file); free(under);
}

/* A message quoting input stays one line (control characters escaped) and,
 * too long for NL_ERROR_LEN, keeps its end: the reason. */
NL_TEST(messages_one_line_with_their_reason)
{
  nl_error err;
  NL_CHECK(nl_fail(&err, NL_EIO, "%s: cannot open", "a\nb\tc\x01\x7f") == NL_EIO);
  NL_CHECK(strcmp(err.msg, "a\\nb\\tc\\x01\\x7f: cannot open") == 0);
  /* escaping twice changes nothing: a tool may quote a message again */
  char again[NL_ERROR_LEN];
  snprintf(again, sizeof again, "%s", err.msg);
  nl_fail(&err, NL_EIO, "%s", again);
  NL_CHECK(strcmp(err.msg, again) == 0);
  /* 3000 bytes of path, twice: the middles go, the reason stays */
  char path[3100];
  memset(path, 'd', 3000);
  strcpy(path + 3000, "/name.tsv");
  nl_fail(&err, NL_EIO, "%s: directory %s does not exist", path, path);
  size_t n = strlen(err.msg);
  NL_CHECK(n < NL_ERROR_LEN && n > NL_ERROR_LEN / 2);
  NL_CHECK(n > 15 && strcmp(err.msg + n - 15, " does not exist") == 0);
  NL_CHECK(strstr(err.msg, "/name.tsv: directory ") != NULL && strstr(err.msg, "...") != NULL);
  NL_CHECK(strncmp(err.msg, "ddd", 3) == 0);
  /* a message of its own argument, as callers prefix a path */
  nl_fail(&err, NL_EIO, "reason");
  nl_fail(&err, NL_EIO, "%s: %s", "x.tsv", err.msg);
  NL_CHECK(strcmp(err.msg, "x.tsv: reason") == 0);
  /* no UTF-8 character is cut in two */
  char wide[2000] = "";
  for (int i = 0; i < 600; i++) strcat(wide, "\xc3\xa9");
  nl_fail(&err, NL_EIO, "%s: bad", wide);
  int whole = 1;
  for (const unsigned char *c = (const unsigned char *)err.msg; *c; c++)
    if (*c == 0xc3) whole &= c[1] == 0xa9;
    else if (*c == 0xa9) whole &= c > (const unsigned char *)err.msg && c[-1] == 0xc3;
  NL_CHECK(whole && strstr(err.msg, ": bad") != NULL);
}

/* A writer killed outright (SIGKILL) leaves its temporary: the next writer
 * of that output removes it, its pid being no live process, and keeps the
 * temporary of a writer still alive. */
NL_TEST(stale_temporaries_are_removed)
{
  nl_error err;
  pid_t dead = fork();
  if (dead == 0) _exit(0);
  waitpid(dead, NULL, 0);
  char name[128];
  char *out = nl_path_join(dir, "stale.tsv");
  snprintf(name, sizeof name, ".stale.%ld.AbC123.tsv", (long)dead);
  char *gone = nl_path_join(dir, name);
  snprintf(name, sizeof name, ".stale.%ld.dEf456.tsv", (long)getppid());
  char *kept = nl_path_join(dir, name);
  snprintf(name, sizeof name, ".other.%ld.AbC123.tsv", (long)dead);
  char *other = nl_path_join(dir, name);
  NL_CHECK(nl_atomic_write(gone, "x", 1, &err) == NL_OK);
  NL_CHECK(nl_atomic_write(kept, "x", 1, &err) == NL_OK);
  NL_CHECK(nl_atomic_write(other, "x", 1, &err) == NL_OK);
  NL_CHECK(nl_atomic_write(out, "y", 1, &err) == NL_OK);
  struct stat st;
  NL_CHECK(stat(gone, &st) != 0);
  NL_CHECK(stat(kept, &st) == 0);    /* its writer is alive */
  NL_CHECK(stat(other, &st) == 0);   /* another output's */
  NL_CHECK(stat(out, &st) == 0 && st.st_size == 1);
  unlink(kept);
  unlink(other);
  unlink(out);
  free(gone);
  free(kept);
  free(other);
  free(out);
}

/* Every name the folder accepts can be written: the temporary of a name of
 * NAME_MAX bytes is a short one in the same folder, and nothing is left. */
NL_TEST(longest_names_are_written)
{
  nl_error err;
  char name[256];
  memset(name, 'n', 251);
  strcpy(name + 251, ".png");
  char *path = nl_path_join(dir, name);
  char *t = nl_temp_sibling(path);
  char want[64];
  snprintf(want, sizeof want, "/.nl.%ld.XXXXXX.png", (long)getpid());
  NL_CHECK(strlen(strrchr(t, '/') + 1) <= 255 && strstr(t, want) != NULL);
  free(t);
  NL_CHECK(nl_atomic_write(path, "x", 1, &err) == NL_OK);
  struct stat st;
  NL_CHECK(stat(path, &st) == 0 && st.st_size == 1);
  /* an extension too long to keep: dropped from the temporary only */
  memset(name, 'e', 255);
  name[0] = 'a';
  name[1] = '.';
  name[255] = '\0';
  char *ext = nl_path_join(dir, name);
  NL_CHECK(nl_atomic_write(ext, "y", 1, &err) == NL_OK);
  NL_CHECK(stat(ext, &st) == 0 && st.st_size == 1);
  DIR *d = opendir(dir);
  int hidden = 0;
  for (struct dirent *e; d && (e = readdir(d));)
    hidden += strncmp(e->d_name, ".nl.", 4) == 0;
  if (d) closedir(d);
  NL_CHECK(hidden == 0);
  unlink(path);
  unlink(ext);
  free(path);
  free(ext);
}

NL_TEST(memory_sizes)
{
  char b[32];
  NL_CHECK(strcmp(nl_format_bytes(b, 160e9), "160 GB") == 0);
  NL_CHECK(strcmp(nl_format_bytes(b, 894004096), "894 MB") == 0);
  NL_CHECK(strcmp(nl_format_bytes(b, 12), "12 bytes") == 0);
  NL_CHECK(nl_mem_physical() > 1e6);
  NL_CHECK(nl_mem_fits(1e6) && !nl_mem_fits(1e18));
  /* Held to what is available (MemAvailable), not the total; a cap lowers it. */
  double avail = nl_mem_available();
  NL_CHECK(avail > 1e6 && avail <= nl_mem_physical());
  nl_mem_cap(5e6);
  NL_CHECK(nl_mem_available() == 5e6 && nl_mem_fits(4e6) && !nl_mem_fits(6e6));
  nl_mem_cap(0);
  NL_CHECK(nl_mem_available() > 5e6);
}

static char *slurp_file(const char *path)
{
  static char buf[8192];
  FILE *f = fopen(path, "r");
  if (!f) return NULL;
  size_t n = fread(buf, 1, sizeof buf - 1, f);
  buf[n] = '\0';
  fclose(f);
  return buf;
}

static void write_old(const char *path)
{
  FILE *f = fopen(path, "w");
  fputs("old\n", f);
  fclose(f);
}

NL_TEST(atomic_write_replaces_whole_or_not_at_all)
{
  nl_error err = {{0}};
  char *sub = nl_path_join(dir, "atomic"), *path = nl_path_join(sub, "t.tsv");
  NL_CHECK(nl_mkdir_p(sub, &err) == NL_OK);
  /* A committed write replaces the file. */
  write_old(path);
  nl_atomic_file af;
  NL_CHECK(nl_atomic_open(&af, path, &err) == NL_OK);
  fputs("new\n", af.fp);
  NL_CHECK(strcmp(slurp_file(path), "old\n") == 0);   /* nothing visible before the commit */
  NL_CHECK(nl_atomic_commit(&af, &err) == NL_OK);
  NL_CHECK(strcmp(slurp_file(path), "new\n") == 0);
  /* An aborted write leaves the old file and no temporary. */
  write_old(path);
  NL_CHECK(nl_atomic_open(&af, path, &err) == NL_OK);
  fputs("half", af.fp);
  nl_atomic_abort(&af);
  NL_CHECK(strcmp(slurp_file(path), "old\n") == 0);
  NL_CHECK(nl_test_no_hidden_files(sub));
  /* A commit whose temporary vanished fails and leaves the old file. */
  NL_CHECK(nl_atomic_open(&af, path, &err) == NL_OK);
  fputs("lost", af.fp);
  NL_CHECK(unlink(af.tmp) == 0);
  NL_CHECK(nl_atomic_commit(&af, &err) != NL_OK && err.msg[0] != '\0');
  NL_CHECK(strcmp(slurp_file(path), "old\n") == 0);
  free(sub); free(path);
}

NL_TEST(atomic_write_that_fails_midway_leaves_the_old_file)
{
  /* A real failed write: a file size limit (as a full disk would) makes the
   * data not fit; in a child, so the limit stays there. */
  char *path = nl_path_join(dir, "big.tsv");
  write_old(path);
  pid_t pid = fork();
  if (pid == 0) {
    signal(SIGXFSZ, SIG_IGN);
    struct rlimit rl = {256, 256};
    if (setrlimit(RLIMIT_FSIZE, &rl)) _exit(3);
    nl_atomic_file af;
    nl_error err;
    if (nl_atomic_open(&af, path, &err)) _exit(4);
    for (int i = 0; i < 10000; i++) fputs("0123456789abcdef\n", af.fp);
    _exit(nl_atomic_commit(&af, &err) == NL_OK ? 1 : 0);   /* 0: the commit failed, as it must */
  }
  int status = -1;
  NL_CHECK(pid > 0 && waitpid(pid, &status, 0) == pid);
  NL_CHECK(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  NL_CHECK(strcmp(slurp_file(path), "old\n") == 0);
  NL_CHECK(nl_test_no_hidden_files(dir));
  free(path);
}

/* Targets that are not regular files are never replaced: a symbolic link is
 * followed (the file it names is written atomically, the link stays), a
 * link to nothing is refused, a FIFO and a character device are written
 * through. The devices are private copies made with mknod, as root only. */
NL_TEST(atomic_write_keeps_links_fifos_and_devices)
{
  nl_error err = {{0}};
  char *sub = nl_path_join(dir, "special");
  NL_CHECK(nl_mkdir_p(sub, &err) == NL_OK);
  char *real = nl_path_join(sub, "real.tsv"), *link = nl_path_join(sub, "link.tsv");
  char *dangling = nl_path_join(sub, "dangling.tsv"), *fifo = nl_path_join(sub, "fifo");
  write_old(real);
  NL_CHECK(symlink("real.tsv", link) == 0);
  NL_CHECK(nl_atomic_write(link, "new\n", 4, &err) == NL_OK);
  struct stat st;
  NL_CHECK(lstat(link, &st) == 0 && S_ISLNK(st.st_mode));
  NL_CHECK(strcmp(slurp_file(real), "new\n") == 0);
  NL_CHECK(symlink("nothing.tsv", dangling) == 0);
  NL_CHECK(nl_atomic_write(dangling, "x\n", 2, &err) == NL_EIO);
  NL_CHECK(strstr(err.msg, "dangling.tsv: symbolic link to a missing file") != NULL);
  NL_CHECK(lstat(dangling, &st) == 0 && S_ISLNK(st.st_mode));
  NL_CHECK(mkfifo(fifo, 0644) == 0);
  int rd = open(fifo, O_RDONLY | O_NONBLOCK);
  NL_CHECK(rd >= 0);
  NL_CHECK(nl_atomic_write(fifo, "through\n", 8, &err) == NL_OK);
  char got[16] = "";
  NL_CHECK(rd >= 0 && read(rd, got, sizeof got - 1) == 8 && strcmp(got, "through\n") == 0);
  if (rd >= 0) close(rd);
  NL_CHECK(lstat(fifo, &st) == 0 && S_ISFIFO(st.st_mode));
  if (geteuid() == 0) {
    char *null = nl_path_join(sub, "null"), *full = nl_path_join(sub, "full");
    NL_CHECK(mknod(null, S_IFCHR | 0666, makedev(1, 3)) == 0);
    NL_CHECK(mknod(full, S_IFCHR | 0666, makedev(1, 7)) == 0);
    NL_CHECK(nl_atomic_write(null, "gone\n", 5, &err) == NL_OK);
    NL_CHECK(lstat(null, &st) == 0 && S_ISCHR(st.st_mode));
    /* /dev/full: the write through fails as a full disk would. */
    NL_CHECK(nl_atomic_write(full, "gone\n", 5, &err) == NL_EIO);
    NL_CHECK(strstr(err.msg, "No space left on device") != NULL);
    NL_CHECK(lstat(full, &st) == 0 && S_ISCHR(st.st_mode));
    unlink(null); unlink(full);
    free(null); free(full);
  }
  NL_CHECK(nl_test_no_hidden_files(sub));
  free(sub); free(real); free(link); free(dangling); free(fifo);
}

/* Several files commit together: when the second does not fit (a file
 * size limit, as a full disk), neither is replaced. */
NL_TEST(atomic_commit_all_is_all_or_nothing)
{
  char *sub = nl_path_join(dir, "pair");
  nl_error err = {{0}};
  NL_CHECK(nl_mkdir_p(sub, &err) == NL_OK);
  char *a = nl_path_join(sub, "a.tsv"), *b = nl_path_join(sub, "b.tsv");
  write_old(a);
  write_old(b);
  pid_t pid = fork();
  if (pid == 0) {
    signal(SIGXFSZ, SIG_IGN);
    struct rlimit rl = {256, 256};
    if (setrlimit(RLIMIT_FSIZE, &rl)) _exit(3);
    nl_atomic_file af[2];
    if (nl_atomic_open(&af[0], a, &err) || nl_atomic_open(&af[1], b, &err)) _exit(4);
    fputs("small\n", af[0].fp);
    for (int i = 0; i < 1000; i++) fputs("0123456789abcdef\n", af[1].fp);
    _exit(nl_atomic_commit_all(af, 2, &err) == NL_EIO && strstr(err.msg, "b.tsv") ? 0 : 1);
  }
  int status = -1;
  NL_CHECK(pid > 0 && waitpid(pid, &status, 0) == pid);
  NL_CHECK(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  NL_CHECK(strcmp(slurp_file(a), "old\n") == 0);
  NL_CHECK(strcmp(slurp_file(b), "old\n") == 0);
  NL_CHECK(nl_test_no_hidden_files(sub));
  free(sub); free(a); free(b);
}

/* The library leaves the host's signal dispositions as they were: a program
 * with its own SIGINT handler keeps it after writing through the library
 * (the noiselab programs install their clean-up: nl_harness_program_start). */
static void host_handler(int sig) { (void)sig; }

NL_TEST(library_installs_no_signal_handler)
{
  static const int sigs[3] = {SIGINT, SIGTERM, SIGHUP};
  pid_t pid = fork();
  if (pid == 0) {   /* a fresh process: the test runner's own state stays out */
    struct sigaction mine, was;
    memset(&mine, 0, sizeof mine);
    mine.sa_handler = host_handler;
    if (sigaction(SIGINT, &mine, NULL)) _exit(3);
    struct sigaction before[3];
    for (int k = 0; k < 3; k++) sigaction(sigs[k], NULL, &before[k]);
    nl_error err;
    char *p = nl_path_join(dir, "host.tsv");
    nl_atomic_file af;
    if (nl_atomic_open(&af, p, &err)) _exit(4);
    fputs("x\n", af.fp);
    if (nl_atomic_commit(&af, &err)) _exit(5);
    if (nl_atomic_write(p, "y\n", 2, &err)) _exit(6);
    for (int k = 0; k < 3; k++) {
      sigaction(sigs[k], NULL, &was);
      if (was.sa_handler != before[k].sa_handler) _exit(10 + k);
    }
    sigaction(SIGINT, NULL, &was);
    if (was.sa_handler != host_handler) _exit(20);
    _exit(0);
  }
  int status = -1;
  NL_CHECK(pid > 0 && waitpid(pid, &status, 0) == pid);
  NL_CHECK(WIFEXITED(status));
  if (WIFEXITED(status) && WEXITSTATUS(status))
    printf("  child exit %d (10..12: a disposition changed; 20: SIGINT's handler)\n",
           WEXITSTATUS(status));
  NL_CHECK(WIFEXITED(status) && WEXITSTATUS(status) == 0);
}

NL_TEST(range_checked_parsing)
{
  nl_error err = {{0}};
  long n = 7;
  double v = 7;
  NL_CHECK(nl_parse_long("--n", "42", 0, 100, &n, &err) == NL_OK && n == 42);
  NL_CHECK(nl_parse_long("--n", "-5", -10, 10, &n, &err) == NL_OK && n == -5);
  NL_CHECK(nl_parse_long("--n", "4294967295", 0, 4294967295L, &n, &err) == NL_OK && n == 4294967295L);
  n = 7;
  NL_CHECK(nl_parse_long("--n", "101", 0, 100, &n, &err) == NL_EINVAL && strstr(err.msg, "--n") && strstr(err.msg, "101"));
  NL_CHECK(nl_parse_long("--n", "4294967296", 0, 4294967295L, &n, &err) == NL_EINVAL);
  NL_CHECK(nl_parse_long("--n", "2.5", 0, 100, &n, &err) == NL_EINVAL);
  NL_CHECK(nl_parse_long("--n", "12abc", 0, 100, &n, &err) == NL_EINVAL);
  NL_CHECK(nl_parse_long("--n", "", 0, 100, &n, &err) == NL_EINVAL);
  NL_CHECK(nl_parse_long("--n", "99999999999999999999999", 0, 100, &n, &err) == NL_EINVAL);
  NL_CHECK(n == 7);   /* untouched on error */
  NL_CHECK(nl_parse_double("--x", "0.25", 0, 1, &v, &err) == NL_OK && v == 0.25);
  NL_CHECK(nl_parse_double("--x", "1e-3", 1e-3, 1, &v, &err) == NL_OK && v == 1e-3);   /* ends included */
  v = 7;
  NL_CHECK(nl_parse_double("--x", "1.5", 0, 1, &v, &err) == NL_EINVAL && strstr(err.msg, "--x"));
  NL_CHECK(nl_parse_double("--x", "nan", 0, 1, &v, &err) == NL_EINVAL);
  NL_CHECK(nl_parse_double("--x", "inf", -INFINITY, INFINITY, &v, &err) == NL_EINVAL);   /* finite only */
  NL_CHECK(nl_parse_double("--x", "x", 0, 1, &v, &err) == NL_EINVAL && strstr(err.msg, "'x'"));
  NL_CHECK(nl_parse_double("--x", "0.5 ", 0, 1, &v, &err) == NL_EINVAL);
  NL_CHECK(nl_parse_double("--x", "", 0, 1, &v, &err) == NL_EINVAL);
  /* one reader with tables: a value that underflows to 0 or is hexadecimal
   * is refused; a subnormal is finite and only the range decides */
  NL_CHECK(nl_parse_double("--x", "1e-400", -1, 1, &v, &err) == NL_EINVAL && strstr(err.msg, "'1e-400' underflows to 0"));
  NL_CHECK(nl_parse_double("--x", "0x10", 0, 100, &v, &err) == NL_EINVAL && strstr(err.msg, "'0x10' is hexadecimal"));
  NL_CHECK(nl_parse_double("--x", "1e999", -INFINITY, INFINITY, &v, &err) == NL_EINVAL && strstr(err.msg, "beyond the double range"));
  NL_CHECK(v == 7);
  NL_CHECK(nl_parse_double("--shape", "1e-308", -1e300, 1e300, &v, &err) == NL_OK && v == 1e-308);
  NL_CHECK(nl_parse_double("--x", "4.9406564584124654e-324", 0, 1, &v, &err) == NL_OK && v > 0);
  NL_CHECK(nl_parse_double("--x", "1e-310", 1e-300, 1, &v, &err) == NL_EINVAL && strstr(err.msg, "outside"));
  NL_CHECK(nl_parse_double("--x", "0e-999", 0, 1, &v, &err) == NL_OK && v == 0);
}

/* nl_parallel_for: every item once, per-item streams, so the output bytes do
 * not depend on the thread count; nested regions run serially; thread ids
 * below nl_parallel_threads; OpenBLAS's thread count restored. */
typedef struct {
  double *out;
  int *calls, *thread_seen, nested_threads;
  unsigned long seed;
} par_ctx;

static void par_item(void *vc, size_t i, int t)
{
  par_ctx *c = vc;
  gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(rng, nl_seed_stream(c->seed, "test.parallel", i));
  double s = 0;   /* work that takes a while and depends on the stream only */
  for (int k = 0; k < 2000; k++) s += sin(gsl_rng_uniform(rng) * (double)(k + 1)) / (k + 1);
  c->out[i] = s;
  c->calls[i]++;
  c->thread_seen[i] = t;
  if (i == 3) c->nested_threads = nl_parallel_threads(100, 4);
  gsl_rng_free(rng);
}

NL_TEST(parallel_for_same_bytes_for_any_thread_count)
{
  enum { N = 301 };
  double ref[N];
  int (*blas_get)(void) = (int (*)(void))dlsym(RTLD_DEFAULT, "openblas_get_num_threads");
  int blas0 = blas_get ? blas_get() : 0;
  const int counts[] = {1, 2, 3, 7};
  for (size_t k = 0; k < sizeof counts / sizeof *counts; k++) {
    double out[N];
    int calls[N] = {0}, seen[N];
    par_ctx c = {.out = out, .calls = calls, .thread_seen = seen, .nested_threads = -1, .seed = 42};
    int nt = nl_parallel_threads(N, counts[k]);
    NL_CHECK(nt == counts[k]);
    nl_parallel_for(N, counts[k], par_item, &c);
    int once = 1, ids = 1;
    for (int i = 0; i < N; i++) { once &= calls[i] == 1; ids &= seen[i] >= 0 && seen[i] < nt; }
    NL_CHECK(once && ids);
    NL_CHECK(c.nested_threads == 1);   /* inside a region: serial */
    if (k == 0) memcpy(ref, out, sizeof ref);
    else NL_CHECK(memcmp(ref, out, sizeof ref) == 0);
    if (blas_get) NL_CHECK(blas_get() == blas0);
  }
  NL_CHECK(nl_parallel_threads(N, 2) == 2);   /* the flag is cleared after a region */
  NL_CHECK(nl_parallel_threads(1, 8) == 1 && nl_parallel_threads(5, 0) == 1);
  NL_CHECK(nl_parallel_threads(1000, 1000) == NL_PARALLEL_MAX);
  NL_CHECK(nl_parallel_cores() >= 1);
  nl_parallel_for(0, 4, par_item, NULL);   /* no items: fn never called */
}

static int task_count(void)
{
  DIR *d = opendir("/proc/self/task");
  int n = 0;
  if (!d) return -1;
  for (struct dirent *e; (e = readdir(d));) n += e->d_name[0] != '.';
  closedir(d);
  return n;
}

static void product(const double *a, const double *b, double *c, size_t n)
{
  gsl_matrix_const_view A = gsl_matrix_const_view_array(a, n, n), B = gsl_matrix_const_view_array(b, n, n);
  gsl_matrix_view C = gsl_matrix_view_array(c, n, n);
  gsl_blas_dgemm(CblasNoTrans, CblasNoTrans, 1.0, &A.matrix, &B.matrix, 0.0, &C.matrix);
}

/* nl_wrap_angle lands in [0, 2 pi) from either side, 0 for the angles
 * just below 0 whose sum with 2 pi rounds to 2 pi; nl_lgamma is lgamma. */
NL_TEST(wrap_angle_and_lgamma)
{
  NL_CHECK(nl_wrap_angle(0) == 0 && nl_wrap_angle(NL_TWO_PI) == 0);
  NL_CHECK_NEAR(nl_wrap_angle(-1.0), NL_TWO_PI - 1.0, 0);
  NL_CHECK_NEAR(nl_wrap_angle(3 * NL_TWO_PI + 0.5), fmod(3 * NL_TWO_PI + 0.5, NL_TWO_PI), 0);
  NL_CHECK(nl_wrap_angle(-1e-300) == 0);   /* -1e-300 + 2 pi rounds to 2 pi */
  for (double t = -50; t < 50; t += 0.37) {
    double w = nl_wrap_angle(t);
    NL_CHECK(w >= 0 && w < NL_TWO_PI);
  }
  const double xs[] = {0.5, 1, 2, 10.5, 171.3, 1e5, -2.5};
  for (size_t k = 0; k < sizeof xs / sizeof *xs; k++) NL_CHECK(nl_lgamma(xs[k]) == lgamma(xs[k]));
  NL_CHECK_NEAR(nl_lgamma(5), log(24.0), 1e-15);
}

/* The limit/restore pair: OpenBLAS at one thread in between, its count
 * given back after; nothing changes without OpenBLAS or at one thread. */
NL_TEST(blas_limit_and_restore)
{
  int (*blas_get)(void) = (int (*)(void))dlsym(RTLD_DEFAULT, "openblas_get_num_threads");
  int before = nl_parallel_blas_threads();
  NL_CHECK(before == (blas_get ? blas_get() : -1));
  int was = nl_parallel_blas_limit();
  NL_CHECK(was == (before > 1 ? before : 0));
  if (blas_get) NL_CHECK(nl_parallel_blas_threads() == 1 || before < 1);
  nl_parallel_blas_restore(was);
  NL_CHECK(nl_parallel_blas_threads() == before);
  printf("  OpenBLAS threads: %d (-1: not loaded)\n", before);
}

/* nl_parallel_blas_idle stops OpenBLAS's idle workers (the process has
 * fewer threads), and a threaded product afterwards, which starts them
 * again, gives the bytes of one before. */
NL_TEST(blas_idle_stops_workers_same_bytes)
{
  int (*blas_get)(void) = (int (*)(void))dlsym(RTLD_DEFAULT, "openblas_get_num_threads");
  if (!blas_get || blas_get() < 2) return;   /* no OpenBLAS, or one thread: nothing to stop */
  enum { N = 400 };   /* 400^3: OpenBLAS runs it on its threads */
  double *a = malloc(N * N * sizeof *a), *b = malloc(N * N * sizeof *b);
  double *c1 = malloc(N * N * sizeof *c1), *c2 = malloc(N * N * sizeof *c2);
  for (int i = 0; i < N * N; i++) { a[i] = sin(0.37 * i) + 1e-3 * (i % 13); b[i] = cos(0.11 * i) - 0.3 * (i % 3); }
  product(a, b, c1, N);
  int before = task_count();
  nl_parallel_blas_idle();
  /* A joined thread can stay listed in /proc/self/task until the kernel has
   * finished its exit (seen under qemu-aarch64): give it up to 2 s. */
  int after = task_count();
  for (int tries = 0; tries < 200 && after >= before; tries++) {
    usleep(10000);
    after = task_count();
  }
  NL_CHECK(after < before);
  product(a, b, c2, N);
  NL_CHECK(memcmp(c1, c2, N * N * sizeof *c1) == 0);
  NL_CHECK(task_count() == before);
  nl_parallel_blas_idle();   /* twice in a row: nothing left to stop */
  nl_parallel_blas_idle();
  free(a); free(b); free(c1); free(c2);
}

NL_TEST(allocation_reports_failure_and_obeys_the_hook)
{
  /* malloc's contract: NULL only on failure, 0 bytes is one, overflow refused. */
  void *p = nl_malloc(0);
  NL_CHECK(p != NULL);
  free(p);
  NL_CHECK(nl_calloc((size_t)-1 / 2, 4) == NULL);
  NL_CHECK(nl_malloc_array((size_t)-1 / 2, 4) == NULL);
  double *d = nl_calloc(3, sizeof *d);
  NL_CHECK(d && d[0] == 0 && d[2] == 0);
  d = nl_realloc(d, 5 * sizeof *d);
  NL_CHECK(d != NULL);
  free(d);
  char *s = nl_strdup("abc");
  NL_CHECK(s && strcmp(s, "abc") == 0);
  free(s);
  nl_error err;
  NL_CHECK(nl_fail_nomem(&err, "nl_thing", 24) == NL_ENOMEM);
  NL_CHECK(strcmp(err.msg, "nl_thing: out of memory allocating 24 bytes") == 0);

  /* The counting hook refuses the k-th allocation only: here a call that
   * allocates twice is refused twice, then runs whole. */
  nl_status st = NL_OK;
  NL_FAIL_EACH_ALLOC(st, (void)0, {
      char *a = nl_strdup("x"), *b = a ? nl_malloc(8) : NULL;
      st = a && b ? NL_OK : NL_ENOMEM;
      free(a); free(b);
    });
  NL_CHECK(nl_test_alloc_runs() == 3);
  p = nl_malloc(1);   /* the hook is removed after the loop */
  NL_CHECK(p != NULL);
  free(p);
}

int main(void)
{
  dir = nl_test_tmpdir();
  return nl_test_run();
}
