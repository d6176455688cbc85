// Backward analysis (seed 002, seed 000): every covered camera pixel scatters its
// importance into the light-space IM with atomicMax on the float's bits (valid for
// finite values >= +0; mirrors sl::rtw::scatterMax).
layout(local_size_x = 8, local_size_y = 8) in;
layout(r32ui, binding = 0) uniform uimage2D u_im;
uniform sampler2D u_gPosition;
uniform sampler2D u_gNormal;
uniform mat4 u_lightViewProj;
uniform vec3 u_cameraPos;
uniform vec3 u_cameraForward;
uniform vec3 u_towardsLight;
#include "rtw/importance.glsl"

void main() {
  ivec2 px = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(px, textureSize(u_gPosition, 0)))) return;
  vec4 P = texelFetch(u_gPosition, px, 0);
  if (P.w <= 0.0) return;
  vec3 N = texelFetch(u_gNormal, px, 0).xyz;
  vec3 V = normalize(u_cameraPos - P.xyz);
  float eyeDepth = dot(P.xyz - u_cameraPos, u_cameraForward);
  float imp = combineImportance(eyeDepth, dot(N, u_towardsLight), dot(N, V), shadowEdgeAt(px));
  if (!(imp > 0.0) || isinf(imp)) return;
  vec4 c = u_lightViewProj * vec4(P.xyz, 1.0);
  vec2 uv = c.xy / c.w * 0.5 + 0.5;
  ivec2 size = imageSize(u_im);
  vec2 f = floor(uv * vec2(size));
  if (!(f.x >= 0.0 && f.x < float(size.x) && f.y >= 0.0 && f.y < float(size.y))) return;
  imageAtomicMax(u_im, ivec2(f), floatBitsToUint(imp));
}
