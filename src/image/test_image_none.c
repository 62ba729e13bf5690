/* Tests of nl_image.c in a build without image support (meson
 * -Dimages=disabled, the arm64 cross build): reading and writing refuse with
 * one line naming the file and the option, and leave no file; the pixel
 * functions (text, montage) still work. test_image.c tests the module. */
#include "image/nl_image.h"
#include "nl_test.h"

#include <sys/stat.h>

static const char *dir;

NL_TEST(read_and_write_name_the_missing_support)
{
  nl_image *im = nl_image_alloc(8, 4, 3);
  char *p = nl_path_join(dir, "a.png");
  nl_error err = {{0}};
  NL_CHECK(nl_image_write(im, p, 8, &err) != NL_OK);
  NL_CHECK(strstr(err.msg, p) && strstr(err.msg, "-Dimages=disabled") && !strchr(err.msg, '\n'));
  struct stat st;
  NL_CHECK(stat(p, &st) != 0);
  FILE *f = fopen(p, "w");   /* a file that exists: the refusal is the same */
  NL_CHECK(f && fclose(f) == 0);
  nl_image *back = NULL;
  NL_CHECK(nl_image_read(p, &back, &err) != NL_OK && back == NULL);
  NL_CHECK(strstr(err.msg, p) && strstr(err.msg, "-Dimages=disabled"));
  NL_CHECK(!nl_image_backend_loaded());
  free(p);
  nl_image_free(im);
}

NL_TEST(text_draws_without_the_module)
{
  nl_image *im = nl_image_alloc(64, 16, 3);
  const float white[3] = {1, 1, 1};
  nl_image_text(im, 1, 1, 1, "ok", white);
  double sum = 0;
  for (int i = 0; i < 64 * 16 * 3; i++) sum += im->data[i];
  NL_CHECK(sum > 0);
  NL_CHECK(nl_image_text_width("ok", 2) == 2 * nl_image_text_width("ok", 1));
  nl_image_free(im);
}

int main(void)
{
  dir = nl_test_tmpdir();
  return nl_test_run();
}
