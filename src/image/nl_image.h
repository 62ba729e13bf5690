/* nl_image.h - float images, read and written through OpenImageIO.
 *
 * An nl_image is width x height pixels of `channels` floats (1 grey, 3 RGB,
 * 4 RGBA), interleaved, rows top to bottom. Integer files map to [0, 1].
 *
 *   nl_image *im = nl_image_alloc(512, 512, 3);
 *   nl_image_write(im, "out.png", 8, &err);    // format from the extension;
 *                                              // bits 8/16 for PNG, 16/32 (half/
 *                                              // float) for EXR, 8/16/32 TIFF
 *   nl_image_read("in.exr", &im, &err);        // any format OIIO reads
 *
 * Writes are atomic (temporary file beside the target, then rename). Errors
 * name the file and carry OpenImageIO's reason.
 *
 * Montage: nl_image_montage() lays images out in a grid with a caption under each
 * panel ("(a) 1 octave"), so a multi-panel figure is one PNG. Text uses the
 * stb_easy_font bitmap font scaled by an integer factor.
 */
#ifndef NL_IMAGE_H
#define NL_IMAGE_H

#include "base/nl_base.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct nl_image {
  int width, height, channels;
  float *data;
} nl_image;

nl_image *nl_image_alloc(int width, int height, int channels);
void nl_image_free(nl_image *im);
static inline float *nl_image_pixel(const nl_image *im, int x, int y)
{ return im->data + ((size_t)y * im->width + x) * im->channels; }

/* Reading refuses, with a message naming the file: NaN or infinite pixel
 * values (the first one named), images beyond NL_IMAGE_MAX_PIXELS or the
 * machine's memory, and EXR headers whose attributes declare more bytes
 * than the file holds (checked before OpenEXR allocates them). Codecs'
 * own stderr lines are muted: the message is the one line. */
#define NL_IMAGE_MAX_PIXELS (1L << 28)
/* Nor may a file declare more samples than its bytes can expand to:
 * deflate (PNG, TIFF, EXR zip) expands at most 1032 times, TIFF's LZW
 * about 1400 times. A header declaring more bytes of samples than
 * NL_IMAGE_MAX_EXPANSION times the file's size (a 264-byte TIFF of
 * 776 x 65474) is refused before the decoder allocates or loops over
 * them; in a tiled file, the samples of the tiles that cover the image
 * (a 1 x 1 TIFF may declare one tile of 16384 x 16384). Not covered:
 * CCITT fax coding and EXR's lossy DWA of constant images, which can go
 * further. */
#define NL_IMAGE_MAX_EXPANSION 2048
nl_status nl_image_read(const char *path, nl_image **out, nl_error *err);
/* Writing embeds no time: TIFF DateTime / EXR capDate are left out, so the
 * same image gives the same bytes; with SOURCE_DATE_EPOCH set (seconds
 * since 1970) that time is written instead. The parent directory of path
 * is checked first ("x/y.png: parent x is not a directory"). */
nl_status nl_image_write(const nl_image *im, const char *path, int bits, nl_error *err);
/* NL_EINVAL (and nl_image_write refuses) when path's format cannot hold
 * `bits` as asked: 32-bit float to an integer format (PNG, JPEG, BMP, GIF,
 * PNM, TGA, WebP), which OpenImageIO would quietly clip to 0..1 at 8 bits,
 * and any depth but 16 (half) or 32 (float) to EXR (bits 0, a program's
 * "not given", passes).
 * Programs call it before computing an image so a refusal costs nothing. */
nl_status nl_image_check_bits(const char *path, int bits, nl_error *err);

/* A grey image from a w*h array of doubles, mapped linearly so that lo -> 0
 * and hi -> 1 (values outside are clamped). */
nl_image *nl_image_from_values(const double *v, int w, int h, double lo, double hi);

/* Converts to `channels` (1, 3 or 4): grey is replicated, RGB -> grey by
 * Rec. 709 luminance, alpha added as 1 or dropped. */
nl_image *nl_image_convert(const nl_image *im, int channels);

/* Draws text with its top-left corner at (x, y), `scale` pixels per font
 * pixel, in colour rgb (3 floats). Clipped to the image. */
void nl_image_text(nl_image *im, int x, int y, int scale, const char *text, const float *rgb);
int nl_image_text_width(const char *text, int scale);
int nl_image_text_height(const char *text, int scale);

/* Box-filter reduction by an integer factor f (w/f x h/f, remainders
 * dropped). */
nl_image *nl_image_downsample(const nl_image *im, int f);

/* n images in a grid of `cols` columns on a white background, each cell as
 * large as the largest image, a caption under each (labels may be NULL or
 * contain NULLs), and an optional title above. Output is RGB. Montages are
 * for reports: when the grid would be wider than NL_MONTAGE_MAX_WIDTH the
 * panels are box-filtered down by the smallest integer factor that fits
 * (the full-size data stays in the experiment's tables and images). */
#define NL_MONTAGE_MAX_WIDTH 2200
nl_image *nl_image_montage(const nl_image *const *images, const char *const *labels, int n,
                           int cols, const char *title);

/* Where nl_image_montage puts things, for the same panel sizes (widths[i] x
 * heights[i]), labels, cols and title, computed without drawing: a test
 * reads a panel back out of a montage file at rects[i] (n of them; may be
 * NULL) to compare it with what its caption says. factor > 1 when the panels
 * were box-filtered down (nl_image_downsample) to fit NL_MONTAGE_MAX_WIDTH:
 * rects are then the reduced panels'. */
typedef struct { int x, y, w, h; } nl_image_rect;
typedef struct {
  int width, height;           /* the montage */
  int factor;                  /* reduction of every panel, 1 for none */
  int cols, pad, scale;        /* grid columns, gap in pixels, caption font scale */
  int cell_w, cell_h;          /* a cell, the largest (reduced) panel */
  int caption_h, title_h;      /* caption band under each row, title band above */
} nl_image_montage_geometry;
void nl_image_montage_layout(const int *widths, const int *heights, const char *const *labels, int n,
                             int cols, const char *title, nl_image_montage_geometry *g, nl_image_rect *rects);

/* OpenImageIO's version string (the one this build was compiled against),
 * for manifests; it does not load the image back-end. */
const char *nl_image_library_version(void);

/* The image back-end (OpenImageIO) is a module, libnl_oiio.so, opened on the
 * first nl_image_read or nl_image_write: a program that writes only tables
 * starts without loading OIIO's ~260 shared libraries. It is looked for at
 * $NL_OIIO_MODULE, then in the build tree, then where `meson install` puts
 * it; if none loads, read and write fail with NL_EIO and a message naming
 * the places tried. 1 once it is loaded (for tests). */
int nl_image_backend_loaded(void);

#ifdef __cplusplus
}
#endif

#endif
