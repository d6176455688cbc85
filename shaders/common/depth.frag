// Depth-only light pass: alpha-tested casters drop their transparent texels. Built twice
// (core/ShadowPass.h DepthProgram): as is for materials whose alphaMode is MASK, and with
// SL_DEPTH_OPAQUE for every other draw, an empty shader with no discard, so the depth test
// runs before shading (llvmpipe: the tile depth pass 2.3x faster, README).
#include "common/material.glsl"
in vec2 v_uv;

void main() {
#ifndef SL_DEPTH_OPAQUE
  if (materialAlphaRejectsLevel0(v_uv)) discard;
#endif
}
