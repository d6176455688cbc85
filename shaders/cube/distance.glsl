// What a cube face stores per texel: the distance from the light along the texel centre's
// ray, normalised by the faces' near and far planes (C++: omni::storedDistance with
// omni::CubeFit's nearM, farM; bound by CubeShadowMap). 1 = nothing within far.
#include "common/light_distance.glsl"
uniform vec3 u_cubeLightPos;           // world, metres
uniform float u_cubeNearM, u_cubeFarM;  // CubeFit::nearM, farM

float cubeStoredDistance(float distanceM) {
  return storedLightDistance(distanceM, u_cubeNearM, u_cubeFarM);
}
