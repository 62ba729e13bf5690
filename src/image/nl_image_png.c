/* nl_image_png.c - PNG reading without OpenImageIO, for a build without
 * image support (meson -Dimages=disabled: the arm64 cross build), where the
 * experiments still read their control patterns and exemplar photographs.
 * stb_image (Debian's libstb-dev) decodes; the samples become floats as
 * OpenImageIO makes them (convert_type in OpenImageIO/fmath.h: v * (1.0f /
 * 255), v * (1.0f / 65535) for 16 bits, straight alpha), and the channels as
 * nl_oiio_read lays them out (grey+alpha stored as RGBA), so a PNG reads to
 * the same bits with either: test_image compares them on every PNG under
 * data/. */
#include "image/nl_image_png.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_STATIC
#define STBI_ONLY_PNG
#define STBI_NO_LINEAR   /* no float-conversion code (it would apply a gamma) */
#define STBI_NO_HDR
/* -Wunused-function is reported at the end of the file, after a pop: the
 * static functions this file does not call stay unwarned for the whole file. */
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#pragma GCC diagnostic ignored "-Wimplicit-fallthrough"
#include <stb/stb_image.h>
#pragma GCC diagnostic pop

nl_status nl_image_png_read(const char *path, nl_image **out, nl_error *err)
{
  *out = NULL;
  FILE *f = fopen(path, "rb");
  if (!f) return nl_fail(err, NL_EIO, "%s: cannot open", path);
  int w, h, ch;
  if (!stbi_info_from_file(f, &w, &h, &ch)) {
    fclose(f);
    return nl_fail(err, NL_EFORMAT, "%s: not a PNG this build can read (%s)", path,
                   stbi_failure_reason());
  }
  if ((double)w * h > NL_IMAGE_MAX_PIXELS) {
    fclose(f);
    return nl_fail(err, NL_EFORMAT, "%s: %d x %d pixels is beyond the %.0f-pixel limit", path,
                   w, h, (double)NL_IMAGE_MAX_PIXELS);
  }
  int sixteen = stbi_is_16_bit_from_file(f);
  void *px = sixteen ? (void *)stbi_load_from_file_16(f, &w, &h, &ch, 0)
                     : (void *)stbi_load_from_file(f, &w, &h, &ch, 0);
  fclose(f);
  if (!px) return nl_fail(err, NL_EFORMAT, "%s: %s", path, stbi_failure_reason());
  const float scale = sixteen ? 1.0f / 65535 : 1.0f / 255;
  nl_image *im = nl_image_alloc(w, h, ch == 2 ? 4 : ch);
  size_t npix = (size_t)w * h;
  for (size_t i = 0; i < npix; i++) {
    float s[4];
    for (int c = 0; c < ch; c++) {
      size_t k = i * (size_t)ch + (size_t)c;
      s[c] = (float)(sixteen ? ((const stbi_us *)px)[k] : ((const stbi_uc *)px)[k]) * scale;
    }
    float *d = im->data + i * (size_t)im->channels;
    if (ch == 2) { d[0] = d[1] = d[2] = s[0]; d[3] = s[1]; }
    else memcpy(d, s, (size_t)ch * sizeof *s);
  }
  stbi_image_free(px);
  *out = im;
  return NL_OK;
}
