// Cube shadow map faces (CubeFit.h).
#include "CubeFit.h"

#include <algorithm>
#include <bit>

#include <glm/gtc/matrix_transform.hpp>

namespace sl::omni {

std::optional<std::string> fitCube(const Light& light, const Aabb& sceneBounds, CubeFit& out) {
  if (light.type == LightType::Directional)
    return "cube shadow map: a directional light has no position (use a point or spot light)";
  if (auto err = light.validate()) return err;
  if (!sceneBounds.valid()) return "scene: empty bounds (no geometry)";
  CubeFit f;
  f.lightPosM = light.positionM;
  float far = 0.0f;
  for (const glm::vec3& c : sceneBounds.corners())
    far = std::max(far, glm::length(c - f.lightPosM));
  if (light.rangeM > 0.0f) far = std::min(far, light.rangeM);
  if (!(far > 0.0f)) return "cube shadow map: the light sits on a point-sized scene";
  f.farM = 1.01f * far;
  f.nearM = 1e-3f * f.farM;
  f.faceMask =
      light.type == LightType::Point
          ? 0x3fu
          : cubeFacesInCone(glm::dvec3(light.spotAxis()), glm::radians(double(light.outerConeDeg)));
  const glm::mat4 proj = glm::perspective(glm::radians(90.0f), 1.0f, f.nearM, f.farM);
  for (int face = 0; face < kCubeFaces; ++face) {
    f.viewProj[size_t(face)] = proj * cubeFaceView(face, f.lightPosM);
    if (f.faceMask & (1u << face)) f.layer[size_t(face)] = f.layers++;
  }
  out = f;
  return std::nullopt;
}

}  // namespace sl::omni
