// Stamminger and Drettakis' post-perspective shadow map (PostPerspective.h).
#include "PostPerspective.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "algo/Focus.h"

namespace sl::warp {

namespace {

bool finite(const glm::dvec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

/// A unit vector perpendicular to unit `a`, as close to `hint` as possible.
glm::dvec3 perpendicular(const glm::dvec3& a, const glm::dvec3& hint) {
  glm::dvec3 p = hint - glm::dot(hint, a) * a;
  if (glm::length(p) < 1e-6) {
    const glm::dvec3 h2 = std::abs(a.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 0, 1);
    p = h2 - glm::dot(h2, a) * a;
  }
  return glm::normalize(p);
}

/// A row acting on post-perspective homogeneous (X, Y, Z, W): v . (X, Y, Z) + c W.
glm::dvec4 row(const glm::dvec3& v, double c) {
  return {v, c};
}

glm::dmat4 fromRows(const glm::dvec4& r0, const glm::dvec4& r1, const glm::dvec4& r2,
                    const glm::dvec4& r3) {
  return glm::transpose(glm::dmat4(r0, r1, r2, r3));
}

}  // namespace

std::optional<double> nearestDepthInView(const ViewFrustum& view, std::span<const Aabb> boxes) {
  std::array<glm::vec3, 8> corners;
  const auto c = view.corners();
  for (size_t i = 0; i < 8; ++i) corners[i] = glm::vec3(c[i]);
  std::optional<double> nearest;
  for (const Aabb& box : boxes) {
    if (!box.valid()) continue;
    for (const glm::vec3& p : intersectFrustumWithBox(corners, box)) {
      const double d = glm::dot(glm::dvec3(p) - view.eye, view.forward);
      if (!nearest || d < *nearest) nearest = d;
    }
  }
  return nearest;
}

const char* psmLightCaseText(PsmLightCase c) {
  switch (c) {
    case PsmLightCase::Point:
      return "light in front of the viewer: a point light in post-perspective space";
    case PsmLightCase::Inverted:
      return "light behind the viewer: a point beyond infinity in post-perspective space "
             "(inverted projection, depth order reversed)";
    case PsmLightCase::Directional:
      return "light parallel to the image plane: directional in post-perspective space";
    case PsmLightCase::Uniform:
      return "no post-perspective map (uniform)";
  }
  return "?";
}

glm::dvec3 PsmFit::mapUvz(const glm::dvec3& world) const {
  const glm::dvec4 h = viewProj * glm::dvec4(world, 1.0);
  return 0.5 * glm::dvec3(h) / h.w + 0.5;
}

DepthMapFrame PsmFit::mapFrame() const {
  DepthMapFrame f;
  f.viewProj = glm::mat4(viewProj);
  f.projective = true;
  return f;
}

std::vector<glm::dvec3> castersTowardsLight(std::span<const glm::dvec3> body,
                                            const glm::dvec3& towardsLight, const glm::dvec3& lo,
                                            const glm::dvec3& hi) {
  std::vector<glm::dvec3> out(body.begin(), body.end());
  const glm::dvec3 l = glm::normalize(towardsLight);
  for (const glm::dvec3& p : body) {
    double tExit = std::numeric_limits<double>::infinity();
    for (int a = 0; a < 3; ++a) {
      if (l[a] > 1e-12) tExit = std::min(tExit, (hi[a] - p[a]) / l[a]);
      if (l[a] < -1e-12) tExit = std::min(tExit, (lo[a] - p[a]) / l[a]);
    }
    if (std::isfinite(tExit) && tExit > 0.0) out.push_back(p + tExit * l);
  }
  return out;
}

std::optional<std::string> fitPostPerspective(const ViewFrustum& view,
                                              std::span<const glm::dvec3> body,
                                              std::span<const glm::dvec3> casters,
                                              const glm::dvec3& towardsLight,
                                              const PsmSettings& settings, PsmFit& out) {
  if (auto e = view.validate()) return e;
  if (body.empty()) return "psm: the body to cover is empty";
  for (const glm::dvec3& p : body)
    if (!finite(p)) return "psm: a body point is not finite";
  for (const glm::dvec3& p : casters)
    if (!finite(p)) return "psm: a caster point is not finite";
  if (!finite(towardsLight) || glm::length(towardsLight) < 1e-12)
    return "psm: the light direction is zero or not finite";
  if (!(settings.extraSlideM >= 0.0)) return "psm: the extra slide-back must be >= 0 metres";

  PsmFit fit;
  const glm::dvec3 L = glm::normalize(towardsLight);
  const glm::dvec3 fwd = view.forward, up = view.up, right = view.right();

  // The virtual camera: slid back until every caster is at least the camera's near plane in
  // front of it (Stamminger and Drettakis' slide-back; Kozlov's virtual camera shift); its
  // near plane at the body's nearest point, its far plane at the farthest of all.
  auto depthOf = [&](const glm::dvec3& p) { return glm::dot(p - view.eye, fwd); };
  double bodyMin = std::numeric_limits<double>::max(), allMin = bodyMin, allMax = -bodyMin;
  for (const glm::dvec3& p : body) {
    bodyMin = std::min(bodyMin, depthOf(p));
    allMax = std::max(allMax, depthOf(p));
  }
  allMin = bodyMin;
  for (const glm::dvec3& p : casters) {
    allMin = std::min(allMin, depthOf(p));
    allMax = std::max(allMax, depthOf(p));
  }
  fit.slideBackM = std::max(0.0, view.nearM - allMin) + settings.extraSlideM;
  fit.nearM = std::max(bodyMin, view.nearM) + fit.slideBackM;
  fit.farM = std::max(allMax + fit.slideBackM, fit.nearM * (1.0 + 1e-6));
  fit.virtualEye = view.eye - fit.slideBackM * fwd;
  {
    glm::dmat4 v(1.0);  // world -> eye: rows right, up, -forward
    for (int c = 0; c < 3; ++c) {
      v[c][0] = right[c];
      v[c][1] = up[c];
      v[c][2] = -fwd[c];
    }
    v[3] = glm::dvec4(-glm::dot(right, fit.virtualEye), -glm::dot(up, fit.virtualEye),
                      glm::dot(fwd, fit.virtualEye), 1.0);
    const double n = fit.nearM, f = fit.farM;
    glm::dmat4 p(0.0);
    p[0][0] = 1.0 / view.tanHalfX();
    p[1][1] = 1.0 / view.tanHalfY();
    p[2][2] = -(f + n) / (f - n);
    p[3][2] = -2.0 * f * n / (f - n);
    p[2][3] = -1.0;
    fit.camera = p * v;
  }
  fit.lightPP = fit.camera * glm::dvec4(L, 0.0);

  // The receivers and casters in post-perspective space (all have clip w >= near > 0).
  auto toPP = [&](const glm::dvec3& p) {
    const glm::dvec4 h = fit.camera * glm::dvec4(p, 1.0);
    return glm::dvec3(h) / h.w;
  };
  std::vector<glm::dvec3> bodyPP, allPP;
  for (const glm::dvec3& p : body) bodyPP.push_back(toPP(p));
  allPP = bodyPP;
  for (const glm::dvec3& p : casters) allPP.push_back(toPP(p));
  glm::dvec3 lo(std::numeric_limits<double>::max()), hi = -lo;
  for (const glm::dvec3& q : bodyPP) {
    lo = glm::min(lo, q);
    hi = glm::max(hi, q);
  }
  const glm::dvec3 centre = 0.5 * (lo + hi);
  const double radius = std::max(0.5 * glm::length(hi - lo), 1e-12);

  auto fallBack = [&](const std::string& why) {
    fit.lightCase = PsmLightCase::Uniform;
    fit.reason = why;
    out = std::move(fit);
    return std::nullopt;
  };

  if (glm::length(glm::cross(L, fwd)) < 1e-5)  // float lights and cameras: within 2 arc s
    return fallBack(
        "psm: the light is exactly along the view axis: its post-perspective map would be the "
        "orthographic map along that axis (no warp), so the uniform map is used");
  const glm::dvec3 l3(fit.lightPP);
  const double lw = fit.lightPP.w;
  glm::dvec4 rx, ry, rz, rw;
  if (glm::length(l3 - lw * centre) > settings.directionalRatio * radius * std::abs(lw)) {
    // Directional in post-perspective space: towards the light is +l3 (the rays P' + s l3 / w).
    if (!(glm::length(l3) > 0.0))
      return fallBack("psm: the light has no post-perspective direction");
    fit.lightCase = PsmLightCase::Directional;
    const glm::dvec3 u = glm::normalize(l3);
    const glm::dvec3 a1 = perpendicular(u, glm::dvec3(1, 0, 0)), a2 = glm::cross(u, a1);
    glm::dvec2 x(std::numeric_limits<double>::max(), -std::numeric_limits<double>::max());
    glm::dvec2 y = x, z = x;
    for (const glm::dvec3& q : bodyPP) {
      x = {std::min(x[0], glm::dot(a1, q)), std::max(x[1], glm::dot(a1, q))};
      y = {std::min(y[0], glm::dot(a2, q)), std::max(y[1], glm::dot(a2, q))};
    }
    for (const glm::dvec3& q : allPP)
      z = {std::min(z[0], -glm::dot(u, q)), std::max(z[1], -glm::dot(u, q))};
    const double sx = 2.0 / std::max(x[1] - x[0], 1e-12), sy = 2.0 / std::max(y[1] - y[0], 1e-12);
    const double pad = 1e-4 * std::max(z[1] - z[0], 1e-12);
    const double sz = 2.0 / (z[1] - z[0] + 2.0 * pad);
    rx = row(sx * a1, -sx * 0.5 * (x[0] + x[1]));
    ry = row(sy * a2, -sy * 0.5 * (y[0] + y[1]));
    rz = row(-sz * u, -sz * 0.5 * (z[0] + z[1]));
    rw = row(glm::dvec3(0.0), 1.0);
  } else {
    // A point light at L' = l3 / w (behind the viewer: w < 0, the point beyond infinity). Its
    // frustum looks from L' at the body; the rays towards the real light run towards L' (in
    // front) or away from it (inverted: there the nearest to the light is the farthest from
    // L', so the depth row is negated).
    fit.lightCase = lw > 0.0 ? PsmLightCase::Point : PsmLightCase::Inverted;
    const glm::dvec3 Lp = l3 / lw;
    if (!(glm::length(centre - Lp) > 1e-12))
      return fallBack("psm: the post-perspective light lies inside the body (uniform)");
    const glm::dvec3 axis = glm::normalize(centre - Lp);
    const glm::dvec3 a1 = perpendicular(axis, glm::dvec3(1, 0, 0)), a2 = glm::cross(axis, a1);
    glm::dvec2 x(std::numeric_limits<double>::max(), -std::numeric_limits<double>::max());
    glm::dvec2 y = x, d = x;
    for (const glm::dvec3& q : allPP) {
      const double dist = glm::dot(axis, q - Lp);
      if (!(dist > 1e-9 * radius))
        return fallBack(
            "psm: the light is (nearly) along the view axis: its post-perspective frustum "
            "would open 180 degrees or more, where the map is the orthographic one (uniform)");
      d = {std::min(d[0], dist), std::max(d[1], dist)};
    }
    for (const glm::dvec3& q : bodyPP) {
      const double dist = glm::dot(axis, q - Lp);
      const double tx = glm::dot(a1, q - Lp) / dist, ty = glm::dot(a2, q - Lp) / dist;
      x = {std::min(x[0], tx), std::max(x[1], tx)};
      y = {std::min(y[0], ty), std::max(y[1], ty)};
    }
    fit.tanHalf = std::max({std::abs(x[0]), std::abs(x[1]), std::abs(y[0]), std::abs(y[1])});
    if (!(fit.tanHalf <= settings.maxTanHalf))
      return fallBack(
          "psm: the light is (nearly) along the view axis: its post-perspective frustum would "
          "open " +
          std::to_string(int(std::lround(2.0 * std::atan(fit.tanHalf) * 180.0 / M_PI))) +
          " degrees, where the map is the orthographic one (uniform)");
    const double dn = d[0] * (1.0 - 1e-4), df = d[1] * (1.0 + 1e-4);
    const double sx = 2.0 / std::max(x[1] - x[0], 1e-12), sy = 2.0 / std::max(y[1] - y[0], 1e-12);
    const double cx = 0.5 * (x[0] + x[1]), cy = 0.5 * (y[0] + y[1]);
    // dist_h = axis . (Q - L' W) = dist W; x_ndc = sx (a1 . (q - L') / dist - cx).
    rw = row(axis, -glm::dot(axis, Lp));
    rx = sx * (row(a1, -glm::dot(a1, Lp)) - cx * rw);
    ry = sy * (row(a2, -glm::dot(a2, Lp)) - cy * rw);
    // z_ndc = A + B / dist: -1 at the nearest to L', +1 at the farthest; inverted: negated.
    const double A = (df + dn) / (df - dn), B = -2.0 * df * dn / (df - dn);
    rz = A * rw + B * glm::dvec4(0, 0, 0, 1);
    if (fit.lightCase == PsmLightCase::Inverted) rz = -rz;
  }
  fit.light = fromRows(rx, ry, rz, rw);
  fit.viewProj = fit.light * fit.camera;
  // Scale the homogeneous matrix to unit size (the same map; float-friendly for the GPU).
  double big = 0.0;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) big = std::max(big, std::abs(fit.viewProj[c][r]));
  if (!(big > 0.0) || !std::isfinite(big)) return fallBack("psm: degenerate matrix (uniform)");
  fit.viewProj /= big;
  out = std::move(fit);
  return std::nullopt;
}

}  // namespace sl::warp
