#include "Camera.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

namespace sl {

namespace {
// `point` turned around `pivot` by yaw (about +y) and pitch (clamped to +-89 degrees),
// keeping its distance.
glm::vec3 rotateAround(const glm::vec3& pivot, const glm::vec3& point, float yawDeg,
                       float pitchDeg) {
  glm::vec3 offset = point - pivot;
  float r = glm::length(offset);
  float yaw = std::atan2(offset.x, offset.z) + glm::radians(yawDeg);
  float pitch = std::asin(std::clamp(offset.y / r, -1.0f, 1.0f)) + glm::radians(pitchDeg);
  pitch = std::clamp(pitch, glm::radians(-89.0f), glm::radians(89.0f));
  return pivot + r * glm::vec3(std::cos(pitch) * std::sin(yaw), std::sin(pitch),
                               std::cos(pitch) * std::cos(yaw));
}
}  // namespace

std::array<glm::vec3, 8> Aabb::corners() const {
  std::array<glm::vec3, 8> c;
  for (int i = 0; i < 8; ++i)
    c[i] = glm::vec3(i & 1 ? max.x : min.x, i & 2 ? max.y : min.y, i & 4 ? max.z : min.z);
  return c;
}

glm::mat4 Camera::view() const {
  return glm::lookAt(position, target, up);
}

glm::mat4 Camera::projection(float aspect) const {
  return glm::perspective(glm::radians(fovYDeg), aspect, nearM, farM);
}

glm::vec3 Camera::forward() const {
  return glm::normalize(target - position);
}

std::string Camera::withoutPrefix(const std::string& error) {
  return error.rfind("camera: ", 0) == 0 ? error.substr(8) : error;
}

std::optional<std::string> Camera::validate() const {
  auto finite = [](const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
  };
  if (!finite(position) || !finite(target) || !finite(up))
    return "camera: position, target or up is not finite";
  if (glm::length(target - position) < 1e-6f) return "camera: position equals target";
  if (!(glm::length(up) > 1e-6f)) return "camera: up is a zero vector";
  if (!(fovYDeg > 1.0f && fovYDeg < 170.0f))
    return "camera: vertical field of view must be in (1, 170) degrees";
  auto number = [](float v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3g", double(v));
    return std::string(buf);
  };
  if (!(nearM >= kMinNearM))
    return "camera: near must be at least " + number(kMinNearM) + " m (got " + number(nearM) + ")";
  if (!(farM > nearM) || !std::isfinite(farM)) return "camera: need 0 < near < far (finite)";
  if (!(farM <= kMaxFarM))
    return "camera: far must be at most " + number(kMaxFarM) + " m (got " + number(farM) + ")";
  if (auto e = depthPrecisionError(nearM, farM)) return "camera: " + *e;
  glm::vec3 f = forward();
  if (glm::length(glm::cross(f, glm::normalize(up))) < 1e-4f)
    return "camera: up vector is parallel to the view direction";
  return std::nullopt;
}

std::optional<std::string> Camera::depthPrecisionError(float nearM, float farM) {
  if (!(double(farM) > double(nearM) * double(kMaxFarOverNear))) return std::nullopt;
  char buf[200];
  std::snprintf(buf, sizeof buf,
                "near %.3g m is too close for far %.3g m (far / near %.3g, at most %.0f: "
                "kMaxFarOverNear, float depth precision); near at least %.3g m",
                double(nearM), double(farM), double(farM) / double(nearM), double(kMaxFarOverNear),
                double(farM) / double(kMaxFarOverNear));
  return std::string(buf);
}

std::array<glm::vec3, 8> Camera::frustumCorners(float aspect, float n, float f) const {
  glm::vec3 fw = forward();
  glm::vec3 right = glm::normalize(glm::cross(fw, up));
  glm::vec3 u = glm::cross(right, fw);
  float t = std::tan(glm::radians(fovYDeg) * 0.5f);
  std::array<glm::vec3, 8> c;
  for (int plane = 0; plane < 2; ++plane) {
    float d = plane ? f : n;
    float hy = t * d, hx = hy * aspect;
    glm::vec3 center = position + fw * d;
    c[plane * 4 + 0] = center - right * hx - u * hy;
    c[plane * 4 + 1] = center + right * hx - u * hy;
    c[plane * 4 + 2] = center + right * hx + u * hy;
    c[plane * 4 + 3] = center - right * hx + u * hy;
  }
  return c;
}

void Camera::orbit(float yawDeg, float pitchDeg) {
  position = rotateAround(target, position, yawDeg, pitchDeg);
}

void Camera::dolly(float factor) {
  glm::vec3 offset = position - target;
  float r = std::clamp(glm::length(offset) * factor, 0.05f, 1e5f);
  position = target + glm::normalize(offset) * r;
}

void Camera::pan(float rightM, float upM) {
  glm::vec3 fw = forward();
  glm::vec3 right = glm::normalize(glm::cross(fw, up));
  glm::vec3 u = glm::cross(right, fw);
  glm::vec3 d = right * rightM + u * upM;
  position += d;
  target += d;
}

void Camera::fly(float forwardM, float rightM, float upM) {
  glm::vec3 fw = forward();
  glm::vec3 right = glm::normalize(glm::cross(fw, up));
  glm::vec3 d = fw * forwardM + right * rightM + up * upM;
  position += d;
  target += d;
}

void Camera::look(float yawDeg, float pitchDeg) {
  target = rotateAround(position, target, yawDeg, pitchDeg);
}

}  // namespace sl
