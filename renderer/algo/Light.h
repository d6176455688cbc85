// The one light model of ShadowLab: KHR_lights_punctual's three kinds (directional, spot,
// point) as plain math on glm. The renderer, the reference, the loader, the CLI, presets,
// suites and the GUI all manipulate this struct; shaders/common/light.glsl mirrors it.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

namespace sl {

/// The light kinds of KHR_lights_punctual. The numbers are the GLSL u_lightType values
/// (shaders/common/light.glsl).
enum class LightType : int { Directional = 0, Spot = 1, Point = 2 };

/// The widest spot cone (outer half-angle, degrees) any entry point accepts: one perspective
/// shadow map covers less than a half-space, and towards 90 degrees its texels spread without
/// bound (89.9999 rendered 5.5 % error where 89 gave 0.9 %). Light::validate refuses wider
/// cones; the glTF loader, whose format allows up to 90, narrows them to this and warns.
inline constexpr float kMaxSpotConeDeg = 89.0f;

/// The farthest a spot or point light may be from the origin (largest |x|, |y| or |z|) and
/// the longest range, in metres: ten times the scene extent the glTF loader accepts
/// (kMaxSceneExtentM, 1e5 m). Positions are floats in world space; beyond ~1.8e19 m the
/// light's distances squared overflow a float and the scene darkens with the reference
/// agreeing (an error of 0 %). Every input (--light, glTF, presets, sessions, suites, claims)
/// goes through Light::validate.
inline constexpr float kMaxLightPositionM = 1e6f;

/// "directional", "spot", "point".
std::string_view lightTypeName(LightType type);
/// The type named `name` (as lightTypeName writes it), or nothing.
std::optional<LightType> lightTypeFromName(std::string_view name);
/// "directional, spot" (for messages).
std::string lightTypeList(const std::vector<LightType>& types);

/// One punctual light. Directional: azimuth around +y measured from +z towards +x and
/// elevation above the horizon (the sun). Spot: a cone from `positionM` along `direction`
/// with outer and inner half-angles (KHR_lights_punctual's outerConeAngle/innerConeAngle,
/// in degrees). Point: light from `positionM` in every direction. Spot and point reach
/// `rangeM` metres (0 = infinite).
struct Light {
  LightType type = LightType::Directional;
  float azimuthDeg = 35.0f;                ///< directional
  float elevationDeg = 50.0f;              ///< directional
  glm::vec3 positionM{0.0f, 5.0f, 0.0f};   ///< spot, point: world, metres
  glm::vec3 direction{0.0f, -1.0f, 0.0f};  ///< spot: the axis it shines along (any length)
  float outerConeDeg = 45.0f;              ///< spot: half-angle, in (0, kMaxSpotConeDeg]
  float innerConeDeg = 0.0f;               ///< spot: half-angle, in [0, outer]
  float rangeM = 0.0f;                     ///< spot, point: reach in metres, 0 = infinite

  bool operator==(const Light&) const = default;

  static Light directional(float azimuthDeg, float elevationDeg);
  /// A directional light whose unit vector towards the light is `towardsLight` (any length).
  static Light directionalFromTowards(const glm::vec3& towardsLight);
  static Light point(const glm::vec3& positionM, float rangeM = 0.0f);
  static Light spot(const glm::vec3& positionM, const glm::vec3& direction, float outerConeDeg,
                    float innerConeDeg = 0.0f, float rangeM = 0.0f);

  /// Directional: the unit vector towards the light from azimuth/elevation (whatever the
  /// type: the directional parametrisation). Use towardsLight(P) for every kind.
  glm::vec3 directionalTowards() const;
  /// Unit vector from world point P towards the light (directional: the same for every P).
  /// At the light's own position: (0, 1, 0).
  glm::vec3 towardsLight(const glm::vec3& P) const;
  /// Spot: the unit axis it shines along.
  glm::vec3 spotAxis() const;
  /// Whether P is inside the light's cone (spot, within the OUTER angle) and range (spot,
  /// point; 0 = infinite). Directional: always. Occlusion is not considered.
  bool illuminates(const glm::vec3& P) const;
  /// Shading weight in [0, 1]: the spot's smooth falloff from the inner to the outer cone
  /// (KHR_lights_punctual's recommended smoothstep) times the range window
  /// (1 - (d/range)^4)^2; 1 for directional and inside the inner cone with infinite range.
  /// The hard shadow mask ignores it (illuminates() only).
  float falloff(const glm::vec3& P) const;

  /// An error naming what is wrong (non-finite field, a position or range beyond
  /// kMaxLightPositionM, zero spot direction, outer cone angle out of (0, kMaxSpotConeDeg]
  /// degrees, inner > outer, negative range, elevation out of -90..90), or nothing when usable.
  std::optional<std::string> validate() const;
  /// A short human description: "directional az 35 el 50", "point at (0, 4, 0) range 10 m",
  /// "spot at (0, 4, 0) dir (0, -1, 0) cone 30/20 deg range inf".
  std::string describe() const;
};

}  // namespace sl
