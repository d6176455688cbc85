// Gaussian blur of both 1D maps, clamp to edge, weights computed on the host by
// sl::rtw::gaussianWeights. Mirrors sl::rtw::gaussianBlur1D (ascending k).
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer Collapsed { float collapsed[]; };
layout(std430, binding = 1) writeonly buffer Blurred { float blurred[]; };
uniform int u_n;
uniform int u_radius;
uniform float u_weights[65];

void main() {
  int i = int(gl_GlobalInvocationID.x);
  if (i >= 2 * u_n) return;
  int axis = i / u_n, k = i - axis * u_n, base = axis * u_n;
  float sum = 0.0;
  for (int d = -u_radius; d <= u_radius; ++d)
    sum += u_weights[d + u_radius] * collapsed[base + clamp(k + d, 0, u_n - 1)];
  blurred[i] = sum;
}
