// One perspective warp along light-space z (Lloyd et al., EGSR 2006, §4: Fig. 3, eqs. 5-6
// and 11), fitted around a convex body the way LiSPSM does (Wimmer et al. 2004).
#include "PerspectiveWarp.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "algo/Focus.h"

namespace sl::warp {

namespace {

bool finite(const glm::dvec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

/// A unit vector perpendicular to `y` (for a light space when no axis is usable).
glm::dvec3 anyPerpendicular(const glm::dvec3& y) {
  const glm::dvec3 a = std::abs(y.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 0, 1);
  return glm::normalize(a - glm::dot(a, y) * y);
}

}  // namespace

double ViewFrustum::tanHalfY() const {
  return std::tan(0.5 * fovYRad);
}

std::array<glm::dvec3, 8> ViewFrustum::corners(double n, double f) const {
  const glm::dvec3 r = right();
  const double tx = tanHalfX(), ty = tanHalfY();
  std::array<glm::dvec3, 8> c;
  const double sx[4] = {-1, 1, 1, -1}, sy[4] = {-1, -1, 1, 1};
  for (int i = 0; i < 4; ++i) {
    c[i] = eye + n * (forward + sx[i] * tx * r + sy[i] * ty * up);
    c[4 + i] = eye + f * (forward + sx[i] * tx * r + sy[i] * ty * up);
  }
  return c;
}

std::optional<std::string> ViewFrustum::validate() const {
  if (!finite(eye) || !finite(forward) || !finite(up)) return "view: eye or axes not finite";
  if (std::abs(glm::length(forward) - 1.0) > 1e-6 || std::abs(glm::length(up) - 1.0) > 1e-6 ||
      std::abs(glm::dot(forward, up)) > 1e-6)
    return "view: forward and up must be orthonormal";
  if (!(nearM > 0.0) || !(farM > nearM) || !std::isfinite(farM))
    return "view: need 0 < near < far (finite)";
  if (!(fovYRad > 0.0) || !(fovYRad < M_PI))
    return "view: field of view must be in (0, 180) degrees";
  if (!(aspect > 0.0) || !std::isfinite(aspect)) return "view: aspect must be positive";
  return std::nullopt;
}

ViewFrustum ViewFrustum::fromCamera(const Camera& camera, double aspect) {
  ViewFrustum v;
  v.eye = glm::dvec3(camera.position);
  v.forward = glm::normalize(glm::dvec3(camera.target) - glm::dvec3(camera.position));
  const glm::dvec3 r = glm::normalize(glm::cross(v.forward, glm::dvec3(camera.up)));
  v.up = glm::cross(r, v.forward);
  v.nearM = camera.nearM;
  v.farM = camera.farM;
  v.fovYRad = glm::radians(double(camera.fovYDeg));
  v.aspect = aspect;
  return v;
}

ViewFrustum ViewFrustum::clippedToBody(std::span<const glm::dvec3> body) const {
  ViewFrustum v = *this;
  double nearBody = farM, farBody = nearM;
  for (const glm::dvec3& p : body) {
    const double d = glm::dot(p - eye, forward);
    nearBody = std::min(nearBody, d);
    farBody = std::max(farBody, d);
  }
  v.nearM = std::max(nearM, nearBody);
  v.farM = std::max(std::min(farM, farBody), v.nearM * (1.0 + 1e-6));
  return v;
}

std::optional<LightSpace> makeLightSpace(const glm::dvec3& towardsLight, const glm::dvec3& axis) {
  const glm::dvec3 y = glm::normalize(towardsLight);
  const glm::dvec3 a = axis - glm::dot(axis, y) * y;
  if (glm::length(a) < 1e-9 * glm::length(axis) || !(glm::length(axis) > 0.0)) return std::nullopt;
  LightSpace s;
  s.y = y;
  s.z = glm::normalize(a);
  s.x = glm::cross(s.z, s.y);
  return s;
}

double nPrimeFromEta(double eta, double nearM, double farM) {
  const double a = farM / nearM, ra = std::sqrt(a);
  if (eta <= -1.0) return std::numeric_limits<double>::infinity();
  if (eta <= 0.0) return nearM * (ra + 1.0 - eta * (a - 1.0)) / (eta + 1.0);
  return nearM * (ra + 1.0) / (eta * ra + 1.0);
}

double etaFromNPrime(double nPrime, double nearM, double farM) {
  if (!std::isfinite(nPrime)) return -1.0;
  const double a = farM / nearM, ra = std::sqrt(a), q = nPrime / nearM;
  if (q >= ra + 1.0) return (ra + 1.0 - q) / (q + a - 1.0);  // eq. 11, first branch solved
  return std::clamp((ra + 1.0 - q) / (q * ra), 0.0, 1.0);    // second branch solved
}

const char* fallbackCauseText(FallbackCause cause) {
  switch (cause) {
    case FallbackCause::None:
      return "warped";
    case FallbackCause::SquareLightBehind:
      return "light behind the viewer, inside the view cone: the frustum looks square from "
             "the light, nothing to warp (uniform)";
    case FallbackCause::SquareLightInFront:
      return "light in front of the viewer, inside the view cone: the frustum looks square "
             "from the light, nothing to warp (uniform)";
    case FallbackCause::TsmFocusBeyondLine:
      return "TSM's focus point lies beyond its line along the light-space depth (uniform)";
    case FallbackCause::Degenerate:
      return "no usable warp: light parallel to the axis, no depth, or the body at the eye "
             "(uniform)";
  }
  return "?";
}

bool frustumLooksSquare(const ViewFrustum& view, const glm::dvec3& towardsLight) {
  const glm::dvec3 y = glm::normalize(towardsLight), r = view.right();
  for (double sign : {1.0, -1.0}) {
    const glm::dvec3 u = sign * y;
    const double dz = glm::dot(u, view.forward);
    if (dz <= 0.0) continue;
    if (std::abs(glm::dot(u, r) / dz) < view.tanHalfX() &&
        std::abs(glm::dot(u, view.up) / dz) < view.tanHalfY())
      return true;
  }
  return false;
}

glm::dvec2 WarpFit::mapUv(const glm::dvec3& world) const {
  const glm::dvec3 p = space.toLight(world);
  if (uniform)
    return {(p.x - lo.x) / std::max(hi.x - lo.x, 1e-300), (p.z - lo.z) / std::max(depthM, 1e-300)};
  const double zp = p.z - lo.z + nPrime, fp = nPrime + depthM;
  const double s = 0.5 * ((p.x - cx) / (zp * tanHalfX) + 1.0);
  const double t = fp * (zp - nPrime) / (depthM * zp);  // eq. 6 in [0, 1]
  return {s, t};
}

glm::dvec2 WarpFit::beamWidths(const glm::dvec3& world) const {
  if (uniform) return {hi.x - lo.x, depthM};  // dx/ds and dz/dt of the orthographic map
  const double zp = space.toLight(world).z - lo.z + nPrime, fp = nPrime + depthM;
  // eq. 3 with ds/dx = 1 / (2 z' tan theta'), eq. 4 with dt/dz' = f' n' / ((f' - n') z'^2)
  return {2.0 * zp * tanHalfX, depthM * zp * zp / (fp * nPrime)};
}

DepthMapFrame WarpFit::mapFrame() const {
  const double np = nPrime, fp = np + depthM;
  DepthMapFrame f;
  f.viewProj = lightProj * lightView;
  f.extentM = glm::vec2(float(2.0 * tanHalfX), float((fp - np) / (fp * np)));
  f.extentWPower = glm::vec2(1.0f, 2.0f);
  f.depthPerM = 0.5f * std::abs(lightProj[2][2]);  // |d depth_ndc / d y| = n' / (yHalf w)
  f.depthWPower = 1.0f;
  return f;
}

std::optional<std::string> fitWarp(const ViewFrustum& view, std::span<const glm::dvec3> body,
                                   const glm::dvec3& towardsLight, const WarpSettings& settings,
                                   WarpFit& out) {
  if (auto e = view.validate()) return e;
  if (body.empty()) return "warp: the body to cover is empty";
  for (const glm::dvec3& p : body)
    if (!finite(p)) return "warp: a body point is not finite";
  if (!finite(towardsLight) || glm::length(towardsLight) < 1e-12)
    return "warp: the light direction is zero or not finite";
  if (settings.kind == WarpKind::Eta && !(settings.eta >= -1.0 && settings.eta <= 1.0))
    return "warp: eta must be in [-1, 1]";
  if (settings.kind == WarpKind::Tsm &&
      !(settings.tsmFocusFraction >= 0.0 && settings.tsmFocusFraction <= 1.0 &&
        settings.tsmFocusLine > 0.0 && settings.tsmFocusLine < 1.0))
    return "warp: TSM focus fraction must be in [0, 1] and its line in (0, 1)";

  WarpFit fit;
  const glm::dvec3 y = glm::normalize(towardsLight);
  const glm::dvec3 axis3 = glm::normalize(settings.axis.value_or(view.forward));
  const glm::dvec3 projected = settings.projectedAxis.value_or(axis3);
  std::optional<LightSpace> space = makeLightSpace(y, projected);
  fit.lightBehindViewer = glm::dot(view.forward, y) < -1e-9;
  auto fallBack = [&](const std::string& why, FallbackCause cause = FallbackCause::Degenerate) {
    fit.uniform = true;
    fit.fallback = settings.kind != WarpKind::Uniform &&
                   !(settings.kind == WarpKind::Eta && settings.eta <= -1.0);
    if (fit.fallback) {
      fit.fallbackReason = why;
      fit.fallbackCause = cause;
    }
  };
  if (space) {
    fit.space = *space;
  } else {
    fit.space = *makeLightSpace(y, anyPerpendicular(y));
    fallBack("the light is parallel to the warp axis: no direction to warp along (uniform)");
  }
  fit.lo = glm::dvec3(std::numeric_limits<double>::max());
  fit.hi = -fit.lo;
  double nearAxis = std::numeric_limits<double>::max();
  for (const glm::dvec3& p : body) {
    const glm::dvec3 q = fit.space.toLight(p);
    fit.lo = glm::min(fit.lo, q);
    fit.hi = glm::max(fit.hi, q);
    nearAxis = std::min(nearAxis, glm::dot(p - view.eye, axis3));
  }
  for (const glm::dvec3& p : settings.depthOnly) {
    if (!finite(p)) return "warp: a depth-only point is not finite";
    const double ly = glm::dot(p, fit.space.y);
    fit.lo.y = std::min(fit.lo.y, ly);
    fit.hi.y = std::max(fit.hi.y, ly);
  }
  fit.depthM = fit.hi.z - fit.lo.z;
  fit.nearAxisM = nearAxis;
  fit.sinGamma = glm::length(glm::cross(axis3, y));

  if (settings.kind == WarpKind::Uniform ||
      (settings.kind == WarpKind::Eta && settings.eta <= -1.0))
    fit.uniform = true;
  if (!fit.uniform && settings.squareFallback && !settings.axis && !settings.projectedAxis &&
      frustumLooksSquare(view, y))
    fallBack(std::string("the light is ") + (fit.lightBehindViewer ? "behind" : "in front of") +
                 " the viewer, inside the view frustum's cone: the frustum looks square from the "
                 "light, no trapezoid to warp (uniform, as the paper's PSM, LiSPSM and TSM do)",
             fit.lightBehindViewer ? FallbackCause::SquareLightBehind
                                   : FallbackCause::SquareLightInFront);
  if (!fit.uniform && !(fit.depthM > 1e-12 * std::max(1.0, glm::length(fit.hi - fit.lo))))
    fallBack("the body has no depth along the warp axis (uniform)");
  if (!fit.uniform && !(nearAxis > 0.0))
    fallBack("the body reaches the eye along the warp axis (uniform)");

  if (!fit.uniform) {
    // Wimmer's general LiSPSM: z0 = n / sin(gamma), z1 = z0 + L sin(gamma); eq. 11 then
    // runs with the effective near distance z0 / sin(gamma) and alpha = z1 / z0 (for an
    // overhead light: sin(gamma) = 1, n and alpha = f / n).
    const double z0 = nearAxis / fit.sinGamma, z1 = z0 + fit.depthM * fit.sinGamma;
    fit.alpha = z1 / z0;
    const double nEff = z0 / fit.sinGamma, fEff = nEff * fit.alpha;
    fit.nPrimeLispsm = nPrimeFromEta(0.0, nEff, fEff);
    double eta = 0.0;
    switch (settings.kind) {
      case WarpKind::Eta:
        eta = settings.eta;
        break;
      case WarpKind::Lispsm:
        eta = 0.0;
        break;
      case WarpKind::Psm:
        eta = 1.0;
        break;
      default:
        break;
    }
    if (settings.kind == WarpKind::Tsm) {
      // The focus point on the view axis, its light-space distance delta from the near
      // face; t(delta) = line gives n' = (1 - line) L delta / (line L - delta).
      const double focusDepth = view.nearM + settings.tsmFocusFraction * (view.farM - view.nearM);
      const double delta = fit.space.toLight(view.eye + focusDepth * view.forward).z - fit.lo.z;
      const double line = settings.tsmFocusLine, L = fit.depthM;
      if (delta >= line * L)
        fallBack("TSM: the focus point lies beyond the " + std::to_string(int(line * 100)) +
                     " % line along the light-space depth (uniform)",
                 FallbackCause::TsmFocusBeyondLine);
      else
        fit.nPrime = (1.0 - line) * L * std::max(delta, 0.0) / (line * L - delta);
      if (!fit.uniform) fit.eta = etaFromNPrime(fit.nPrime, nEff, fEff);
    } else {
      fit.nPrime = nPrimeFromEta(eta, nEff, fEff);
      fit.eta = eta;
    }
    if (!fit.uniform && fit.nPrime < settings.minNearShare * fit.depthM) {
      fit.nPrime = settings.minNearShare * fit.depthM;
      fit.nearClamped = true;
      fit.note = "n' raised to " + std::to_string(settings.minNearShare) +
                 " of the light-space depth: the projection centre would touch the body "
                 "(PSM's singularity; a virtual shift back, after Kozlov)";
    }
    if (!fit.uniform && !(fit.nPrime < 1e9 * fit.depthM))
      fallBack("n' is effectively infinite: no warp left (uniform)");
  }
  if (fit.uniform) {
    fit.eta = -1.0;
    fit.nPrime = std::numeric_limits<double>::infinity();
  }
  if (fit.lightBehindViewer && !fit.uniform)
    fit.note += std::string(fit.note.empty() ? "" : "; ") +
                "light behind the viewer: the light-space warp keeps its centre on the "
                "viewer's side, no inverted projection needed";

  // The warping frustum's x opening and the matrices.
  fit.cx = 0.5 * (fit.lo.x + fit.hi.x);
  const double yMid = 0.5 * (fit.lo.y + fit.hi.y),
               yHalf = std::max(0.5 * (fit.hi.y - fit.lo.y), 1e-9);
  glm::dmat4 view4(1.0);  // world -> (x, z, y): right-handed, looks along -y (the light's way)
  for (int c = 0; c < 3; ++c) {
    view4[c][0] = fit.space.x[c];
    view4[c][1] = fit.space.z[c];
    view4[c][2] = fit.space.y[c];
  }
  glm::dmat4 proj(0.0);  // columns: X = light x, Y = light z, Z = light y, W
  if (fit.uniform) {
    const double xHalf = std::max(0.5 * (fit.hi.x - fit.lo.x), 1e-9);
    const double zHalf = std::max(0.5 * fit.depthM, 1e-9);
    proj[0][0] = 1.0 / xHalf;
    proj[3][0] = -fit.cx / xHalf;
    proj[1][1] = 1.0 / zHalf;
    proj[3][1] = -(fit.lo.z + zHalf) / zHalf;
    proj[2][2] = -1.0 / yHalf;
    proj[3][2] = yMid / yHalf;
    proj[3][3] = 1.0;
  } else {
    fit.tanHalfX = 0.0;
    for (const glm::dvec3& p : body) {
      const glm::dvec3 q = fit.space.toLight(p);
      fit.tanHalfX = std::max(fit.tanHalfX, std::abs(q.x - fit.cx) / (q.z - fit.lo.z + fit.nPrime));
    }
    fit.tanHalfX = std::max(fit.tanHalfX, 1e-12);
    const double np = fit.nPrime, fp = np + fit.depthM, zc = fit.lo.z - np;
    // w = z' = Y - zc; x_ndc = (X - cx) / (z' tan); t_ndc = A + B / z' (eq. 6 in [-1, 1]);
    // depth_ndc = -n' (Z - yMid) / (yHalf z'): linear along each light ray, within [-1, 1].
    const double A = (fp + np) / (fp - np), B = -2.0 * fp * np / (fp - np);
    proj[0][0] = 1.0 / fit.tanHalfX;
    proj[3][0] = -fit.cx / fit.tanHalfX;
    proj[1][1] = A;
    proj[3][1] = -A * zc + B;
    proj[2][2] = -np / yHalf;
    proj[3][2] = np * yMid / yHalf;
    proj[1][3] = 1.0;
    proj[3][3] = -zc;
  }
  fit.lightView = glm::mat4(view4);
  fit.lightProj = glm::mat4(proj);
  out = std::move(fit);
  return std::nullopt;
}

FocusedBody focusedBody(const Camera& camera, double aspect, const Aabb& sceneBounds) {
  FocusedBody f;
  const std::vector<glm::vec3> inside = intersectFrustumWithBox(
      camera.frustumCorners(float(aspect), camera.nearM, camera.farM), sceneBounds);
  const auto box = sceneBounds.corners();
  if (inside.empty())
    f.body.assign(box.begin(), box.end());
  else
    f.body.assign(inside.begin(), inside.end());
  f.depthOnly.assign(box.begin(), box.end());
  f.view = ViewFrustum::fromCamera(camera, aspect).clippedToBody(f.body);
  return f;
}

std::optional<std::string> fitFocusedWarp(const Camera& camera, double aspect,
                                          const Aabb& sceneBounds, const glm::dvec3& towardsLight,
                                          WarpSettings settings, WarpFit& out) {
  FocusedBody f = focusedBody(camera, aspect, sceneBounds);
  settings.depthOnly = std::move(f.depthOnly);
  return fitWarp(f.view, f.body, towardsLight, settings, out);
}

glm::dmat4 uvRectCrop(const glm::dvec2& uvMin, const glm::dvec2& uvMax) {
  // uv' = (uv − uvMin) / size with uv = (clip / w + 1) / 2: clip' = clip / size +
  // w ((1 − 2 uvMin) / size − 1).
  const glm::dvec2 size = uvMax - uvMin;
  glm::dmat4 s(1.0);
  s[0][0] = 1.0 / size.x;
  s[1][1] = 1.0 / size.y;
  s[3][0] = (1.0 - 2.0 * uvMin.x) / size.x - 1.0;
  s[3][1] = (1.0 - 2.0 * uvMin.y) / size.y - 1.0;
  return s;
}

}  // namespace sl::warp
