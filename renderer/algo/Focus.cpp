#include "Focus.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace sl {

namespace {

struct Plane {
  glm::vec3 n;  // inside: dot(n, p) + d >= 0
  float d;
  float eval(const glm::vec3& p) const { return glm::dot(n, p) + d; }
};

using Polygon = std::vector<glm::vec3>;

Polygon clipPolygon(const Polygon& poly, const Plane& plane) {
  Polygon out;
  if (poly.empty()) return out;
  for (size_t i = 0; i < poly.size(); ++i) {
    const glm::vec3& a = poly[i];
    const glm::vec3& b = poly[(i + 1) % poly.size()];
    float da = plane.eval(a), db = plane.eval(b);
    if (da >= 0) out.push_back(a);
    if ((da >= 0) != (db >= 0)) out.push_back(a + (b - a) * (da / (da - db)));
  }
  return out;
}

Plane planeThrough(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c,
                   const glm::vec3& inside) {
  glm::vec3 n = glm::normalize(glm::cross(b - a, c - a));
  Plane p{n, -glm::dot(n, a)};
  if (p.eval(inside) < 0) p = Plane{-n, -p.d};
  return p;
}

// Faces of a hexahedron given in the frustumCorners order (0-3 near, 4-7 far, CCW).
std::array<std::array<int, 4>, 6> hexFaces() {
  return {{{0, 1, 2, 3}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}}};
}

}  // namespace

std::vector<glm::vec3> intersectFrustumWithBox(const std::array<glm::vec3, 8>& fc,
                                               const Aabb& box) {
  // Box corners in the same hexahedron order as the frustum.
  std::array<glm::vec3, 8> bc = {
      glm::vec3(box.min.x, box.min.y, box.min.z), glm::vec3(box.max.x, box.min.y, box.min.z),
      glm::vec3(box.max.x, box.max.y, box.min.z), glm::vec3(box.min.x, box.max.y, box.min.z),
      glm::vec3(box.min.x, box.min.y, box.max.z), glm::vec3(box.max.x, box.min.y, box.max.z),
      glm::vec3(box.max.x, box.max.y, box.max.z), glm::vec3(box.min.x, box.max.y, box.max.z)};
  auto planesOf = [](const std::array<glm::vec3, 8>& c) {
    glm::vec3 inside(0.0f);
    for (const auto& p : c) inside += p / 8.0f;
    std::vector<Plane> planes;
    for (const auto& f : hexFaces())
      planes.push_back(planeThrough(c[f[0]], c[f[1]], c[f[2]], inside));
    return planes;
  };
  std::vector<Plane> boxPlanes = planesOf(bc), frustumPlanes = planesOf(fc);
  std::vector<glm::vec3> points;
  auto clipFaces = [&](const std::array<glm::vec3, 8>& c, const std::vector<Plane>& planes) {
    for (const auto& f : hexFaces()) {
      Polygon poly = {c[f[0]], c[f[1]], c[f[2]], c[f[3]]};
      for (const Plane& p : planes) poly = clipPolygon(poly, p);
      points.insert(points.end(), poly.begin(), poly.end());
    }
  };
  clipFaces(fc, boxPlanes);
  clipFaces(bc, frustumPlanes);
  return points;
}

glm::mat4 lightBaseView(const glm::vec3& towardsLight) {
  glm::vec3 d = glm::normalize(towardsLight);
  glm::vec3 up = std::abs(d.y) > 0.99f ? glm::vec3(0, 0, -1) : glm::vec3(0, 1, 0);
  return glm::lookAt(glm::vec3(0.0f), -d, up);
}

glm::mat4 imagePlaneRotation(const glm::mat2& r) {
  glm::mat4 m(1.0f);
  m[0][0] = r[0][0];
  m[0][1] = r[0][1];
  m[1][0] = r[1][0];
  m[1][1] = r[1][1];
  return m;
}

namespace {

/// Flat boxes grown a little so that the clipping stays well conditioned.
Aabb paddedBounds(const Aabb& sceneBounds) {
  Aabb box = sceneBounds;
  glm::vec3 pad = glm::max(box.size() * 0.001f, glm::vec3(1e-3f));
  box.min -= pad;
  box.max += pad;
  return box;
}

/// The orthographic light frustum around `focus` (x, y) whose depth range reaches every
/// caster of `box` towards the light.
void fitOrthoAroundFocus(std::vector<glm::vec3> focus, const Aabb& box,
                         const glm::vec3& towardsLight, const FocusSettings& settings,
                         LightFit& out) {
  glm::mat4 view = imagePlaneRotation(settings.rotation) * lightBaseView(towardsLight);
  glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
  for (const glm::vec3& p : focus) {
    glm::vec3 q = glm::vec3(view * glm::vec4(p, 1.0f));
    lo = glm::min(lo, q);
    hi = glm::max(hi, q);
  }
  // Casters anywhere in the scene between the light and the focus region must be in the
  // depth range: extend towards the light (larger view z) to the scene's extent.
  for (const glm::vec3& p : box.corners()) {
    glm::vec3 q = glm::vec3(view * glm::vec4(p, 1.0f));
    hi.z = std::max(hi.z, q.z);
  }
  if (settings.extent == FocusExtent::RotationInvariant) {
    // The bounding circle in the unrotated image plane, then its centre rotated: the
    // square's side depends only on the focus region, never on the rotation.
    const glm::mat4 base = lightBaseView(towardsLight);
    glm::vec2 blo(std::numeric_limits<float>::max()), bhi(-std::numeric_limits<float>::max());
    for (const glm::vec3& p : focus) {
      glm::vec2 q = glm::vec2(base * glm::vec4(p, 1.0f));
      blo = glm::min(blo, q);
      bhi = glm::max(bhi, q);
    }
    const glm::vec2 centre = 0.5f * (blo + bhi);
    float radius = 0.0f;
    for (const glm::vec3& p : focus)
      radius = std::max(radius, glm::length(glm::vec2(base * glm::vec4(p, 1.0f)) - centre));
    const glm::vec2 c = settings.rotation * centre;
    lo.x = c.x - radius, hi.x = c.x + radius, lo.y = c.y - radius, hi.y = c.y + radius;
  }
  glm::vec2 extent(hi.x - lo.x, hi.y - lo.y);
  glm::vec2 grow = glm::max(extent * settings.paddingFraction, glm::vec2(1e-3f));
  lo.x -= grow.x, hi.x += grow.x, lo.y -= grow.y, hi.y += grow.y;
  float zPad = std::max(1e-3f, 0.01f * (hi.z - lo.z));
  out.view = view;
  out.proj = glm::ortho(lo.x, hi.x, lo.y, hi.y, -(hi.z + zPad), -(lo.z - zPad));
  out.viewProj = out.proj * out.view;
  out.extentM = glm::vec2(hi.x - lo.x, hi.y - lo.y);
  out.depthRangeM = (hi.z - lo.z) + 2 * zPad;
  out.focusPoints = std::move(focus);
}

}  // namespace

std::optional<std::string> fitDirectionalLight(const Camera& camera, float aspect,
                                               const Aabb& sceneBounds,
                                               const glm::vec3& towardsLight,
                                               const FocusSettings& settings, LightFit& out) {
  if (auto err = camera.validate()) return err;
  if (!(aspect > 0.0f) || !std::isfinite(aspect)) return "camera: aspect ratio must be > 0";
  float len = glm::length(towardsLight);
  if (!(len > 1e-6f) || !std::isfinite(len)) return "light: direction is zero or not finite";
  if (!sceneBounds.valid()) return "scene: empty bounds (no geometry)";

  const Aabb box = paddedBounds(sceneBounds);

  std::vector<glm::vec3> focus =
      intersectFrustumWithBox(camera.frustumCorners(aspect, camera.nearM, camera.farM), box);
  if (focus.empty()) {
    auto c = box.corners();
    focus.assign(c.begin(), c.end());
  }
  fitOrthoAroundFocus(std::move(focus), box, towardsLight, settings, out);
  return std::nullopt;
}

std::optional<std::string> fitDirectionalLightToScene(const Aabb& sceneBounds,
                                                      const glm::vec3& towardsLight,
                                                      LightFit& out) {
  float len = glm::length(towardsLight);
  if (!(len > 1e-6f) || !std::isfinite(len)) return "light: direction is zero or not finite";
  if (!sceneBounds.valid()) return "scene: empty bounds (no geometry)";
  const Aabb box = paddedBounds(sceneBounds);
  auto c = box.corners();
  fitOrthoAroundFocus(std::vector<glm::vec3>(c.begin(), c.end()), box, towardsLight,
                      FocusSettings{}, out);
  return std::nullopt;
}

std::optional<std::string> fitSpotLight(const Light& light, const Aabb& sceneBounds,
                                        LightFit& out) {
  if (light.type != LightType::Spot) return "light: not a spot light";
  if (auto err = light.validate()) return err;
  if (!sceneBounds.valid()) return "scene: empty bounds (no geometry)";
  const glm::vec3 pos = light.positionM, axis = light.spotAxis();
  // Farthest point of the bounds along the axis, within range.
  float far = 0.0f;
  for (const glm::vec3& c : sceneBounds.corners()) far = std::max(far, glm::dot(c - pos, axis));
  if (light.rangeM > 0.0f) far = std::min(far, light.rangeM);
  // Nearest point of the bounds: a point inside the cone at distance r lies at least
  // r cos(outer) along the axis.
  const glm::vec3 nearest = glm::clamp(pos, sceneBounds.min, sceneBounds.max);
  const float dist = glm::length(nearest - pos);
  const float cosOuter = std::cos(glm::radians(light.outerConeDeg));
  float near = std::max(0.99f * dist * cosOuter, 1e-3f * far);
  far *= 1.01f;
  out.sceneOutside = !(far > 0.0f) || !(near < far);
  if (out.sceneOutside) {
    // No point of the scene lies inside the cone within range: every point is shadowed (as
    // the resolve and the reference say of points outside the cone). Any valid frustum
    // along the axis draws that; this one holds no geometry.
    far = light.rangeM > 0.0f ? light.rangeM : 1.0f;
    near = 1e-3f * far;
  }
  const glm::vec3 up = std::abs(axis.y) > 0.99f ? glm::vec3(0, 0, -1) : glm::vec3(0, 1, 0);
  const float fov = 2.0f * glm::radians(light.outerConeDeg);
  out.view = glm::lookAt(pos, pos + axis, up);
  out.proj = glm::perspective(fov, 1.0f, near, far);
  out.viewProj = out.proj * out.view;
  const float side = 2.0f * std::tan(0.5f * fov);
  out.extentM = glm::vec2(side);
  out.depthRangeM = far - near;
  out.perspective = true;
  out.nearM = near;
  out.farM = far;
  out.focusPoints.clear();
  return std::nullopt;
}

}  // namespace sl
