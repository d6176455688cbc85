// The FVSM panel's camera thumbnail (fvsm.camera): the camera's image in a fixed
// SL_FVSM_THUMBNAIL² float image, the frame scaled to fit with its aspect kept, at the
// bottom-left (the rest -2, so the panel finds the frame's part). Unshadowed: the G-buffer's
// normal against the directional light, 0.2 + 0.8 max(N.L, 0); -1 without a surface.
// Dispatched only while the panel asks for the key.
#include "common/shared_constants.h"
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = SL_UNIT_G_POSITION) uniform sampler2D u_gPosition;
layout(binding = SL_UNIT_G_NORMAL) uniform sampler2D u_gNormal;
layout(r32f, binding = SL_IMAGE_FVSM_CAMERA) writeonly uniform image2D o_camera;
uniform ivec2 u_frameSize;
uniform ivec2 u_used;         // the frame's part of the thumbnail, from (0, 0)
uniform vec3 u_towardsLight;  // unit, world

void main() {
  ivec2 t = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(t, ivec2(SL_FVSM_THUMBNAIL)))) return;
  if (any(greaterThanEqual(t, u_used))) {
    imageStore(o_camera, t, vec4(-2.0));
    return;
  }
  // sl::fvsm::thumbnailSamplePixel, in integers as there.
  ivec2 pixel = min(((2 * t + 1) * u_frameSize) / (2 * u_used), u_frameSize - 1);
  if (texelFetch(u_gPosition, pixel, 0).w <= 0.0) {
    imageStore(o_camera, t, vec4(-1.0));
    return;
  }
  vec3 N = texelFetch(u_gNormal, pixel, 0).xyz;
  imageStore(o_camera, t, vec4(0.2 + 0.8 * max(dot(N, u_towardsLight), 0.0)));
}
