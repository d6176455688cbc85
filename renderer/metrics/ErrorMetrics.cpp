// Pixel error of a shadow mask against the exact reference, and the error image.
#include "metrics/ErrorMetrics.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

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

DistanceSplitError splitErrorByDistance(std::span<const std::uint8_t> technique,
                                        std::span<const std::uint8_t> reference,
                                        std::span<const glm::vec4> positions, glm::vec3 eye) {
  if (technique.size() != reference.size() || positions.size() != reference.size())
    throw std::invalid_argument("splitErrorByDistance: technique mask has " +
                                std::to_string(technique.size()) + " pixels, reference " +
                                std::to_string(reference.size()) + ", positions " +
                                std::to_string(positions.size()));
  DistanceSplitError s;
  auto covered = [&](std::size_t i) {
    return technique[i] != kMaskUncovered && reference[i] != kMaskUncovered &&
           positions[i].w > 0.0f;
  };
  auto distance = [&](std::size_t i) { return double(glm::length(glm::vec3(positions[i]) - eye)); };
  std::vector<double> sorted;
  for (std::size_t i = 0; i < technique.size(); ++i)
    if (covered(i)) sorted.push_back(distance(i));
  if (sorted.empty()) return s;
  // The lower median: with an even count the far set is the upper half exactly.
  const auto mid = sorted.begin() + std::ptrdiff_t((sorted.size() - 1) / 2);
  std::nth_element(sorted.begin(), mid, sorted.end());
  s.medianDistanceM = *mid;
  for (std::size_t i = 0; i < technique.size(); ++i) {
    if (!covered(i)) continue;
    const bool wrong = (technique[i] != kMaskShadowed) != (reference[i] != kMaskShadowed);
    const bool far = distance(i) > s.medianDistanceM;
    (far ? s.farCovered : s.nearCovered) += 1;
    (far ? s.farWrong : s.nearWrong) += wrong ? 1 : 0;
  }
  if (s.nearCovered) s.nearErrorPct = 100.0 * double(s.nearWrong) / double(s.nearCovered);
  if (s.farCovered) s.farErrorPct = 100.0 * double(s.farWrong) / double(s.farCovered);
  return s;
}

ImageRGBA8 makeErrorImage(const ImageRGBA8& shaded, std::span<const std::uint8_t> technique,
                          std::span<const std::uint8_t> reference, int dilatePx) {
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
  if (dilatePx <= 0) return out;
  // Dilate: false shadow first, false lit over it (the rarer, usually the worse, error).
  const int w = shaded.width, h = shaded.height;
  auto covered = [&](std::size_t i) {
    return technique[i] != kMaskUncovered && reference[i] != kMaskUncovered;
  };
  for (const bool falseLit : {false, true})
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const std::size_t i = std::size_t(y) * std::size_t(w) + std::size_t(x);
        const bool techLit = technique[i] != kMaskShadowed, refLit = reference[i] != kMaskShadowed;
        if (!covered(i) || techLit == refLit || techLit != falseLit) continue;
        const Rgba8& colour = falseLit ? kFalseLitColor : kFalseShadowColor;
        for (int yy = std::max(y - dilatePx, 0); yy <= std::min(y + dilatePx, h - 1); ++yy)
          for (int xx = std::max(x - dilatePx, 0); xx <= std::min(x + dilatePx, w - 1); ++xx) {
            const std::size_t j = std::size_t(yy) * std::size_t(w) + std::size_t(xx);
            if (covered(j)) std::copy(colour.begin(), colour.end(), out.pixels.data() + 4 * j);
          }
      }
  return out;
}

}  // namespace sl
