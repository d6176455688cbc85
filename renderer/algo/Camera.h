// Camera and the small geometric types shared by every layer (the light: Light.h).
// Plain math on glm, no GL: the GUI, CLI and tests all manipulate these.
#pragma once

#include <array>
#include <optional>
#include <string>

#include <glm/glm.hpp>

namespace sl {

struct Aabb {
  glm::vec3 min{std::numeric_limits<float>::max()};
  glm::vec3 max{-std::numeric_limits<float>::max()};
  bool valid() const { return min.x <= max.x && min.y <= max.y && min.z <= max.z; }
  void extend(const glm::vec3& p) {
    min = glm::min(min, p);
    max = glm::max(max, p);
  }
  void extend(const Aabb& b) {
    if (b.valid()) extend(b.min), extend(b.max);
  }
  glm::vec3 center() const { return 0.5f * (min + max); }
  glm::vec3 size() const { return max - min; }
  std::array<glm::vec3, 8> corners() const;
};

/// A perspective camera looking from `position` at `target` (y is up in world space).
struct Camera {
  glm::vec3 position{0.0f, 3.0f, 8.0f};  ///< metres, world space
  glm::vec3 target{0.0f};                ///< metres, world space
  glm::vec3 up{0.0f, 1.0f, 0.0f};
  float fovYDeg = 50.0f;
  float nearM = 0.1f;
  float farM = 200.0f;

  glm::mat4 view() const;
  glm::mat4 projection(float aspect) const;
  glm::vec3 forward() const;
  /// The nearest near plane a frame renders with (float depth: 1e-40 renders nothing).
  static constexpr float kMinNearM = 1e-6f;
  /// The farthest far plane (a thousand times the largest scene extent the loader accepts;
  /// 3e38 leaves nothing on screen).
  static constexpr float kMaxFarM = 1e8f;
  /// The largest far / near ratio (2^20). Depth is float: window depth near the far plane is
  /// about 1 - near / distance, and a float below 1 is spaced 2^-24, so at far / near = 2^20
  /// the farthest half of the view is still 2^-19 (32 steps) away from 1. A 1e-6 m near
  /// plane with a 200 m far one (2e8) rounded 13 % of the geometry onto the far plane, where
  /// the depth test drops it.
  static constexpr float kMaxFarOverNear = 1048576.0f;

  /// An error naming what is wrong (NaN position, eye == target, a zero up vector, near
  /// below kMinNearM, far not above near or beyond kMaxFarM or kMaxFarOverNear times near,
  /// fov out of (1, 170) degrees, up
  /// parallel to the view direction), or nothing when usable. Each starts "camera: ".
  std::optional<std::string> validate() const;
  /// "near N m is too close for far F m (far / near ..., at most ...: kMaxFarOverNear ...)"
  /// when far / near exceeds kMaxFarOverNear, else nothing (no "camera: " prefix).
  static std::optional<std::string> depthPrecisionError(float nearM, float farM);
  /// validate()'s error without its "camera: ", for a message whose own words already name
  /// the camera ("camera 'tracker' ignored: ...", a JSON path "camera: ...").
  static std::string withoutPrefix(const std::string& error);
  /// World-space corners of the view frustum between `nearM` and `farM`
  /// (0-3 near plane, 4-7 far plane).
  std::array<glm::vec3, 8> frustumCorners(float aspect, float nearM, float farM) const;

  // Interactive controls (degrees and metres). They keep the camera valid.
  void orbit(float yawDeg, float pitchDeg);  ///< around the target
  void dolly(float factor);                  ///< distance to target *= factor
  void pan(float rightM, float upM);         ///< moves position and target
  void fly(float forwardM, float rightM, float upM);
  void look(float yawDeg, float pitchDeg);  ///< turns the view, position fixed
};

}  // namespace sl
