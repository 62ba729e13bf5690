/* dladdr (the installed library finds its image module beside itself). */
#ifndef NL_OIIO_STATIC
#define _GNU_SOURCE
#endif
#include "image/nl_image.h"
#include "image/nl_image_config.h"
#include "image/nl_image_png.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#ifndef NL_OIIO_STATIC
#include <dlfcn.h>
#include <pthread.h>
#endif

/* Under AddressSanitizer, what OpenImageIO and its ~260 libraries allocate
 * while loading and inside a read or write is kept out of LeakSanitizer's
 * report (__lsan_disable marks a thread's allocations as ignored): their
 * thread-local blocks (glibc's thread vector grown by dlopen, GLib's slice
 * magazines, boost's per-thread error strings) look leaked because our
 * sanitizer runs do not scan thread-local storage (use_tls=0,
 * tests/meson.build), and matching them against suppressions made
 * LeakSanitizer symbolize libasan's DWARF in every image-touching process:
 * 1.64 -> 1.20 s of CPU for one analyse. Memory we allocate is
 * allocated outside these regions, so its leaks are still found. GCC defines
 * __SANITIZE_ADDRESS__; clang 14 (the fuzz targets) does not, and those keep
 * tests/fuzz/lsan.supp. */
#if defined(__SANITIZE_ADDRESS__)
#include <sanitizer/lsan_interface.h>
#define QUIET_BEGIN() __lsan_disable()
#define QUIET_END() __lsan_enable()
#define QUIET 1
#else
#define QUIET_BEGIN() ((void)0)
#define QUIET_END() ((void)0)
#define QUIET 0
#endif

/* ---- the image back-end, loaded on first use ------------------------- */

typedef nl_status (*nl_oiio_read_fn)(const char *, nl_image **, nl_error *);
typedef nl_status (*nl_oiio_encode_fn)(const nl_image *, const char *, int, unsigned char **,
                                       size_t *, nl_error *);

#ifdef NL_OIIO_STATIC
/* The fuzz targets link nl_image_oiio.cpp in. */
nl_status nl_oiio_read(const char *path, nl_image **out, nl_error *err);
nl_status nl_oiio_encode(const nl_image *im, const char *path, int bits, unsigned char **data,
                         size_t *size, nl_error *err);
static nl_oiio_read_fn oiio_read = nl_oiio_read;
static nl_oiio_encode_fn oiio_encode = nl_oiio_encode;
static nl_status backend(const char *path, nl_error *err) { (void)path; (void)err; return NL_OK; }
int nl_image_backend_loaded(void) { return 1; }
#else
static nl_oiio_read_fn oiio_read;
static nl_oiio_encode_fn oiio_encode;
static pthread_once_t oiio_once = PTHREAD_ONCE_INIT;
static char oiio_why[NL_ERROR_LEN];

/* Where the module is looked for, in order: $NL_OIIO_MODULE; noiselab/ beside
 * the object that holds this code (an installed libnoiselab.so, wherever it
 * was copied: `meson install --destdir`, a relocated prefix); the build tree;
 * the configured prefix. */
static void backend_open(void)
{
  const char *env = getenv("NL_OIIO_MODULE");
  static char beside[4096];
  Dl_info self;
  const char *slash = dladdr((void *)backend_open, &self) && self.dli_fname
                      ? strrchr(self.dli_fname, '/') : NULL;
  if (slash)
    snprintf(beside, sizeof beside, "%.*s/noiselab/libnl_oiio.so",
             (int)(slash - self.dli_fname), self.dli_fname);
  const char *tries[4] = {env && *env ? env : NULL, beside[0] ? beside : NULL,
                          NL_OIIO_MODULE_BUILD, NL_OIIO_MODULE_INSTALLED};
  for (int i = 0; i < 4; i++) {
    if (!tries[i]) continue;
    QUIET_BEGIN();
    void *h = dlopen(tries[i], RTLD_NOW | RTLD_LOCAL);
    QUIET_END();
    if (h) {
      oiio_read = (nl_oiio_read_fn)(void (*)(void))dlsym(h, "nl_oiio_read");
      oiio_encode = (nl_oiio_encode_fn)(void (*)(void))dlsym(h, "nl_oiio_encode");
      if (oiio_read && oiio_encode) return;
      oiio_read = NULL;
      oiio_encode = NULL;
    }
    const char *e = dlerror();   /* why dlopen or dlsym failed: the message names the file */
    if (h) dlclose(h);
    size_t used = strlen(oiio_why);   /* snprintf truncates what does not fit */
    snprintf(oiio_why + used, sizeof oiio_why - used, "%s%s", used ? "; " : "", e ? e : tries[i]);
  }
}

static nl_status backend(const char *path, nl_error *err)
{
  if (!NL_OIIO_BUILT)
    return nl_fail(err, NL_EIO,
                   "%s: this build has no image support but PNG reading (meson -Dimages=disabled)",
                   path);
  pthread_once(&oiio_once, backend_open);
  if (oiio_read) return NL_OK;
  return nl_fail(err, NL_EIO, "%s: image support (OpenImageIO module) not loaded: %s", path, oiio_why);
}

int nl_image_backend_loaded(void) { return oiio_read != NULL; }
#endif

/* What the file system says about an input (missing, a directory, not
 * readable) is said before the image library is loaded: its start-up is
 * 0.5 s of CPU, 1 s under the sanitizers. The module then checks
 * only the EXR header. */
static nl_status readable(const char *path, nl_error *err)
{
  struct stat st;
  if (stat(path, &st) != 0) return nl_fail(err, NL_EIO, "%s: cannot open: %s", path, strerror(errno));
  if (S_ISDIR(st.st_mode)) return nl_fail(err, NL_EIO, "%s: is a directory", path);
  if (!S_ISREG(st.st_mode)) return nl_fail(err, NL_EIO, "%s: not a regular file", path);
  FILE *f = fopen(path, "rb");
  if (!f) return nl_fail(err, NL_EIO, "%s: cannot open: %s", path, strerror(errno));
  fclose(f);
  return NL_OK;
}

nl_status nl_image_read(const char *path, nl_image **out, nl_error *err)
{
  *out = NULL;
  nl_status s = readable(path, err);
  if (s) return s;
#if !NL_OIIO_BUILT
  /* No module: a PNG (the patterns and exemplars) through stb_image, the
   * pixels the module would give (nl_image_png.c); other formats refused. */
  size_t len = strlen(path);
  if (len >= 4 && strcasecmp(path + len - 4, ".png") == 0) return nl_image_png_read(path, out, err);
#endif
  s = backend(path, err);
  if (s) return s;
  QUIET_BEGIN();
  s = oiio_read(path, out, err);
  QUIET_END();
  if (QUIET && !s) {   /* the image the module allocated is ignored: a tracked copy */
    nl_image *im = nl_image_alloc((*out)->width, (*out)->height, (*out)->channels);
    memcpy(im->data, (*out)->data, (size_t)im->width * im->height * im->channels * sizeof *im->data);
    nl_image_free(*out);
    *out = im;
  }
  return s;
}

nl_status nl_image_check_bits(const char *path, int bits, nl_error *err)
{
  static const char *const integer_only[][2] = {
    {".png", "PNG"}, {".jpg", "JPEG"}, {".jpeg", "JPEG"}, {".bmp", "BMP"}, {".gif", "GIF"},
    {".ppm", "PNM"}, {".pgm", "PNM"}, {".pnm", "PNM"}, {".tga", "TGA"}, {".webp", "WebP"}};
  size_t len = strlen(path);
  /* EXR stores half or float samples only: "8 bits" would be written as
   * half and reported as what it is not. */
  if (bits != 0 && bits != 16 && bits != 32 && len >= 4 && strcasecmp(path + len - 4, ".exr") == 0)
    return nl_fail(err, NL_EINVAL, "%s: EXR holds 16-bit half or 32-bit float, not %d-bit; use "
                   "16 or 32, or .png or .tif for 8 bits", path, bits);
  if (bits != 32) return NL_OK;
  for (size_t i = 0; i < sizeof integer_only / sizeof *integer_only; i++) {
    size_t e = strlen(integer_only[i][0]);
    if (len >= e && strcasecmp(path + len - e, integer_only[i][0]) == 0)
      return nl_fail(err, NL_EINVAL, "%s: %s cannot hold 32-bit float; use .exr or .tif",
                     path, integer_only[i][1]);
  }
  return NL_OK;
}

nl_status nl_image_source_date(const char *path, int *set, long long *t, nl_error *err)
{
  *set = 0;
  *t = 0;
  const char *e = getenv("SOURCE_DATE_EPOCH");
  if (!e || !*e) return NL_OK;
  char *end;
  errno = 0;
  long long v = strtoll(e, &end, 10);
  /* 253402300799 is 9999-12-31 23:59:59: beyond it a year has five digits. */
  if (*end || errno || v < 0 || v > 253402300799LL)
    return nl_fail(err, NL_EINVAL, "%s: SOURCE_DATE_EPOCH '%s' is not a number of seconds since 1970",
                   path, e);
  *set = 1;
  *t = v;
  return NL_OK;
}

/* A PNG ends with its IEND chunk: length 0, "IEND", CRC ae 42 60 82. */
static int png_whole(const unsigned char *d, size_t n)
{
  static const unsigned char iend[12] = {0, 0, 0, 0, 'I', 'E', 'N', 'D', 0xae, 0x42, 0x60, 0x82};
  return n >= 8 + sizeof iend && memcmp(d + n - sizeof iend, iend, sizeof iend) == 0;
}

nl_status nl_image_write(const nl_image *im, const char *path, int bits, nl_error *err)
{
  nl_status s = nl_image_check_bits(path, bits, err);
  if (s) return s;
  /* A target that cannot be written is named before the codec is loaded. */
  s = nl_path_check_writable(path, err);
  if (s) return s;
  unsigned char *data = NULL;
  size_t n = 0;
  const char *dot = strrchr(path, '.');
  int png = dot && strcasecmp(dot, ".png") == 0;
#if NL_PNG_WRITE && !defined(NL_OIIO_STATIC)
  /* Grey with alpha is left to OpenImageIO, which treats the second
   * channel as associated alpha and divides it out. */
  if (png && im->channels != 2) {
    s = nl_image_png_encode(im, path, bits, NL_PNG_LEVEL, &data, &n, err);
    if (!s) s = nl_atomic_write(path, data, n, err);
    free(data);
    return s;
  }
#endif
  s = backend(path, err);
  if (s) return s;
  QUIET_BEGIN();
  s = oiio_encode(im, path, bits, &data, &n, err);
  QUIET_END();
  if (s) return s;
  if (png && !png_whole(data, n))
    s = nl_fail(err, NL_EIO, "%s: the PNG encoder stopped before the end (no IEND chunk)", path);
  else
    s = nl_atomic_write(path, data, n, err);
  free(data);
  return s;
}

const char *nl_image_library_version(void) { return NL_OIIO_VERSION; }

/* The font: stb_easy_font (public domain, Debian's libstb-dev) turns text
 * into axis-aligned quads, which we fill as rectangles. Unused-function
 * warnings come from its static API. */
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wconversion"
#include <stb/stb_easy_font.h>
#pragma GCC diagnostic pop

nl_image *nl_image_alloc(int width, int height, int channels)
{
  nl_image *im = nl_xmalloc(sizeof *im);
  im->width = width;
  im->height = height;
  im->channels = channels;
  im->data = nl_xcalloc((size_t)width * height * channels, sizeof *im->data);
  return im;
}

void nl_image_free(nl_image *im)
{
  if (!im) return;
  free(im->data);
  free(im);
}

nl_image *nl_image_from_values(const double *v, int w, int h, double lo, double hi)
{
  nl_image *im = nl_image_alloc(w, h, 1);
  double s = hi > lo ? 1.0 / (hi - lo) : 0.0;
  for (size_t i = 0; i < (size_t)w * h; i++) {
    double u = (v[i] - lo) * s;
    im->data[i] = (float)(u < 0 ? 0 : u > 1 ? 1 : u);
  }
  return im;
}

nl_image *nl_image_convert(const nl_image *im, int channels)
{
  nl_image *o = nl_image_alloc(im->width, im->height, channels);
  size_t n = (size_t)im->width * im->height;
  for (size_t i = 0; i < n; i++) {
    const float *s = im->data + i * im->channels;
    float *d = o->data + i * channels;
    float r = s[0], g = im->channels >= 3 ? s[1] : s[0], b = im->channels >= 3 ? s[2] : s[0];
    float a = im->channels == 4 ? s[3] : 1.0f;
    if (channels == 1) d[0] = 0.2126f * r + 0.7152f * g + 0.0722f * b;
    else { d[0] = r; d[1] = g; d[2] = b; if (channels == 4) d[3] = a; }
  }
  return o;
}

int nl_image_text_width(const char *text, int scale)
{ return stb_easy_font_width((char *)text) * scale; }

int nl_image_text_height(const char *text, int scale)
{ return stb_easy_font_height((char *)text) * scale; }

static void fill_rect(nl_image *im, int x0, int y0, int x1, int y1, const float *rgb)
{
  if (x0 < 0) x0 = 0;
  if (y0 < 0) y0 = 0;
  if (x1 > im->width) x1 = im->width;
  if (y1 > im->height) y1 = im->height;
  for (int y = y0; y < y1; y++)
    for (int x = x0; x < x1; x++) {
      float *p = nl_image_pixel(im, x, y);
      for (int c = 0; c < im->channels && c < 3; c++) p[c] = rgb[im->channels == 1 ? 0 : c];
    }
}

void nl_image_text(nl_image *im, int x, int y, int scale, const char *text, const float *rgb)
{
  /* ~270 bytes per character, 16 bytes per vertex, 4 vertices per quad. */
  size_t cap = 300 * (strlen(text) + 1);
  float *vb = nl_xmalloc(cap);
  int nq = stb_easy_font_print(0, 0, (char *)text, NULL, vb, (int)cap);
  for (int q = 0; q < nq; q++) {
    const float *v = vb + q * 16;           /* 4 vertices of 4 floats */
    float qx0 = v[0], qy0 = v[1], qx1 = v[8], qy1 = v[9];
    fill_rect(im, x + (int)lrintf(qx0 * scale), y + (int)lrintf(qy0 * scale),
              x + (int)lrintf(qx1 * scale), y + (int)lrintf(qy1 * scale), rgb);
  }
  free(vb);
}

nl_image *nl_image_downsample(const nl_image *im, int f)
{
  int w = im->width / f, h = im->height / f, c = im->channels;
  if (w < 1) w = 1;
  if (h < 1) h = 1;
  nl_image *o = nl_image_alloc(w, h, c);
  for (int y = 0; y < h; y++)
    for (int x = 0; x < w; x++) {
      float *d = nl_image_pixel(o, x, y);
      for (int dy = 0; dy < f && y * f + dy < im->height; dy++)
        for (int dx = 0; dx < f && x * f + dx < im->width; dx++) {
          const float *s = nl_image_pixel(im, x * f + dx, y * f + dy);
          for (int k = 0; k < c; k++) d[k] += s[k] / (float)(f * f);
        }
    }
  return o;
}

/* Breaks `text` at spaces into lines no wider than `width` pixels at
 * `scale` (a word wider than that stays whole on its own line), writing them
 * '\n'-separated into out (strlen(text) + 1 bytes); returns the line count.
 * A caption wider than its panel would run into its neighbours' captions. */
static int caption_wrap(const char *text, int scale, int width, char *out)
{
  size_t n = strlen(text);
  int lines = 1;
  size_t start = 0; /* first byte of the current line in out */
  memcpy(out, text, n + 1);
  for (size_t k = 0; k < n; k++) {
    if (out[k] != ' ') continue;
    /* the line so far plus the next word */
    size_t end = k + 1;
    while (end < n && out[end] != ' ') end++;
    char save = out[end];
    out[end] = 0;
    int wide = nl_image_text_width(out + start, scale) > width;
    out[end] = save;
    if (wide && k > start) {
      out[k] = '\n';
      start = k + 1;
      lines++;
    }
  }
  return lines;
}

void nl_image_montage_layout(const int *widths, const int *heights, const char *const *labels, int n,
                             int cols, const char *title, nl_image_montage_geometry *g, nl_image_rect *rects)
{
  int cw = 1, chh = 1, pad = 8;
  for (int i = 0; i < n; i++) {
    if (widths[i] > cw) cw = widths[i];
    if (heights[i] > chh) chh = heights[i];
  }
  if (cols < 1) cols = 1;
  if (cols > n) cols = n;
  int f = 1;
  while (pad + cols * (cw / f + pad) > NL_MONTAGE_MAX_WIDTH && cw / f > 64) f++;
  if (f > 1) {   /* the panels box-filtered down by f (nl_image_downsample's sizes) */
    cw = chh = 1;
    for (int i = 0; i < n; i++) {
      int w = widths[i] / f > 1 ? widths[i] / f : 1, h = heights[i] / f > 1 ? heights[i] / f : 1;
      if (w > cw) cw = w;
      if (h > chh) chh = h;
    }
  }
  /* Captions scale with the panels so they stay legible in large montages. */
  int scale = cw >= 384 ? 3 : 2;
  int lines = 1;
  for (int i = 0; labels && i < n; i++)
    if (labels[i]) {
      char *buf = nl_xmalloc(strlen(labels[i]) + 1);
      int k = caption_wrap(labels[i], scale, cw, buf);
      if (k > lines) lines = k;
      free(buf);
    }
  int caph = 12 * scale * lines + pad;
  /* The title, too, is broken into lines as wide as the grid. */
  int width = pad + cols * (cw + pad);
  int tlines = 0;
  if (title) {
    char *tbuf = nl_xmalloc(strlen(title) + 1);
    tlines = caption_wrap(title, scale, width - 2 * pad, tbuf);
    free(tbuf);
  }
  int titleh = title ? 14 * scale * tlines + pad : 0;
  int rows = (n + cols - 1) / cols;
  g->width = width;
  g->height = titleh + pad + rows * (chh + caph + pad);
  g->factor = f;
  g->cols = cols;
  g->pad = pad;
  g->scale = scale;
  g->cell_w = cw;
  g->cell_h = chh;
  g->caption_h = caph;
  g->title_h = titleh;
  for (int i = 0; rects && i < n; i++) {
    int w = f > 1 ? (widths[i] / f > 1 ? widths[i] / f : 1) : widths[i];
    int h = f > 1 ? (heights[i] / f > 1 ? heights[i] / f : 1) : heights[i];
    rects[i].x = pad + (i % cols) * (cw + pad) + (cw - w) / 2;
    rects[i].y = titleh + pad + (i / cols) * (chh + caph + pad);
    rects[i].w = w;
    rects[i].h = h;
  }
}

nl_image *nl_image_montage(const nl_image *const *images, const char *const *labels, int n,
                           int cols, const char *title)
{
  int *wh = nl_xmalloc(2 * (size_t)(n > 0 ? n : 1) * sizeof *wh);
  for (int i = 0; i < n; i++) {
    wh[i] = images[i]->width;
    wh[n + i] = images[i]->height;
  }
  nl_image_montage_geometry g;
  nl_image_rect *rect = nl_xmalloc((size_t)(n > 0 ? n : 1) * sizeof *rect);
  nl_image_montage_layout(wh, wh + n, labels, n, cols, title, &g, rect);
  free(wh);
  nl_image *m = nl_image_alloc(g.width, g.height, 3);
  for (size_t i = 0; i < (size_t)m->width * m->height * 3; i++) m->data[i] = 1.0f;
  const float black[3] = {0, 0, 0};
  int scale = g.scale, pad = g.pad, cw = g.cell_w, chh = g.cell_h;
  cols = g.cols;
  if (title) {
    char *tbuf = nl_xmalloc(strlen(title) + 1);
    caption_wrap(title, scale, g.width - 2 * pad, tbuf);
    char *l = tbuf;
    for (int line = 0; l; line++) {
      char *nl = strchr(l, '\n');
      if (nl) *nl = 0;
      nl_image_text(m, pad, pad + 14 * scale * line, scale, l, black);
      l = nl ? nl + 1 : NULL;
    }
    free(tbuf);
  }
  for (int i = 0; i < n; i++) {
    nl_image *small = g.factor > 1 ? nl_image_downsample(images[i], g.factor) : NULL;
    nl_image *rgb = nl_image_convert(small ? small : images[i], 3);
    nl_image_free(small);
    int x0 = rect[i].x, y0 = rect[i].y;
    for (int y = 0; y < rgb->height; y++)
      memcpy(nl_image_pixel(m, x0, y0 + y), nl_image_pixel(rgb, 0, y), (size_t)rgb->width * 3 * sizeof(float));
    if (labels && labels[i]) {
      char *buf = nl_xmalloc(strlen(labels[i]) + 1);
      caption_wrap(labels[i], scale, cw, buf);
      char *l = buf;
      for (int line = 0; l; line++) {
        char *nl = strchr(l, '\n');
        if (nl) *nl = 0;
        int tw = nl_image_text_width(l, scale);
        int tx = pad + (i % cols) * (cw + pad) + (cw - tw) / 2;
        nl_image_text(m, tx, y0 + chh + pad / 2 + 12 * scale * line, scale, l, black);
        l = nl ? nl + 1 : NULL;
      }
      free(buf);
    }
    nl_image_free(rgb);
  }
  free(rect);
  return m;
}
