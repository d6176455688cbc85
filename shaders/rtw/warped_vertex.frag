// Seed 002's warped shadow map, fragment stage: depth is the rasteriser's, interpolated
// linearly in warped space (C++ reference: sl::rtw::rasterizeWarpedInterpolated);
// alpha-tested casters drop their transparent texels.
#include "common/material.glsl"
in vec2 v_uv;

void main() {
  if (materialAlphaRejectsLevel0(v_uv)) discard;
}
