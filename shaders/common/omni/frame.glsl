// The light, frame and depth range of the omni maps that store, per texel, the exact distance
// from the light along the texel's own ray (dual-paraboloid/paraboloid.glsl,
// spherical/latlong.glsl; C++: OmniRayMap::setMapping in renderer/core/omni/OmniRayMap.h).
// The frame is omni::ParaboloidFrame's (x, y, axis) or omni::LatLongFrame's (x, y, pole).
#include "common/light_distance.glsl"
uniform vec3 u_omniLight;                   // world, metres
uniform vec3 u_omniX, u_omniY, u_omniAxis;  // unit, x × y = axis
uniform float u_omniNearM, u_omniFarM;      // stored = (L - near) / (far - near)

// World direction -> the frame (any length kept).
vec3 omniLocal(vec3 d) { return vec3(dot(d, u_omniX), dot(d, u_omniY), dot(d, u_omniAxis)); }

// The stored value of a distance (omni::storedDistance).
float omniStoredDistance(float distanceM) {
  return storedLightDistance(distanceM, u_omniNearM, u_omniFarM);
}

// Distance from the light along unit `dir` to the plane through P with normal N; -1 when the
// ray runs (nearly) inside the plane or away from it.
float omniPlaneDistance(vec3 dir, vec3 P, vec3 N) {
  return planeDistanceAlongRay(u_omniLight, dir, P, N);
}
