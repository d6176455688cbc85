// Spherical (lat-long) depth pass, vertex stage: world positions and material uv to the
// geometry stage (spherical/depth.geom), which maps each triangle as a whole.
layout(location = 0) in vec3 a_position;
layout(location = 2) in vec2 a_uv;
out vec3 vg_worldPos;
out vec2 vg_uv;

void main() {
  vg_worldPos = a_position;
  vg_uv = a_uv;
}
