// Test only (tests/gl/EyeDepthTest.cpp): every pixel's world position rebuilt from the tiled
// techniques' eye-space depth buffer with the very functions apply_tile.comp and smtmm.comp
// use (common/tiled/eye_depth.glsl, eq. 1); w = 1 where the buffer holds a surface, else 0.
#include "common/shared_constants.h"
layout(local_size_x = 8, local_size_y = 8) in;
layout(rgba32f, binding = 0) writeonly uniform image2D o_world;
#include "common/tiled/eye_depth.glsl"

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, textureSize(u_eyeDepth, 0)))) return;
  float d = eyeDepthAt(p);
  imageStore(o_world, p, d > 0.0 ? vec4(worldPositionAt(p, d), 1.0) : vec4(0.0));
}
