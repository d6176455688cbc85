// The light model (Light.h): KHR_lights_punctual's directional, spot and point lights.
// shaders/common/light.glsl evaluates the same formulas per pixel.
#include "Light.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace sl {

namespace {
bool finite(const glm::vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}
}  // namespace

std::string_view lightTypeName(LightType type) {
  switch (type) {
    case LightType::Directional:
      return "directional";
    case LightType::Spot:
      return "spot";
    case LightType::Point:
      return "point";
  }
  return "unknown";
}

std::optional<LightType> lightTypeFromName(std::string_view name) {
  for (LightType t : {LightType::Directional, LightType::Spot, LightType::Point})
    if (lightTypeName(t) == name) return t;
  return std::nullopt;
}

std::string lightTypeList(const std::vector<LightType>& types) {
  std::string s;
  for (LightType t : types) s += (s.empty() ? "" : ", ") + std::string(lightTypeName(t));
  return s.empty() ? "none" : s;
}

Light Light::directional(float azimuthDeg, float elevationDeg) {
  Light l;
  l.azimuthDeg = azimuthDeg;
  l.elevationDeg = elevationDeg;
  return l;
}

Light Light::directionalFromTowards(const glm::vec3& towards) {
  glm::vec3 d = glm::normalize(towards);
  Light l;
  l.elevationDeg = glm::degrees(std::asin(std::clamp(d.y, -1.0f, 1.0f)));
  l.azimuthDeg = glm::degrees(std::atan2(d.x, d.z));
  return l;
}

Light Light::point(const glm::vec3& positionM, float rangeM) {
  Light l;
  l.type = LightType::Point;
  l.positionM = positionM;
  l.rangeM = rangeM;
  return l;
}

Light Light::spot(const glm::vec3& positionM, const glm::vec3& direction, float outerConeDeg,
                  float innerConeDeg, float rangeM) {
  Light l;
  l.type = LightType::Spot;
  l.positionM = positionM;
  l.direction = direction;
  l.outerConeDeg = outerConeDeg;
  l.innerConeDeg = innerConeDeg;
  l.rangeM = rangeM;
  return l;
}

glm::vec3 Light::directionalTowards() const {
  float az = glm::radians(azimuthDeg), el = glm::radians(elevationDeg);
  return glm::vec3(std::cos(el) * std::sin(az), std::sin(el), std::cos(el) * std::cos(az));
}

glm::vec3 Light::towardsLight(const glm::vec3& P) const {
  if (type == LightType::Directional) return directionalTowards();
  glm::vec3 d = positionM - P;
  float len = glm::length(d);
  return len > 0.0f ? d / len : glm::vec3(0.0f, 1.0f, 0.0f);
}

glm::vec3 Light::spotAxis() const {
  float len = glm::length(direction);
  return len > 0.0f ? direction / len : glm::vec3(0.0f, -1.0f, 0.0f);
}

bool Light::illuminates(const glm::vec3& P) const {
  if (type == LightType::Directional) return true;
  const glm::vec3 d = P - positionM;
  const float dist = glm::length(d);
  if (rangeM > 0.0f && dist > rangeM) return false;
  if (type == LightType::Point) return true;
  if (!(dist > 0.0f)) return false;
  return glm::dot(d / dist, spotAxis()) > std::cos(glm::radians(outerConeDeg));
}

float Light::falloff(const glm::vec3& P) const {
  if (type == LightType::Directional) return 1.0f;
  if (!illuminates(P)) return 0.0f;
  const glm::vec3 d = P - positionM;
  const float dist = glm::length(d);
  float w = 1.0f;
  if (rangeM > 0.0f) {
    float r = dist / rangeM, r4 = r * r * r * r;
    w = std::clamp(1.0f - r4, 0.0f, 1.0f);
    w *= w;
  }
  if (type == LightType::Spot) {
    float cosOuter = std::cos(glm::radians(outerConeDeg));
    float cosInner = std::cos(glm::radians(innerConeDeg));
    float cd = glm::dot(d / dist, spotAxis());
    float t = std::clamp((cd - cosOuter) / std::max(cosInner - cosOuter, 1e-4f), 0.0f, 1.0f);
    w *= t * t * (3.0f - 2.0f * t);
  }
  return w;
}

std::optional<std::string> Light::validate() const {
  switch (type) {
    case LightType::Directional:
      if (!std::isfinite(azimuthDeg) || !std::isfinite(elevationDeg))
        return "light: azimuth or elevation is not finite";
      if (elevationDeg < -90.0f || elevationDeg > 90.0f)
        return "light: elevation must be in -90..90 degrees";
      return std::nullopt;
    case LightType::Spot:
    case LightType::Point:
      break;
    default:
      return "light: unknown type " + std::to_string(int(type));
  }
  const std::string kind(lightTypeName(type));
  if (!finite(positionM)) return kind + " light: position is not finite";
  if (!std::isfinite(rangeM)) return kind + " light: range is not finite";
  if (rangeM < 0.0f) return kind + " light: range must be >= 0 metres (0 = infinite)";
  const float reach =
      std::max({std::abs(positionM.x), std::abs(positionM.y), std::abs(positionM.z)});
  if (reach > kMaxLightPositionM || rangeM > kMaxLightPositionM) {
    char buf[200];
    std::snprintf(buf, sizeof buf,
                  "%s light: %s %.3g m is beyond %.0e m from the origin (kMaxLightPositionM: "
                  "float distances to the light would overflow)",
                  kind.c_str(), reach > kMaxLightPositionM ? "position" : "range",
                  double(reach > kMaxLightPositionM ? reach : rangeM), double(kMaxLightPositionM));
    return std::string(buf);
  }
  if (type == LightType::Point) return std::nullopt;
  if (!finite(direction)) return "spot light: direction is not finite";
  if (!(glm::length(direction) > 1e-6f)) return "spot light: direction is zero";
  if (!std::isfinite(outerConeDeg) || !(outerConeDeg > 0.0f && outerConeDeg <= kMaxSpotConeDeg)) {
    char buf[200];
    std::snprintf(buf, sizeof buf,
                  "spot light: outer cone angle must be in (0, %g] degrees, got %.7g "
                  "(kMaxSpotConeDeg: one perspective shadow map covers less than a half-space)",
                  double(kMaxSpotConeDeg), double(outerConeDeg));
    return std::string(buf);
  }
  if (!std::isfinite(innerConeDeg) || innerConeDeg < 0.0f)
    return "spot light: inner cone angle must be >= 0 degrees";
  if (innerConeDeg > outerConeDeg)
    return "spot light: inner cone angle must not exceed the outer one";
  return std::nullopt;
}

std::string Light::describe() const {
  char buf[256];
  auto range = [&]() {
    char r[32];
    if (rangeM > 0.0f)
      std::snprintf(r, sizeof r, "%g m", double(rangeM));
    else
      std::snprintf(r, sizeof r, "inf");
    return std::string(r);
  };
  switch (type) {
    case LightType::Directional:
      std::snprintf(buf, sizeof buf, "directional az %g el %g", double(azimuthDeg),
                    double(elevationDeg));
      break;
    case LightType::Point:
      std::snprintf(buf, sizeof buf, "point at (%g, %g, %g) range %s", double(positionM.x),
                    double(positionM.y), double(positionM.z), range().c_str());
      break;
    case LightType::Spot:
      std::snprintf(buf, sizeof buf,
                    "spot at (%g, %g, %g) dir (%g, %g, %g) cone %g/%g deg range %s",
                    double(positionM.x), double(positionM.y), double(positionM.z),
                    double(direction.x), double(direction.y), double(direction.z),
                    double(outerConeDeg), double(innerConeDeg), range().c_str());
      break;
    default:
      return "unknown light";
  }
  return buf;
}

}  // namespace sl
