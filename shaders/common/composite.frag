// Final shading: albedo lit by the sun (Lambert, shadowed by the technique's filtered
// visibility) plus a sky ambient; a sky gradient where there is no surface.
uniform sampler2D u_gPosition;
uniform sampler2D u_gNormal;
uniform sampler2D u_gAlbedo;
uniform sampler2D u_visibility;
uniform vec3 u_towardsLight;
uniform float u_ambient;
uniform vec3 u_cameraPos;
in vec2 v_uv;
out vec4 o_color;

void main() {
  ivec2 px = ivec2(gl_FragCoord.xy);
  vec4 P = texelFetch(u_gPosition, px, 0);
  if (P.w <= 0.0) {
    vec3 horizon = vec3(0.78, 0.85, 0.93), zenith = vec3(0.36, 0.55, 0.80);
    o_color = vec4(mix(horizon, zenith, clamp(v_uv.y * 1.3 - 0.2, 0.0, 1.0)), 1.0);
    return;
  }
  vec3 N = texelFetch(u_gNormal, px, 0).xyz;
  vec3 albedo = texelFetch(u_gAlbedo, px, 0).rgb;
  float vis = texelFetch(u_visibility, px, 0).r;
  float ndl = max(dot(N, u_towardsLight), 0.0);
  float sky = 0.5 + 0.5 * N.y;
  vec3 light = vec3(1.0, 0.96, 0.88) * ndl * vis + u_ambient * mix(vec3(0.55, 0.5, 0.45), vec3(0.75, 0.85, 1.0), sky);
  vec3 c = albedo * light;
  // Soft distance fog keeps far geometry readable.
  float d = length(P.xyz - u_cameraPos);
  c = mix(c, vec3(0.78, 0.85, 0.93), clamp((d - 150.0) / 900.0, 0.0, 0.6));
  o_color = vec4(pow(c, vec3(1.0 / 2.2)), 1.0);
}
