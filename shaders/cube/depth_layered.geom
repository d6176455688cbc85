// Cube shadow map, layered pass: each triangle goes to every rendered face's layer
// (gl_Layer) through that face's 90° perspective (C++: omni::fitCube), skipped where it
// lies wholly outside one plane of the face's frustum. Stored: the distance from the light
// (cube/distance.frag, the same interpolants as the six-pass cube/distance.vert).
#include "cube/distance.glsl"
layout(triangles) in;
layout(triangle_strip, max_vertices = 18) out;
in vec2 vs_uv[];
out vec2 v_uv;
out vec3 v_fromLight;
uniform int u_layerCount;          // rendered faces (6 for a point light)
uniform mat4 u_layerViewProj[6];   // world -> clip of the face in layer l

// True when all three clip positions lie beyond one frustum plane.
bool outsideFrustum(vec4 c0, vec4 c1, vec4 c2) {
  for (int axis = 0; axis < 3; ++axis) {
    if (c0[axis] > c0.w && c1[axis] > c1.w && c2[axis] > c2.w) return true;
    if (c0[axis] < -c0.w && c1[axis] < -c1.w && c2[axis] < -c2.w) return true;
  }
  return false;
}

void main() {
  for (int l = 0; l < u_layerCount; ++l) {
    vec4 c0 = u_layerViewProj[l] * gl_in[0].gl_Position;
    vec4 c1 = u_layerViewProj[l] * gl_in[1].gl_Position;
    vec4 c2 = u_layerViewProj[l] * gl_in[2].gl_Position;
    if (outsideFrustum(c0, c1, c2)) continue;
    gl_Layer = l;
    gl_Position = c0;
    v_uv = vs_uv[0];
    v_fromLight = gl_in[0].gl_Position.xyz - u_cubeLightPos;
    EmitVertex();
    gl_Layer = l;
    gl_Position = c1;
    v_uv = vs_uv[1];
    v_fromLight = gl_in[1].gl_Position.xyz - u_cubeLightPos;
    EmitVertex();
    gl_Layer = l;
    gl_Position = c2;
    v_uv = vs_uv[2];
    v_fromLight = gl_in[2].gl_Position.xyz - u_cubeLightPos;
    EmitVertex();
    EndPrimitive();
  }
}
