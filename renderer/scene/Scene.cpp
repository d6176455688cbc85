// The flattened scene's small queries: triangle count, material lookup, a framing camera
// and camera-path sampling (linear positions, slerped rotations between glTF keyframes).
#include "Scene.h"

#include <algorithm>
#include <cmath>

namespace sl {

Camera cameraFromPose(const glm::vec3& positionM, const glm::quat& rotation, float fovYDeg,
                      float nearM, float farM, float targetDistanceM) {
  glm::quat q = glm::normalize(rotation);
  glm::vec3 forward = glm::normalize(q * glm::vec3(0.0f, 0.0f, -1.0f));
  Camera cam;
  cam.position = positionM;
  cam.target = positionM + forward * std::max(targetDistanceM, 1e-3f);
  // Straight up or down: world +y would be parallel to the view, use the pose's own +y.
  cam.up = std::abs(forward.y) > 0.999f ? glm::normalize(q * glm::vec3(0.0f, 1.0f, 0.0f))
                                        : glm::vec3(0.0f, 1.0f, 0.0f);
  cam.fovYDeg = fovYDeg;
  cam.nearM = nearM;
  cam.farM = farM;
  return cam;
}

Camera CameraPath::sample(float timeS) const {
  if (keys.empty()) return Camera{};
  const CameraKey* a = &keys.front();
  const CameraKey* b = a;
  if (timeS >= keys.back().timeS || !std::isfinite(timeS)) {
    a = b = &keys.back();
    if (std::isnan(timeS)) a = b = &keys.front();
  } else if (timeS > keys.front().timeS) {
    // First key strictly after t; the segment is [it - 1, it].
    auto it = std::upper_bound(keys.begin(), keys.end(), timeS,
                               [](float t, const CameraKey& k) { return t < k.timeS; });
    b = &*it;
    a = &*(it - 1);
  }
  float span = b->timeS - a->timeS;
  float u = span > 0.0f ? std::clamp((timeS - a->timeS) / span, 0.0f, 1.0f) : 0.0f;
  glm::vec3 position = glm::mix(a->position, b->position, u);
  glm::quat rotation = glm::slerp(glm::normalize(a->rotation), glm::normalize(b->rotation), u);
  return cameraFromPose(position, rotation, fovYDeg, nearM, farM, 1.0f);
}

std::size_t Scene::triangleCount() const {
  std::size_t n = 0;
  for (const MeshPrimitive& p : primitives) n += p.indices.size() / 3;
  return n;
}

const Material& Scene::materialOf(const MeshPrimitive& prim) const {
  // glTF's default material: white, opaque, single-sided.
  static const Material kDefaultMaterial{"default"};
  if (prim.material >= 0 && std::size_t(prim.material) < materials.size())
    return materials[std::size_t(prim.material)];
  return kDefaultMaterial;
}

Camera Scene::defaultCamera() const {
  Camera cam;
  if (!bounds.valid()) return cam;
  glm::vec3 center = bounds.center();
  float radius = std::max(0.5f * glm::length(bounds.size()), 0.05f);
  // Far enough that the bounding sphere fits the vertical field of view, with a margin.
  float distance = 1.1f * radius / std::sin(glm::radians(cam.fovYDeg) * 0.5f);
  // Seen from the azimuth 35 degrees, 30 degrees above the horizon.
  const float azimuth = glm::radians(35.0f), elevation = glm::radians(30.0f);
  glm::vec3 fromCenter(std::cos(elevation) * std::sin(azimuth), std::sin(elevation),
                       std::cos(elevation) * std::cos(azimuth));
  cam.target = center;
  cam.position = center + distance * fromCenter;
  cam.up = glm::vec3(0.0f, 1.0f, 0.0f);
  cam.farM = distance + 2.0f * radius;
  cam.nearM = std::max(std::min(0.1f, cam.farM * 1e-3f), cam.farM * 1e-5f);
  return cam;
}

}  // namespace sl
