// The outside view's geometry (OutsideView.h): frustum corners from clip matrices, the
// segments to draw and the third camera framing them.
#include "OutsideView.h"

#include <algorithm>
#include <cmath>

#include "PartitionColours.h"
#include "common/shared_constants.h"

namespace sl {

const char* outlineRoleName(OutlineRole role) {
  switch (role) {
    case OutlineRole::Camera:
      return "camera";
    case OutlineRole::Split:
      return "split";
    case OutlineRole::LightMap:
      return "light map";
    case OutlineRole::Warp:
      return "warp";
  }
  return "?";
}

glm::vec3 outlineColour(OutlineRole role, int map) {
  switch (role) {
    case OutlineRole::Camera:
      return {SL_OUTLINE_CAMERA_COLOUR};
    case OutlineRole::Split:
      return {SL_OUTLINE_SPLIT_COLOUR};
    case OutlineRole::Warp:
      return {SL_OUTLINE_WARP_COLOUR};
    case OutlineRole::LightMap:
      break;
  }
  return partitionColour(map);
}

std::array<glm::vec3, 8> clipCubeCorners(const glm::mat4& worldToClip) {
  const glm::dmat4 inv = glm::inverse(glm::dmat4(worldToClip));
  std::array<glm::vec3, 8> out;
  for (int i = 0; i < 8; ++i) {
    const int face = i & 3;
    const double x = (face == 1 || face == 2) ? 1.0 : -1.0;
    const double y = (face >= 2) ? 1.0 : -1.0;
    const double z = i < 4 ? -1.0 : 1.0;
    const glm::dvec4 p = inv * glm::dvec4(x, y, z, 1.0);
    out[size_t(i)] = glm::vec3(glm::dvec3(p) / p.w);
  }
  return out;
}

std::optional<glm::vec3> projectionCentre(const glm::mat4& worldToClip) {
  const glm::dvec4 p = glm::inverse(glm::dmat4(worldToClip)) * glm::dvec4(0.0, 0.0, 1.0, 0.0);
  const double scale = glm::length(glm::dvec3(p));
  if (!(std::abs(p.w) > 1e-9 * scale)) return std::nullopt;
  const glm::dvec3 c = glm::dvec3(p) / p.w;
  if (!std::isfinite(c.x) || !std::isfinite(c.y) || !std::isfinite(c.z)) return std::nullopt;
  return glm::vec3(c);
}

FrustumOutline FrustumOutline::fromClip(const glm::mat4& worldToClip, OutlineRole role, int map) {
  FrustumOutline f;
  f.corners = clipCubeCorners(worldToClip);
  if (auto c = projectionCentre(worldToClip)) f.apex = std::array<glm::vec3, 4>{*c, *c, *c, *c};
  f.role = role;
  f.map = map;
  return f;
}

float outlineFarM(const Camera& camera, const Aabb& sceneBounds) {
  if (!sceneBounds.valid()) return camera.farM;
  const glm::vec3 f = camera.forward();
  float deepest = camera.nearM;
  for (const glm::vec3& c : sceneBounds.corners())
    deepest = std::max(deepest, glm::dot(c - camera.position, f));
  return std::clamp(deepest, camera.nearM, camera.farM);
}

namespace {

void addBox(std::vector<OutlineSegment>& out, const std::array<glm::vec3, 8>& c, OutlineRole role,
            int map) {
  const glm::vec3 colour = outlineColour(role, map);
  for (int i = 0; i < 4; ++i) {
    const int j = (i + 1) % 4;
    out.push_back({c[size_t(i)], c[size_t(j)], colour, role, map});
    out.push_back({c[size_t(i + 4)], c[size_t(j + 4)], colour, role, map});
    out.push_back({c[size_t(i)], c[size_t(i + 4)], colour, role, map});
  }
}

bool finite(const std::array<glm::vec3, 8>& c) {
  for (const glm::vec3& p : c)
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return false;
  return true;
}

}  // namespace

std::vector<OutlineSegment> outlineSegments(const Camera& camera, float aspect,
                                            const Aabb& sceneBounds,
                                            const FrameOutlines& outlines) {
  std::vector<OutlineSegment> out;
  const float farM = outlineFarM(camera, sceneBounds);
  addBox(out, camera.frustumCorners(aspect, camera.nearM, farM), OutlineRole::Camera, 0);
  for (float d : outlines.splitDepthsM) {
    if (!(d > camera.nearM && d < farM)) continue;
    const auto c = camera.frustumCorners(aspect, d, d);
    const glm::vec3 colour = outlineColour(OutlineRole::Split, 0);
    for (int i = 0; i < 4; ++i)
      out.push_back({c[size_t(i)], c[size_t((i + 1) % 4)], colour, OutlineRole::Split, 0});
  }
  for (const FrustumOutline& f : outlines.frusta) {
    const auto& c = f.corners;
    if (!finite(c)) continue;
    addBox(out, c, f.role, f.map);
    if (f.role != OutlineRole::Warp || !f.apex) continue;
    const glm::vec3 colour = outlineColour(OutlineRole::Warp, f.map);
    for (int i = 0; i < 4; ++i) {
      // From the side edge's end nearer to the apex.
      const glm::vec3 apex = (*f.apex)[size_t(i)];
      const glm::vec3 a = c[size_t(i)], b = c[size_t(i + 4)];
      const glm::vec3 nearer = glm::length(a - apex) < glm::length(b - apex) ? a : b;
      if (!std::isfinite(apex.x) || !std::isfinite(apex.y) || !std::isfinite(apex.z)) continue;
      out.push_back({nearer, apex, colour, OutlineRole::Warp, f.map, false});
    }
  }
  return out;
}

Camera fitOutsideCamera(const Camera& camera, float aspect,
                        std::span<const OutlineSegment> segments,
                        const OutsideViewSettings& settings) {
  Aabb box;
  for (const OutlineSegment& s : segments)
    if (s.framed) box.extend(s.a), box.extend(s.b);
  const glm::vec3 centre = box.valid() ? box.center() : camera.target;
  float radius = 0.0f;
  for (const OutlineSegment& s : segments)
    if (s.framed) radius = std::max({radius, glm::length(s.a - centre), glm::length(s.b - centre)});
  if (!(radius > 1e-3f)) radius = std::max(1.0f, glm::length(camera.position - camera.target));
  const float zoom = std::clamp(settings.zoom, 1e-4f, 1.0f);
  // Zooming in moves the centre onto the main camera's view axis, zoom of the way to the
  // framed centre's depth (a kilometre-deep frustum: towards what the camera sees first).
  const glm::vec3 onAxis =
      camera.position +
      camera.forward() *
          (zoom * std::max(glm::dot(centre - camera.position, camera.forward()), 0.0f));
  const glm::vec3 target = onAxis + (centre - onAxis) * zoom;
  radius *= zoom;

  // Horizontal forward and right of the main camera (world +y up).
  glm::vec3 forward = camera.forward();
  forward.y = 0.0f;
  forward = glm::length(forward) > 1e-4f ? glm::normalize(forward) : glm::vec3(0.0f, 0.0f, -1.0f);
  const glm::vec3 right = glm::normalize(glm::cross(forward, glm::vec3(0.0f, 1.0f, 0.0f)));
  const float az = glm::radians(settings.azimuthDeg), el = glm::radians(settings.elevationDeg);
  const glm::vec3 horizontal = -forward * std::cos(az) + right * std::sin(az);
  const glm::vec3 towardsEye =
      glm::normalize(horizontal * std::cos(el) + glm::vec3(0.0f, 1.0f, 0.0f) * std::sin(el));

  const float halfY = glm::radians(settings.fovYDeg) * 0.5f;
  const float halfX = std::atan(std::tan(halfY) * std::max(aspect, 1e-3f));
  const float distance = radius / std::sin(std::min(halfX, halfY));

  Camera out;
  out.fovYDeg = settings.fovYDeg;
  out.target = target;
  out.position = target + towardsEye * distance;
  out.up = glm::vec3(0.0f, 1.0f, 0.0f);
  out.nearM = std::max(distance * 1e-3f, distance - 1.5f * radius);
  out.farM = distance + 3.0f * radius;
  return out;
}

}  // namespace sl
