// Cube shadow map, layered pass (CubeShadowMap, cube.layered = 1): world positions and uvs
// to the geometry shader, which projects each triangle into every rendered face.
layout(location = 0) in vec3 a_position;
layout(location = 2) in vec2 a_uv;
out vec2 vs_uv;

void main() {
  vs_uv = a_uv;
  gl_Position = vec4(a_position, 1.0);
}
