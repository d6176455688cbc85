// The light of the frame (C++: sl::Light, algo/Light.h; bound by sl::bindLight,
// core/LightBinding.cpp): KHR_lights_punctual's directional, spot and point lights.
// u_lightType: 0 directional, 1 spot, 2 point (sl::LightType).
uniform int u_lightType;
uniform vec3 u_lightTowards;    // directional: unit vector towards the light
uniform vec3 u_lightPosition;   // spot, point: world metres
uniform vec3 u_lightAxis;       // spot: unit axis it shines along
uniform float u_lightCosOuter;  // spot: cos(outer cone half-angle)
uniform float u_lightCosInner;  // spot: cos(inner cone half-angle)
uniform float u_lightRange;     // spot, point: metres, 0 = infinite

// Unit vector from P towards the light (sl::Light::towardsLight).
vec3 towardsLight(vec3 P) {
  if (u_lightType == 0) return u_lightTowards;
  vec3 d = u_lightPosition - P;
  float len = length(d);
  return len > 0.0 ? d / len : vec3(0.0, 1.0, 0.0);
}

// 1 when P is inside the spot's outer cone and the range, else 0; directional: 1
// (sl::Light::illuminates). The hard mask treats 0 as shadowed, like the reference.
float lightIlluminates(vec3 P) {
  if (u_lightType == 0) return 1.0;
  vec3 d = P - u_lightPosition;
  float dist = length(d);
  if (u_lightRange > 0.0 && dist > u_lightRange) return 0.0;
  if (u_lightType == 2) return 1.0;
  if (!(dist > 0.0)) return 0.0;
  return dot(d / dist, u_lightAxis) > u_lightCosOuter ? 1.0 : 0.0;
}

// Shading weight: spot smoothstep from the outer to the inner cone times the range window
// (1 - (d/range)^4)^2 (sl::Light::falloff).
float lightFalloff(vec3 P) {
  if (u_lightType == 0) return 1.0;
  if (lightIlluminates(P) < 0.5) return 0.0;
  vec3 d = P - u_lightPosition;
  float dist = length(d);
  float w = 1.0;
  if (u_lightRange > 0.0) {
    float r = dist / u_lightRange, r4 = r * r * r * r;
    w = clamp(1.0 - r4, 0.0, 1.0);
    w *= w;
  }
  if (u_lightType == 1) {
    float t = clamp((dot(d / dist, u_lightAxis) - u_lightCosOuter) /
                        max(u_lightCosInner - u_lightCosOuter, 1e-4),
                    0.0, 1.0);
    w *= t * t * (3.0 - 2.0 * t);
  }
  return w;
}
