/* nl_image_png.h - PNG reading without OpenImageIO (nl_image_png.c): what
 * nl_image_read uses in a build without image support. Private to the
 * library; the same pixels as the OpenImageIO module's reader. */
#ifndef NL_IMAGE_PNG_H
#define NL_IMAGE_PNG_H
#include "image/nl_image.h"

/* PATH (a PNG, 8 or 16 bits, 1 to 4 channels) into *out; NL_EIO or
 * NL_EFORMAT with a one-line message naming the file. */
nl_status nl_image_png_read(const char *path, nl_image **out, nl_error *err);

#endif
