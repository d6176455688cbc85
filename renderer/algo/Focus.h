// Focusing a directional light's orthographic frustum on what the camera sees:
// the light's x/y extent covers the intersection of the view frustum and the scene
// bounds (the "focus region"), the depth range covers every possible caster.
// Also carries DA-RTW's rotation of the light image plane (seed 000, R_k), and the
// perspective frustum of a spot light (its cone, near/far fitted to the scene).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "Camera.h"
#include "Light.h"

namespace sl {

/// Vertices of the convex polyhedron (camera frustum between nearM and farM) ∩ box.
/// Empty when they do not intersect.
std::vector<glm::vec3> intersectFrustumWithBox(const std::array<glm::vec3, 8>& frustumCorners,
                                               const Aabb& box);

/// The light's base view (no image-plane rotation): looks along -towardsLight, with
/// a stable up vector.
glm::mat4 lightBaseView(const glm::vec3& towardsLight);

/// 4x4 rotation about the light's view axis from a 2x2 rotation [[c,-s],[s,c]].
glm::mat4 imagePlaneRotation(const glm::mat2& rotation);

struct LightFit {
  glm::mat4 view{1.0f};      ///< world -> light view (rotation applied)
  glm::mat4 proj{1.0f};      ///< orthographic (directional) or perspective (spot)
  glm::mat4 viewProj{1.0f};  ///< proj * view
  /// Width and height of the light frustum in metres at clip w = 1: orthographic, the
  /// frustum's size; perspective, its size at 1 m along the axis (2 tan(cone)); metres per
  /// unit of light uv at a point = extentM * its clip w.
  glm::vec2 extentM{0.0f};
  float depthRangeM = 0.0f;            ///< near..far of the light frustum in metres
  bool perspective = false;            ///< proj is a perspective projection (spot)
  float nearM = 0.0f, farM = 0.0f;     ///< perspective: near and far planes, metres
  std::vector<glm::vec3> focusPoints;  ///< vertices of the focus region (world)
  /// Spot: no point of the scene bounds lies inside the cone within range (behind the light,
  /// beyond its range): the frustum is a valid one along the axis, and every point is
  /// outside the cone, so shadowed.
  bool sceneOutside = false;
};

/// How the light frustum's x/y extent is fitted around the focus region.
enum class FocusExtent {
  /// The tightest box in the (rotated) light frame: its area, and the texels per m² of a
  /// map, change with the rotation.
  Tight,
  /// The square around the focus region's bounding circle in the light's image plane
  /// (centre: the middle of the unrotated box; radius: the farthest focus point from it).
  /// Rotating the image plane rotates this square about the circle's centre and changes
  /// nothing else: its side, area and texel density are the same at every angle, and it
  /// always covers the focus region.
  RotationInvariant,
};

struct FocusSettings {
  glm::mat2 rotation{1.0f};  ///< image-plane rotation (DA-RTW), identity otherwise
  FocusExtent extent = FocusExtent::Tight;
  float paddingFraction = 0.01f;  ///< grow x/y extent by this share on each side
};

/// Fits the light frustum. Returns an error (and no fit) for a degenerate light or
/// camera, or when the camera sees none of the scene bounds (then the whole scene is
/// used as focus region instead, and no error).
std::optional<std::string> fitDirectionalLight(const Camera& camera, float aspect,
                                               const Aabb& sceneBounds,
                                               const glm::vec3& towardsLight,
                                               const FocusSettings& settings, LightFit& out);

/// A directional light's orthographic frustum around the whole scene, independent of any
/// camera (adaptive shadow maps keep pages between frames: they stay valid while the light
/// and the geometry stay). Error for a degenerate direction or empty bounds.
std::optional<std::string> fitDirectionalLightToScene(const Aabb& sceneBounds,
                                                      const glm::vec3& towardsLight, LightFit& out);

/// A spot light's one perspective frustum: from its position along its axis, a square
/// field of view of twice the outer cone angle (the cone's bounding square), near and far
/// fitted to the scene bounds within the light's range. Every point of the scene inside
/// the cone lies inside the frustum: near is the bounds' distance times cos(cone) (or
/// 1e-3 far when the light is inside the bounds). Bounds wholly behind the light or beyond
/// its range: a valid frustum with sceneOutside set (the scene is all shadowed). Error for a
/// light that is not a valid spot, or empty bounds.
std::optional<std::string> fitSpotLight(const Light& light, const Aabb& sceneBounds, LightFit& out);

}  // namespace sl
