/* libFuzzer target: the image reader, nl_image_read (src/image/nl_image.h)
 * through OpenImageIO. The first byte picks the file's extension (0 PNG,
 * 1 EXR, 2 TIFF, modulo 3), the rest is the file. A read image must have
 * positive size, 1, 3 or 4 channels and no NaN. */
#include "image/nl_image.h"
#include "nl_fuzz.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
  static const char *const ext[] = {"png", "exr", "tif"};
  if (size < 1) return 0;
  const char *path = nl_fuzz_file(data + 1, size - 1, ext[data[0] % 3]);
  nl_image *im = NULL;
  nl_error err = {{0}};
  nl_status st = nl_image_read(path, &im, &err);
  nl_fuzz_check_error(st, &err);
  if (st == NL_OK) {
    if (!im || im->width < 1 || im->height < 1 ||
        (im->channels != 1 && im->channels != 3 && im->channels != 4)) {
      fprintf(stderr, "nl_fuzz: nl_image_read returned a malformed image\n");
      abort();
    }
    size_t n = (size_t)im->width * im->height * im->channels;
    for (size_t i = 0; i < n; i++)
      if (im->data[i] != im->data[i]) {
        fprintf(stderr, "nl_fuzz: NaN pixel value at %zu\n", i);
        abort();
      }
    nl_image_free(im);
  } else if (im) {
    fprintf(stderr, "nl_fuzz: nl_image_read failed but returned an image\n");
    abort();
  }
  return 0;
}
