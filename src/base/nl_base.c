#include "base/nl_base.h"

#include <ctype.h>
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio_ext.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

/* ---- one-line messages ---------------------------------------------- */

/* fmt formatted in full, with every control character escaped (newline as
 * \n, tab as \t, the others and DEL as \xNN): an input echoed in a message,
 * a file name or an argument holding a newline, still gives one line.
 * Backslashes stay as they are, so escaping twice changes nothing. */
static char *message_vformat(const char *fmt, va_list ap)
{
  va_list aq;
  va_copy(aq, ap);
  int n = vsnprintf(NULL, 0, fmt, aq);
  va_end(aq);
  if (n < 0) return nl_xstrdup("(the message could not be formatted)");
  char *raw = nl_xmalloc((size_t)n + 1);
  vsnprintf(raw, (size_t)n + 1, fmt, ap);
  char *out = nl_xmalloc(4 * (size_t)n + 1);
  char *o = out;
  for (const unsigned char *c = (const unsigned char *)raw; *c; c++) {
    if (*c == '\n') { *o++ = '\\'; *o++ = 'n'; }
    else if (*c == '\t') { *o++ = '\\'; *o++ = 't'; }
    else if (*c < 0x20 || *c == 0x7f) o += sprintf(o, "\\x%02x", *c);
    else *o++ = (char)*c;
  }
  *o = '\0';
  free(raw);
  return out;
}

/* Width a word keeps when it is shortened, "head...tail", and its least. */
enum { MESSAGE_WORD_MIN = 24 };

static int utf8_continuation(char c) { return ((unsigned char)c & 0xc0) == 0x80; }

/* Copies word w (length n) into d shortened to about `keep` bytes: a third
 * from its start, the rest from its end (a path's file name), "..." between;
 * no UTF-8 character is cut. Returns the bytes written. */
static size_t message_word_cut(char *d, const char *w, size_t n, size_t keep)
{
  if (n <= keep) {
    memcpy(d, w, n);
    return n;
  }
  size_t head = (keep - 3) / 3, tail = keep - 3 - head;
  while (head > 0 && utf8_continuation(w[head])) head--;
  while (tail > 0 && utf8_continuation(w[n - tail])) tail--;
  memcpy(d, w, head);
  memcpy(d + head, "...", 3);
  memcpy(d + head + 3, w + n - tail, tail);
  return head + 3 + tail;
}

/* Length of s with every word (a run without spaces) over `keep` bytes cut. */
static size_t message_fitted_length(const char *s, size_t keep)
{
  size_t total = 0;
  while (*s) {
    size_t w = strcspn(s, " ");
    total += (w > keep ? keep : w);
    s += w;
    size_t sp = strspn(s, " ");
    total += sp;
    s += sp;
  }
  return total;
}

/* Puts s into dst[cap]. A message too long for it loses the middle of its
 * longest words, never its end: the long words are the paths and the values
 * echoed ("/very/lo...ng/name.tsv: directory /very/lo...ng does not exist"),
 * the reason is short words after them. */
static void message_fit(char *dst, size_t cap, const char *s)
{
  size_t len = strlen(s);
  if (len < cap) {
    memcpy(dst, s, len + 1);
    return;
  }
  /* the widest cut that fits: the fitted length grows with it */
  size_t lo = MESSAGE_WORD_MIN, hi = len;
  while (lo < hi) {
    size_t mid = lo + (hi - lo + 1) / 2;
    if (message_fitted_length(s, mid) < cap) lo = mid;
    else hi = mid - 1;
  }
  size_t keep = lo;
  /* Each word is cut into cut[] first; what is left of dst may be shorter
   * still when even MESSAGE_WORD_MIN is too long (then the end is lost). */
  char *cut = nl_xmalloc(keep + 1);
  char *d = dst, *end = dst + cap - 1;
  while (*s && d < end) {
    size_t w = strcspn(s, " ");
    size_t m = message_word_cut(cut, s, w, keep);
    size_t room = (size_t)(end - d);
    if (m > room) m = room;
    memcpy(d, cut, m);
    d += m;
    s += w;
    while (*s == ' ' && d < end) *d++ = *s++;
  }
  free(cut);
  *d = '\0';
}

nl_status nl_fail(nl_error *err, nl_status status, const char *fmt, ...)
{
  if (err) {
    va_list ap;
    va_start(ap, fmt);
    char *m = message_vformat(fmt, ap);
    va_end(ap);
    message_fit(err->msg, sizeof err->msg, m);
    free(m);
  }
  return status;
}

void nl_vmessage(FILE *f, const char *fmt, va_list ap)
{
  char *m = message_vformat(fmt, ap);
  fprintf(f, "%s\n", m);
  free(m);
}

void nl_message(FILE *f, const char *fmt, ...)
{
  va_list ap;
  va_start(ap, fmt);
  nl_vmessage(f, fmt, ap);
  va_end(ap);
}

static nl_alloc_hook alloc_hook = NULL;
static void *alloc_hook_ctx = NULL;

void nl_alloc_set_hook(nl_alloc_hook h, void *ctx)
{
  alloc_hook = h;
  alloc_hook_ctx = ctx;
}

static int alloc_allowed(size_t n)
{
  return !alloc_hook || alloc_hook(n, alloc_hook_ctx);
}

void *nl_malloc(size_t n)
{
  return alloc_allowed(n) ? malloc(n ? n : 1) : NULL;
}

void *nl_malloc_array(size_t n, size_t size)
{
  if (size && n > SIZE_MAX / size) return NULL;
  return nl_malloc(n * size);
}

void *nl_calloc(size_t n, size_t size)
{
  if (size && n > SIZE_MAX / size) return NULL;
  return alloc_allowed(n * size) ? calloc(n ? n : 1, size ? size : 1) : NULL;
}

void *nl_realloc(void *p, size_t n)
{
  return alloc_allowed(n) ? realloc(p, n ? n : 1) : NULL;
}

char *nl_strdup(const char *s)
{
  size_t n = strlen(s) + 1;
  char *d = nl_malloc(n);
  if (d) memcpy(d, s, n);
  return d;
}

nl_status nl_fail_nomem(nl_error *err, const char *what, size_t n)
{
  if (what) return nl_fail(err, NL_ENOMEM, "%s: out of memory allocating %zu bytes", what, n);
  return nl_fail(err, NL_ENOMEM, "out of memory allocating %zu bytes", n);
}

/* NULL: abort() after the message, as GSL's default error handler does. */
static nl_oom_handler oom_handler = NULL;

nl_oom_handler nl_set_oom_handler(nl_oom_handler h)
{
  nl_oom_handler old = oom_handler;
  oom_handler = h;
  return old;
}

/* The message is always the same; the handler only decides how to end. */
static void oom(size_t n)
{
  fprintf(stderr, "noiselab: out of memory allocating %zu bytes\n", n);
  if (oom_handler) oom_handler(n);
  abort();   /* the default, and a handler must not return */
}

void *nl_xmalloc(size_t n)
{
  void *p = malloc(n ? n : 1);
  if (!p) oom(n);
  return p;
}

void *nl_xcalloc(size_t n, size_t size)
{
  void *p = calloc(n ? n : 1, size ? size : 1);
  if (!p) oom(n * size);
  return p;
}

void *nl_xrealloc(void *p, size_t n)
{
  void *q = realloc(p, n ? n : 1);
  if (!q) oom(n);
  return q;
}

char *nl_xstrdup(const char *s)
{
  size_t n = strlen(s) + 1;
  char *d = nl_xmalloc(n);
  memcpy(d, s, n);
  return d;
}

char *nl_path_join(const char *dir, const char *name)
{
  size_t a = strlen(dir), b = strlen(name);
  char *p = nl_xmalloc(a + b + 2);
  memcpy(p, dir, a);
  size_t k = a;
  if (a > 0 && dir[a - 1] != '/') p[k++] = '/';
  memcpy(p + k, name, b + 1);
  return p;
}

/* The longest file name the folder `dir` (length dirlen, "" for ".")
 * accepts: pathconf's, or POSIX's usual 255 when it cannot say. */
static size_t name_max_in(const char *dir, size_t dirlen)
{
  char *d = dirlen ? nl_xmalloc(dirlen + 1) : nl_xstrdup(".");
  if (dirlen) {
    memcpy(d, dir, dirlen);
    d[dirlen] = '\0';
  }
  long m = pathconf(d, _PC_NAME_MAX);
  free(d);
  return m > 0 ? (size_t)m : 255;
}

/* nl_temp_sibling's template; *suffix: the bytes after its XXXXXX, for
 * mkstemps. The writer's pid is in the name, so that a later writer of the
 * same output can tell a temporary whose writer was killed outright
 * (SIGKILL runs no clean-up) from one being written (remove_stale_temps). */
static char *temp_template(const char *path, int *suffix)
{
  const char *slash = strrchr(path, '/');
  const char *base = slash ? slash + 1 : path;
  const char *dot = strrchr(base, '.');
  size_t dirlen = (size_t)(base - path);
  size_t stemlen = dot ? (size_t)(dot - base) : strlen(base);
  const char *ext = dot ? dot : "";
  size_t extlen = strlen(ext), name_max = name_max_in(path, dirlen);
  char pid[24];
  size_t pidlen = (size_t)snprintf(pid, sizeof pid, "%ld", (long)getpid());
  /* ".stem.PID.XXXXXX.ext" is 9 + pidlen bytes longer than the name: for a
   * name the folder accepts but that leaves no room, the temporary is
   * ".nl.PID.XXXXXX.ext" (without the extension if even that is too long),
   * a name the clean-up of leftovers still knows (".?*.XXXXXX[.*]",
   * scripts/noiselab). */
  const char *stem = base;
  size_t extra = 9 + pidlen;
  if (stemlen + extlen + extra > name_max) {
    stem = "nl";
    stemlen = 2;
    if (stemlen + extlen + extra > name_max) extlen = 0;
  }
  size_t n = dirlen + 1 + stemlen + extra + extlen + 1;
  char *t = nl_xmalloc(n);
  snprintf(t, n, "%.*s.%.*s.%s.XXXXXX%.*s", (int)dirlen, path, (int)stemlen, stem, pid,
           (int)extlen, ext);
  *suffix = (int)extlen;
  return t;
}

/* With name ".PREFIX.PID.XXXXXX" + a tail (one of the temporary names of
 * temp_template for this target), the writer's pid; else 0. */
static long temp_writer(const char *name, const char *prefix, size_t plen, const char *ext)
{
  if (strncmp(name, prefix, plen)) return 0;
  const char *p = name + plen, *q = p;
  while (*q >= '0' && *q <= '9') q++;
  if (q == p || q - p > 18 || *q != '.') return 0;
  for (int k = 1; k <= 6; k++)
    if (!q[k] || q[k] == '/') return 0;
  if (strcmp(q + 7, ext) && q[7]) return 0;
  return strtol(p, NULL, 10);
}

/* Removes the temporaries of `target` (temp_template's names, the short
 * ".nl." form included) whose writer is no live process: a writer killed
 * outright left them. A writer alive, or one this process may not signal
 * (EPERM: it exists), keeps its file. */
static void remove_stale_temps(const char *target)
{
  const char *slash = strrchr(target, '/');
  const char *base = slash ? slash + 1 : target;
  const char *dot = strrchr(base, '.');
  size_t stemlen = dot ? (size_t)(dot - base) : strlen(base);
  const char *ext = dot ? dot : "";
  char *dir = slash ? nl_xmalloc((size_t)(slash - target) + 2) : nl_xstrdup(".");
  if (slash) {
    size_t dl = slash == target ? 1 : (size_t)(slash - target);
    memcpy(dir, target, dl);
    dir[dl] = '\0';
  }
  char *prefix = nl_xmalloc(stemlen + 3);
  snprintf(prefix, stemlen + 3, ".%.*s.", (int)stemlen, base);
  DIR *d = opendir(dir);
  if (d) {
    pid_t me = getpid();
    for (struct dirent *e; (e = readdir(d));) {
      long pid = temp_writer(e->d_name, prefix, stemlen + 2, ext);
      if (!pid) pid = temp_writer(e->d_name, ".nl.", 4, ext);
      if (pid <= 0 || pid == me || pid > 0x7fffffffL) continue;
      if (kill((pid_t)pid, 0) != 0 && errno == ESRCH) unlinkat(dirfd(d), e->d_name, 0);
    }
    closedir(d);
  }
  free(prefix);
  free(dir);
}

char *nl_temp_sibling(const char *path)
{
  int suffix;
  return temp_template(path, &suffix);
}

/* ---- the temporaries open in this process ---------------------------
 *
 * A fixed table of the temporaries open in this process, claimed and
 * released with atomic exchanges so that threads writing at once need no
 * lock and a signal handler can read it: nl_atomic_unlink_open only calls
 * unlink() (async-signal-safe). The pid kept with each entry stops a forked
 * child that calls exit() from removing its parent's files. Who calls it, at
 * exit or on a signal, is the program's choice (the lab's
 * nl_harness_program_start): the library installs no handler. */
#define LIVE_MAX 256
static char *live_name[LIVE_MAX];
static pid_t live_pid[LIVE_MAX];

void nl_atomic_unlink_open(void)
{
  pid_t me = getpid();
  for (int i = 0; i < LIVE_MAX; i++) {
    char *name = __atomic_load_n(&live_name[i], __ATOMIC_ACQUIRE);
    if (name && __atomic_load_n(&live_pid[i], __ATOMIC_ACQUIRE) == me) unlink(name);
  }
}

static int live_add(char *name)
{
  for (int i = 0; i < LIVE_MAX; i++) {
    char *none = NULL;
    __atomic_store_n(&live_pid[i], getpid(), __ATOMIC_RELEASE);
    if (__atomic_compare_exchange_n(&live_name[i], &none, name, 0, __ATOMIC_ACQ_REL,
                                    __ATOMIC_ACQUIRE))
      return i + 1;
  }
  return 0;   /* full: this temporary is still removed by commit and abort */
}

static void live_remove(int slot)
{
  if (slot > 0) __atomic_store_n(&live_name[slot - 1], NULL, __ATOMIC_RELEASE);
}

/* ---- atomic output ----------------------------------------------------- */

static nl_status path_check_folder(const char *path, nl_error *err);

/* Closes and removes whatever af still holds, and frees it. */
static void atomic_release(nl_atomic_file *af)
{
  if (af->fp) fclose(af->fp);
  live_remove(af->slot);
  if (af->tmp) unlink(af->tmp);
  if (af->target != af->path) free(af->target);
  free(af->path);
  free(af->tmp);
  memset(af, 0, sizeof *af);
}

/* A character device or a FIFO is written in place: replacing it by a file
 * would break what reads it (a pipe) or the system (/dev/null as root). */
static nl_status atomic_through(nl_atomic_file *af, const char *path, const char *target,
                                nl_error *err)
{
  int fd = open(target, O_WRONLY | O_NOCTTY | O_CLOEXEC);
  if (fd < 0) return nl_fail(err, NL_EIO, "%s: cannot open: %s", path, strerror(errno));
  af->fp = fdopen(fd, "w");
  if (!af->fp) {
    nl_status s = nl_fail(err, NL_EIO, "%s: cannot open: %s", path, strerror(errno));
    close(fd);
    return s;
  }
  af->path = nl_xstrdup(path);
  af->target = af->path;
  return NL_OK;
}

/* What is at path decides the target (nl_base.h); *through is set for a
 * device or FIFO. Returns the target (path itself, or a link's resolution
 * the caller frees) or NULL after a refusal. */
static char *atomic_target(const char *path, int *through, nl_error *err)
{
  struct stat st;
  *through = 0;
  if (lstat(path, &st) != 0) {
    if (errno == ENOENT) return (char *)path;
    nl_fail(err, NL_EIO, "%s: %s", path, strerror(errno));
    return NULL;
  }
  char *target = (char *)path;
  if (S_ISLNK(st.st_mode)) {
    if (stat(path, &st) != 0) {
      nl_fail(err, NL_EIO, "%s: symbolic link to a missing file; not followed", path);
      return NULL;
    }
    /* /dev/stdout names /proc/self/fd/1, which may be a pipe: opened as is. */
    if (S_ISCHR(st.st_mode) || S_ISFIFO(st.st_mode)) {
      *through = 1;
      return target;
    }
    target = realpath(path, NULL);
    if (!target) {
      nl_fail(err, NL_EIO, "%s: cannot follow symbolic link: %s", path, strerror(errno));
      return NULL;
    }
  }
  if (S_ISREG(st.st_mode)) return target;
  if (S_ISCHR(st.st_mode) || S_ISFIFO(st.st_mode)) {
    *through = 1;
    return target;
  }
  if (S_ISDIR(st.st_mode)) nl_fail(err, NL_EIO, "%s: is a directory", path);
  else nl_fail(err, NL_EIO, "%s: not a regular file, character device or FIFO; not replaced", path);
  if (target != path) free(target);
  return NULL;
}

nl_status nl_atomic_open(nl_atomic_file *af, const char *path, nl_error *err)
{
  memset(af, 0, sizeof *af);
  /* "", "dir/", a directory or a parent that is a file: say so, naming the
   * target, before a temporary file is made. */
  nl_status c = path_check_folder(path, err);
  if (c) return c;
  int through;
  char *target = atomic_target(path, &through, err);
  if (!target) return NL_EIO;
  if (through) {
    nl_status s = atomic_through(af, path, target, err);
    if (target != path) free(target);
    return s;
  }
  if (target != path && (c = path_check_folder(target, err))) {
    free(target);
    return c;
  }
  af->path = nl_xstrdup(path);
  af->target = target == path ? af->path : target;
  remove_stale_temps(af->target);
  int suffix;
  af->tmp = temp_template(af->target, &suffix);
  int fd = mkstemps(af->tmp, suffix);
  if (fd < 0) {
    int e = errno;
    /* The reason, naming the target rather than the temporary name. */
    nl_status s = path_check_folder(af->target, err);
    if (!s) s = nl_fail(err, NL_EIO, "%s: cannot create: %s", path, strerror(e));
    free(af->tmp);
    af->tmp = NULL;
    atomic_release(af);
    return s;
  }
  af->slot = live_add(af->tmp);
  /* mkstemp makes 0600 files; results are meant to be shared. */
  fchmod(fd, 0644);
  af->fp = fdopen(fd, "w");
  if (!af->fp) {
    nl_status s = nl_fail(err, NL_EIO, "%s: cannot open: %s", path, strerror(errno));
    close(fd);
    atomic_release(af);
    return s;
  }
  return NL_OK;
}

/* Flushes and closes af->fp and checks that every byte is on the disk:
 * stdio's error flag, fsync, the file's size against the bytes written,
 * close. A full disk or a file size limit shows in one of them even where
 * a library writing through stdio ignored its own failed writes. */
static nl_status atomic_finish(nl_atomic_file *af, nl_error *err)
{
  int e = 0;
  long long wrote = -1, size = -1;
  /* A failed write sets the stream's error flag and errno; later calls
   * that succeed leave errno as it was, so it still names the reason. */
  if (fflush(af->fp) != 0 || ferror(af->fp)) {
    e = errno ? errno : EIO;
  } else if (af->tmp) {
    struct stat st;
    int fd = fileno(af->fp);
    wrote = (long long)ftello(af->fp);
    if (fsync(fd) != 0) e = errno;
    else if (fstat(fd, &st) != 0) e = errno;
    else size = (long long)st.st_size;
  }
  if (fclose(af->fp) != 0 && !e) e = errno;
  af->fp = NULL;
  if (e) return nl_fail(err, NL_EIO, "%s: write failed: %s", af->path, strerror(e));
  if (wrote != size)
    return nl_fail(err, NL_EIO, "%s: write failed: %lld of %lld bytes reached the disk",
                   af->path, size, wrote);
  return NL_OK;
}

nl_status nl_atomic_commit_all(nl_atomic_file *af, size_t n, nl_error *err)
{
  nl_status s = NL_OK;
  for (size_t i = 0; i < n; i++)
    if (af[i].fp) {
      nl_status t = atomic_finish(&af[i], s ? NULL : err);
      if (!s) s = t;
    }
  for (size_t i = 0; i < n; i++) {
    if (!af[i].path) continue;
    if (!s && af[i].tmp) {
      if (rename(af[i].tmp, af[i].target) != 0) {
        s = nl_fail(err, NL_EIO, "%s: cannot rename into place: %s", af[i].path,
                    strerror(errno));
      } else {
        live_remove(af[i].slot);
        af[i].slot = 0;
        free(af[i].tmp);
        af[i].tmp = NULL;
      }
    }
    atomic_release(&af[i]);
  }
  return s;
}

nl_status nl_atomic_commit(nl_atomic_file *af, nl_error *err)
{
  return nl_atomic_commit_all(af, 1, err);
}

void nl_atomic_abort(nl_atomic_file *af)
{
  atomic_release(af);
}

nl_status nl_atomic_write(const char *path, const void *data, size_t n, nl_error *err)
{
  nl_atomic_file af;
  nl_status s = nl_atomic_open(&af, path, err);
  if (s) return s;
  if (fwrite(data, 1, n, af.fp) != n) {
    s = nl_fail(err, NL_EIO, "%s: write failed: %s", path, strerror(errno));
    nl_atomic_abort(&af);
    return s;
  }
  return nl_atomic_commit(&af, err);
}

nl_status nl_mkdir_p(const char *dir, nl_error *err)
{
  if (!dir || !*dir) return nl_fail(err, NL_EINVAL, "'': empty directory name");
  char *p = nl_xstrdup(dir);
  for (char *q = p + 1; ; q++) {
    if (*q == '/' || *q == '\0') {
      char c = *q;
      *q = '\0';
      if (mkdir(p, 0755) != 0 && errno != EEXIST) {
        nl_status s;
        if (errno == ENOTDIR) {
          /* name the component that is a file */
          struct stat st;
          char *q2 = p + 1;
          for (;; q2++)
            if (*q2 == '/' || *q2 == '\0') {
              char c2 = *q2;
              *q2 = '\0';
              int file = stat(p, &st) == 0 && !S_ISDIR(st.st_mode);
              if (file || c2 == '\0') break;
              *q2 = c2;
            }
          s = nl_fail(err, NL_EIO, "%s: cannot create directory: %s is not a directory", dir, p);
        } else {
          s = nl_fail(err, NL_EIO, "%s: cannot create directory %s: %s", dir, p, strerror(errno));
        }
        free(p);
        return s;
      }
      *q = c;
      if (c == '\0') break;
    }
  }
  struct stat st;
  nl_status s = NL_OK;
  if (stat(dir, &st) != 0 || !S_ISDIR(st.st_mode))
    s = nl_fail(err, NL_EIO, "%s: not a directory", dir);
  free(p);
  return s;
}

/* The checks of nl_path_check_writable on the name itself and its folder. */
static nl_status path_check_folder(const char *path, nl_error *err)
{
  if (!path || !*path) return nl_fail(err, NL_EINVAL, "'': empty file name");
  size_t n = strlen(path);
  if (path[n - 1] == '/') return nl_fail(err, NL_EINVAL, "%s: names a directory, not a file", path);
  /* A device or FIFO is written through (nl_atomic_open): its folder need
   * not be writable (/dev/null, /dev/stdout for a user). */
  struct stat dev;
  if (stat(path, &dev) == 0 && (S_ISCHR(dev.st_mode) || S_ISFIFO(dev.st_mode))) return NL_OK;
  const char *slash = strrchr(path, '/');
  char *dir = slash ? nl_xstrdup(path) : nl_xstrdup(".");
  if (slash) dir[slash == path ? 1 : (size_t)(slash - path)] = '\0';
  struct stat st;
  nl_status s = NL_OK;
  if (stat(dir, &st) != 0) {
    if (errno == ENOTDIR)
      s = nl_fail(err, NL_EIO, "%s: a parent of %s is not a directory", path, dir);
    else if (errno == ENOENT)
      s = nl_fail(err, NL_EIO, "%s: directory %s does not exist", path, dir);
    else
      s = nl_fail(err, NL_EIO, "%s: parent %s: %s", path, dir, strerror(errno));
  } else if (!S_ISDIR(st.st_mode)) {
    s = nl_fail(err, NL_EIO, "%s: parent %s is not a directory", path, dir);
  } else if (access(dir, W_OK) != 0) {
    s = nl_fail(err, NL_EIO, "%s: directory %s is not writable: %s", path, dir, strerror(errno));
  } else if (stat(path, &st) == 0 && S_ISDIR(st.st_mode)) {
    s = nl_fail(err, NL_EIO, "%s: is a directory", path);
  }
  free(dir);
  return s;
}

nl_status nl_path_check_writable(const char *path, nl_error *err)
{
  nl_status s = path_check_folder(path, err);
  if (s) return s;
  /* What is there (nl_atomic_open's rules): a link to nothing, a socket or
   * a block device is refused now, before any work; a link's target must
   * be writable in its own folder. */
  int through;
  char *target = atomic_target(path, &through, err);
  if (!target) return NL_EIO;
  if (target != path) {
    s = through ? NL_OK : path_check_folder(target, err);
    free(target);
  }
  return s;
}

double nl_mem_physical(void)
{
  long pages = sysconf(_SC_PHYS_PAGES), size = sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || size <= 0) return 0;
  return (double)pages * (double)size;
}

static double mem_cap;   /* nl_mem_cap: 0 for none */

void nl_mem_cap(double bytes) { mem_cap = bytes > 0 ? bytes : 0; }

/* MemAvailable is the kernel's estimate of what can be allocated without
 * swapping (free memory plus the reclaimable caches); a machine whose other
 * processes hold most of its RAM cannot give us the total. Linux before 3.14
 * has no MemAvailable: the total is the best we know there. */
double nl_mem_available(void)
{
  double avail = 0, total = 0;
  FILE *f = fopen("/proc/meminfo", "r");
  if (f) {
    char line[256];
    while (fgets(line, sizeof line, f)) {
      double kb;
      if (sscanf(line, "MemAvailable: %lf kB", &kb) == 1) avail = kb * 1024;
      else if (sscanf(line, "MemTotal: %lf kB", &kb) == 1) total = kb * 1024;
    }
    fclose(f);
  }
  double m = avail > 0 ? avail : total > 0 ? total : nl_mem_physical();
  if (mem_cap > 0 && (m <= 0 || mem_cap < m)) m = mem_cap;
  return m;
}

int nl_mem_fits(double bytes)
{
  double m = nl_mem_available();
  return m <= 0 || bytes <= m;
}

const char *nl_format_bytes(char *buf, double bytes)
{
  if (bytes >= 1e12) snprintf(buf, 32, "%.3g TB", bytes / 1e12);
  else if (bytes >= 1e9) snprintf(buf, 32, "%.3g GB", bytes / 1e9);
  else if (bytes >= 1e6) snprintf(buf, 32, "%.3g MB", bytes / 1e6);
  else if (bytes >= 1e3) snprintf(buf, 32, "%.3g kB", bytes / 1e3);
  else snprintf(buf, 32, "%.0f bytes", bytes);
  return buf;
}

double nl_time_now(void)
{
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

double nl_time_thread_cpu(void)
{
  struct timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

nl_number_kind nl_number_read(const char *s, double *v)
{
  char *end;
  errno = 0;
  *v = strtod(s, &end);
  if (end == s) return NL_NUMBER_NONE;
  int range = errno == ERANGE;
  if (*end) return NL_NUMBER_NONE;
  const char *p = s;
  while (isspace((unsigned char)*p)) p++;
  if (*p == '+' || *p == '-') p++;
  if (p[0] == '0' && (p[1] == 'x' || p[1] == 'X')) return NL_NUMBER_HEX;
  if (isnan(*v) || (isinf(*v) && !range)) return NL_NUMBER_NONFINITE;
  if (isinf(*v)) return NL_NUMBER_OVERFLOW;
  /* glibc sets ERANGE for every inexact subnormal too: only a result of 0
   * from digits that are not all zero has lost the value. */
  if (range && *v == 0.0) return NL_NUMBER_UNDERFLOW;
  return NL_NUMBER_OK;
}

const char *nl_number_problem(nl_number_kind k)
{
  switch (k) {
  case NL_NUMBER_OK: return "is a number";
  case NL_NUMBER_NONE: return "is not a number";
  case NL_NUMBER_NONFINITE: return "is not a finite number";
  case NL_NUMBER_OVERFLOW: return "is beyond the double range (1.8e308)";
  case NL_NUMBER_UNDERFLOW: return "underflows to 0 (nearer 0 than 4.9e-324, the least double)";
  case NL_NUMBER_HEX: return "is hexadecimal (write numbers in decimal)";
  }
  return "is not a number";
}

nl_status nl_parse_double(const char *what, const char *s, double lo, double hi,
                          double *out, nl_error *err)
{
  if (!s || !*s) return nl_fail(err, NL_EINVAL, "%s: missing value", what);
  double v;
  nl_number_kind k = nl_number_read(s, &v);
  if (k != NL_NUMBER_OK) return nl_fail(err, NL_EINVAL, "%s: '%s' %s", what, s, nl_number_problem(k));
  if (v < lo || v > hi)
    return nl_fail(err, NL_EINVAL, "%s: %s is outside [%g, %g]", what, s, lo, hi);
  *out = v;
  return NL_OK;
}

nl_status nl_parse_long(const char *what, const char *s, long lo, long hi,
                        long *out, nl_error *err)
{
  if (!s || !*s) return nl_fail(err, NL_EINVAL, "%s: missing value", what);
  char *end;
  errno = 0;
  long v = strtol(s, &end, 10);
  if (*end != '\0' || end == s)
    return nl_fail(err, NL_EINVAL, "%s: '%s' is not an integer", what, s);
  if (errno == ERANGE || v < lo || v > hi)
    return nl_fail(err, NL_EINVAL, "%s: %s is outside [%ld, %ld]", what, s, lo, hi);
  *out = v;
  return NL_OK;
}

/* splitmix64 (Steele, Lea & Flood, "Fast splittable pseudorandom number
 * generators", OOPSLA 2014): the golden-ratio increment, then Stafford's
 * variant 13 finaliser. A bijection on 64 bits, so distinct inputs never
 * collide before the final truncation. */
unsigned long long nl_seed_mix(unsigned long long x)
{
  unsigned long long z = x + 0x9E3779B97F4A7C15ULL;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

unsigned long nl_seed_stream(unsigned long seed, const char *role, unsigned long index)
{
  unsigned long long h = 0xcbf29ce484222325ULL;   /* FNV-1a 64 of the role name */
  for (const unsigned char *p = (const unsigned char *)role; *p; p++) {
    h ^= *p;
    h *= 0x100000001b3ULL;
  }
  unsigned long long z = nl_seed_mix((unsigned long long)seed);
  z = nl_seed_mix(z ^ h);
  z = nl_seed_mix(z ^ (unsigned long long)index);
  return (unsigned long)z;
}

unsigned long nl_seed_replicate(unsigned long base, long k)
{
  return base + (unsigned long)k;
}

double nl_wrap_angle(double t)
{
  t = fmod(t, NL_TWO_PI);
  if (t < 0) t += NL_TWO_PI;
  return t >= NL_TWO_PI ? 0.0 : t;
}

double nl_lgamma(double x)
{
  int sign;
  return lgamma_r(x, &sign);
}

const char *nl_file_image_kind(FILE *fp)
{
  static const struct { const char *name; unsigned char magic[8]; size_t n; } KINDS[] = {
    {"PNG", {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'}, 8},
    {"OpenEXR", {0x76, 0x2f, 0x31, 0x01}, 4},
    {"TIFF", {'I', 'I', 42, 0}, 4},
    {"TIFF", {'M', 'M', 0, 42}, 4},
    {"JPEG", {0xff, 0xd8, 0xff}, 3},
    {"GIF", {'G', 'I', 'F', '8'}, 4},
  };
  struct stat st;
  if (fstat(fileno(fp), &st) || !S_ISREG(st.st_mode))
    return NULL;   /* a pipe cannot be rewound: its bytes are the reader's */
  unsigned char head[8];
  size_t got = fread(head, 1, sizeof head, fp);
  rewind(fp);
  for (size_t k = 0; k < sizeof KINDS / sizeof KINDS[0]; k++)
    if (got >= KINDS[k].n && !memcmp(head, KINDS[k].magic, KINDS[k].n))
      return KINDS[k].name;
  return NULL;
}

nl_status nl_stream_close(FILE *f, const char *what, nl_error *err)
{
  int pending = __fpending(f) != 0, failed = ferror(f) != 0, e = 0;
  /* After a failed write the buffer still holds what was not written: one
   * more flush fails the same way and sets errno, which the caller of the
   * first failed write may have lost. */
  errno = 0;
  if (fflush(f) != 0) e = errno ? errno : EIO;
  failed |= e != 0;
  errno = 0;
  int closed = fclose(f) == 0, ce = errno;
  if (!closed && !(ce == EBADF && !pending && !failed)) {
    failed = 1;
    if (!e) e = ce ? ce : EIO;
  }
  if (!failed) return NL_OK;
  if (!e) return nl_fail(err, NL_EIO, "write error on %s", what);
  return nl_fail(err, NL_EIO, "write error on %s: %s", what, strerror(e));
}
