// Forward analysis (Rosen 2012): each light texel's nearest surface is projected into the
// camera and gets an importance if the camera frustum contains it. Hybrid adds an
// eye-depth visibility test against the camera G-buffer, so surfaces the camera cannot
// see get none (the flaw seed 000 names in forward analysis).
#include "common/material.glsl"
#include "rtw/importance.glsl"
in vec3 v_worldPos;
in vec3 v_worldNormal;
in vec2 v_uv;
uniform mat4 u_cameraViewProj;
uniform vec3 u_cameraPos;
uniform vec3 u_cameraForward;
#include "common/light.glsl"
uniform int u_hybrid;
uniform float u_visibilityToleranceM;
uniform sampler2D u_gPosition;
layout(location = 0) out uint o_importance;  // float bits

void main() {
  if (materialAlphaRejects(v_uv)) discard;
  o_importance = 0u;
  vec4 c = u_cameraViewProj * vec4(v_worldPos, 1.0);
  if (c.w <= 0.0 || any(greaterThan(abs(c.xyz), vec3(c.w)))) return;
  vec2 uv = c.xy / c.w * 0.5 + 0.5;
  ivec2 size = textureSize(u_gPosition, 0);
  ivec2 px = clamp(ivec2(uv * vec2(size)), ivec2(0), size - 1);
  if (u_hybrid != 0) {
    vec4 seen = texelFetch(u_gPosition, px, 0);
    if (seen.w <= 0.0 || distance(seen.xyz, v_worldPos) > u_visibilityToleranceM) return;
  }
  vec3 N = normalize(v_worldNormal);
  vec3 V = normalize(u_cameraPos - v_worldPos);
  if (dot(N, V) < 0.0) N = -N;
  float eyeDepth = dot(v_worldPos - u_cameraPos, u_cameraForward);
  float imp = combineImportance(eyeDepth, dot(N, towardsLight(v_worldPos)), dot(N, V), shadowEdgeAt(px));
  if (imp > 0.0 && !isinf(imp)) o_importance = floatBitsToUint(imp);
}
