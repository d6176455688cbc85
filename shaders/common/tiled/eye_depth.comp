// The tiled techniques' eye-space depth buffer (Giegl & Wimmer 2007, §3.2 and fvsm's step 1,
// §4.2; C++: sl::EyeDepthBuffer::update in core/tiled/EyeDepthBuffer): per pixel the linear
// depth along the camera's view axis, −z_eye in metres (0: no surface), from the G-buffer's
// world position. This is the one pass of virtual-tiled and fvsm that reads the position
// texture: the tile passes and the SMTMM rebuild positions from this buffer with eq. 1
// (common/tiled/eye_depth.glsl).
#include "common/shared_constants.h"
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = SL_UNIT_G_POSITION) uniform sampler2D u_gPosition;
layout(r32f, binding = SL_IMAGE_EYE_DEPTH) writeonly uniform image2D o_eyeDepth;
uniform ivec2 u_size;         // frame size in pixels
uniform mat4 u_eyeFromWorld;  // the camera's view matrix

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, u_size))) return;
  vec4 P = texelFetch(u_gPosition, p, 0);
  imageStore(o_eyeDepth, p, vec4(P.w > 0.0 ? -(u_eyeFromWorld * vec4(P.xyz, 1.0)).z : 0.0));
}
