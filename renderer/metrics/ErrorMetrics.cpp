// Pixel error of a shadow mask against the exact reference, and the error image.
#include "metrics/ErrorMetrics.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace sl {

ShadowErrorStats compareShadowMasks(std::span<const std::uint8_t> technique,
                                    std::span<const std::uint8_t> reference) {
  if (technique.size() != reference.size())
    throw std::invalid_argument("compareShadowMasks: technique mask has " +
                                std::to_string(technique.size()) + " pixels, reference " +
                                std::to_string(reference.size()));
  ShadowErrorStats s;
  for (std::size_t i = 0; i < technique.size(); ++i) {
    const bool techCovered = technique[i] != kMaskUncovered;
    const bool refCovered = reference[i] != kMaskUncovered;
    if (techCovered != refCovered) ++s.coverageMismatch;
    if (!techCovered || !refCovered) continue;
    ++s.covered;
    const bool techLit = technique[i] != kMaskShadowed;
    const bool refLit = reference[i] != kMaskShadowed;
    if (techLit && !refLit) ++s.falseLit;
    if (!techLit && refLit) ++s.falseShadow;
  }
  if (s.covered > 0) {
    const double scale = 100.0 / double(s.covered);
    s.falseLitPct = scale * double(s.falseLit);
    s.falseShadowPct = scale * double(s.falseShadow);
    s.errorPct = scale * double(s.falseLit + s.falseShadow);
  }
  return s;
}

ImageRGBA8 makeErrorImage(const ImageRGBA8& shaded, std::span<const std::uint8_t> technique,
                          std::span<const std::uint8_t> reference) {
  if (!shaded.valid()) throw std::invalid_argument("makeErrorImage: invalid shaded image");
  const std::size_t n = shaded.pixelCount();
  if (technique.size() != n || reference.size() != n)
    throw std::invalid_argument("makeErrorImage: masks have " + std::to_string(technique.size()) +
                                " and " + std::to_string(reference.size()) + " pixels, image " +
                                std::to_string(n));
  ImageRGBA8 out = shaded;
  for (std::size_t i = 0; i < n; ++i) {
    if (technique[i] == kMaskUncovered || reference[i] == kMaskUncovered) continue;
    const bool techLit = technique[i] != kMaskShadowed;
    const bool refLit = reference[i] != kMaskShadowed;
    std::uint8_t* p = out.pixels.data() + 4 * i;
    Rgba8 c;
    if (techLit && !refLit) {
      c = kFalseLitColor;
    } else if (!techLit && refLit) {
      c = kFalseShadowColor;
    } else {
      const float luma = 0.2126f * p[0] + 0.7152f * p[1] + 0.0722f * p[2];
      const auto grey = static_cast<std::uint8_t>(std::lround(std::min(0.5f * luma, 255.0f)));
      c = {grey, grey, grey, 255};
    }
    std::copy(c.begin(), c.end(), p);
  }
  return out;
}

}  // namespace sl
