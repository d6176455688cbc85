// Eq. (1) of Giegl & Wimmer 2007 (§3.2; CPU mirror sl::fvsm::eyePosition): a pixel's eye-space
// position from its screen position and its linear depth in the tiled techniques' eye-space
// depth buffer (eye_depth.comp), and its world position through the inverse view. Eq. 1 is
// z_e times two constant matrices applied to the window position; sl::EyeDepthBuffer::bind
// (core/tiled/EyeDepthBuffer) sets their product, an affine map per axis, from the camera's
// projection P and the frame size: OpenGL's clip w is −z_eye = d, so x_e / d = (ndc_x + b_x) /
// a_x with ndc_x = 2 x_w / width − 1, a_x = P[0][0], b_x = P[2][0] (the paper's eq. 1 in its
// own convention, w = z_e).
layout(binding = SL_UNIT_EYE_DEPTH) uniform sampler2D u_eyeDepth;
uniform vec4 u_eyeRayFromPixel;  // (x_e, y_e) / d = pixel * .xy + .zw
uniform mat4 u_worldFromEye;     // the inverse of the camera's view matrix

// Metres along the view axis at pixel p (0: no surface).
float eyeDepthAt(ivec2 p) {
  return texelFetch(u_eyeDepth, p, 0).r;
}

// Eye-space position of screen position `pixel` (pixels from the frame's bottom-left corner; a
// pixel's centre at +0.5) at depth d (eq. 1).
vec3 eyePosition(vec2 pixel, float d) {
  return vec3((pixel * u_eyeRayFromPixel.xy + u_eyeRayFromPixel.zw) * d, -d);
}

// Eye-space position of the surface at pixel p's centre, d = eyeDepthAt(p) > 0.
vec3 eyePositionAt(ivec2 p, float d) {
  return eyePosition(vec2(p) + 0.5, d);
}

// World position of an eye-space position.
vec3 worldFromEye(vec3 e) {
  return (u_worldFromEye * vec4(e, 1.0)).xyz;
}

// World position of the surface at pixel p's centre, d = eyeDepthAt(p) > 0.
vec3 worldPositionAt(ivec2 p, float d) {
  return worldFromEye(eyePositionAt(p, d));
}
