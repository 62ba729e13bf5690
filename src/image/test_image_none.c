/* Tests of nl_image.c in a build without image support (meson
 * -Dimages=disabled, the arm64 cross build): PNGs are read (stb_image,
 * nl_image_png.c: the patterns and exemplars), other reads and every write
 * refuse with one line naming the file and the option, and leave no file;
 * the pixel functions (text) still work. test_image.c tests the module, and
 * there that both readers give the same pixels. */
#include "image/nl_image.h"
#include "harness/nl_build_info.h"   /* NL_SOURCE_ROOT: data/ */
#include "nl_test.h"

#include <sys/stat.h>

static const char *dir;

NL_TEST(png_read_other_formats_and_writes_refused)
{
  nl_error err = {{0}};
  nl_image *im = NULL;
  char *pat = nl_path_join(NL_SOURCE_ROOT, "data/patterns/disc.png");
  NL_CHECK(nl_image_read(pat, &im, &err) == NL_OK);
  NL_CHECK(im && im->width == 128 && im->height == 128 && im->channels == 4);
  free(pat);
  char *ex = nl_path_join(NL_SOURCE_ROOT, "data/exemplars/granite.png");
  nl_image *grey = NULL;
  NL_CHECK(nl_image_read(ex, &grey, &err) == NL_OK && grey && grey->channels == 1);
  free(ex);
  nl_image_free(grey);
  char *p = nl_path_join(dir, "a.png");
  NL_CHECK(nl_image_write(im, p, 8, &err) != NL_OK);
  NL_CHECK(strstr(err.msg, p) && strstr(err.msg, "-Dimages=disabled") && !strchr(err.msg, '\n'));
  struct stat st;
  NL_CHECK(stat(p, &st) != 0);
  free(p);
  p = nl_path_join(dir, "b.exr");
  FILE *f = fopen(p, "w");   /* a file that exists: refused all the same */
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
