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
