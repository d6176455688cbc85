// 8-bit RGBA images in memory and on disk (PNG and any other format OpenImageIO reads),
// plus a perceptual colour map (viridis, van der Walt & Smith 2015) for float images such
// as importance maps and aliasing heat maps. No GL, no Qt.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace sl {

/// An 8-bit RGBA image. Row 0 is the TOP row (as in PNG files); 4 bytes per pixel,
/// rows tightly packed: pixel (x, y) starts at byte 4 * (y * width + x).
/// GL readbacks have row 0 at the bottom: pass them through flipVertically().
struct ImageRGBA8 {
  int width = 0, height = 0;
  std::vector<std::uint8_t> pixels;  ///< width * height * 4 bytes

  std::size_t pixelCount() const {
    return width > 0 && height > 0 ? std::size_t(width) * std::size_t(height) : 0;
  }
  /// True when the size is positive and `pixels` holds exactly width * height * 4 bytes.
  bool valid() const { return pixelCount() > 0 && pixels.size() == pixelCount() * 4; }
  std::uint8_t* pixel(int x, int y) { return pixels.data() + 4 * (std::size_t(y) * width + x); }
  const std::uint8_t* pixel(int x, int y) const {
    return pixels.data() + 4 * (std::size_t(y) * width + x);
  }
};

using Rgba8 = std::array<std::uint8_t, 4>;

/// A width x height image filled with one colour (opaque black by default).
ImageRGBA8 makeImage(int width, int height, Rgba8 fill = {0, 0, 0, 255});
/// Swaps rows in place (top <-> bottom): converts GL readbacks (row 0 = bottom) to
/// ImageRGBA8's row 0 = top convention and back.
void flipVertically(ImageRGBA8& image);
/// Flips rows of any tightly packed row-major buffer of `height` rows of `rowBytes` bytes
/// (e.g. float readbacks of `width * channels * sizeof(float)` bytes per row).
void flipRowsVertically(std::span<std::uint8_t> data, std::size_t rowBytes, int height);

/// Writes `image` to `path`; the format follows the extension (".png" for PNG; anything
/// OpenImageIO can write). Creates missing parent directories. Alpha is stored as is
/// (not premultiplied). Returns an error message naming the path, or nothing on success.
std::optional<std::string> writeImage(const std::filesystem::path& path, const ImageRGBA8& image);
/// Whether writeImage can write `path`'s format (by its extension), checked before any work:
/// an error naming the path ("has no extension ...", "no image format for '.xyz'"), or nothing.
std::optional<std::string> checkImageFormat(const std::filesystem::path& path);

/// Reads any image OpenImageIO can read and converts it to RGBA8 (the first subimage):
/// 1 channel -> grey, 2 -> grey + alpha, 3 -> RGB + opaque alpha, >= 4 -> the first four.
/// Float and 16-bit data are clamped to [0, 1] and scaled linearly (no colour-space
/// conversion). Alpha is returned as stored (not premultiplied). On failure returns
/// nothing and, when `error` is given, stores a message naming the path.
std::optional<ImageRGBA8> readImage(const std::filesystem::path& path,
                                    std::string* error = nullptr);

/// The viridis colour map at t in [0, 1] (clamped; NaN gives t = 0): dark purple
/// (68, 1, 84) at 0, teal near 0.5, yellow (253, 231, 37) at 1. Opaque.
/// Piecewise linear through every 16th entry of the 256-entry table.
Rgba8 viridis(float t);

/// Maps a single-channel float image through viridis: `lo` -> t = 0, `hi` -> t = 1
/// (lo > hi reverses the map; lo == hi maps values >= hi to 1 and the rest to 0).
/// `values` has w * h entries in the same row order as the result (row 0 = top; flip GL
/// readbacks first). NaN values become opaque black; +-inf clamp to the ends.
/// Throws std::invalid_argument when values.size() != w * h or w, h < 0.
ImageRGBA8 colorMapped(std::span<const float> values, int w, int h, float lo, float hi);

}  // namespace sl
