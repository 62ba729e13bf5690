#include "base/nl_base.h"
#include "nl_test.h"

#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

static const char *dir;

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

NL_TEST(memory_sizes)
{
  char b[32];
  NL_CHECK(strcmp(nl_format_bytes(b, 160e9), "160 GB") == 0);
  NL_CHECK(strcmp(nl_format_bytes(b, 894004096), "894 MB") == 0);
  NL_CHECK(strcmp(nl_format_bytes(b, 12), "12 bytes") == 0);
  NL_CHECK(nl_mem_physical() > 1e6);
  NL_CHECK(nl_mem_fits(1e6) && !nl_mem_fits(1e18));
}

int main(void)
{
  dir = nl_test_tmpdir();
  return nl_test_run();
}
