// The exact shadow of the built-in `plane-box` scene: a thin square occluder above a ground
// plane, lit by a directional light. The scene generator builds the scene from these
// constants and the tests use the functions as the analytic reference. Header-only, glm only.
//
// For an infinitely thin square at height h the shadow is the square translated by
// -h * L.xz / L.y (L = towards the light). The occluder here is a box of thickness t, so the
// exact shadow is the square swept between the offsets for heights h - t/2 and h + t/2.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include <glm/glm.hpp>

namespace sl {
namespace planebox {

inline constexpr float kGroundHalfSizeM = 10.0f;       ///< ground: 20 x 20 m, y = 0, centred
inline constexpr float kOccluderHalfSizeM = 1.0f;      ///< occluder: 2 x 2 m in x and z
inline constexpr float kOccluderCenterHeightM = 1.0f;  ///< centred 1 m above the origin
inline constexpr float kOccluderThicknessM = 0.02f;    ///< in y
inline constexpr float kSunAzimuthDeg = 30.0f;         ///< from +z towards +x
inline constexpr float kSunElevationDeg = 60.0f;       ///< above the horizon

/// The scene's sun, unit vector towards the light (same convention as Light::directionalTowards):
/// (cos 60 sin 30, sin 60, cos 60 cos 30) = (0.25, 0.8660, 0.4330).
inline glm::vec3 sunTowardsLight() {
  const float az = glm::radians(kSunAzimuthDeg), el = glm::radians(kSunElevationDeg);
  return glm::vec3(std::cos(el) * std::sin(az), std::sin(el), std::cos(el) * std::cos(az));
}

/// Ground-plane offset of the shadow of a point at height `heightM`: -height * L.xz / L.y.
inline glm::vec2 shadowOffsetXZ(float heightM, const glm::vec3& towardsLight) {
  return -heightM * glm::vec2(towardsLight.x, towardsLight.z) / towardsLight.y;
}

/// Corners of the exact shadow outline on the ground as (x, z) points, counter-clockwise in
/// the (x, z) plane (positive cross products); `count` of them (6, or 4 when the light is
/// vertical; 0 when it is at or below the horizon).
inline std::array<glm::vec2, 8> shadowOutlineXZ(const glm::vec3& towardsLight, int& count) {
  count = 0;
  std::array<glm::vec2, 8> hull{};
  if (!(towardsLight.y > 0.0f)) return hull;
  const float a = kOccluderHalfSizeM;
  const float bottom = kOccluderCenterHeightM - 0.5f * kOccluderThicknessM;
  const float top = kOccluderCenterHeightM + 0.5f * kOccluderThicknessM;
  std::array<glm::vec2, 8> pts;
  int n = 0;
  for (float h : {bottom, top})
    for (glm::vec2 c : {glm::vec2(-a, -a), glm::vec2(a, -a), glm::vec2(a, a), glm::vec2(-a, a)})
      pts[std::size_t(n++)] = c + shadowOffsetXZ(h, towardsLight);
  // Andrew's monotone chain.
  std::sort(pts.begin(), pts.end(), [](const glm::vec2& p, const glm::vec2& q) {
    return p.x < q.x || (p.x == q.x && p.y < q.y);
  });
  auto cross = [](const glm::vec2& o, const glm::vec2& p, const glm::vec2& q) {
    return (p.x - o.x) * (q.y - o.y) - (p.y - o.y) * (q.x - o.x);
  };
  std::array<glm::vec2, 16> h{};
  int k = 0;
  for (int i = 0; i < 8; ++i) {
    while (k >= 2 &&
           cross(h[std::size_t(k - 2)], h[std::size_t(k - 1)], pts[std::size_t(i)]) <= 0.0f)
      --k;
    h[std::size_t(k++)] = pts[std::size_t(i)];
  }
  for (int i = 6, lower = k + 1; i >= 0; --i) {
    while (k >= lower &&
           cross(h[std::size_t(k - 2)], h[std::size_t(k - 1)], pts[std::size_t(i)]) <= 0.0f)
      --k;
    h[std::size_t(k++)] = pts[std::size_t(i)];
  }
  count = std::min(k - 1, 8);
  for (int i = 0; i < count; ++i) hull[std::size_t(i)] = h[std::size_t(i)];
  return hull;
}

}  // namespace planebox

/// True when the ground point (pointXZ.x, 0, pointXZ.y) is in the exact shadow of the
/// plane-box occluder under a directional light towards `towardsLight` (any length, y > 0):
/// the ray from the point towards the light hits the occluder box. False when the light is
/// at or below the horizon.
inline bool planeBoxAnalyticShadow(glm::vec2 pointXZ, glm::vec3 towardsLight) {
  using namespace planebox;
  if (!(towardsLight.y > 0.0f)) return false;
  // Slab test of the ray p + s * L against the box; s is the height parameter scaled by L.y.
  float sMin = (kOccluderCenterHeightM - 0.5f * kOccluderThicknessM) / towardsLight.y;
  float sMax = (kOccluderCenterHeightM + 0.5f * kOccluderThicknessM) / towardsLight.y;
  const float origin[2] = {pointXZ.x, pointXZ.y};
  const float dir[2] = {towardsLight.x, towardsLight.z};
  for (int axis = 0; axis < 2; ++axis) {
    if (std::abs(dir[axis]) < 1e-12f) {
      if (std::abs(origin[axis]) > kOccluderHalfSizeM) return false;
      continue;
    }
    float s0 = (-kOccluderHalfSizeM - origin[axis]) / dir[axis];
    float s1 = (kOccluderHalfSizeM - origin[axis]) / dir[axis];
    sMin = std::max(sMin, std::min(s0, s1));
    sMax = std::min(sMax, std::max(s0, s1));
  }
  return sMin <= sMax;
}

/// Signed distance in metres, on the ground, from `pointXZ` to the outline of the exact
/// shadow: negative inside, positive outside (lets a test skip pixels near the edge).
/// +infinity when the light is at or below the horizon.
inline float planeBoxShadowSignedDistanceM(glm::vec2 pointXZ, glm::vec3 towardsLight) {
  int n = 0;
  std::array<glm::vec2, 8> hull = planebox::shadowOutlineXZ(towardsLight, n);
  if (n < 3) return std::numeric_limits<float>::infinity();
  float nearest = std::numeric_limits<float>::infinity();
  bool inside = true;
  for (int i = 0; i < n; ++i) {
    glm::vec2 a = hull[std::size_t(i)], b = hull[std::size_t((i + 1) % n)];
    glm::vec2 ab = b - a, ap = pointXZ - a;
    if (ab.x * ap.y - ab.y * ap.x < 0.0f) inside = false;  // right of a counter-clockwise edge
    float t = std::clamp(glm::dot(ap, ab) / glm::dot(ab, ab), 0.0f, 1.0f);
    nearest = std::min(nearest, glm::length(ap - t * ab));
  }
  return inside ? -nearest : nearest;
}

}  // namespace sl
