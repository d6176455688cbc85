// RMSM page requests (Lefohn, Sengupta, Owens 2007; techniques.md §5): per camera pixel the
// light-space (s, t) and the LOD l = log2(sqrt(A)), A = |dX × dY| in virtual texels, turned
// into the key of the page that serves it; dedup (a request stays only when its left and
// lower neighbours ask for a different page), compaction, sort and unique. Plain C++: the
// CPU reference of shaders/rmsm/requests.comp, which mirrors requestLevel / requestPage.
#pragma once

#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "VirtualPages.h"

namespace sl::pages {

/// floor(log2(sqrt(|dX × dY|))) - lodBias with dX, dY the pixel's steps in light uv scaled
/// to virtual texels, clamped to [0, topLevel]; a degenerate footprint (A = 0) asks for level
/// 0. lodBias > 0 asks for pages that many levels finer than the footprint (2^bias texels per
/// pixel side). Float arithmetic in the shader's order.
int requestLevel(glm::vec2 dUvDx, glm::vec2 dUvDy, const VirtualLayout& layout, int lodBias = 0);
/// The page at `level` containing light uv `st`; kNoPage outside [0, 1]².
PageKey requestPage(glm::vec2 st, int level, const VirtualLayout& layout);

/// A camera pixel's light-space position: uv = (s, t), covered = the G-buffer has a surface
/// there that the light map covers; its world position and normal (same-surface derivatives).
struct PixelUv {
  glm::vec2 st{0.0f};
  bool covered = false;
  glm::vec3 position{0.0f};
  glm::vec3 normal{0.0f};
};

/// Which neighbour a pixel's screen derivative steps to (lod.derivatives).
enum class Derivatives {
  /// The right / upper neighbour, else the left / lower one, whatever surface it lies on: at a
  /// silhouette the step jumps to another surface and the footprint is far too large.
  Neighbour = SL_RMSM_DERIVATIVES_NEIGHBOUR,
  /// The first of those two that lies on the pixel's own surface (sameSurface), else as
  /// Neighbour: what a GPU's derivative of the rasterised (s, t) gives, whose helper pixels
  /// lie on the pixel's own triangle.
  SameSurface = SL_RMSM_DERIVATIVES_SAME_SURFACE,
};
/// `other` lies on `here`'s surface: its offset leaves here's tangent plane by at most
/// SL_RMSM_SAME_SURFACE_PLANE of its length and the normals agree within
/// acos(SL_RMSM_SAME_SURFACE_NORMAL_COS).
bool sameSurface(const PixelUv& here, const PixelUv& other);

/// Per pixel (row by row, y = 0 the bottom row) the requested key or kNoPage. The screen
/// derivatives are forward differences to the right / upper neighbour, backward ones at the
/// last column / row or where that neighbour is not covered (or, SameSurface, not on the
/// pixel's surface when the other is), zero when neither is covered.
std::vector<PageKey> pixelRequests(std::span<const PixelUv> pixels, int width, int height,
                                   const VirtualLayout& layout, int lodBias = 0,
                                   Derivatives derivatives = Derivatives::Neighbour);
/// The dedup step: a pixel keeps its key only when the left (x-1) and lower (y-1)
/// neighbours ask for a different page (a missing neighbour counts as different).
std::vector<PageKey> dedupRequests(std::span<const PageKey> requests, int width, int height);
/// Compaction: the keys that are not kNoPage, in pixel order.
std::vector<PageKey> compactRequests(std::span<const PageKey> requests);
/// Sort + unique.
std::vector<PageKey> sortUnique(std::span<const PageKey> requests);

}  // namespace sl::pages
