// Outside view (view.outside): the outline segments of algo/OutsideView (outlineSegments),
// world space, drawn as lines by the third camera; u_pixelOffset (clip units at w = 1)
// shifts a repeated draw by one pixel so lines are two pixels wide.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_colour;
uniform mat4 u_viewProj;
uniform vec2 u_pixelOffset;
out vec3 v_colour;

void main() {
  v_colour = a_colour;
  gl_Position = u_viewProj * vec4(a_position, 1.0);
  gl_Position.xy += u_pixelOffset * gl_Position.w;
}
