// Depth-only light pass: alpha-tested casters drop their transparent texels.
#include "common/material.glsl"
in vec2 v_uv;

void main() {
  if (materialAlphaRejectsLevel0(v_uv)) discard;
}
