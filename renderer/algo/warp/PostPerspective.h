// The perspective shadow map as Stamminger and Drettakis wrote it ("Perspective Shadow Maps",
// SIGGRAPH 2002): the scene and the light are taken into the camera's post-perspective space
// (the NDC cube), where perspective aliasing is gone, and an ordinary shadow map is fitted
// there. A directional light becomes a point light (its vanishing point) when it has a
// component along the view vector, stays directional when it is parallel to the image plane,
// and is "inverted" (a point beyond infinity: its rays run away from that point) when it
// comes from behind the viewer; the virtual camera slides back so casters behind the viewer
// are in front of it (Kozlov, "Perspective Shadow Maps: Care and Feeding", GPU Gems 2004;
// Lloyd et al. 2006 §4.4 on why PSM needs its own analysis for a general light).
#pragma once

#include <optional>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "algo/Camera.h"
#include "algo/ShadowBias.h"
#include "algo/warp/PerspectiveWarp.h"

namespace sl::warp {

/// What the light became in post-perspective space.
enum class PsmLightCase {
  Point,        ///< in front of the viewer: a point light at its vanishing point
  Inverted,     ///< behind the viewer: a point beyond infinity, depth order reversed
  Directional,  ///< parallel to the image plane (or nearly): still directional
  Uniform,      ///< no usable post-perspective map (light along the view axis): uniform
};
/// One line for a panel.
const char* psmLightCaseText(PsmLightCase c);

struct PsmSettings {
  /// Extra slide-back of the virtual camera beyond what the casters need, metres (Kozlov's
  /// remedy for texels crowded at the near plane: a weaker warp; 0 = the paper).
  double extraSlideM = 0.0;
  /// The post-perspective light counts as directional when it is farther from the body's
  /// centre than this many times the body's post-perspective radius.
  double directionalRatio = 1e5;
  /// The largest tangent of the light frustum's half-angle in post-perspective space; a
  /// light nearly along the view axis needs more (the frustum approaches 180 degrees: there
  /// the post-perspective map is the orthographic one anyway) and falls back to uniform.
  double maxTanHalf = 100.0;
};

/// The nearest view depth (metres along the view vector from the eye) of any of `boxes`
/// inside the view frustum between its near and far planes; nothing when none is in view.
/// PSM pushes its near plane there (Stamminger and Drettakis: "as far as possible").
std::optional<double> nearestDepthInView(const ViewFrustum& view, std::span<const Aabb> boxes);

struct PsmFit {
  PsmLightCase lightCase = PsmLightCase::Uniform;
  std::string reason;              ///< why uniform (empty otherwise)
  double slideBackM = 0.0;         ///< how far the virtual eye moved back along -v
  double nearM = 0.0, farM = 0.0;  ///< the virtual camera's near and far planes
  glm::dvec3 virtualEye{0.0};
  glm::dmat4 camera{1.0};    ///< world -> the virtual camera's clip space
  glm::dvec4 lightPP{0.0};   ///< the light in post-perspective homogeneous coords
  glm::dmat4 light{1.0};     ///< post-perspective homogeneous -> the map's clip
  glm::dmat4 viewProj{1.0};  ///< light * camera: world -> the map's clip
  double tanHalf = 0.0;      ///< the light frustum's largest half-angle tangent

  bool uniform() const { return lightCase == PsmLightCase::Uniform; }
  /// A world point's map uv (0..1) and window depth (0..1), the GL pass's convention.
  glm::dvec3 mapUvz(const glm::dvec3& world) const;
  /// The map as the lookup's bias model sees it: a general projective matrix.
  DepthMapFrame mapFrame() const;
};

/// The points that may cast into `body` under a directional light: every body point and
/// where its ray towards the light leaves the box [lo, hi] (the scene's bounds).
std::vector<glm::dvec3> castersTowardsLight(std::span<const glm::dvec3> body,
                                            const glm::dvec3& towardsLight, const glm::dvec3& lo,
                                            const glm::dvec3& hi);

/// Fits the post-perspective map: receivers `body` (view frustum ∩ scene, its near plane
/// pushed to nearestDepthInView) decide the map's extent and the camera's near plane,
/// `casters` (castersTowardsLight) its depth range and the slide-back. Errors name
/// the problem (no points, non-finite values, bad view).
std::optional<std::string> fitPostPerspective(const ViewFrustum& view,
                                              std::span<const glm::dvec3> body,
                                              std::span<const glm::dvec3> casters,
                                              const glm::dvec3& towardsLight,
                                              const PsmSettings& settings, PsmFit& out);

}  // namespace sl::warp
