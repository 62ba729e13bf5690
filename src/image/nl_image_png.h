/* nl_image_png.h - PNG without OpenImageIO (nl_image_png.c): the writer
 * nl_image_write uses for every .png when the build has zlib, and the
 * reader nl_image_read uses in a build without image support. Private to
 * the library; the same samples as the OpenImageIO module's. */
#ifndef NL_IMAGE_PNG_H
#define NL_IMAGE_PNG_H
#include "image/nl_image.h"

#ifdef __cplusplus
extern "C" {
#endif

/* PATH (a PNG, 8 or 16 bits, 1 to 4 channels) into *out; NL_EIO or
 * NL_EFORMAT with a one-line message naming the file. */
nl_status nl_image_png_read(const char *path, nl_image **out, nl_error *err);

/* IM (1, 3 or 4 channels) as a PNG of `bits` (8 or 16) bits a sample in memory (*data malloc'd,
 * *size bytes), deflated at zlib `level` (0-9): the bytes nl_image_write
 * puts in a .png when the build has zlib (NL_PNG_WRITE). IHDR, then tIME
 * when SOURCE_DATE_EPOCH is set, one IDAT, IEND. */
nl_status nl_image_png_encode(const nl_image *im, const char *path, int bits, int level,
                              unsigned char **data, size_t *size, nl_error *err);

/* SOURCE_DATE_EPOCH (reproducible-builds.org): *set 0 when unset or empty,
 * else 1 and *t its seconds since 1970; NL_EINVAL naming path when it is
 * not a number of seconds in years 1970-9999. */
nl_status nl_image_source_date(const char *path, int *set, long long *t, nl_error *err);

#ifdef __cplusplus
}
#endif

#endif
