// The one file that speaks C++: OpenImageIO behind the C functions of
// nl_image.h. Nothing else in noiselab includes an OIIO header.
//
// Built as a loadable module (libnl_oiio.so, see meson.build): OIIO pulls in
// some 260 shared libraries, 0.6 s of CPU at every program start, so
// nl_image.c opens this module on the first image read or write and a
// program that only writes tables never loads it. The entry points are
// nl_oiio_read / nl_oiio_encode; nl_image.c's nl_image_read/nl_image_write
// call them (directly when NL_OIIO_STATIC links this file in, as the fuzz
// targets do).
#include "image/nl_image_png.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <ctime>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <exception>
#include <memory>
#include <new>
#include <string>
#include <vector>

extern "C" {
#include "image/nl_image.h"
}

using namespace OIIO;

// OIIO messages can span lines; the contract is one line. A truncated TIFF
// gives one line per strip: the first reason, and how many more there were.
static std::string one_line(const std::string &why)
{
  std::string w = why;
  size_t lines = 0;
  size_t nl = w.find_first_of("\r\n");
  if (nl != std::string::npos) {
    for (size_t k = nl; k < w.size(); k++)
      if (w[k] == '\n' && k + 1 < w.size()) lines++;
    w.erase(nl);
  }
  while (!w.empty() && w.back() == ' ') w.pop_back();
  if (lines > 0) w += " (and " + std::to_string(lines) + " more)";
  return w;
}

static nl_status set_err(nl_error *err, nl_status s, const char *path, const std::string &why)
{
  std::string w = why;
  for (char &c : w) if (c == '\n' || c == '\r') c = ' ';
  while (!w.empty() && w.back() == ' ') w.pop_back();
  return nl_fail(err, s, "%s: %s", path, w.empty() ? "unknown OpenImageIO error" : w.c_str());
}

// libpng (and other codecs) print their own "libpng error: ..." line on
// stderr before OIIO reports the same reason to us; our contract is one
// line, so stderr is muted while a file is opened and read (noiselab reads
// images on one thread).
namespace {
struct mute_stderr {
  int saved = -1, devnull = -1;
  mute_stderr()
  {
    std::fflush(stderr);
    saved = dup(2);
    devnull = open("/dev/null", O_WRONLY);
    if (saved >= 0 && devnull >= 0) dup2(devnull, 2);
  }
  ~mute_stderr()
  {
    if (saved >= 0 && devnull >= 0) dup2(saved, 2);
    if (saved >= 0) close(saved);
    if (devnull >= 0) close(devnull);
  }
};
}

// A tiny hostile file must not make a codec allocate a gigabyte: OpenEXR
// allocates each header attribute at its declared size before it finds the
// file too short (a 284-byte file declaring an 894 MB attribute took 20 s
// and 1 GB). We walk an EXR header ourselves first: every attribute must
// fit in what is left of the file, and the data window within the pixel
// cap. Anything else is left to OpenEXR's own checks.
static bool rd32(FILE *f, int32_t *v)
{
  unsigned char b[4];
  if (std::fread(b, 1, 4, f) != 4) return false;
  *v = (int32_t)((uint32_t)b[0] | (uint32_t)b[1] << 8 | (uint32_t)b[2] << 16 | (uint32_t)b[3] << 24);
  return true;
}

static bool rdname(FILE *f, char *buf, size_t max, size_t *len)
{
  size_t n = 0;
  for (;;) {
    int c = std::fgetc(f);
    if (c == EOF) return false;
    if (c == 0) break;
    if (n + 1 >= max) return false;
    buf[n++] = (char)c;
  }
  buf[n] = '\0';
  *len = n;
  return true;
}

static nl_status check_exr_header(const char *path, FILE *f, long long fsize, nl_error *err)
{
  int32_t magic, version;
  if (!rd32(f, &magic) || magic != 20000630) return NL_OK;   // not EXR: OIIO decides
  if (!rd32(f, &version)) return NL_OK;
  bool longnames = version & 0x400, multipart = version & 0x1000;
  size_t maxname = longnames ? 256 : 32;
  char name[300], type[300];
  for (int part = 0; ; part++) {
    for (int attr = 0; ; attr++) {
      size_t nlen;
      long long at = std::ftell(f);
      if (!rdname(f, name, maxname, &nlen))
        return nl_fail(err, NL_EFORMAT, "%s: EXR header: attribute name at byte %lld is unterminated or too long", path, at);
      if (nlen == 0) {
        if (attr == 0 && (part > 0 || !multipart)) {
          if (part == 0) return nl_fail(err, NL_EFORMAT, "%s: EXR header has no attributes", path);
          return NL_OK;   // the empty header ends a multi-part list
        }
        break;            // end of this header
      }
      size_t tlen;
      int32_t size;
      if (!rdname(f, type, maxname, &tlen) || !rd32(f, &size))
        return nl_fail(err, NL_EFORMAT, "%s: EXR header: attribute '%s' is truncated", path, name);
      long long left = fsize - (long long)std::ftell(f);
      if (size < 0 || (long long)size > left)
        return nl_fail(err, NL_EFORMAT, "%s: EXR header: attribute '%s' declares %lld bytes but the file has %lld left (%lld bytes in all)",
                       path, name, (long long)size, left, fsize);
      if (!std::strcmp(name, "dataWindow") && !std::strcmp(type, "box2i") && size == 16) {
        int32_t b[4];
        for (int k = 0; k < 4; k++) if (!rd32(f, &b[k])) return NL_OK;
        double w = (double)b[2] - b[0] + 1, h = (double)b[3] - b[1] + 1;
        if (w < 1 || h < 1 || w * h > NL_IMAGE_MAX_PIXELS)
          return nl_fail(err, NL_EFORMAT, "%s: EXR data window %.0f x %.0f is empty or beyond %.0f pixels",
                         path, w, h, (double)NL_IMAGE_MAX_PIXELS);
      } else if (std::fseek(f, size, SEEK_CUR) != 0) {
        return NL_OK;
      }
    }
    if (!multipart) return NL_OK;
  }
}

/* Pixels along one axis that the tiles covering n pixels hold (n when the
 * file is not tiled: tile size 0). */
// The bit depth in a PNG's IHDR (byte 24 of the file), or 0 if the file
// does not start as a PNG does.
static int png_bit_depth(const char *path)
{
  unsigned char h[25];
  FILE *fp = std::fopen(path, "rb");
  if (!fp) return 0;
  size_t got = std::fread(h, 1, sizeof h, fp);
  std::fclose(fp);
  if (got < sizeof h || std::memcmp(h, "\x89PNG\r\n\x1a\n", 8) || std::memcmp(h + 12, "IHDR", 4))
    return 0;
  return h[24];
}

static double tile_grid(int n, int tile)
{
  if (n < 1) n = 1;
  return tile > 0 ? std::ceil((double)n / tile) * tile : n;
}

/* nl_image_read (nl_image.c) has named a missing, unreadable or special
 * file before loading this module; what stays here is the EXR header check
 * (its size and open can still fail if the file changed since). */
static nl_status precheck(const char *path, long long *size, nl_error *err)
{
  struct stat st;
  if (stat(path, &st) != 0) return nl_fail(err, NL_EIO, "%s: cannot open: %s", path, std::strerror(errno));
  *size = (long long)st.st_size;
  FILE *f = std::fopen(path, "rb");
  if (!f) return nl_fail(err, NL_EIO, "%s: cannot open: %s", path, std::strerror(errno));
  nl_status s = check_exr_header(path, f, (long long)st.st_size, err);
  std::fclose(f);
  return s;
}

static nl_status read_image(const char *path, nl_image **out, nl_error *err)
{
  *out = nullptr;
  long long file_bytes = 0;
  nl_status ps = precheck(path, &file_bytes, err);
  if (ps) return ps;
  // Pixels are kept unassociated (straight) alpha: a transparent pixel keeps
  // its colour, which control patterns and round trips rely on.
  ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  std::unique_ptr<ImageInput> in;
  {
    mute_stderr m;
    in = ImageInput::open(path, &config);
  }
  if (!in) return set_err(err, NL_EIO, path, OIIO::geterror());
  const ImageSpec &spec = in->spec();
  if (spec.width < 1 || spec.height < 1 || spec.nchannels < 1)
    return set_err(err, NL_EFORMAT, path, "image has no pixels");
  int ch = spec.nchannels > 4 ? 4 : spec.nchannels;
  // Refuse sizes no exemplar or pattern needs before allocating them.
  double npixd = (double)spec.width * spec.height;
  double bytes = npixd * (ch + (ch == 2 ? 4 : ch)) * sizeof(float);
  if (npixd * spec.depth > NL_IMAGE_MAX_PIXELS)
    return nl_fail(err, NL_EFORMAT, "%s: %d x %d pixels%s is beyond the %.0f-pixel limit",
                   path, spec.width, spec.height, spec.depth > 1 ? " (and depth)" : "",
                   (double)NL_IMAGE_MAX_PIXELS);
  // A header can declare any size; the samples must come from the file's
  // bytes. A special file (a FIFO: size 0) is not held to it. A tiled file
  // stores whole tiles, and a codec decodes (OIIO converts) a whole tile to
  // read any pixel of it: a 1 x 1 TIFF may declare 16384 x 16384 tiles,
  // 1 GB and 25 s (fuzz build) from 162 bytes. What is held to the file's size
  // is therefore the grid of tiles that covers the image.
  double grid = tile_grid(spec.width, spec.tile_width) * tile_grid(spec.height, spec.tile_height) *
                tile_grid(spec.depth, spec.tile_depth);
  if (grid > NL_IMAGE_MAX_PIXELS)
    return nl_fail(err, NL_EFORMAT, "%s: %d x %d pixels in tiles of %d x %d is beyond the "
                   "%.0f-pixel limit", path, spec.width, spec.height, spec.tile_width,
                   spec.tile_height, (double)NL_IMAGE_MAX_PIXELS);
  int bits = spec.get_int_attribute("oiio:BitsPerSample", (int)spec.format.size() * 8);
  // OIIO reports a 1-, 2- or 4-bit PNG as 8 bits: its stored bits come from
  // the header (an all-black 1-bit 4096 x 4096 PNG is 2,116 valid bytes).
  if (!std::strcmp(in->format_name(), "png")) {
    int png = png_bit_depth(path);
    if (png > 0 && png < bits) bits = png;
  }
  double raw = grid * spec.nchannels * (bits > 0 ? bits : 1) / 8.0;
  if (file_bytes > 0 && raw > (double)file_bytes * NL_IMAGE_MAX_EXPANSION) {
    char tiles[64] = "";
    if (spec.tile_width > 0)
      std::snprintf(tiles, sizeof tiles, " in tiles of %d x %d", spec.tile_width, spec.tile_height);
    return nl_fail(err, NL_EFORMAT, "%s: declares %d x %d pixels%s (%.3g bytes of samples) in %lld "
                   "bytes, more than compression expands to (%dx): the file is damaged",
                   path, spec.width, spec.height, tiles, raw, file_bytes, NL_IMAGE_MAX_EXPANSION);
  }
  // OpenImageIO 2.4 sizes its strip buffer by the file's RowsPerStrip
  // without clamping it to the image's rows as libtiff does: a 444-byte
  // TIFF of 8 x 65274 pixels declaring 1,073,742,026 rows per strip asked
  // for 8.6 GB (found by fuzz_image). A strip taller than the image is held
  // to the bound of the samples above.
  if (!std::strcmp(in->format_name(), "tiff")) {
    const ParamValue *rp = spec.find_attribute("tiff:RowsPerStrip");
    double rows = rp ? (double)(uint32_t)rp->get_int() : 0.0;
    double strip = rows * (double)spec.scanline_bytes();
    double bound = std::max(raw, (double)file_bytes * NL_IMAGE_MAX_EXPANSION);
    if (rows > spec.height && strip > bound)
      return nl_fail(err, NL_EFORMAT, "%s: declares %.0f rows per strip for an image of %d rows "
                     "(%.3g bytes a strip): the file is damaged", path, rows, spec.height, strip);
  }
  if (!nl_mem_fits(bytes)) {
    char b1[32], b2[32];
    return nl_fail(err, NL_ENOMEM, "%s: %d x %d x %d pixels need %s to read; %s is available",
                   path, spec.width, spec.height, ch, nl_format_bytes(b1, bytes),
                   nl_format_bytes(b2, nl_mem_available()));
  }
  // Grey+alpha (2 channels) is read as grey and alpha, stored as RGBA.
  size_t npix = (size_t)spec.width * spec.height;
  std::unique_ptr<float[]> buf(new float[npix * ch]);
  // Every sample starts as NaN, so a sample the codec never delivered is
  // found below. read_image can return true with an error pending: libtiff
  // reports a strip cut short as an error but OIIO hands back the image with
  // the missing rows as zeros (a TIFF cut to 30% read with mean 0.119
  // instead of 0.505). Both are asked before any pixel is used.
  for (size_t i = 0; i < npix * ch; i++) buf[i] = NAN;
  bool ok;
  {
    mute_stderr m;
    ok = in->read_image(0, 0, 0, ch, TypeDesc::FLOAT, buf.get());
  }
  if (!ok) return set_err(err, NL_EFORMAT, path, in->geterror());
  if (in->has_error()) {
    std::string why = one_line(in->geterror());
    return nl_fail(err, NL_EFORMAT, "%s: truncated or damaged: %s", path, why.c_str());
  }
  // Integer samples cannot be NaN: one still NaN was not delivered. (A float
  // file's NaN is refused below as a value.)
  if (!spec.format.is_floating_point()) {
    size_t got = 0;
    for (size_t p = 0; p < npix; p++) {
      bool whole = true;
      for (int c = 0; c < ch; c++) whole = whole && !std::isnan(buf[p * ch + c]);
      got += whole;
    }
    if (got < npix)
      return nl_fail(err, NL_EFORMAT, "%s: truncated or damaged: %zu of %zu pixels were read",
                     path, got, npix);
  }
  // NaN and infinities are no pixel values (an all-inf EXR once became a
  // params file holding inf and -nan): name the first one.
  for (size_t i = 0; i < npix * ch; i++)
    if (!std::isfinite(buf[i])) {
      size_t p = i / ch;
      return nl_fail(err, NL_EFORMAT, "%s: pixel (%zu, %zu) channel %zu is %s; pixel values must be finite",
                     path, p % (size_t)spec.width, p / (size_t)spec.width, i % ch + 1,
                     std::isnan(buf[i]) ? "NaN" : buf[i] > 0 ? "inf" : "-inf");
    }
  nl_image *im = nl_image_alloc(spec.width, spec.height, ch == 2 ? 4 : ch);
  for (size_t i = 0; i < npix; i++) {
    float *d = im->data + i * im->channels;
    const float *s = buf.get() + i * ch;
    if (ch == 2) { d[0] = d[1] = d[2] = s[0]; d[3] = s[1]; }
    else std::memcpy(d, s, ch * sizeof(float));
  }
  *out = im;
  return NL_OK;
}

// No C++ exception may cross into C: OpenImageIO 2.4's TIFF reader throws
// std::length_error on some tile layouts (found by fuzz_image), and new[]
// throws std::bad_alloc. Either becomes a status. Every allocation above is
// owned by an object until *out is set, so nothing leaks on the way out.
template <class F> static nl_status guarded(const char *path, nl_error *err, F f)
{
  try {
    return f();
  } catch (const std::bad_alloc &) {
    return nl_fail(err, NL_ENOMEM, "%s: out of memory", path);
  } catch (const std::exception &e) {
    return set_err(err, NL_EFORMAT, path, std::string("damaged or unsupported: ") + e.what());
  } catch (...) {
    return nl_fail(err, NL_EFORMAT, "%s: damaged or unsupported (the image library failed)", path);
  }
}

extern "C" nl_status nl_oiio_read(const char *path, nl_image **out, nl_error *err)
{
  *out = nullptr;
  return guarded(path, err, [&] { return read_image(path, out, err); });
}

static TypeDesc type_for(const std::string &path, int bits)
{
  std::string ext = path.substr(path.find_last_of('.') + 1);
  for (char &c : ext) c = (char)tolower(c);
  if (ext == "exr") return bits == 32 ? TypeDesc::FLOAT : TypeDesc::HALF;
  if (bits == 32) return TypeDesc::FLOAT;
  return bits == 16 ? TypeDesc::UINT16 : TypeDesc::UINT8;
}

// SOURCE_DATE_EPOCH as the DateTime attribute ("" when unset: none written).
static nl_status nl_image_timestamp(const char *path, std::string *out, nl_error *err)
{
  out->clear();
  int set;
  long long t;
  nl_status s = nl_image_source_date(path, &set, &t, err);
  if (s || !set) return s;
  time_t tt = (time_t)t;
  struct tm tm;
  gmtime_r(&tt, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y:%m:%d %H:%M:%S", &tm);
  *out = buf;
  return NL_OK;
}

// Encodes into memory (an IOVecOutput), never into a file: the codecs do not
// all report failed writes (the PNG writer ignores a full disk), so the bytes
// go to disk through nl_atomic_write, which checks every one of them and
// knows what to do with a symbolic link or a device. *data is malloc'd.
static nl_status encode_image(const nl_image *im, const char *path, int bits,
                              unsigned char **data, size_t *size, nl_error *err)
{
  if (bits != 8 && bits != 16 && bits != 32)
    return nl_fail(err, NL_EINVAL, "%s: bit depth %d is not 8, 16 or 32", path, bits);
  if (!std::strrchr(path, '.'))
    return nl_fail(err, NL_EINVAL, "%s: no file extension to choose a format from", path);
  auto out = ImageOutput::create(path);
  if (!out) return set_err(err, NL_EIO, path, OIIO::geterror());
  if (!out->supports("ioproxy"))
    return nl_fail(err, NL_EIO, "%s: the %s writer cannot write to memory", path, out->format_name());
  ImageSpec spec(im->width, im->height, im->channels, type_for(path, bits));
  if (im->channels == 4) spec.attribute("oiio:UnassociatedAlpha", 1);
  // Same input, same bytes: TIFF and EXR writers stamp the current time
  // (DateTime, EXR capDate) unless told otherwise; an empty DateTime writes
  // none. SOURCE_DATE_EPOCH (reproducible-builds.org) gives a fixed one.
  std::string when;
  nl_status ws = nl_image_timestamp(path, &when, err);
  if (ws) return ws;
  spec.attribute("DateTime", when);
  std::vector<unsigned char> buf;
  Filesystem::IOVecOutput vec(buf);
  // Integer formats clamp to [0, 1] on conversion from float.
  bool ok = out->set_ioproxy(&vec) && out->open(path, spec);
  ok = ok && out->write_image(TypeDesc::FLOAT, im->data);
  std::string why = ok ? "" : out->geterror();
  ok = out->close() && ok;
  if (!ok) return set_err(err, NL_EIO, path, why.empty() ? out->geterror() : why);
  *data = static_cast<unsigned char *>(std::malloc(buf.size() ? buf.size() : 1));
  if (!*data) return nl_fail(err, NL_ENOMEM, "%s: out of memory for %zu bytes", path, buf.size());
  std::memcpy(*data, buf.data(), buf.size());
  *size = buf.size();
  return NL_OK;
}

extern "C" nl_status nl_oiio_encode(const nl_image *im, const char *path, int bits,
                                    unsigned char **data, size_t *size, nl_error *err)
{
  *data = nullptr;
  *size = 0;
  nl_status st = guarded(path, err, [&] { return encode_image(im, path, bits, data, size, err); });
  if (st && *data) { std::free(*data); *data = nullptr; *size = 0; }
  return st;
}

extern "C" const char *nl_oiio_version(void)
{
  return OIIO_VERSION_STRING;
}
