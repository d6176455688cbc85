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
    if (s.stabilize) {
      // Extent quantum: 1/8 of the power of two below the sphere's diameter.
      const double T =
          frustum.tanHalfX() * frustum.tanHalfX() + frustum.tanHalfY() * frustum.tanHalfY();
      const double diameter = 2.0 * p.farM * std::sqrt(1.0 + T);  // an upper bound
      const double quantum = std::exp2(std::floor(std::log2(diameter)) - 3.0);
      StableOrtho o;
      if (auto e = stabilizeCascade(frustum, p.nearM, p.farM, L, s.resolution, quantum, 0.0, o))
        return e;
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
    p.texelM = std::max(p.extentM.x, p.extentM.y) / s.resolution;
    fit.parts.push_back(p);
  }
  out = std::move(fit);
  return std::nullopt;
}

}  // namespace sl::partition
