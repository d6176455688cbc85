// Image files through OpenImageIO (or, built with SHADOWLAB_OIIO=OFF, PNG through stb), row
// flips and the viridis colour map.
#include "metrics/Image.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <system_error>

#if SHADOWLAB_HAVE_OIIO
#include <OpenImageIO/imageio.h>
#else
#include <cctype>
#include <cerrno>
#include <cstring>

#include <stb_image.h>
#include <stb_image_write.h>
#endif

namespace sl {

ImageRGBA8 makeImage(int width, int height, Rgba8 fill) {
  ImageRGBA8 image;
  image.width = std::max(width, 0);
  image.height = std::max(height, 0);
  image.pixels.resize(image.pixelCount() * 4);
  for (std::size_t i = 0; i < image.pixelCount(); ++i)
    std::copy(fill.begin(), fill.end(), image.pixels.begin() + std::ptrdiff_t(4 * i));
  return image;
}

void flipRowsVertically(std::span<std::uint8_t> data, std::size_t rowBytes, int height) {
  if (height <= 1 || rowBytes == 0) return;
  if (data.size() < rowBytes * std::size_t(height))
    throw std::invalid_argument("flipRowsVertically: buffer smaller than rowBytes * height");
  for (int top = 0, bottom = height - 1; top < bottom; ++top, --bottom)
    std::swap_ranges(data.begin() + std::ptrdiff_t(rowBytes * top),
                     data.begin() + std::ptrdiff_t(rowBytes * (top + 1)),
                     data.begin() + std::ptrdiff_t(rowBytes * bottom));
}

void flipVertically(ImageRGBA8& image) {
  if (!image.valid()) return;
  flipRowsVertically(image.pixels, std::size_t(image.width) * 4, image.height);
}

std::optional<std::string> writeImage(const std::filesystem::path& path, const ImageRGBA8& image) {
  const std::string name = path.string();
  if (!image.valid())
    return "cannot write " + name + ": invalid image (" + std::to_string(image.width) + "x" +
           std::to_string(image.height) + ", " + std::to_string(image.pixels.size()) + " bytes)";
  if (path.has_parent_path()) {
    std::error_code ec;
    std::filesystem::create_directories(path.parent_path(), ec);
    if (ec)
      return "cannot create directory " + path.parent_path().string() + " for " + name + ": " +
             ec.message();
  }
#if SHADOWLAB_HAVE_OIIO
  auto out = OIIO::ImageOutput::create(name);
  if (!out) return "cannot write " + name + ": " + OIIO::geterror();
  OIIO::ImageSpec spec(image.width, image.height, 4, OIIO::TypeDesc::UINT8);
  // Our alpha is straight (unassociated): store it as is, without un-premultiplying.
  spec.attribute("oiio:UnassociatedAlpha", 1);
  if (!out->open(name, spec)) return "cannot write " + name + ": " + out->geterror();
  if (!out->write_image(OIIO::TypeDesc::UINT8, image.pixels.data())) {
    std::string err = out->geterror();
    out->close();
    return "cannot write " + name + ": " + err;
  }
  if (!out->close()) return "cannot write " + name + ": " + out->geterror();
  return std::nullopt;
#else
  std::string ext = path.extension().string();
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  if (ext != ".png")
    return "cannot write " + name + ": this build writes PNG only (built with SHADOWLAB_OIIO=OFF)";
  if (!stbi_write_png(name.c_str(), image.width, image.height, 4, image.pixels.data(),
                      image.width * 4))
    return "cannot write " + name + ": " + std::strerror(errno);
  return std::nullopt;
#endif
}

std::optional<std::string> checkImageFormat(const std::filesystem::path& path) {
  const std::string name = path.string();
  if (path.extension().empty() || path.filename() == path.extension())
    return "'" + name + "' has no extension: name the image format (.png)";
#if SHADOWLAB_HAVE_OIIO
  // Finds the writer by the extension without creating the file.
  if (!OIIO::ImageOutput::create(name)) {
    (void)OIIO::geterror();  // clear it
    return "'" + name + "': no image format for '" + path.extension().string() + "' (use .png)";
  }
#else
  std::string ext = path.extension().string();
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  if (ext != ".png")
    return "'" + name + "': this build writes PNG only (built with SHADOWLAB_OIIO=OFF)";
#endif
  return std::nullopt;
}

std::optional<ImageRGBA8> readImage(const std::filesystem::path& path, std::string* error) {
  const std::string name = path.string();
  auto fail = [&](const std::string& why) -> std::optional<ImageRGBA8> {
    if (error) *error = "cannot read " + name + ": " + why;
    return std::nullopt;
  };
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return fail("no such file");
#if SHADOWLAB_HAVE_OIIO
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);  // alpha as stored, not premultiplied
  auto in = OIIO::ImageInput::open(name, &config);
  if (!in) return fail(OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0)
    return fail("empty image (" + std::to_string(spec.width) + "x" + std::to_string(spec.height) +
                ", " + std::to_string(spec.nchannels) + " channels)");
  const int channels = std::min(spec.nchannels, 4);
  const std::size_t count = std::size_t(spec.width) * std::size_t(spec.height);
  std::vector<std::uint8_t> raw(count * std::size_t(channels));
  if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::UINT8, raw.data()))
    return fail(in->geterror());
  in->close();
  const int width = spec.width, height = spec.height;
#else
  // stb: PNG, JPEG, BMP, TGA, PSD, GIF, HDR, PIC, PNM; 8 bits per channel.
  int width = 0, height = 0, fileChannels = 0;
  std::uint8_t* data = stbi_load(name.c_str(), &width, &height, &fileChannels, 0);
  if (!data) return fail(stbi_failure_reason() ? stbi_failure_reason() : "unreadable image");
  if (width <= 0 || height <= 0 || fileChannels <= 0) {
    stbi_image_free(data);
    return fail("empty image");
  }
  const int channels = std::min(fileChannels, 4);
  const std::size_t count = std::size_t(width) * std::size_t(height);
  std::vector<std::uint8_t> raw(data, data + count * std::size_t(channels));
  stbi_image_free(data);
#endif

  ImageRGBA8 image;
  image.width = width;
  image.height = height;
  image.pixels.resize(count * 4);
  for (std::size_t i = 0; i < count; ++i) {
    const std::uint8_t* s = raw.data() + i * std::size_t(channels);
    std::uint8_t* d = image.pixels.data() + i * 4;
    switch (channels) {
      case 1:
        d[0] = d[1] = d[2] = s[0], d[3] = 255;
        break;
      case 2:
        d[0] = d[1] = d[2] = s[0], d[3] = s[1];
        break;
      case 3:
        d[0] = s[0], d[1] = s[1], d[2] = s[2], d[3] = 255;
        break;
      default:
        d[0] = s[0], d[1] = s[1], d[2] = s[2], d[3] = s[3];
        break;
    }
  }
  return image;
}

namespace {

// Viridis (Stefan van der Walt and Nathaniel Smith, CC0): entries 0, 16, ..., 240 and 255
// of the 256-entry table used by matplotlib, linear RGB in [0, 1].
constexpr int kViridisKnots = 17;
constexpr float kViridis[kViridisKnots][3] = {
    {0.267004f, 0.004874f, 0.329415f}, {0.282327f, 0.094955f, 0.417331f},
    {0.278826f, 0.175490f, 0.483397f}, {0.258965f, 0.251537f, 0.524736f},
    {0.229739f, 0.322361f, 0.545706f}, {0.199430f, 0.387607f, 0.554642f},
    {0.172719f, 0.448791f, 0.557885f}, {0.149039f, 0.508051f, 0.557250f},
    {0.127568f, 0.566949f, 0.550556f}, {0.120638f, 0.625828f, 0.533488f},
    {0.157851f, 0.683765f, 0.501686f}, {0.246070f, 0.738910f, 0.452024f},
    {0.369214f, 0.788888f, 0.382914f}, {0.515992f, 0.831158f, 0.294279f},
    {0.678489f, 0.863742f, 0.189503f}, {0.845561f, 0.887322f, 0.099702f},
    {0.993248f, 0.906157f, 0.143936f},
};

/// Table index (0..255) of knot k.
constexpr float knotIndex(int k) {
  return k == kViridisKnots - 1 ? 255.0f : 16.0f * k;
}

std::uint8_t toByte(float v) {
  return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
}

}  // namespace

Rgba8 viridis(float t) {
  if (std::isnan(t)) t = 0.0f;
  const float index = std::clamp(t, 0.0f, 1.0f) * 255.0f;
  int k = std::min(static_cast<int>(index / 16.0f), kViridisKnots - 2);
  const float f = (index - knotIndex(k)) / (knotIndex(k + 1) - knotIndex(k));
  Rgba8 c{0, 0, 0, 255};
  for (int i = 0; i < 3; ++i)
    c[i] = toByte(kViridis[k][i] + f * (kViridis[k + 1][i] - kViridis[k][i]));
  return c;
}

ImageRGBA8 colorMapped(std::span<const float> values, int w, int h, float lo, float hi) {
  if (w < 0 || h < 0) throw std::invalid_argument("colorMapped: negative size");
  if (values.size() != std::size_t(w) * std::size_t(h))
    throw std::invalid_argument("colorMapped: " + std::to_string(values.size()) + " values for a " +
                                std::to_string(w) + "x" + std::to_string(h) + " image");
  ImageRGBA8 image = makeImage(w, h);
  for (std::size_t i = 0; i < values.size(); ++i) {
    const float v = values[i];
    Rgba8 c{0, 0, 0, 255};
    if (!std::isnan(v)) {
      float t;
      if (hi == lo)
        t = v >= hi ? 1.0f : 0.0f;
      else
        t = std::clamp((v - lo) / (hi - lo), 0.0f, 1.0f);  // +-inf clamp to the ends
      c = viridis(t);
    }
    std::copy(c.begin(), c.end(), image.pixels.begin() + std::ptrdiff_t(4 * i));
  }
  return image;
}

}  // namespace sl
