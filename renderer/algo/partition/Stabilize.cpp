// Stabilised cascades: bounding-sphere extent (quantised) and texel-snapped centre.
#include "Stabilize.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace sl::partition {

std::optional<std::string> stabilizeCascade(const warp::ViewFrustum& view, double sliceNear,
                                            double sliceFar, const glm::dvec3& towardsLight,
                                            int resolution, double extentQuantumM,
                                            double casterExtraM, StableOrtho& out) {
  if (auto e = view.validate()) return e;
  if (!(sliceNear > 0.0) || !(sliceFar > sliceNear) || !std::isfinite(sliceFar))
    return "cascade: need 0 < slice near < slice far (finite)";
  if (resolution < 2 || resolution > 65536) return "cascade: resolution must be in 2..65536";
  if (!std::isfinite(extentQuantumM) || !(casterExtraM >= 0.0) || !std::isfinite(casterExtraM))
    return "cascade: extent quantum and caster extra must be finite (extra >= 0)";
  if (!(glm::length(towardsLight) > 1e-12)) return "cascade: the light direction is zero";
  StableOrtho s;
  s.towardsLight = glm::normalize(towardsLight);
  // The light basis depends on the light only (as algo/Focus's lightBaseView).
  const glm::dvec3 worldUp =
      std::abs(s.towardsLight.y) > 0.99 ? glm::dvec3(0, 0, -1) : glm::dvec3(0, 1, 0);
  s.right = glm::normalize(glm::cross(-s.towardsLight, worldUp));
  s.up = glm::cross(s.right, -s.towardsLight);

  // Bounding sphere of the slice, centred on the view axis: depends on the slice's shape
  // only, not on the camera's orientation (its radius never changes as the camera turns).
  const double T = view.tanHalfX() * view.tanHalfX() + view.tanHalfY() * view.tanHalfY();
  const double a = sliceNear, b = sliceFar;
  const double c = std::min(0.5 * (a + b) * (1.0 + T), b);
  const double r =
      std::max(std::sqrt((c - a) * (c - a) + a * a * T), std::sqrt((b - c) * (b - c) + b * b * T));
  s.sphereRadiusM = r;
  s.extentM = 2.0 * r;
  if (extentQuantumM > 0.0) s.extentM = std::ceil(s.extentM / extentQuantumM) * extentQuantumM;
  s.texelM = s.extentM / resolution;
  const glm::dvec3 centre = view.eye + c * view.forward;
  const glm::dvec2 cLs(glm::dot(centre, s.right), glm::dot(centre, s.up));
  const glm::dvec2 snapped = glm::round(cLs / s.texelM) * s.texelM;
  s.minXY = snapped - 0.5 * s.extentM;
  s.maxXY = snapped + 0.5 * s.extentM;
  const double cz = glm::dot(centre, s.towardsLight);
  s.zMin = cz - r;
  s.zMax = cz + r + casterExtraM;

  glm::dmat4 v(1.0);
  for (int i = 0; i < 3; ++i) {
    v[i][0] = s.right[i];
    v[i][1] = s.up[i];
    v[i][2] = s.towardsLight[i];
  }
  s.view = glm::mat4(v);
  // View space looks along -z = -towardsLight: z = zMax is the near plane.
  s.proj = glm::mat4(glm::ortho(s.minXY.x, s.maxXY.x, s.minXY.y, s.maxXY.y, -s.zMax, -s.zMin));
  out = s;
  return std::nullopt;
}

}  // namespace sl::partition
