#define _GNU_SOURCE   /* memmem */
#include "image/nl_image.h"
#include "image/nl_image_png.h"
#include "harness/nl_build_info.h"   /* NL_SOURCE_ROOT: data/ */
#include "image/nl_image_config.h"
#include "nl_test.h"

#include <dlfcn.h>
#include <math.h>

#include <dirent.h>
#include <stdlib.h>
#include <string.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

static const char *dir;

static nl_image *ramp(int w, int h, int c)
{
  nl_image *im = nl_image_alloc(w, h, c);
  for (size_t i = 0; i < (size_t)w * h * c; i++) im->data[i] = (float)(i % 256) / 255.0f;
  return im;
}

static double max_diff(const nl_image *a, const nl_image *b)
{
  if (a->width != b->width || a->height != b->height || a->channels != b->channels) return 1e9;
  double d = 0;
  /* A comparison, not fmax (a NaN is skipped by both): aarch64 gcc 12 stops
   * with an internal error vectorizing this fmax reduction. */
  for (size_t i = 0; i < (size_t)a->width * a->height * a->channels; i++) {
    double e = fabs((double)a->data[i] - b->data[i]);
    if (e > d) d = e;
  }
  return d;
}

static void round_trip(const char *name, int bits, int channels, double tol)
{
  nl_image *a = ramp(37, 23, channels), *b = NULL;
  char *p = nl_path_join(dir, name);
  nl_error err = {{0}};
  NL_CHECK(nl_image_write(a, p, bits, &err) == NL_OK);
  NL_CHECK(nl_image_read(p, &b, &err) == NL_OK);
  if (b && max_diff(a, b) > tol) fprintf(stderr, "  %s: max diff %g\n", name, max_diff(a, b));
  if (b) NL_CHECK(max_diff(a, b) <= tol);
  else fprintf(stderr, "  %s: %s\n", name, err.msg);
  nl_image_free(a); nl_image_free(b); free(p);
}

/* First test: OpenImageIO is a module opened on the first image it is
 * needed for, so that programs writing only tables or PNGs start in
 * milliseconds: a PNG is written without it, a TIFF loads it. */
NL_TEST(backend_loads_on_first_use)
{
  NL_CHECK(!nl_image_backend_loaded());
  NL_CHECK(strlen(nl_image_library_version()) > 0);   /* the manifest's: no load */
  NL_CHECK(!nl_image_backend_loaded());
  nl_image *im = nl_image_alloc(2, 2, 1);
  char *p = nl_path_join(dir, "first.png"), *t = nl_path_join(dir, "first.tif");
  nl_error err;
  NL_CHECK(nl_image_write(im, p, 8, &err) == NL_OK);
  NL_CHECK(nl_image_backend_loaded() == !NL_PNG_WRITE);
  NL_CHECK(nl_image_write(im, t, 8, &err) == NL_OK);
  NL_CHECK(nl_image_backend_loaded());
  free(p);
  free(t);
  nl_image_free(im);
}

/* The PNG writer (nl_image_png.c) against OpenImageIO's, called in its
 * module: both files decode to the same samples, 8 and 16 bits, 1, 3 and 4
 * channels (grey with alpha goes to the module), at random values in [-0.25, 1.25] and at every quantisation
 * boundary (k + 1/2) / max and the floats either side of it, where a
 * rounding rule that differs would show; and both stamp SOURCE_DATE_EPOCH
 * as the same tIME chunk. */
typedef nl_status (*oiio_encode_fn)(const nl_image *, const char *, int, unsigned char **, size_t *,
                                    nl_error *);
static nl_image *png_decode(const char *name, const unsigned char *d, size_t n)
{
  char *p = nl_path_join(dir, name);
  FILE *f = fopen(p, "wb");
  NL_CHECK(f && fwrite(d, 1, n, f) == n && fclose(f) == 0);
  nl_image *im = NULL;
  nl_error err = {{0}};
  NL_CHECK(nl_image_png_read(p, &im, &err) == NL_OK);
  free(p);
  return im;
}

NL_TEST(png_writer_gives_the_module_samples)
{
#if NL_PNG_WRITE
  void *h = dlopen(NL_OIIO_MODULE_BUILD, RTLD_NOW | RTLD_LOCAL);
  NL_CHECK(h != NULL);
  if (!h) return;
  oiio_encode_fn oiio = (oiio_encode_fn)(void (*)(void))dlsym(h, "nl_oiio_encode");
  NL_CHECK(oiio != NULL);
  unsigned long long st = 0x9e3779b97f4a7c15ULL;
  for (int bits = 8; bits <= 16; bits += 8)
    for (int c = 1; c <= 4 && oiio; c += c == 1 ? 2 : 1) {
      const float max = bits == 16 ? 65535.0f : 255.0f;
      nl_image *im = nl_image_alloc(301, 67, c);
      size_t n = (size_t)im->width * im->height * c, k = 0;
      for (unsigned q = 0; q <= (unsigned)max && k + 3 <= n / 2; q += bits == 16 ? 97 : 1) {
        float b = ((float)q + 0.5f) / max;
        im->data[k++] = b;
        im->data[k++] = nextafterf(b, 0.0f);
        im->data[k++] = nextafterf(b, 2.0f);
      }
      for (; k < n; k++) {
        st = st * 6364136223846793005ULL + 1442695040888963407ULL;
        im->data[k] = (float)((double)(st >> 11) * 0x1.0p-53 * 1.5 - 0.25);
      }
      setenv("SOURCE_DATE_EPOCH", "1234567890", 1);
      unsigned char *a = NULL, *b = NULL;
      size_t na = 0, nb = 0;
      nl_error err = {{0}};
      NL_CHECK(nl_image_png_encode(im, "ours.png", bits, 6, &a, &na, &err) == NL_OK);
      NL_CHECK(oiio(im, "oiio.png", bits, &b, &nb, &err) == NL_OK);
      unsetenv("SOURCE_DATE_EPOCH");
      NL_CHECK(a && b && memmem(a, na, "tIME", 4) && memmem(b, nb, "tIME", 4));
      if (a && b)
        NL_CHECK(memcmp(memmem(a, na, "tIME", 4), memmem(b, nb, "tIME", 4), 4 + 7) == 0);
      nl_image *da = a ? png_decode("ours.png", a, na) : NULL;
      nl_image *db = b ? png_decode("oiio.png", b, nb) : NULL;
      size_t nd = da ? (size_t)da->width * da->height * da->channels : 0;
      int same = da && db && da->channels == db->channels && da->width == db->width &&
                 memcmp(da->data, db->data, nd * sizeof *da->data) == 0;
      if (!same) fprintf(stderr, "  %d-bit, %d channels: the two encoders' samples differ\n", bits, c);
      if (!same && da && db && da->channels == db->channels)
        for (size_t i = 0; i < nd; i++)
          if (da->data[i] != db->data[i]) {
            fprintf(stderr, "    decoded sample %zu: ours %.9g, oiio %.9g\n", i,
                    (double)da->data[i] * max, (double)db->data[i] * max);
            break;
          }
      NL_CHECK(same);
      nl_image_free(da); nl_image_free(db); nl_image_free(im);
      free(a); free(b);
    }
  dlclose(h);
#endif
}

NL_TEST(png_exr_tiff_round_trips)
{
  round_trip("a.png", 8, 1, 1e-7);        /* k/255 survives 8 bits (to float rounding) */
  round_trip("b.png", 16, 3, 1e-7);
  round_trip("c.png", 8, 4, 1e-7);
  round_trip("d.exr", 32, 3, 0.0);
  round_trip("e.tif", 32, 1, 0.0);
}

static int fails_naming(const char *path, const char *content)
{
  if (content) { FILE *f = fopen(path, "w"); fputs(content, f); fclose(f); }
  nl_image *im = NULL;
  nl_error err = {{0}};
  nl_status s = nl_image_read(path, &im, &err);
  int ok = s != NL_OK && !im && strncmp(err.msg, path, strlen(path)) == 0 && !strchr(err.msg, '\n');
  if (!ok) fprintf(stderr, "  %s -> '%s'\n", path, err.msg);
  return ok;
}

NL_TEST(bad_images_name_the_file)
{
  char *missing = nl_path_join(dir, "missing.png");
  char *text = nl_path_join(dir, "text.png");
  NL_CHECK(fails_naming(missing, NULL));
  NL_CHECK(fails_naming(text, "this is not an image\n"));
  /* A PNG cut in half. */
  nl_image *a = ramp(64, 64, 3);
  char *full = nl_path_join(dir, "full.png");
  nl_error err;
  NL_CHECK(nl_image_write(a, full, 8, &err) == NL_OK);
  FILE *f = fopen(full, "rb");
  char buf[8192];
  size_t n = fread(buf, 1, sizeof buf, f);
  fclose(f);
  char *cut = nl_path_join(dir, "cut.png");
  f = fopen(cut, "wb");
  fwrite(buf, 1, n / 2, f);
  fclose(f);
  NL_CHECK(fails_naming(cut, NULL));
  nl_image_free(a);
  free(missing); free(text); free(full); free(cut);
}

NL_TEST(failed_write_leaves_nothing)
{
  nl_image *a = ramp(8, 8, 1);
  nl_error err;
  NL_CHECK(nl_image_write(a, "/nonexistent/x.png", 8, &err) != NL_OK);
  NL_CHECK(strstr(err.msg, "/nonexistent/x.png") != NULL);
  char *noext = nl_path_join(dir, "noext");
  NL_CHECK(nl_image_write(a, noext, 8, &err) == NL_EINVAL);
  char *png = nl_path_join(dir, "float.png");
  NL_CHECK(nl_image_write(a, png, 32, &err) == NL_EINVAL);
  NL_CHECK(strstr(err.msg, "PNG cannot hold 32-bit") != NULL);
  NL_CHECK(access(png, F_OK) != 0);
  NL_CHECK(nl_image_check_bits("x.JPG", 32, &err) == NL_EINVAL);
  NL_CHECK(nl_image_check_bits("x.tif", 32, &err) == NL_OK);
  free(png);
  /* No temporary files left in the directory. */
  DIR *d = opendir(dir);
  struct dirent *e;
  int hidden = 0;
  while ((e = readdir(d))) if (e->d_name[0] == '.' && strlen(e->d_name) > 2) hidden++;
  closedir(d);
  NL_CHECK(hidden == 0);
  nl_image_free(a); free(noext);
}

NL_TEST(montage_layout_and_text)
{
  nl_image *a = ramp(50, 40, 1), *b = ramp(30, 60, 3);
  const nl_image *ims[] = {a, b, a};
  const char *labels[] = {"(a) one", "(b) two", NULL};
  nl_image *m = nl_image_montage(ims, labels, 3, 2, "title");
  NL_CHECK(m->channels == 3 && m->width == 8 + 2 * (50 + 8));
  /* Some caption pixel is black (the text was drawn). */
  int dark = 0;
  for (int y = 0; y < m->height; y++)
    for (int x = 0; x < m->width; x++) if (nl_image_pixel(m, x, y)[0] == 0.0f && y > 40 + 36) dark++;
  NL_CHECK(dark > 10);
  nl_image_free(a); nl_image_free(b); nl_image_free(m);
}

/* A caption wider than its panel is broken at spaces onto more lines (the
 * montage grows taller) and no caption pixel lands outside its own column;
 * a title wider than the grid, likewise. */
NL_TEST(montage_wraps_long_captions)
{
  nl_image *a = ramp(128, 128, 1);   /* S3's quick panels */
  const nl_image *ims[] = {a, a};
  const char *shortl[] = {"(a)", "(b)"};
  const char *longl[] = {"(a) lacunarity 0.5", "(b) lacunarity 1"};
  nl_image *s = nl_image_montage(ims, shortl, 2, 2, NULL);
  nl_image *m = nl_image_montage(ims, longl, 2, 2, NULL);
  NL_CHECK(m->width == s->width && m->height > s->height);
  int stray = 0;
  for (int y = 8 + 128; y < m->height; y++)
    for (int x = 0; x < m->width; x++) {
      int gap = x < 8 || (x >= 8 + 128 && x < 8 + 128 + 8) || x >= 8 + 2 * 128 + 8;
      if (gap && nl_image_pixel(m, x, y)[0] == 0.0f) stray++;
    }
  NL_CHECK(stray == 0);
  /* A title wider than the grid takes more lines; no pixel of it is cut. */
  nl_image *ts = nl_image_montage(ims, shortl, 2, 2, "Fig. 4");
  nl_image *tl = nl_image_montage(ims, shortl, 2, 2, "Fig. 4: F2 - F1 - F1F1 wrinkles, octaves");
  NL_CHECK(tl->width == ts->width && tl->height > ts->height);
  int edge = 0;
  for (int y = 0; y < tl->height; y++)
    for (int x = tl->width - 8; x < tl->width; x++) edge += nl_image_pixel(tl, x, y)[0] == 0.0f;
  NL_CHECK(edge == 0);
  nl_image_free(a); nl_image_free(s); nl_image_free(m); nl_image_free(ts); nl_image_free(tl);
}

NL_TEST(downsample_box_filter_and_wide_montage)
{
  nl_image *a = nl_image_alloc(4, 2, 1);
  for (int i = 0; i < 8; i++) a->data[i] = (float)i;     /* rows 0 1 2 3 / 4 5 6 7 */
  nl_image *d = nl_image_downsample(a, 2);
  NL_CHECK(d->width == 2 && d->height == 1);
  NL_CHECK_NEAR(d->data[0], 2.5, 1e-6);                   /* (0 + 1 + 4 + 5) / 4 */
  NL_CHECK_NEAR(d->data[1], 4.5, 1e-6);
  nl_image *big = nl_image_alloc(600, 100, 1);
  const nl_image *ims[] = {big, big, big, big, big};
  nl_image *m = nl_image_montage(ims, NULL, 5, 5, NULL);
  NL_CHECK(m->width <= NL_MONTAGE_MAX_WIDTH && m->width == 8 + 5 * (300 + 8));
  nl_image_free(a); nl_image_free(d); nl_image_free(big); nl_image_free(m);
}

static long file_bytes(const char *path, unsigned char *buf, size_t cap)
{
  FILE *f = fopen(path, "rb");
  if (!f) return -1;
  size_t n = fread(buf, 1, cap, f);
  fclose(f);
  return (long)n;
}

/* Same image, same bytes: no timestamp in TIFF or EXR. */
NL_TEST(same_image_same_bytes)
{
  const char *names[][2] = {{"s1.png", "s2.png"}, {"s1.tif", "s2.tif"}, {"s1.exr", "s2.exr"}};
  static unsigned char a[65536], b[65536];
  nl_image *im = ramp(32, 16, 3);
  unsetenv("SOURCE_DATE_EPOCH");
  for (int k = 0; k < 3; k++) {
    char *p1 = nl_path_join(dir, names[k][0]), *p2 = nl_path_join(dir, names[k][1]);
    nl_error err;
    NL_CHECK(nl_image_write(im, p1, 16, &err) == NL_OK);
    sleep(1);   /* a timestamp would now differ */
    NL_CHECK(nl_image_write(im, p2, 16, &err) == NL_OK);
    long n1 = file_bytes(p1, a, sizeof a), n2 = file_bytes(p2, b, sizeof b);
    NL_CHECK(n1 > 0 && n1 == n2 && memcmp(a, b, (size_t)n1) == 0);
    free(p1); free(p2);
  }
  /* SOURCE_DATE_EPOCH gives a fixed time; a malformed one is an error. */
  char *p = nl_path_join(dir, "epoch.tif");
  nl_error err;
  setenv("SOURCE_DATE_EPOCH", "0", 1);
  NL_CHECK(nl_image_write(im, p, 8, &err) == NL_OK);
  long n = file_bytes(p, a, sizeof a);
  NL_CHECK(n > 0 && memmem(a, (size_t)n, "1970:01:01 00:00:00", 19) != NULL);
  setenv("SOURCE_DATE_EPOCH", "yesterday", 1);
  NL_CHECK(nl_image_write(im, p, 8, &err) == NL_EINVAL && strstr(err.msg, "SOURCE_DATE_EPOCH"));
  unsetenv("SOURCE_DATE_EPOCH");
  nl_image_free(im); free(p);
}

/* Infinities are rejected like NaN, naming the first bad pixel (13.6). */
NL_TEST(non_finite_pixels_rejected)
{
  nl_image *im = ramp(8, 4, 3), *back = NULL;
  nl_image_pixel(im, 5, 2)[1] = INFINITY;
  nl_image_pixel(im, 6, 3)[0] = NAN;
  char *p = nl_path_join(dir, "inf.exr");
  nl_error err;
  NL_CHECK(nl_image_write(im, p, 32, &err) == NL_OK);
  NL_CHECK(nl_image_read(p, &back, &err) == NL_EFORMAT && back == NULL);
  NL_CHECK(strstr(err.msg, "pixel (5, 2) channel 2 is inf") != NULL);
  if (!strstr(err.msg, "pixel (5, 2)")) fprintf(stderr, "  %s\n", err.msg);
  nl_image_free(im); free(p);
}

/* A few hundred bytes declaring an 894 MB header attribute: refused before
 * OpenEXR allocates it, quickly (13.8). */
NL_TEST(hostile_exr_header_refused_quickly)
{
  unsigned char h[278] = {0x76, 0x2f, 0x31, 0x01, 0x02, 0, 0, 0};
  memcpy(h + 8, "channels\0chlist\0", 16);
  h[24] = 0x80; h[25] = 0x6b; h[26] = 0x49; h[27] = 0x35;   /* 894,004,096 */
  char *p = nl_path_join(dir, "hostile.exr");
  FILE *f = fopen(p, "wb");
  fwrite(h, 1, sizeof h, f);
  fclose(f);
  nl_image *im = NULL;
  nl_error err;
  double t0 = nl_time_now();
  NL_CHECK(nl_image_read(p, &im, &err) == NL_EFORMAT && im == NULL);
  NL_CHECK(nl_time_now() - t0 < 2.0);
  NL_CHECK(strstr(err.msg, "attribute 'channels' declares 894004096 bytes") != NULL);
  NL_CHECK(strncmp(err.msg, p, strlen(p)) == 0 && !strchr(err.msg, '\n'));
  /* A data window beyond the pixel cap: refused from the header too. */
  nl_image *ok = ramp(4, 4, 1);
  NL_CHECK(nl_image_write(ok, p, 32, &err) == NL_OK);
  static unsigned char buf[8192];
  long n = file_bytes(p, buf, sizeof buf);
  unsigned char *dw = memmem(buf, (size_t)n, "dataWindow\0box2i\0", 17);
  NL_CHECK(dw != NULL);
  if (dw) {
    unsigned char *xmax = dw + 17 + 4 + 8;       /* size, then xmin ymin xmax ymax */
    xmax[0] = 0xff; xmax[1] = 0xff; xmax[2] = 0xff; xmax[3] = 0x3f;   /* 2^30 - 1 */
    f = fopen(p, "wb");
    fwrite(buf, 1, (size_t)n, f);
    fclose(f);
    NL_CHECK(nl_image_read(p, &im, &err) == NL_EFORMAT && strstr(err.msg, "data window") != NULL);
  }
  nl_image_free(ok); free(p);
}

/* A 264-byte uncompressed TIFF whose header declares 776 x 65474 pixels
 * (50 million, 4.1 GB as the decoder reads them): refused from the header
 * against the file's size, before anything that large is allocated. */
static void put16(unsigned char *b, unsigned v) { b[0] = v & 0xff; b[1] = v >> 8 & 0xff; }
static void put32(unsigned char *b, unsigned long v)
{
  put16(b, v & 0xffff);
  put16(b + 2, (unsigned)(v >> 16));
}

NL_TEST(header_larger_than_file_refused)
{
  static const unsigned long tags[9][3] = {   /* tag, type (3 short, 4 long), value */
    {256, 4, 776}, {257, 4, 65474}, {258, 3, 8}, {259, 3, 1}, {262, 3, 1},
    {273, 4, 122}, {277, 3, 1}, {278, 4, 65474}, {279, 4, 776ul * 65474}};
  unsigned char t[264] = {'I', 'I', 42, 0, 8, 0, 0, 0, 9, 0};
  for (int i = 0; i < 9; i++) {
    unsigned char *e = t + 10 + 12 * i;
    put16(e, (unsigned)tags[i][0]);
    put16(e + 2, (unsigned)tags[i][1]);
    put32(e + 4, 1);
    if (tags[i][1] == 3) put16(e + 8, (unsigned)tags[i][2]);
    else put32(e + 8, tags[i][2]);
  }
  char *p = nl_path_join(dir, "huge_header.tif");
  FILE *f = fopen(p, "wb");
  fwrite(t, 1, sizeof t, f);
  fclose(f);
  nl_image *im = NULL;
  nl_error err = {{0}};
  double t0 = nl_time_now();
  NL_CHECK(nl_image_read(p, &im, &err) == NL_EFORMAT && im == NULL);
  NL_CHECK(nl_time_now() - t0 < 5.0);
  NL_CHECK(strstr(err.msg, "declares 776 x 65474 pixels (5.08e+07 bytes of samples) in 264 bytes")
           != NULL);
  if (im) nl_image_free(im);
  free(p);
}

/* A 150-byte TIFF of 1 x 1 pixel in one tile of 16384 x 16384: a codec
 * decodes, and OpenImageIO converts to float, the whole tile to read the
 * pixel (1 GB, over 10 s under the fuzzers' sanitizers). The tiles
 * covering the image are held to the file's size, not the image alone. */
NL_TEST(tiles_larger_than_file_refused)
{
  static const unsigned long tags[10][3] = {   /* tag, type (3 short, 4 long), value */
    {256, 4, 1}, {257, 4, 1}, {258, 3, 8}, {259, 3, 1}, {262, 3, 1}, {277, 3, 1},
    {322, 4, 16384}, {323, 4, 16384}, {324, 4, 134}, {325, 4, 16}};
  unsigned char t[150] = {'I', 'I', 42, 0, 8, 0, 0, 0, 10, 0};
  for (int i = 0; i < 10; i++) {
    unsigned char *e = t + 10 + 12 * i;
    put16(e, (unsigned)tags[i][0]);
    put16(e + 2, (unsigned)tags[i][1]);
    put32(e + 4, 1);
    if (tags[i][1] == 3) put16(e + 8, (unsigned)tags[i][2]);
    else put32(e + 8, tags[i][2]);
  }
  memset(t + 134, 0x80, 16);
  char *p = nl_path_join(dir, "huge_tiles.tif");
  FILE *f = fopen(p, "wb");
  fwrite(t, 1, sizeof t, f);
  fclose(f);
  nl_image *im = NULL;
  nl_error err = {{0}};
  NL_CHECK(nl_image_read(p, &im, &err) == NL_EFORMAT && im == NULL);
  NL_CHECK(strstr(err.msg, "declares 1 x 1 pixels in tiles of 16384 x 16384 (2.68e+08 bytes of "
                  "samples) in 150 bytes") != NULL);
  if (!strstr(err.msg, "tiles of")) fprintf(stderr, "  %s\n", err.msg);
  if (im) nl_image_free(im);
  free(p);
}

NL_TEST(write_names_the_parent_problem)
{
  nl_image *a = ramp(4, 4, 1);
  char *file = nl_path_join(dir, "afile"), *under = nl_path_join(dir, "afile/x.png");
  FILE *f = fopen(file, "w");
  fclose(f);
  nl_error err;
  NL_CHECK(nl_image_write(a, under, 8, &err) == NL_EIO);
  char want[600];
  snprintf(want, sizeof want, "%s: parent %s is not a directory", under, file);
  NL_CHECK(strcmp(err.msg, want) == 0);
  if (strcmp(err.msg, want)) fprintf(stderr, "  %s\n", err.msg);
  nl_image_free(a); free(file); free(under);
}

static int same_bytes(const char *a, const char *b)
{
  char cmd[1200];
  snprintf(cmd, sizeof cmd, "cmp -s '%s' '%s'", a, b);
  return system(cmd) == 0;
}

/* A full disk, made by a file size limit with SIGXFSZ ignored (writes then
 * fail with EFBIG, as on a full disk with ENOSPC): each format fails with a
 * message naming the file, the old file stays whole and no temporary is
 * left. OpenImageIO's PNG writer ignores its failed writes: before images
 * went to disk through the checked atomic writer, a PNG reported success
 * and was left truncated. */
NL_TEST(full_disk_fails_and_keeps_the_old_file)
{
  static const char *names[3] = {"full.png", "full.exr", "full.tif"};
  char *sub = nl_path_join(dir, "fulldisk");
  nl_error err;
  NL_CHECK(nl_mkdir_p(sub, &err) == NL_OK);
  nl_image *small = ramp(4, 4, 3), *big = ramp(256, 256, 3);
  unsigned x = 1;   /* noise: no codec packs it into the 4 kB limit */
  for (size_t k = 0; k < (size_t)256 * 256 * 3; k++) {
    x = x * 1103515245u + 12345u;
    big->data[k] = (float)(x >> 16) / 65536.0f;
  }
  for (int i = 0; i < 3; i++) {
    char *p = nl_path_join(sub, names[i]), *keep = nl_path_join(sub, "keep");
    NL_CHECK(nl_image_write(small, p, 16, &err) == NL_OK);
    char cp[1200];
    snprintf(cp, sizeof cp, "cp '%s' '%s'", p, keep);
    NL_CHECK(system(cp) == 0);
    /* In this process: a fork after OpenImageIO started its threads can
     * deadlock. Only the soft limit moves, so it can be put back. */
    struct rlimit was, rl;
    NL_CHECK(getrlimit(RLIMIT_FSIZE, &was) == 0);
    rl = was;
    rl.rlim_cur = 4096;
    void (*old)(int) = signal(SIGXFSZ, SIG_IGN);
    NL_CHECK(setrlimit(RLIMIT_FSIZE, &rl) == 0);
    nl_error e2 = {{0}};
    nl_status st = nl_image_write(big, p, 16, &e2);
    setrlimit(RLIMIT_FSIZE, &was);
    signal(SIGXFSZ, old);
    NL_CHECK(st == NL_EIO && strstr(e2.msg, names[i]) && strstr(e2.msg, "File too large"));
    if (st != NL_EIO) fprintf(stderr, "  %s: status %d: %s\n", names[i], (int)st, e2.msg);
    NL_CHECK(same_bytes(p, keep));
    unlink(keep);
    free(p); free(keep);
  }
  DIR *d = opendir(sub);
  struct dirent *e;
  int hidden = 0;
  while ((e = readdir(d))) if (e->d_name[0] == '.' && strlen(e->d_name) > 2) hidden++;
  closedir(d);
  NL_CHECK(hidden == 0);
  nl_image_free(small); nl_image_free(big); free(sub);
}

/* A symbolic link is followed (the file it names is replaced, the link
 * stays); a FIFO is written through, never replaced by a file. */
NL_TEST(links_and_fifos_stay_what_they_are)
{
  nl_image *a = ramp(8, 8, 1);
  nl_error err;
  char *real = nl_path_join(dir, "real.png"), *link = nl_path_join(dir, "link.png");
  char *fifo = nl_path_join(dir, "fifo.png"), *got = nl_path_join(dir, "fromfifo.png");
  NL_CHECK(nl_image_write(a, real, 8, &err) == NL_OK);
  NL_CHECK(symlink("real.png", link) == 0);
  nl_image *b = ramp(16, 16, 1), *back = NULL;
  NL_CHECK(nl_image_write(b, link, 8, &err) == NL_OK);
  struct stat st;
  NL_CHECK(lstat(link, &st) == 0 && S_ISLNK(st.st_mode));
  NL_CHECK(nl_image_read(real, &back, &err) == NL_OK && back && back->width == 16);
  nl_image_free(back);
  /* The reader opens first (O_NONBLOCK: no writer yet), so the write's
   * open does not wait; the PNG fits in the pipe's buffer. */
  NL_CHECK(mkfifo(fifo, 0644) == 0);
  int rd = open(fifo, O_RDONLY | O_NONBLOCK);
  NL_CHECK(rd >= 0);
  NL_CHECK(nl_image_write(b, fifo, 8, &err) == NL_OK);
  NL_CHECK(lstat(fifo, &st) == 0 && S_ISFIFO(st.st_mode));
  static unsigned char buf[65536];
  ssize_t n = rd >= 0 ? read(rd, buf, sizeof buf) : -1;
  if (rd >= 0) close(rd);
  FILE *g = fopen(got, "wb");
  if (g && n > 0) fwrite(buf, 1, (size_t)n, g);
  if (g) fclose(g);
  NL_CHECK(same_bytes(real, got));
  unlink(link); unlink(fifo); unlink(got); unlink(real);
  nl_image_free(a); nl_image_free(b);
  free(real); free(link); free(fifo); free(got);
}

/* A file cut short is refused, not read with the missing pixels as zeros:
 * libtiff reports a short strip as a pending error while OIIO's read_image
 * returns true (a TIFF cut to 30% read with mean 0.119 instead of 0.505).
 * Every format the tools write, cut to 30% as `head -c` would. */
NL_TEST(truncated_files_refused)
{
  const char *names[] = {"cut.tif", "cut.png", "cut.exr", "cut16.tif"};
  const int bits[] = {8, 8, 16, 16};
  nl_image *im = nl_image_alloc(128, 96, 3);
  unsigned long long x = 88172645463325252ULL;   /* xorshift: incompressible pixels */
  for (size_t i = 0; i < (size_t)128 * 96 * 3; i++) {
    x ^= x << 13; x ^= x >> 7; x ^= x << 17;
    im->data[i] = (float)(x >> 40) / (float)(1 << 24);
  }
  for (int k = 0; k < 4; k++) {
    char *p = nl_path_join(dir, names[k]);
    nl_error err = {{0}};
    NL_CHECK(nl_image_write(im, p, bits[k], &err) == NL_OK);
    struct stat st;
    NL_CHECK(stat(p, &st) == 0 && truncate(p, st.st_size * 3 / 10) == 0);
    nl_image *back = NULL;
    nl_status s = nl_image_read(p, &back, &err);
    if (s != NL_EFORMAT) fprintf(stderr, "  %s: read as %s\n", names[k], s ? err.msg : "complete");
    NL_CHECK(s == NL_EFORMAT && back == NULL);
    NL_CHECK(strncmp(err.msg, p, strlen(p)) == 0 && !strchr(err.msg, '\n'));
    if (strstr(names[k], ".png")) {   /* the reader of a build without the module */
      nl_image *b = NULL;
      NL_CHECK(nl_image_png_read(p, &b, &err) == NL_EFORMAT && b == NULL);
      NL_CHECK(strncmp(err.msg, p, strlen(p)) == 0 && !strchr(err.msg, '\n'));
      nl_image_free(b);
    }
    nl_image_free(back);
    free(p);
  }
  nl_image_free(im);
}

/* The PNG reader of a build without image support (nl_image_png.c) gives
 * the module's pixels bit for bit: every PNG under data/ (RGBA patterns,
 * RGB and grey exemplars) and 16-bit and grey ones written here. */
static void same_pixels(const char *path)
{
  nl_image *a = NULL, *b = NULL;
  nl_error err = {{0}};
  NL_CHECK(nl_image_read(path, &a, &err) == NL_OK);
  NL_CHECK(nl_image_png_read(path, &b, &err) == NL_OK);
  if (!a || !b) { fprintf(stderr, "  %s: %s\n", path, err.msg); nl_image_free(a); nl_image_free(b); return; }
  size_t n = (size_t)a->width * a->height * a->channels;
  int same = a->width == b->width && a->height == b->height && a->channels == b->channels &&
             memcmp(a->data, b->data, n * sizeof *a->data) == 0;
  if (!same) fprintf(stderr, "  %s: the two readers differ\n", path);
  NL_CHECK(same);
  nl_image_free(a);
  nl_image_free(b);
}

NL_TEST(png_reader_without_the_module_gives_its_pixels)
{
  const char *folders[] = {"data/patterns", "data/exemplars"};
  int files = 0;
  for (int f = 0; f < 2; f++) {
    char *d = nl_path_join(NL_SOURCE_ROOT, folders[f]);
    DIR *dp = opendir(d);
    NL_CHECK(dp != NULL);
    for (struct dirent *e; dp && (e = readdir(dp));) {
      size_t len = strlen(e->d_name);
      if (len < 5 || strcmp(e->d_name + len - 4, ".png")) continue;
      char *p = nl_path_join(d, e->d_name);
      same_pixels(p);
      free(p);
      files++;
    }
    if (dp) closedir(dp);
    free(d);
  }
  NL_CHECK(files >= 13);
  const int kinds[][2] = {{16, 3}, {8, 1}, {16, 4}};
  for (int k = 0; k < 3; k++) {
    nl_image *im = ramp(19, 7, kinds[k][1]);
    char name[32];
    snprintf(name, sizeof name, "png%d_%d.png", kinds[k][0], kinds[k][1]);
    char *p = nl_path_join(dir, name);
    nl_error err = {{0}};
    NL_CHECK(nl_image_write(im, p, kinds[k][0], &err) == NL_OK);
    same_pixels(p);
    free(p);
    nl_image_free(im);
  }
  nl_image *none = NULL;
  nl_error err = {{0}};
  char *p = nl_path_join(dir, "not.png");
  FILE *fp = fopen(p, "w");
  NL_CHECK(fp && fputs("not a png", fp) >= 0 && fclose(fp) == 0);
  NL_CHECK(nl_image_png_read(p, &none, &err) == NL_EFORMAT && !none && strstr(err.msg, p));
  free(p);
}

int main(void)
{
  dir = nl_test_tmpdir();
  return nl_test_run();
}
