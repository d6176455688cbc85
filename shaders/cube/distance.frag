// Cube shadow map, fragment stage of both modes: the DISTANCE from the light, not the face's
// window depth (seed 001: "depth stored as distance to the light"). The position relative
// to the light is interpolated perspective-correctly at the texel centre, so the stored
// value is the distance along that centre's own ray (omni::cubeTexelCentreDirection); along
// one ray distance and window depth grow together, so the depth test keeps the nearest
// surface either way. Alpha-tested casters drop their transparent texels.
#include "common/material.glsl"
#include "cube/distance.glsl"
in vec2 v_uv;
in vec3 v_fromLight;

void main() {
  if (materialAlphaRejectsLevel0(v_uv)) discard;
  gl_FragDepth = clamp(cubeStoredDistance(length(v_fromLight)), 0.0, 1.0);
}
