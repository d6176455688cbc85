#include "view/LightGizmo.h"

#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

namespace sl::ui {

LightGizmo lightGizmo(const sl::Scene* scene, const sl::Light& light, const sl::Camera& camera,
                      double width, double height) {
  LightGizmo g;
  if (!scene || !scene->bounds.valid() || width <= 0 || height <= 0) return g;
  const glm::mat4 viewProj = camera.projection(float(width / height)) * camera.view();
  auto project = [&](const glm::vec3& p) -> std::optional<QPointF> {
    const glm::vec4 c = viewProj * glm::vec4(p, 1.0f);
    if (!(c.w > 1e-4f)) return std::nullopt;  // behind the camera
    return QPointF((c.x / c.w * 0.5 + 0.5) * width, (0.5 - c.y / c.w * 0.5) * height);
  };
  auto line = [&](const glm::vec3& a, const glm::vec3& b) {
    auto pa = project(a), pb = project(b);
    if (pa && pb) g.lines.append(QLineF(*pa, *pb));
  };
  const float size = glm::length(scene->bounds.size());
  if (light.type == sl::LightType::Directional) {
    // An arrow from the sky down to the scene's centre, along the light.
    const glm::vec3 end = scene->bounds.center();
    const glm::vec3 start = end + light.directionalTowards() * (0.35f * size);
    line(start, end);
    const glm::vec3 d = glm::normalize(end - start);
    const glm::vec3 side = glm::normalize(
        glm::cross(d, std::abs(d.y) > 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0)));
    const float head = 0.04f * size;
    line(end, end - d * head + side * (0.5f * head));
    line(end, end - d * head - side * (0.5f * head));
    g.point = project(start);
    return g;
  }
  const glm::vec3 pos = light.positionM;
  g.point = project(pos);
  if (light.type == sl::LightType::Point) {  // a bulb: short rays around the point
    const float r = 0.03f * size;
    for (glm::vec3 d : {glm::vec3(1, 0, 0), glm::vec3(0, 1, 0), glm::vec3(0, 0, 1)}) {
      line(pos + d * r, pos + d * (2.0f * r));
      line(pos - d * r, pos - d * (2.0f * r));
    }
    line(pos, glm::vec3(pos.x, scene->bounds.min.y, pos.z));  // its foot on the ground
    return g;
  }
  // Spot: the outer cone's outline down to the scene's floor (or 1/3 of its size).
  const glm::vec3 axis = light.spotAxis();
  float len = 0.33f * size;
  if (axis.y < -0.05f) len = std::min(2.0f * size, (pos.y - scene->bounds.min.y) / -axis.y);
  const glm::vec3 u = glm::normalize(
      glm::cross(axis, std::abs(axis.y) > 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0)));
  const glm::vec3 v = glm::cross(axis, u);
  const float radius = len * std::tan(glm::radians(light.outerConeDeg));
  glm::vec3 previous{};
  for (int i = 0; i <= 32; ++i) {
    const float a = float(i) / 32.0f * 6.2831853f;
    const glm::vec3 p = pos + axis * len + (u * std::cos(a) + v * std::sin(a)) * radius;
    if (i > 0) line(previous, p);
    if (i % 8 == 0 && i < 32) line(pos, p);
    previous = p;
  }
  return g;
}

}  // namespace sl::ui
