// Distance from a point light, as the omni maps store it (cube, dual paraboloid; seed 001):
// the stored value and the receiver's plane met by a texel's own ray. CPU mirrors:
// omni::storedDistance and sl::planeDistanceAlongRay (algo/omni/OmniMapping.h,
// algo/ShadowBias.h).

// (distanceM - near) / (far - near): 0 at the near distance, 1 at the far one (= nothing).
float storedLightDistance(float distanceM, float nearM, float farM) {
  return (distanceM - nearM) / (farM - nearM);
}

// Distance from `light` along unit `dir` to the plane through P with normal N; -1 when the
// ray runs (nearly) inside the plane (|N.dir| < 1e-6 |N|) or meets it behind the light.
float planeDistanceAlongRay(vec3 light, vec3 dir, vec3 P, vec3 N) {
  float nd = dot(N, dir);
  if (abs(nd) < 1e-6 * length(N)) return -1.0;
  float t = dot(N, P - light) / nd;
  return t > 0.0 ? t : -1.0;
}
