// The one file that speaks C++: OpenImageIO behind the C functions of
// nl_image.h. Nothing else in noiselab includes an OIIO header.
#include <OpenImageIO/imageio.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <unistd.h>
#include <memory>
#include <string>

extern "C" {
#include "image/nl_image.h"
}

using namespace OIIO;

static nl_status set_err(nl_error *err, nl_status s, const char *path, const std::string &why)
{
  std::string w = why;
  // OIIO messages can span lines; the contract is one line.
  for (char &c : w) if (c == '\n' || c == '\r') c = ' ';
  while (!w.empty() && w.back() == ' ') w.pop_back();
  return nl_fail(err, s, "%s: %s", path, w.empty() ? "unknown OpenImageIO error" : w.c_str());
}

extern "C" nl_status nl_image_read(const char *path, nl_image **out, nl_error *err)
{
  *out = nullptr;
  // Pixels are kept unassociated (straight) alpha: a transparent pixel keeps
  // its colour, which control patterns and round trips rely on.
  ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  auto in = ImageInput::open(path, &config);
  if (!in) return set_err(err, NL_EIO, path, OIIO::geterror());
  const ImageSpec &spec = in->spec();
  if (spec.width < 1 || spec.height < 1 || spec.nchannels < 1)
    return set_err(err, NL_EFORMAT, path, "image has no pixels");
  int ch = spec.nchannels > 4 ? 4 : spec.nchannels;
  nl_image *im = nl_image_alloc(spec.width, spec.height, ch == 2 ? 4 : ch);
  // Grey+alpha (2 channels) is read as grey and alpha, stored as RGBA.
  std::unique_ptr<float[]> buf(new float[(size_t)spec.width * spec.height * ch]);
  // libpng prints its own "libpng error: ..." line on stderr before OIIO
  // reports the same reason to us; our contract is one line, so stderr is
  // muted for the duration of the read (noiselab reads images on one thread).
  fflush(stderr);
  int saved = dup(2), devnull = open("/dev/null", O_WRONLY);
  if (saved >= 0 && devnull >= 0) dup2(devnull, 2);
  bool ok = in->read_image(0, 0, 0, ch, TypeDesc::FLOAT, buf.get());
  if (saved >= 0 && devnull >= 0) dup2(saved, 2);
  if (saved >= 0) close(saved);
  if (devnull >= 0) close(devnull);
  if (!ok) {
    std::string why = in->geterror();
    nl_image_free(im);
    return set_err(err, NL_EFORMAT, path, why);
  }
  size_t npix = (size_t)spec.width * spec.height;
  for (size_t i = 0; i < npix; i++) {
    float *d = im->data + i * im->channels;
    const float *s = buf.get() + i * ch;
    if (ch == 2) { d[0] = d[1] = d[2] = s[0]; d[3] = s[1]; }
    else std::memcpy(d, s, ch * sizeof(float));
  }
  for (size_t i = 0; i < npix * im->channels; i++)
    if (!(im->data[i] == im->data[i])) {
      nl_image_free(im);
      return set_err(err, NL_EFORMAT, path, "image holds NaN pixel values");
    }
  *out = im;
  return NL_OK;
}

static TypeDesc type_for(const std::string &path, int bits)
{
  std::string ext = path.substr(path.find_last_of('.') + 1);
  for (char &c : ext) c = (char)tolower(c);
  if (ext == "exr") return bits == 32 ? TypeDesc::FLOAT : TypeDesc::HALF;
  if (bits == 32) return TypeDesc::FLOAT;
  return bits == 16 ? TypeDesc::UINT16 : TypeDesc::UINT8;
}

extern "C" nl_status nl_image_write(const nl_image *im, const char *path, int bits, nl_error *err)
{
  if (bits != 8 && bits != 16 && bits != 32)
    return nl_fail(err, NL_EINVAL, "%s: bit depth %d is not 8, 16 or 32", path, bits);
  if (!std::strrchr(path, '.'))
    return nl_fail(err, NL_EINVAL, "%s: no file extension to choose a format from", path);
  char *tmp = nl_temp_sibling(path);
  // mkstemps is not needed: the XXXXXX is made unique from the pid below.
  std::string t(tmp);
  free(tmp);
  size_t x = t.find("XXXXXX");
  char pid[16];
  snprintf(pid, sizeof pid, "%06d", (int)(getpid() % 1000000));
  t.replace(x, 6, pid);
  auto out = ImageOutput::create(path);
  if (!out) return set_err(err, NL_EIO, path, OIIO::geterror());
  ImageSpec spec(im->width, im->height, im->channels, type_for(path, bits));
  if (im->channels == 4) spec.attribute("oiio:UnassociatedAlpha", 1);
  // Integer formats clamp to [0, 1] on conversion from float.
  if (!out->open(t, spec)) { std::string why = out->geterror(); std::remove(t.c_str()); return set_err(err, NL_EIO, path, why); }
  bool ok = out->write_image(TypeDesc::FLOAT, im->data);
  std::string why = ok ? "" : out->geterror();
  ok = out->close() && ok;
  if (ok && std::rename(t.c_str(), path) != 0) { ok = false; why = std::strerror(errno); }
  if (!ok) { std::remove(t.c_str()); return set_err(err, NL_EIO, path, why.empty() ? out->geterror() : why); }
  return NL_OK;
}

extern "C" const char *nl_image_library_version(void)
{
  return OIIO_VERSION_STRING;
}
