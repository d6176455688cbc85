// Camera G-buffer pass. Normals are flipped to face the camera (scenes are drawn without
// culling), so the resolve pass and the Embree reference see the same surface side.
#include "common/material.glsl"
in vec3 v_worldPos;
in vec3 v_worldNormal;
in vec2 v_uv;
uniform vec3 u_cameraPos;
layout(location = 0) out vec4 o_position;  // xyz world, w = 1 covered
layout(location = 1) out vec4 o_normal;    // xyz world unit normal
layout(location = 2) out vec4 o_albedo;

void main() {
  if (materialAlphaRejects(v_uv)) discard;
  vec3 n = normalize(v_worldNormal);
  if (dot(n, u_cameraPos - v_worldPos) < 0.0) n = -n;
  o_position = vec4(v_worldPos, 1.0);
  o_normal = vec4(n, 0.0);
  o_albedo = vec4(materialBaseColor(v_uv).rgb, 1.0);
}
