/* nl_tool.c - the tools' common start (nl_tool.h). */
#include "nl_tool.h"

#include "harness/nl_harness.h"

#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdarg.h>
#include <spawn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

static const char *tool_name = "noiselab";

/* atexit: registered before any output's clean-up (nl_atomic_open registers
 * its own on first use), so it runs last, once the temporaries are gone. */
static void tool_close_stdout(void)
{
  nl_error err;
  if (nl_stream_close(stdout, "standard output", &err)) {
    nl_message(stderr, "%s: %s", tool_name, err.msg);
    _exit(2);
  }
}

void nl_tool_start(const char *name)
{
  tool_name = name;
  nl_harness_program_start();
  signal(SIGXFSZ, SIG_IGN);
  atexit(tool_close_stdout);
  /* Test hook (nl_mem_cap, base/nl_base.h): NL_MEMAVAILABLE_OVERRIDE=BYTES
   * counts at most BYTES as available, so the suite tests a refusal at a
   * size this machine could allocate. */
  const char *mem_cap = getenv("NL_MEMAVAILABLE_OVERRIDE");
  if (mem_cap && *mem_cap) nl_mem_cap(strtod(mem_cap, NULL));
}

void nl_tool_die(const char *prefix, const char *fmt, ...)
{
  va_list ap;
  va_start(ap, fmt);
  fputs(prefix, stderr);
  nl_vmessage(stderr, fmt, ap);
  va_end(ap);
  exit(2);
}

/* path made absolute with every link resolved; for a path that does not
 * exist yet, its folder resolved and its name kept. NULL when even the
 * folder cannot be resolved (the output's own check says why). */
static char *resolved(const char *path)
{
  char *r = realpath(path, NULL);
  if (r) return r;
  const char *slash = strrchr(path, '/');
  char *dir = slash ? strndup(path, slash == path ? 1 : (size_t)(slash - path)) : nl_xstrdup(".");
  char *rdir = dir ? realpath(dir, NULL) : NULL;
  free(dir);
  if (!rdir) return NULL;
  char *j = nl_path_join(rdir, slash ? slash + 1 : path);
  free(rdir);
  return j;
}

static int inside(const char *path, const char *dir)
{
  size_t n = strlen(dir);
  return !strncmp(path, dir, n) && (path[n] == '/' || path[n] == '\0');
}

/* git's answer for rel inside root: 0 tracked, 1 not tracked, -1 no answer
 * (no git, not a checkout, a git that refuses the folder). posix_spawn, not
 * fork: the process may have threads (OpenBLAS's). GIT_DIR and
 * GIT_WORK_TREE, which would point git elsewhere, are left out. */
static int git_tracked(const char *root, const char *rel)
{
  extern char **environ;
  size_t n = 0;
  while (environ[n]) n++;
  char **env = nl_xcalloc(n + 1, sizeof *env);
  for (size_t i = 0, k = 0; i < n; i++)
    if (strncmp(environ[i], "GIT_DIR=", 8) && strncmp(environ[i], "GIT_WORK_TREE=", 14))
      env[k++] = environ[i];
  char *argv[] = {"git", "--literal-pathspecs", "-C", (char *)root, "ls-files",
                  "--error-unmatch", "--", (char *)rel, NULL};
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  for (int fd = 0; fd < 3; fd++)
    posix_spawn_file_actions_addopen(&fa, fd, "/dev/null", fd ? O_WRONLY : O_RDONLY, 0);
  pid_t pid;
  int rc = posix_spawnp(&pid, "git", &fa, NULL, argv, env);
  posix_spawn_file_actions_destroy(&fa);
  free(env);
  if (rc != 0) return -1;
  int st;
  while (waitpid(pid, &st, 0) < 0)
    if (errno != EINTR) return -1;
  if (!WIFEXITED(st)) return -1;
  return WEXITSTATUS(st) == 0 ? 0 : WEXITSTATUS(st) == 1 ? 1 : -1;
}

/* 1 when abs names a file of the sources (nl_tool.h), with *root set to
 * the source tree (caller frees). */
static int source_file(const char *abs, char **root)
{
  *root = realpath(NL_TOOL_SOURCE_ROOT, NULL);
  if (!*root || !inside(abs, *root) || !strcmp(abs, *root)) return 0;
  const char *rel = abs + strlen(*root) + 1;
  if (inside(rel, "results")) return 0;
  char *build = realpath(NL_TOOL_BUILD_ROOT, NULL);
  int in_build = build && inside(abs, build);
  free(build);
  if (in_build) return 0;
  int g = git_tracked(*root, rel);
  if (g >= 0) return g == 0;
  struct stat st;
  return strncmp(rel, "build", 5) && lstat(abs, &st) == 0;
}

void nl_tool_check_output(const char *out, const char *const *inputs, int n)
{
  if (!out || !strcmp(out, "-")) return;
  struct stat so;
  int have = stat(out, &so) == 0;
  if (have && (S_ISCHR(so.st_mode) || S_ISFIFO(so.st_mode))) return;
  char *ro = resolved(out);
  for (int i = 0; i < n; i++) {
    const char *in = inputs[i];
    struct stat si;
    if (!in || !strcmp(in, "-")) continue;
    int same;
    if (have && stat(in, &si) == 0) same = so.st_dev == si.st_dev && so.st_ino == si.st_ino;
    else {
      char *ri = resolved(in);
      same = ro && ri && !strcmp(ro, ri);
      free(ri);
    }
    if (same) {
      nl_message(stderr, "%s: %s: is the input %s; an output never replaces what the command "
                 "reads (choose another name)", tool_name, out, in);
      exit(1);
    }
  }
  char *root = NULL;
  if (ro && source_file(ro, &root)) {
    nl_message(stderr, "%s: %s: a file of the noiselab sources in %s; outputs go outside the "
               "repository, or into its results/ or build folder", tool_name, out, root);
    exit(1);
  }
  free(root);
  free(ro);
}
