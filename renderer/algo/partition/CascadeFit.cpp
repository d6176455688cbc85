// Cascade fitting (CascadeFit.h): split range, slices, one orthographic frustum per slice.
#include "CascadeFit.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <glm/gtc/matrix_transform.hpp>

#include "Stabilize.h"
#include "algo/Focus.h"
#include "algo/warp/PerspectiveWarp.h"

namespace sl::partition {

namespace {

Aabb padded(const Aabb& b) {  // as algo/Focus: flat boxes grown so that clipping stays sane
  Aabb box = b;
  const glm::vec3 pad = glm::max(box.size() * 0.001f, glm::vec3(1e-3f));
  box.min -= pad;
  box.max += pad;
  return box;
}

// 1/8 octave steps: the stabilised split range changes only when it crosses one.
double quantiseDown(double x) {
  return std::exp2(std::floor(8.0 * std::log2(x)) / 8.0);
}
double quantiseUp(double x) {
  return std::exp2(std::ceil(8.0 * std::log2(x)) / 8.0);
}

}  // namespace

glm::dvec2 visibleDepthRange(const Camera& camera, float aspect, const Aabb& box) {
  const std::vector<glm::vec3> pts = intersectFrustumWithBox(
      camera.frustumCorners(aspect, camera.nearM, camera.farM), padded(box));
  if (pts.empty()) return {camera.nearM, camera.farM};
  const glm::dvec3 eye(camera.position), fwd(camera.forward());
  double lo = std::numeric_limits<double>::max(), hi = -lo;
  for (const glm::vec3& p : pts) {
    const double d = glm::dot(glm::dvec3(p) - eye, fwd);
    lo = std::min(lo, d);
    hi = std::max(hi, d);
  }
  return {std::clamp(lo, double(camera.nearM), double(camera.farM)),
          std::clamp(hi, double(camera.nearM), double(camera.farM))};
}

glm::dvec2 holdDepthRange(const std::optional<glm::dvec2>& held, const glm::dvec2& measured,
                          double slack) {
  if (held && held->x <= measured.x && held->y >= measured.y && held->x * slack >= measured.x &&
      held->y <= measured.y * slack)
    return *held;
  const double w = std::sqrt(slack);
  return {measured.x / w, measured.y * w};
}

double histogramQuantileLog2(const std::vector<std::uint32_t>& bins, double q, double log2Min,
                             double log2Max) {
  std::uint64_t total = 0;
  for (std::uint32_t b : bins) total += b;
  if (total == 0 || bins.empty()) return 0.0;
  const double need = std::clamp(q, 0.0, 1.0) * double(total);
  const double width = (log2Max - log2Min) / double(bins.size());
  std::uint64_t sum = 0;
  for (std::size_t i = 0; i < bins.size(); ++i) {
    sum += bins[i];
    if (double(sum) >= need && bins[i] > 0) return std::exp2(log2Min + width * double(i + 1));
  }
  return std::exp2(log2Max);
}

std::vector<float> sliceEdgesInMapUv(const std::array<glm::dvec3, 8>& c,
                                     const glm::mat4& viewProj) {
  const glm::dmat4 m(viewProj);
  std::array<glm::dvec4, 8> clip;
  for (std::size_t i = 0; i < 8; ++i) clip[i] = m * glm::dvec4(c[i], 1.0);
  std::vector<float> out;
  auto edge = [&](std::size_t a, std::size_t b) {
    glm::dvec4 p = clip[a], q = clip[b];
    const double eps = 1e-9 * std::max({std::abs(p.w), std::abs(q.w), 1e-300});
    if (p.w <= eps && q.w <= eps) return;
    if (p.w <= eps) p = p + (q - p) * ((eps - p.w) / (q.w - p.w));
    if (q.w <= eps) q = q + (p - q) * ((eps - q.w) / (p.w - q.w));
    glm::dvec2 u0 = glm::dvec2(p) / p.w * 0.5 + 0.5, u1 = glm::dvec2(q) / q.w * 0.5 + 0.5;
    // Liang-Barsky against [-1, 2]^2: the map and a margin, never kilometres of uv.
    double t0 = 0.0, t1 = 1.0;
    const glm::dvec2 d = u1 - u0;
    for (int axis = 0; axis < 2; ++axis)
      for (double side : {-1.0, 1.0}) {
        const double num = side < 0.0 ? u0[axis] - (-1.0) : 2.0 - u0[axis];
        const double den = side < 0.0 ? -d[axis] : d[axis];
        if (den == 0.0) {
          if (num < 0.0) return;
        } else {
          const double t = num / den;
          if (den < 0.0)
            t0 = std::max(t0, t);
          else
            t1 = std::min(t1, t);
        }
      }
    if (t0 > t1) return;
    const glm::dvec2 a0 = u0 + t0 * d, a1 = u0 + t1 * d;
    out.insert(out.end(), {float(a0.x), float(a0.y), float(a1.x), float(a1.y)});
  };
  for (std::size_t i = 0; i < 4; ++i) {
    edge(i, (i + 1) % 4);          // near ring
    edge(4 + i, 4 + (i + 1) % 4);  // far ring
    edge(i, i + 4);                // sides
  }
  return out;
}

std::optional<std::string> fitCascades(const Camera& camera, float aspect, const Aabb& sceneBounds,
                                       const glm::vec3& towardsLight, const CascadeSettings& s,
                                       CascadeFit& out) {
  if (auto e = camera.validate()) return e;
  if (!(aspect > 0.0f) || !std::isfinite(aspect)) return "camera: aspect ratio must be > 0";
  if (!sceneBounds.valid()) return "scene: empty bounds (no geometry)";
  if (!(glm::length(towardsLight) > 1e-6f)) return "light: direction is zero or not finite";
  if (s.partitions < 1 || s.partitions > 8)
    return "cascades: partitions must be 1..8 (got " + std::to_string(s.partitions) + ")";
  if (s.resolution < 2) return "cascades: resolution must be >= 2";
  if (s.warp && !(s.eta >= -1.0 && s.eta <= 1.0))
    return "cascades: warp.eta must be in [-1, 1] (got " + std::to_string(s.eta) + ")";

  // The range the splits cut: what the camera can see of the scene, then (when measured)
  // what it did see.
  glm::dvec2 range = visibleDepthRange(camera, aspect, sceneBounds);
  if (s.visibleDepthM && s.visibleDepthM->y > s.visibleDepthM->x && s.visibleDepthM->x > 0.0) {
    range.x = std::max(range.x, s.visibleDepthM->x);
    range.y = std::min(range.y, s.visibleDepthM->y);
  }
  if (s.stabilize) range = {quantiseDown(range.x), quantiseUp(range.y)};
  range.x = std::clamp(range.x, double(camera.nearM), double(camera.farM));
  range.y = std::clamp(range.y, double(camera.nearM), double(camera.farM));
  if (!(range.y > range.x * (1.0 + 1e-6))) {  // nothing (or one depth) visible
    range.x = std::max(double(camera.nearM), range.x / 1.0905);
    range.y = std::min(double(camera.farM), std::max(range.y, range.x) * 1.0905);
  }
  CascadeFit fit;
  fit.nearM = range.x;
  fit.farM = range.y;
  try {
    fit.splits = splitDistances(s.split, range.x, range.y, s.partitions, s.lambda);
  } catch (const std::invalid_argument& e) {
    return std::string("cascades: ") + e.what();
  }

  const glm::dvec3 L = glm::normalize(glm::dvec3(towardsLight));
  const Aabb box = padded(sceneBounds);
  double boxTowardsLight = -std::numeric_limits<double>::max();
  for (const glm::vec3& c : box.corners())
    boxTowardsLight = std::max(boxTowardsLight, glm::dot(glm::dvec3(c), L));
  const warp::ViewFrustum frustum = warp::ViewFrustum::fromCamera(camera, aspect);

  for (int i = 0; i < s.partitions; ++i) {
    CascadePart p;
    p.nearM = fit.splits[size_t(i)];
    p.farM = fit.splits[size_t(i) + 1];
    if (s.warp) {
      // LiSPSM (eq. 11 with eta) around slice ∩ scene, as `lispsm` fits the whole frustum:
      // the slice's depth range clipped to the body, casters toward the light depth-only.
      Camera slice = camera;
      slice.nearM = float(p.nearM);
      slice.farM = float(p.farM);
      const std::vector<glm::vec3> pts =
          intersectFrustumWithBox(slice.frustumCorners(aspect, slice.nearM, slice.farM), box);
      std::vector<glm::dvec3> body(pts.begin(), pts.end());
      if (body.empty()) {  // the slice sees none of the scene: cover the slice itself
        const auto c = frustum.corners(p.nearM, p.farM);
        body.assign(c.begin(), c.end());
      }
      const warp::ViewFrustum view = frustum.clippedToBody(body);
      warp::WarpSettings ws;
      ws.kind = warp::WarpKind::Eta;
      ws.eta = s.eta;
      const auto bc = box.corners();
      ws.depthOnly.assign(bc.begin(), bc.end());
      warp::WarpFit wf;
      if (auto e = warp::fitWarp(view, body, L, ws, wf)) return "cascades: " + *e;
      p.warpFit = std::move(wf);
    }
    if (p.warped()) {
      const warp::WarpFit& w = *p.warpFit;
      p.view = w.lightView;
      p.proj = w.lightProj;
      // The body's light-space width and depth; texels vary with w: the coarsest, at the
      // slice's far face (w = n' + L), is texelM.
      p.extentM = glm::dvec2(w.hi.x - w.lo.x, w.depthM);
      p.depthRangeM = w.hi.y - w.lo.y;
      const DepthMapFrame f = w.mapFrame();
      const double wFar = w.nPrime + w.depthM;
      p.texelM =
          std::max(double(f.extentM.x) * wFar, double(f.extentM.y) * wFar * wFar) / s.resolution;
    } else if (s.stabilize) {
      // Extent quantum: 1/8 of the power of two below the sphere's diameter.
      const double T =
          frustum.tanHalfX() * frustum.tanHalfX() + frustum.tanHalfY() * frustum.tanHalfY();
      const double diameter = 2.0 * p.farM * std::sqrt(1.0 + T);  // an upper bound
      const double quantum = std::exp2(std::floor(std::log2(diameter)) - 3.0);
      StableOrtho o;
      if (auto e = stabilizeCascade(frustum, p.nearM, p.farM, L, s.resolution, quantum, 0.0, o))
        return e;
      if (s.clampToScene) {
        // The whole scene's square in the same camera-free light basis: when the slice's
        // sphere is wider, cover the scene instead. It does not depend on the camera, so
        // it is as stable as the sphere (and finer: a small scene in a deep slice).
        glm::dvec2 lo(std::numeric_limits<double>::max()), hi(-lo);
        for (const glm::vec3& c : box.corners()) {
          const glm::dvec2 q(glm::dot(glm::dvec3(c), o.right), glm::dot(glm::dvec3(c), o.up));
          lo = glm::min(lo, q);
          hi = glm::max(hi, q);
        }
        const double side = std::max(hi.x - lo.x, hi.y - lo.y);
        if (side < o.extentM) {
          const glm::dvec2 centre = 0.5 * (lo + hi);
          o.extentM = side;
          o.texelM = side / s.resolution;
          o.minXY = centre - 0.5 * side;
          o.maxXY = centre + 0.5 * side;
          p.sceneClamped = true;
        }
      }
      // Casters anywhere in the scene between the light and the slice.
      o.zMax = std::max(o.zMax, boxTowardsLight + 1e-3 * (o.zMax - o.zMin));
      o.proj = glm::mat4(glm::ortho(o.minXY.x, o.maxXY.x, o.minXY.y, o.maxXY.y, -o.zMax, -o.zMin));
      p.view = o.view;
      p.proj = o.proj;
      p.extentM = glm::dvec2(o.extentM);
      p.depthRangeM = o.zMax - o.zMin;
    } else {
      Camera slice = camera;
      slice.nearM = float(p.nearM);
      slice.farM = float(p.farM);
      LightFit lf;
      if (auto e =
              fitDirectionalLight(slice, aspect, sceneBounds, towardsLight, FocusSettings{}, lf))
        return e;
      p.view = lf.view;
      p.proj = lf.proj;
      p.extentM = glm::dvec2(lf.extentM);
      p.depthRangeM = lf.depthRangeM;
    }
    p.viewProj = p.proj * p.view;
    if (!p.warped()) p.texelM = std::max(p.extentM.x, p.extentM.y) / s.resolution;
    p.sliceUv = sliceEdgesInMapUv(frustum.corners(p.nearM, p.farM), p.viewProj);
    fit.parts.push_back(p);
  }
  out = std::move(fit);
  return std::nullopt;
}

}  // namespace sl::partition
