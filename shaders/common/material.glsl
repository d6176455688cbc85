// Material inputs shared by every scene pass; set per draw by SceneGpu::draw (C++).
uniform sampler2D u_baseColorTex;
uniform vec4 u_baseColor;
uniform int u_hasTexture;
uniform int u_alphaMask;
uniform float u_alphaCutoff;

vec4 materialBaseColor(vec2 uv) {
  vec4 c = u_baseColor;
  if (u_hasTexture != 0) c *= texture(u_baseColorTex, uv);
  return c;
}

// glTF alphaMode MASK: fragments below the cutoff are not there (foliage, fences).
bool materialAlphaRejects(vec2 uv) {
  return u_alphaMask != 0 && materialBaseColor(uv).a < u_alphaCutoff;
}

// The same test on the texture's finest level, as the exact reference does
// (ShadowReference's alpha filter samples level 0 bilinearly): light passes use this, so a
// caster's holes do not depend on the light pass's mip footprint (a warped texel's footprint
// varies by orders of magnitude across the map).
bool materialAlphaRejectsLevel0(vec2 uv) {
  if (u_alphaMask == 0) return false;
  float a = u_baseColor.a;
  if (u_hasTexture != 0) a *= textureLod(u_baseColorTex, uv, 0.0).a;
  return a < u_alphaCutoff;
}
