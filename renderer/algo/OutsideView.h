// The outside view (issue 10, "Panels"): a third camera that shows the main camera's frustum,
// its split planes, every shadow map's light frustum and a warp's frustum as lines, so a
// lecturer can show what a warp or a partition does. Plain math: techniques publish what
// to draw (FrameOutlines), the renderer draws the segments this file computes.
#pragma once

#include <array>
#include <optional>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "Camera.h"

namespace sl {

/// What an outline stands for; its colour follows (outlineColour).
enum class OutlineRole {
  Camera,    ///< the main camera's view frustum
  Split,     ///< a split plane of a multi-map technique (a cross-section of the view frustum)
  LightMap,  ///< a shadow map's light frustum (orthographic box or perspective frustum)
  Warp,      ///< a warped map's frustum (PSM / LiSPSM / TSM): its sides meet at the warp's centre
};
const char* outlineRoleName(OutlineRole role);  ///< "camera", "split", "light map", "warp"

/// One frustum a technique publishes: 8 world-space corners (0-3 one face, 4-7 the opposite
/// one, in the same order), and for a perspective one the point each side edge (i, i + 4)
/// converges to (its centre of projection, or a point of its apex line).
struct FrustumOutline {
  std::array<glm::vec3, 8> corners{};
  std::optional<std::array<glm::vec3, 4>> apex;
  OutlineRole role = OutlineRole::LightMap;
  int map = 0;  ///< the map's index (LightMap: coloured like the partition overlay)
  /// The volume `worldToClip` maps into the GL clip cube [-1, 1]^3 (the inverse of a map's
  /// lightViewProj): clipCubeCorners, apex = projectionCentre when it is perspective.
  static FrustumOutline fromClip(const glm::mat4& worldToClip, OutlineRole role, int map = 0);
};

/// What a technique publishes each frame for the outside view (FrameContext::outlines).
struct FrameOutlines {
  std::vector<FrustumOutline> frusta;
  /// View depths (metres along the camera's forward axis) of the split planes between
  /// partitions; empty for a single-map technique.
  std::vector<float> splitDepthsM;
};

/// A line segment to draw, world space.
struct OutlineSegment {
  glm::vec3 a{0.0f}, b{0.0f};
  glm::vec3 colour{1.0f};
  OutlineRole role = OutlineRole::Camera;
  int map = 0;
  bool framed = true;  ///< fitOutsideCamera keeps it in view
};

/// The colour of a role (shared_constants.h: SL_OUTLINE_*; LightMap: SL_PARTITION_COLOUR_<map mod
/// 8>).
glm::vec3 outlineColour(OutlineRole role, int map);

/// The 8 corners of the volume `worldToClip` maps to the clip cube: 0-3 at clip z = -1, 4-7 at
/// z = +1, each face counter-clockwise (x, y) = (-,-), (+,-), (+,+), (-,+). Non-finite corners
/// (a singular matrix) are returned as they come.
std::array<glm::vec3, 8> clipCubeCorners(const glm::mat4& worldToClip);

/// The centre of projection of a perspective `worldToClip` (the world point with clip
/// x = y = w = 0); none for an orthographic (affine) matrix.
std::optional<glm::vec3> projectionCentre(const glm::mat4& worldToClip);

/// How far the main camera's frustum is drawn: its near plane to the deepest corner of the
/// scene bounds along its forward axis, clamped to [near, far] (the depth range the
/// techniques focus on: view frustum ∩ scene bounds). Far when the bounds are invalid.
float outlineFarM(const Camera& camera, const Aabb& sceneBounds);

/// Every segment of the outside view: the main camera's frustum from near to outlineFarM
/// (12 edges), a rectangle per split depth within that range, 12 edges per published frustum
/// and, for a Warp frustum with an apex, its 4 side edges extended from the face nearer to
/// the apex to it (`framed` false: the third camera does not frame them).
std::vector<OutlineSegment> outlineSegments(const Camera& camera, float aspect,
                                            const Aabb& sceneBounds, const FrameOutlines& outlines);

/// Where the third camera looks from. Azimuth is measured around world +y from behind the
/// main camera (0: behind it, looking along its horizontal forward; 90: from its right),
/// elevation above the horizon. Zoom 1 frames every framed segment; zoom z < 1 frames a
/// sphere z times as large centred near the main camera's view axis, z of the way to the
/// segments' centre (0.05: the first twentieth of a kilometre-deep frustum).
struct OutsideViewSettings {
  float azimuthDeg = 60.0f;
  float elevationDeg = 35.0f;
  float zoom = 1.0f;
  float fovYDeg = 40.0f;
};

/// The third camera: looks at the centre of the framed segments' bounding box from the
/// settings' direction, far enough that their bounding sphere fills the smaller field of view,
/// near and far around that sphere (unframed segments may leave the view). Falls back to the main
/// camera's target when there are no segments.
Camera fitOutsideCamera(const Camera& camera, float aspect,
                        std::span<const OutlineSegment> segments,
                        const OutsideViewSettings& settings);

}  // namespace sl
