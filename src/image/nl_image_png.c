/* nl_image_png.c - PNG without OpenImageIO.
 *
 * Writing (nl_image_png_encode): every PNG the programs write, so a program
 * that writes PNGs never loads OpenImageIO's ~260 libraries (0.2-0.5 s of
 * wall time before the first pixel). zlib deflates; the samples are
 * quantised as OpenImageIO quantises them (see png_sample), and test_image
 * checks that both encoders' files decode to the same samples.
 *
 * Reading (nl_image_png_read), for a build without image support (meson
 * -Dimages=disabled: the arm64 cross build), where the experiments still
 * read their control patterns and exemplar photographs.
 * stb_image (Debian's libstb-dev) decodes; the samples become floats as
 * OpenImageIO makes them (convert_type in OpenImageIO/fmath.h: v * (1.0f /
 * 255), v * (1.0f / 65535) for 16 bits, straight alpha), and the channels as
 * nl_oiio_read lays them out (grey+alpha stored as RGBA), so a PNG reads to
 * the same bits with either: test_image compares them on every PNG under
 * data/. */
#include "image/nl_image_png.h"
#include "image/nl_image_config.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <errno.h>
#include <stdint.h>
#include <sys/stat.h>
#include <time.h>
#if NL_PNG_WRITE
#include <zlib.h>
#endif

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

#if NL_PNG_WRITE
/* A float sample as OpenImageIO stores it in an integer file
 * (scaled_conversion in OpenImageIO/fmath.h): v * max + 0.5, clamped to
 * [0, max], truncated; NaN becomes 0. */
static inline unsigned png_sample(float v, float max)
{
  float s = roundf(v * max);
  return s >= 0.0f ? (s <= max ? (unsigned)s : (unsigned)max) : 0u;
}

static void be32(unsigned char *p, uint32_t v)
{
  p[0] = (unsigned char)(v >> 24); p[1] = (unsigned char)(v >> 16);
  p[2] = (unsigned char)(v >> 8); p[3] = (unsigned char)v;
}

/* Appends one chunk (length, type, data, CRC over type and data). */
static void chunk(unsigned char **o, const char *type, const unsigned char *d, uint32_t n)
{
  be32(*o, n);
  memcpy(*o + 4, type, 4);
  if (n) memcpy(*o + 8, d, n);
  uLong crc = crc32(0L, *o + 4, 4 + n);
  be32(*o + 8 + n, (uint32_t)crc);
  *o += 12 + n;
}

/* PNG filter types (PNG spec sec. 9.2) on one row of `len` bytes, bpp bytes
 * a pixel, against the previous row (prev NULL for the first). The row
 * written is the one whose bytes, read as signed, have the smallest sum of
 * magnitudes: the PNG spec's recommended heuristic (sec. 12.8), which
 * libpng and so OpenImageIO use. */
static unsigned char paeth(int a, int b, int c)
{
  int p = a + b - c, pa = abs(p - a), pb = abs(p - b), pc = abs(p - c);
  return (unsigned char)(pa <= pb && pa <= pc ? a : pb <= pc ? b : c);
}

static void filter_row(const unsigned char *row, const unsigned char *prev, size_t len, int bpp,
                       unsigned char *out, unsigned char *trial)
{
  unsigned long best = ~0UL;
  for (int f = 0; f < 5; f++) {
    unsigned long cost = 0;
    trial[0] = (unsigned char)f;
    for (size_t i = 0; i < len; i++) {
      int a = i >= (size_t)bpp ? row[i - bpp] : 0, b = prev ? prev[i] : 0;
      int c = prev && i >= (size_t)bpp ? prev[i - bpp] : 0;
      int x = row[i];
      unsigned char v = (unsigned char)(f == 0 ? x : f == 1 ? x - a : f == 2 ? x - b
                                        : f == 3 ? x - ((a + b) >> 1) : x - paeth(a, b, c));
      trial[1 + i] = v;
      cost += (unsigned long)abs((signed char)v);
    }
    if (cost < best) {
      best = cost;
      memcpy(out, trial, len + 1);
    }
  }
}

nl_status nl_image_png_encode(const nl_image *im, const char *path, int bits, int level,
                              unsigned char **data, size_t *size, nl_error *err)
{
  *data = NULL;
  *size = 0;
  if (bits != 8 && bits != 16)
    return nl_fail(err, NL_EINVAL, "%s: bit depth %d is not 8 or 16 (PNG)", path, bits);
  if (im->channels < 1 || im->channels > 4 || im->channels == 2 || im->width < 1 || im->height < 1)
    return nl_fail(err, NL_EINVAL, "%s: %d x %d pixels of %d channels cannot be a PNG", path,
                   im->width, im->height, im->channels);
  static const unsigned char colour_type[5] = {0, 0, 0, 2, 6};   /* grey, RGB, RGBA (straight alpha) */
  int sets = 0;
  long long when = 0;
  nl_status s = nl_image_source_date(path, &sets, &when, err);
  if (s) return s;
  const int bpp = im->channels * bits / 8;
  const size_t len = (size_t)im->width * (size_t)bpp, h = (size_t)im->height;
  unsigned char *raw = malloc(2 * len), *filt = malloc(h * (len + 1)), *trial = malloc(len + 1);
  uLong bound = compressBound((uLong)(h * (len + 1)));
  unsigned char *png = malloc((size_t)bound + 128);
  if (!raw || !filt || !trial || !png) {
    free(raw); free(filt); free(trial); free(png);
    return nl_fail(err, NL_ENOMEM, "%s: out of memory for a %d x %d PNG", path, im->width, im->height);
  }
  const float max = bits == 16 ? 65535.0f : 255.0f;
  for (size_t y = 0; y < h; y++) {
    unsigned char *row = raw + (y & 1) * len, *prev = y ? raw + ((y - 1) & 1) * len : NULL;
    const float *src = im->data + y * (size_t)im->width * (size_t)im->channels;
    size_t nsamp = (size_t)im->width * (size_t)im->channels;
    if (bits == 8)
      for (size_t i = 0; i < nsamp; i++) row[i] = (unsigned char)png_sample(src[i], max);
    else
      for (size_t i = 0; i < nsamp; i++) {
        unsigned v = png_sample(src[i], max);
        row[2 * i] = (unsigned char)(v >> 8);
        row[2 * i + 1] = (unsigned char)v;
      }
    filter_row(row, prev, len, bpp, filt + y * (len + 1), trial);
  }
  free(raw);
  free(trial);
  unsigned char *o = png;
  memcpy(o, "\x89PNG\r\n\x1a\n", 8);
  o += 8;
  unsigned char ihdr[13];
  be32(ihdr, (uint32_t)im->width);
  be32(ihdr + 4, (uint32_t)im->height);
  ihdr[8] = (unsigned char)bits;
  ihdr[9] = colour_type[im->channels];
  ihdr[10] = ihdr[11] = ihdr[12] = 0;   /* deflate, adaptive filtering, no interlace */
  chunk(&o, "IHDR", ihdr, 13);
  if (sets) {   /* the time OpenImageIO's writer stamps, so both give the same chunks */
    time_t tt = (time_t)when;
    struct tm tm;
    gmtime_r(&tt, &tm);
    unsigned char ti[7] = {(unsigned char)((tm.tm_year + 1900) >> 8), (unsigned char)(tm.tm_year + 1900),
                           (unsigned char)(tm.tm_mon + 1), (unsigned char)tm.tm_mday,
                           (unsigned char)tm.tm_hour, (unsigned char)tm.tm_min,
                           (unsigned char)tm.tm_sec};
    chunk(&o, "tIME", ti, 7);
  }
  /* The IDAT's data is deflated in place after its 8-byte header. */
  uLongf zn = bound;
  int zs = compress2(o + 8, &zn, filt, (uLong)(h * (len + 1)), level);
  free(filt);
  if (zs != Z_OK) {
    free(png);
    return nl_fail(err, zs == Z_MEM_ERROR ? NL_ENOMEM : NL_EIO, "%s: deflate failed (zlib %d)", path, zs);
  }
  be32(o, (uint32_t)zn);
  memcpy(o + 4, "IDAT", 4);
  be32(o + 8 + zn, (uint32_t)crc32(0L, o + 4, (uInt)(4 + zn)));
  o += 12 + zn;
  chunk(&o, "IEND", NULL, 0);
  *size = (size_t)(o - png);
  *data = png;
  return NL_OK;
}
#endif
