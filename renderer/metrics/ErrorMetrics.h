// Shadow error against the exact reference (techniques.md, "Measuring"): the share of
// covered pixels whose hard shadow test disagrees with the ray-traced answer, split into
// false-lit and false-shadowed, and an error image that shows where.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "common/shared_constants.h"
#include "metrics/Image.h"

namespace sl {

/// Shadow-mask encoding shared by the technique's readback and ShadowReference.
/// Any value other than kMaskShadowed and kMaskUncovered is read as lit.
inline constexpr std::uint8_t kMaskShadowed = SL_MASK_SHADOWED;
inline constexpr std::uint8_t kMaskLit = SL_MASK_LIT;
inline constexpr std::uint8_t kMaskUncovered = SL_MASK_EMPTY;

struct ShadowErrorStats {
  std::size_t covered = 0;      ///< pixels covered in both masks
  std::size_t falseLit = 0;     ///< technique lit, reference shadowed (light leaks)
  std::size_t falseShadow = 0;  ///< technique shadowed, reference lit (acne, over-shadowing)
  double errorPct = 0.0;        ///< 100 * (falseLit + falseShadow) / covered, 0 when none
  double falseLitPct = 0.0;     ///< 100 * falseLit / covered
  double falseShadowPct = 0.0;  ///< 100 * falseShadow / covered
  /// Pixels covered in one mask but not the other (should be 0: both come from the same
  /// G-buffer). They are left out of `covered` and of the percentages.
  std::size_t coverageMismatch = 0;
};

/// Compares two masks of the same frame (1 lit, 0 shadowed, 255 not covered).
/// Throws std::invalid_argument when the sizes differ. No covered pixel: all zero.
ShadowErrorStats compareShadowMasks(std::span<const std::uint8_t> technique,
                                    std::span<const std::uint8_t> reference);

/// The error split by distance from the camera (the DA-RTW poster's "regions distant to the
/// camera"): the pixels covered in both masks at or nearer than their (lower) median distance,
/// and those beyond it. The split comes from the frame's geometry alone, so two techniques
/// rendering the same frame are split alike (their errors pair pixel set by pixel set).
struct DistanceSplitError {
  double medianDistanceM = 0.0;  ///< the median distance of the covered pixels (0: none)
  std::size_t nearCovered = 0, farCovered = 0;
  std::size_t nearWrong = 0, farWrong = 0;
  double nearErrorPct = 0.0;  ///< 100 * nearWrong / nearCovered, 0 when none
  double farErrorPct = 0.0;   ///< 100 * farWrong / farCovered, 0 when none
};

/// `positions`: the frame's world positions (w > 0: covered), the masks' pixel order; `eye`:
/// the camera's position. Throws std::invalid_argument when the sizes differ.
DistanceSplitError splitErrorByDistance(std::span<const std::uint8_t> technique,
                                        std::span<const std::uint8_t> reference,
                                        std::span<const glm::vec4> positions, glm::vec3 eye);

/// Colours of the error image (opaque RGBA).
inline constexpr Rgba8 kFalseLitColor = {255, 0, 255, 255};     ///< magenta: light leak
inline constexpr Rgba8 kFalseShadowColor = {0, 255, 255, 255};  ///< cyan: wrong shadow

/// The error image: every pixel covered in both masks shows the shaded colour desaturated
/// and darkened to grey (0.5 * Rec. 709 luma) unless the masks disagree: false-lit pixels
/// are magenta (kFalseLitColor), false-shadowed pixels cyan (kFalseShadowColor).
/// Pixels not covered in both masks are copied unchanged from `shaded`.
/// The masks are in the same row order as `shaded` (row 0 = top: flip GL readbacks first).
/// Throws std::invalid_argument when `shaded` is not valid or a mask's size is not
/// shaded.width * shaded.height.
/// `dilatePx` > 0 (for print, where single-pixel lines vanish): every wrong pixel is drawn
/// as a (2 dilatePx + 1)^2 square, over covered pixels only; false lit drawn over false
/// shadow where squares meet.
ImageRGBA8 makeErrorImage(const ImageRGBA8& shaded, std::span<const std::uint8_t> technique,
                          std::span<const std::uint8_t> reference, int dilatePx = 0);

}  // namespace sl
